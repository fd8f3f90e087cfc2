#!/usr/bin/env python3
"""A scripted mutation fuzzer for efg's input readers (issue 14): scene files (YAML syntax, schema,
cross-references, solver maps) and Exodus meshes; and (issue 55) loads singular at a time the run
reaches on 1-3 ranks, damaged restart files, links planted in the output folder. Each case mutates a seed file, runs
`efg check` on it (and `efg run` on some that pass, on a tiny model; every mutated mesh is also
run read in slices, mesh.read: distributed, on 1 or 2 ranks), and requires a clean outcome:
exit 0, 2 (bad input), 3 (numerical failure: check builds the model and plans explicit steps too)
or, for runs, 4 (verification); no signal, no timeout, no raw library exception (exit 1). Deterministic for a given --seed.

usage: fuzz_inputs.py EFG WORKDIR [--cases N] [--seed S] [--timeout SECONDS]
Prints each failing case and leaves it in WORKDIR/failures; exit 1 when any case failed.
"""
import argparse
import os
import random
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# Values that have broken readers before: huge, tiny, non-finite, wrong types, empty, odd text.
NASTY = ["0", "-1", "1e300", "-1e300", "1e-300", "nan", ".nan", ".inf", "-.inf", "2147483648",
         "9223372036854775808", "3e9", "''", "~", "[]", "{}", "[1, 2, 3, 4]", "[[1]]", "true",
         "'0x10'", "!!binary aGk=", "&a x", "*a", "\"\\u0000\"", "1_000", "0.1e", "--1", "+5",
         "hex8", "tet4", "quad4", "xmin", "all", "block_1", "implicit", "explicit", "direct",
         "MueLu", "Ifpack2", "none", "penalty", "nitsche", "neo_hookean", "a" * 300]
TOKENS = [": ", "- ", "[", "]", "{", "}", ",", "#", "\t", "\n", "---", "...", "&x ", "*x", "? ",
          "|", ">", "%YAML 1.2\n", "\"", "'", "!!str ", "<<: "]


def mutate_scene(text, rng):
    lines = text.split("\n")
    for _ in range(rng.randint(1, 3)):
        kind = rng.randrange(7)
        i = rng.randrange(len(lines))
        line = lines[i]
        if kind == 0 and ":" in line:  # replace a value
            key = line[: line.index(":") + 1]
            lines[i] = key + " " + rng.choice(NASTY)
        elif kind == 1:  # delete a line
            del lines[i]
        elif kind == 2:  # duplicate a line
            lines.insert(i, line)
        elif kind == 3 and line:  # insert a syntax token
            j = rng.randrange(len(line) + 1)
            lines[i] = line[:j] + rng.choice(TOKENS) + line[j:]
        elif kind == 4:  # replace a number inside flow lists
            words = line.split(",")
            if len(words) > 1:
                k = rng.randrange(len(words))
                words[k] = " " + rng.choice(NASTY)
                lines[i] = ",".join(words)
        elif kind == 5 and line:  # flip a character
            j = rng.randrange(len(line))
            lines[i] = line[:j] + chr(rng.randrange(32, 127)) + line[j + 1:]
        else:  # swap two lines
            k = rng.randrange(len(lines))
            lines[i], lines[k] = lines[k], lines[i]
        if not lines:
            lines = [""]
    return "\n".join(lines)


def mutate_bytes(data, rng):
    data = bytearray(data)
    kind = rng.randrange(3)
    if kind == 0:  # flip bytes
        for _ in range(rng.randint(1, 8)):
            data[rng.randrange(len(data))] = rng.randrange(256)
    elif kind == 1:  # truncate
        data = data[: rng.randrange(len(data))]
    else:  # overwrite a run with 0xff or 0x00
        at = rng.randrange(len(data))
        data[at : at + 16] = bytes([rng.choice([0, 255])]) * 16
    return bytes(data)


def seeds():
    scenes = []
    for folder in ["input", "tests/scenes", "tests/scenes/solvers", "tests/scenes/impact"]:
        path = os.path.join(ROOT, folder)
        for name in sorted(os.listdir(path)):
            if name.endswith(".yaml"):
                scenes.append(os.path.join(path, name))
    return scenes


def run(cmd, cwd, timeout):
    # Each run its own Open MPI session folder: two MPI starts at once in one folder race on
    # creating it (Open MPI 4.1: "mkdir ... File exists", orte_init fails, exit 1), and the
    # fuzzer's two workers start processes side by side. Short, under /tmp: it holds sockets.
    session = tempfile.mkdtemp(prefix="efz")
    env = dict(os.environ, OMPI_MCA_orte_tmpdir_base=session)
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout,
                           errors="replace", env=env)
        return p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired:
        return "timeout", ""
    finally:
        shutil.rmtree(session, ignore_errors=True)


