#!/usr/bin/env python3
"""A mesh node in no cell is refused with its number and position (issue 55, item 7).

Before, such a mesh passed `efg check` and `efg run` stopped in the factorization ("MUMPS
singular (3 null pivots)") naming no node. The test writes a 2 x 2 quad mesh with `efg mesh`,
appends a node no cell uses (netCDF4: num_nodes + 1), and expects `check` and `run` to exit 2
naming node 10 at (5, 7).

usage: check_orphan_node.py EFG WORKDIR
"""
import os
import shutil
import subprocess
import sys

import netCDF4
import numpy as np

SCENE = """mesh:
  %s
parts:
  - {name: p, blocks: [block_1], material: steel}
materials:
  - {name: steel, model: linear_elastic, youngs_modulus: 2e5, poissons_ratio: 0.3}
boundary_conditions:
  - {name: clamp, type: displacement, node_set: xmin, x: 0, y: 0}
stages:
  - {name: s, driver: implicit, end_time: 1.0}
"""


def with_extra_node(source, target, x, y):
    """Copies an Exodus file, with one more node (coordinates x, y) that no cell uses."""
    with netCDF4.Dataset(source) as src, netCDF4.Dataset(target, "w", format=src.data_model) as dst:
        dst.setncatts({a: src.getncattr(a) for a in src.ncattrs()})
        for name, dim in src.dimensions.items():
            size = None if dim.isunlimited() else len(dim) + (1 if name == "num_nodes" else 0)
            dst.createDimension(name, size)
        for name, var in src.variables.items():
            out = dst.createVariable(name, var.datatype, var.dimensions)
            out.setncatts({a: var.getncattr(a) for a in var.ncattrs()})
            data = var[:]
            if name in ("coordx", "coordy"):
                data = np.append(data, x if name == "coordx" else y)
            elif "num_nodes" in var.dimensions:
                sys.exit(f"unexpected nodal variable {name}")
            out[:] = data


def main():
    efg, work = sys.argv[1], os.path.abspath(sys.argv[2])
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    generated = os.path.join(work, "generated.yaml")
    with open(generated, "w") as f:
        f.write(SCENE % "generate: {element: quad4, lower: [0, 0], upper: [2, 2], cells: [2, 2]}")
    p = subprocess.run([efg, "mesh", generated, os.path.join(work, "square.exo")],
                       capture_output=True, text=True, timeout=60)
    if p.returncode != 0:
        sys.exit(f"efg mesh failed:\n{p.stdout}{p.stderr}")
    with_extra_node(os.path.join(work, "square.exo"), os.path.join(work, "orphan.exo"), 5.0, 7.0)
    scene = os.path.join(work, "orphan.yaml")
    with open(scene, "w") as f:
        f.write(SCENE % "file: orphan.exo")
    failures = []
    for command in ["check", "run"]:
        out = os.path.join(work, "out")
        p = subprocess.run([efg, command, scene] + (["-o", out] if command == "run" else []),
                           capture_output=True, text=True, timeout=60)
        text = p.stdout + p.stderr
        expected = "has 1 node(s) in no cell (the first: node 10 at (5, 7))"
        if p.returncode != 2 or expected not in text or "mesh.file" not in text:
            failures.append(f"{command}: exit {p.returncode}\n{text[-1500:]}")
    if failures:
        sys.exit("\n".join(failures))
    print("a node in no cell refused by check and run, named with its position")


if __name__ == "__main__":
    main()
