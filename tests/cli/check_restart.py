#!/usr/bin/env python3
"""Restart from a record (scene key initial_state, issue 15 item 1): a run split in two at a
stage boundary, the second part reading the first's last record (generalized displacement and
velocity, J2 material history), ends where the whole run ends.
The scene is the strip of tests/verification/strip_springback (coarsest level): explicit bending
in two stages, then the implicit springback. Three cases, each against the whole run:
  - restart into the implicit springback stage: fields equal to 1e-12 (relative);
  - restart into the second explicit stage: fields equal to 1e-9 (the energy account restarts);
  - the springback restart on 2 ranks from a one-rank record: 1e-8;
  - the same with the mesh made in slices (mesh.read: distributed: each rank reads its slice of
    the record and fetches its part's nodes; results one file per rank, joined here by node id):
    1e-8.
usage: check_restart.py EFG OUTDIR [LAUNCHER]   (LAUNCHER: the MPI launch command for 2 ranks,
words joined by '|', e.g. mpiexec|--allow-run-as-root|-n|2; without it the 2-rank case is skipped)
(exit 1 when a check fails)"""
import copy
import glob
import os
import re
import subprocess
import sys

import netCDF4
import numpy as np
import yaml

efg, out = sys.argv[1], os.path.abspath(sys.argv[2])
launcher = sys.argv[3].split("|") if len(sys.argv) > 3 and sys.argv[3] else []
here = os.path.dirname(os.path.abspath(__file__))
base = yaml.safe_load(open(os.path.join(here, "..", "verification", "strip_springback",
                                        "strip_springback.yaml")))
base["output"]["fields"] = ["displacement", "stress", "plastic_strain", "generalized_displacement",
                            "generalized_velocity", "material_state"]
T = "T"
base["stages"] = [
    {"name": "form", "driver": "explicit", "end_time": "T / 2", "output_interval": "T / 4"},
    {"name": "form_more", "driver": "explicit", "end_time": T, "output_interval": "T / 4"},
    {"name": "release", "driver": "implicit", "end_time": "2 * T", "load_steps": 4,
     "springback": True, "output_interval": "T / 4"},
]
for bc in base["boundary_conditions"]:
    if bc["stages"] == ["form"]:
        bc["stages"] = ["form", "form_more"]
failures = []


def check(ok, text):
    print(("ok    " if ok else "FAIL  ") + text)
    if not ok:
        failures.append(text)


def run(name, stages, restart=None, parallel=False, distributed=False):
    scene = copy.deepcopy(base)
    if distributed:
        scene["mesh"]["read"] = "distributed"
    scene["stages"] = [s for s in scene["stages"] if s["name"] in stages]
    for bc in scene["boundary_conditions"]:
        bc["stages"] = [s for s in bc["stages"] if s in stages] or ["unused"]
    scene["boundary_conditions"] = [bc for bc in scene["boundary_conditions"]
                                    if bc["stages"] != ["unused"]]
    if restart:
        scene["initial_state"] = {"file": restart}
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, name + ".yaml")
    yaml.safe_dump(scene, open(path, "w"), sort_keys=False)
    cmd = [efg, "run", path, "-o", os.path.join(out, name)]
    if parallel:
        cmd = launcher + cmd
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("%s: efg failed (exit %d):\n%s" % (name, r.returncode, (r.stdout + r.stderr)[-3000:]))
    return os.path.join(out, name, name + ".e")


def last_fields_of(path):
    d = netCDF4.Dataset(path)
    names = ["".join(c.decode() for c in row if c) for row in d["name_nod_var"][:].data]
    fields = {n: np.array(d["vals_nod_var%d" % (i + 1)][-1]) for i, n in enumerate(names)}
    ids = np.array(d["node_num_map"][:]) if "node_num_map" in d.variables else \
        np.arange(1, len(next(iter(fields.values()))) + 1)
    return float(d["time_whole"][-1]), fields, ids


def last_fields(path):
    """The last record's nodal fields; a run written one file per rank (path.<ranks>.<rank>)
    is joined by the pieces' node ids."""
    pieces = [path] if os.path.exists(path) else sorted(
        p for p in glob.glob(path + ".*.*") if re.fullmatch(r"\.\d+\.\d+", p[len(path):]))
    joined, t = {}, None
    for piece in pieces:
        t, fields, ids = last_fields_of(piece)
        for name, values in fields.items():
            joined.setdefault(name, {}).update(zip(ids.tolist(), values.tolist()))
    return t, {n: np.array([v[i] for i in sorted(v)]) for n, v in joined.items()}


def compare(a, b, what, tolerance):
    ta, fa = last_fields(a)
    tb, fb = last_fields(b)
    worst, where = 0.0, ""
    for name in ("displacement_x", "displacement_y", "stress_xx", "plastic_strain",
                 "material_state_7"):
        scale = np.max(np.abs(fa[name]))
        if not scale > 0:
            check(False, f"{what}: {name} is zero everywhere in the whole run")
            continue
        diff = np.max(np.abs(fa[name] - fb[name])) / scale
        if diff >= worst:
            worst, where = diff, name
    check(abs(ta - tb) < 1e-12 * abs(ta) and worst < tolerance,
          f"{what}: last record t = {tb:.6g} vs {ta:.6g}, largest difference {worst:.2e} "
          f"({where}) < {tolerance:g}")


whole = run("whole", ["form", "form_more", "release"])
formed = run("formed", ["form", "form_more"])
compare(whole, run("springback_restart", ["release"], restart=formed), "restart into the implicit "
        "springback stage", 1e-12)
half = run("half", ["form"])
compare(whole, run("explicit_restart", ["form_more", "release"], restart=half),
        "restart into the second explicit stage", 1e-9)
if launcher:
    compare(whole, run("springback_restart_np2", ["release"], restart=formed, parallel=True),
            "springback restart on 2 ranks from a one-rank record", 1e-8)
    compare(whole, run("springback_restart_distributed", ["release"], restart=formed,
                       parallel=True, distributed=True),
            "springback restart on 2 ranks, mesh and record read in slices", 1e-8)
sys.exit(1 if failures else 0)