def verdict(code, log, allowed):
    if code == "timeout":
        return "hang (timeout)"
    if code < 0:
        return "crash (signal %d)" % -code
    if code not in allowed:
        return "exit %d: %s" % (code, log.strip().splitlines()[-1] if log.strip() else "")
    return None


def mpi_launch(rng, ranks_max=3):
    ranks = rng.randint(1, ranks_max)
    if ranks == 1 or not shutil.which("mpirun"):
        return [], 1
    launch = ["mpirun", "-np", str(ranks), "--oversubscribe"]
    if os.geteuid() == 0:
        launch.append("--allow-run-as-root")
    return launch, ranks


def runtime_case(args, rng, case, restart_bytes):
    """The families of issue 55: a load singular at a time the run reaches, on 1-3 ranks (never
    a hang); a damaged restart file (exit 0 or 2, never a restart from zeros by exit 1 or a
    crash); links planted in the output folder (never followed)."""
    kind = rng.randrange(3)
    if kind == 0:
        singular = rng.choice(["0.003", "0.004", "0.0055", "0.01", "0"])
        text = SINGULAR_SCENE.replace("T0", singular)
        with open(os.path.join(case, "scene.yaml"), "w") as f:
            f.write(text)
        launch, ranks = mpi_launch(rng)
        code, log = run(launch + [args.efg, "run", "scene.yaml", "-o", "out"], case, args.timeout)
        return "singular load at t = %s on %d rank(s)" % (singular, ranks), verdict(code, log, (0, 2, 3))
    if kind == 1:
        with open(os.path.join(case, "explicit_contact.e"), "wb") as f:
            f.write(mutate_bytes(restart_bytes, rng))
        shutil.copy(os.path.join(ROOT, "tests/scenes/faults/implicit_restart.yaml"),
                    os.path.join(case, "scene.yaml"))
        launch, ranks = mpi_launch(rng, 2)
        code, log = run([args.efg, "check", "scene.yaml"], case, args.timeout)
        problem = verdict(code, log, (0, 2, 3))
        if problem is None:
            code, log = run(launch + [args.efg, "run", "scene.yaml", "-o", "out"], case,
                            args.timeout)
            problem = verdict(code, log, (0, 2, 3))
        return "damaged restart file on %d rank(s)" % ranks, problem
    outside = os.path.join(case, "outside")
    os.makedirs(outside)
    os.makedirs(os.path.join(case, "out"))
    names = ["scene.e.part", "scene.e", "history.csv.part", "history.csv", "scene.e.report.json"]
    for name in rng.sample(names, rng.randint(1, len(names))):
        target = os.path.join(outside, name)
        with open(target, "w") as f:
            f.write("outside\n")
        os.symlink(target, os.path.join(case, "out", name))
    with open(os.path.join(case, "scene.yaml"), "w") as f:
        f.write(SINGULAR_SCENE.replace("1/(t-T0)", "1"))
    code, log = run([args.efg, "run", "scene.yaml", "-o", "out"], case, args.timeout)
    problem = verdict(code, log, (0,))
    for name in os.listdir(outside):
        with open(os.path.join(outside, name)) as f:
            if f.read() != "outside\n":
                problem = "wrote through the planted link %s" % name
    return "links planted in the output folder", problem


def one_case(args, index, scene_seeds, mesh_bytes, restart_bytes):
    rng = random.Random(args.seed * 1000003 + index)
    case = os.path.join(args.workdir, "case%05d" % index)
    os.makedirs(case, exist_ok=True)
    if rng.random() < 0.2:  # run-time failures, restarts, links (issue 55)
        what, problem = runtime_case(args, rng, case, restart_bytes)
        return finish_case(args, case, what, problem)
    if rng.random() < 0.25:  # a mutated Exodus mesh behind a valid scene
        with open(os.path.join(case, "mesh.e"), "wb") as f:
            f.write(mutate_bytes(mesh_bytes, rng))
        text = MESH_SCENE
        what = "exodus"
    else:
        with open(rng.choice(scene_seeds)) as f:
            text = mutate_scene(f.read(), rng)
        what = "scene"
    scene = os.path.join(case, "scene.yaml")
    with open(scene, "w") as f:
        f.write(text)
    code, log = run([args.efg, "check", "scene.yaml"], case, args.timeout)
    problem = verdict(code, log, (0, 2, 3))
    # The mutated mesh read in slices (mesh.read: distributed), on 1 or 2 ranks: every rank
    # reads part of the file, so a bad index or set must stop them all cleanly, never hang.
    if problem is None and what == "exodus":
        with open(os.path.join(case, "distributed.yaml"), "w") as f:
            f.write(text.replace("file: mesh.e", "file: mesh.e\n  read: distributed"))
        launch = []
        if rng.random() < 0.5 and shutil.which("mpirun"):
            launch = ["mpirun", "-np", "2", "--oversubscribe"]
            if os.geteuid() == 0:
                launch.append("--allow-run-as-root")
        code, log = run(launch + [args.efg, "run", "distributed.yaml", "-o", "out"], case,
                        args.timeout)
        problem = verdict(code, log, (0, 2, 3, 4))
        what += "+distributed run on %d rank(s)" % (2 if launch else 1)
    # A scene that passes check and is small must also run cleanly (tiny meshes only).
    if problem is None and code == 0 and what == "scene" and rng.random() < 0.3 and small(text):
        code, log = run([args.efg, "run", "scene.yaml", "-o", "out"], case, args.timeout)
        problem = verdict(code, log, (0, 2, 3, 4))
        what += "+run"
    return finish_case(args, case, what, problem)


