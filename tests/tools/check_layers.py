#!/usr/bin/env python3
"""The folder graph of efg's sources (issue 13, item 11): every #include "folder/..." between
top-level folders must go from a higher layer to a lower one (or stay inside its folder), so that
no cycle can form. The order, lowest first:

  tensor < materials                     physics kernels (physics/), free of Trilinos
  core < expressions < geometry < mesh < parallel < io < scene < discretization
  < model                                model data the operators read (scene, mesh, parts,
                                         curves, exact solutions)
  < solvers < operators < shells         shells: the shell formulation beside the solid's
  < verification                         verification: error norms of a solution
  < contact                              rigid bodies and contact forces (operators' level)
  < drivers < run < app

usage: check_layers.py SOURCE_ROOT   (exit 1 naming each include that points upward or sideways)
"""
import os
import re
import sys

ORDER = ["tensor", "materials", "core", "expressions", "geometry", "mesh", "parallel", "io", "scene",
         "discretization", "model", "solvers", "operators", "shells", "verification", "contact", "drivers",
         "run",
         "app"]
RANK = {name: i for i, name in enumerate(ORDER)}
# physics kernels must not reach into the Trilinos side at all
PHYSICS = {"tensor", "materials"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/')

root = sys.argv[1]
problems, edges = [], set()
for top in ["src", "physics"]:
    for folder in sorted(os.listdir(os.path.join(root, top))):
        path = os.path.join(root, top, folder)
        if not os.path.isdir(path):
            continue
        if folder not in RANK:
            problems.append("%s/%s: a folder the layer order does not know" % (top, folder))
            continue
        for dirpath, _, files in os.walk(path):
            for name in files:
                if not name.endswith((".hpp", ".cpp", ".hpp.in")):
                    continue
                file = os.path.join(dirpath, name)
                with open(file) as f:
                    for number, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if not m or m.group(1) == folder:
                            continue
                        target = m.group(1)
                        edges.add((folder, target))
                        bad = target not in RANK or RANK[target] > RANK[folder] or (
                            folder in PHYSICS and target not in PHYSICS)
                        if bad:
                            problems.append("%s:%d: %s includes %s (not below it)" %
                                            (os.path.relpath(file, root), number, folder, target))
for p in problems:
    print(p)
print("%d folder dependencies checked, %d problems" % (len(edges), len(problems)))
sys.exit(1 if problems else 0)
