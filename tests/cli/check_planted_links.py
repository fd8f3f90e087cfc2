#!/usr/bin/env python3
"""Writes never escape the output folder through symbolic links (issue 55, item 3).

1. Links planted in the output folder at every name a run writes (NAME.e.part, NAME.e, the
   history's .part and final name, the report and its .part) and pointing outside it: the run
   replaces them with its own regular files, and the link targets outside stay as they were.
2. output.file through a linked subfolder (link/x.e, link -> a folder outside): exit 2 naming
   output.file and "leads outside the output folder"; nothing is written outside.

usage: check_planted_links.py EFG WORKDIR
"""
import os
import shutil
import subprocess
import sys

SCENE = """title: planted links
mesh:
  generate: {element: quad4, lower: [0, 0], upper: [1, 1], cells: [4, 4]}
parts:
  - {name: p, blocks: [block_1], material: m, plane: strain}
materials:
  - {name: m, model: linear_elastic, youngs_modulus: 1000.0, poissons_ratio: 0.3, density: 1.0}
boundary_conditions:
  - {name: base, type: displacement, node_set: ymin, x: 0, y: 0}
loads:
  - {name: pull, type: traction, side_set: ymax, value: [0, 1]}
stages:
  - {name: s, driver: implicit, end_time: 1}
output:
  %s
  history: history.csv
"""


def main():
    efg, work = sys.argv[1], os.path.abspath(sys.argv[2])
    shutil.rmtree(work, ignore_errors=True)
    outside, out = os.path.join(work, "outside"), os.path.join(work, "out")
    os.makedirs(outside)
    os.makedirs(out)
    failures = []

    # 1. Links at every name the run writes.
    scene = os.path.join(work, "links.yaml")
    with open(scene, "w") as f:
        f.write(SCENE % "fields: [displacement]")
    names = ["links.e.part", "links.e", "history.csv.part", "history.csv",
             "links.e.report.json", "links.e.report.json.part"]
    for name in names:
        target = os.path.join(outside, name + ".target")
        with open(target, "w") as f:
            f.write("precious\n")
        os.symlink(target, os.path.join(out, name))
    p = subprocess.run([efg, "run", scene, "-o", out], capture_output=True, text=True, timeout=100)
    if p.returncode != 0:
        failures.append(f"run with planted links: exit {p.returncode}\n{p.stdout[-1500:]}{p.stderr}")
    for name in names:
        with open(os.path.join(outside, name + ".target")) as f:
            if f.read() != "precious\n":
                failures.append(f"the run wrote through the link {name} into its target outside")
    for name in ["links.e", "history.csv", "links.e.report.json"]:
        path = os.path.join(out, name)
        if os.path.islink(path) or not os.path.isfile(path) or os.path.getsize(path) == 0:
            failures.append(f"{name} is not the run's own regular file")
    for name in ["links.e.part", "history.csv.part", "links.e.report.json.part"]:
        if os.path.lexists(os.path.join(out, name)):
            failures.append(f"{name} left behind")

    # 2. output.file through a linked subfolder.
    escape = os.path.join(work, "escape.yaml")
    with open(escape, "w") as f:
        f.write(SCENE % "file: link/x.e\n  fields: [displacement]")
    out2 = os.path.join(work, "out2")
    os.makedirs(out2)
    os.symlink(outside, os.path.join(out2, "link"))
    before = sorted(os.listdir(outside))
    for command in ["check", "run"]:
        p = subprocess.run([efg, command, escape, "-o", out2], capture_output=True, text=True,
                           timeout=100)
        text = p.stdout + p.stderr
        if p.returncode != 2 or "output.file: 'out2/link/x.e' leads outside the output folder" \
                not in text.replace(work + "/", ""):
            failures.append(f"{command} through a linked folder: exit {p.returncode}\n{text[-1500:]}")
    if sorted(os.listdir(outside)) != before:
        failures.append(f"files written outside: {sorted(set(os.listdir(outside)) - set(before))}")

    if failures:
        sys.exit("\n".join(failures))
    print("planted links replaced, never followed; a linked output folder refused")


if __name__ == "__main__":
    main()