def finish_case(args, case, what, problem):
    if problem is None:
        shutil.rmtree(case, ignore_errors=True)
        return None
    failed = os.path.join(args.workdir, "failures", os.path.basename(case))
    shutil.rmtree(failed, ignore_errors=True)
    shutil.move(case, failed)
    return "%s (%s): %s [%s]" % (os.path.basename(case), what, problem, failed)


def small(text):
    # Runs only on meshes of at most a few hundred cells: the fuzzer looks for crashes, not work.
    import re
    for m in re.finditer(r"cells:\s*\[([^\]]*)\]", text):
        total = 1
        for w in m.group(1).split(","):
            try:
                total *= int(w)
            except ValueError:
                return False
        if total > 400:
            return False
    return "end_time" not in text or "1e" not in text


MESH_SCENE = """mesh:
  file: mesh.e
parts:
  - {name: p, blocks: [block_1], material: m}
materials:
  - {name: m, model: linear_elastic, youngs_modulus: 100.0, poissons_ratio: 0.3}
boundary_conditions:
  - {name: clamp, type: displacement, node_set: xmin, x: 0, y: 0, z: 0}
stages:
  - {name: load, driver: implicit, end_time: 1}
"""


# A load infinite at t = T0, a time an explicit run of dt 0.001 may reach (issue 55, item 1).
SINGULAR_SCENE = """mesh:
  generate: {element: quad4, lower: [0, 0], upper: [10, 2], cells: [10, 4]}
parts:
  - {name: p, blocks: [block_1], material: m}
materials:
  - {name: m, model: linear_elastic, youngs_modulus: 1, poissons_ratio: 0.3, density: 1}
boundary_conditions:
  - {name: clamp, type: displacement, node_set: xmin, x: 0, y: 0}
loads:
  - {name: tip, type: traction, side_set: xmax, value: [0, "1/(t-T0)"]}
stages:
  - {name: s, driver: explicit, end_time: 0.01, dt: 0.001, energy_balance_limit: 0}
output:
  history: history.csv
"""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("efg")
    ap.add_argument("workdir")
    ap.add_argument("--cases", type=int, default=300)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=30)
    args = ap.parse_args()
    args.efg = os.path.abspath(args.efg)
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    # The mesh seed: efg writes one for a small generated box.
    with open(os.path.join(args.workdir, "box.yaml"), "w") as f:
        f.write(MESH_SCENE.replace("file: mesh.e",
                                   "generate: {element: hex8, lower: [0, 0, 0], upper: [2, 1, 1], "
                                   "cells: [4, 2, 2]}"))
    subprocess.run([args.efg, "mesh", "box.yaml", "mesh.e"], cwd=args.workdir, check=True,
                   capture_output=True)
    with open(os.path.join(args.workdir, "mesh.e"), "rb") as f:
        mesh_bytes = f.read()
    # The restart seed: an explicit run's results with the restart fields.
    subprocess.run([args.efg, "run", os.path.join(ROOT, "tests/scenes/faults/explicit_contact.yaml"),
                    "-o", "restart"], cwd=args.workdir, check=True, capture_output=True)
    with open(os.path.join(args.workdir, "restart", "explicit_contact.e"), "rb") as f:
        restart_bytes = f.read()
    scene_seeds = seeds()
    with ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(lambda i: one_case(args, i, scene_seeds, mesh_bytes, restart_bytes),
                                range(args.cases)))
    failures = [r for r in results if r]
    for r in failures:
        print("FAILED " + r)
    print("%d cases (seed %d), %d failures" % (args.cases, args.seed, len(failures)))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
