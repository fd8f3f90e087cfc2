#!/usr/bin/env python3
"""Quarter annulus a <= r <= b, 0 <= theta <= 90 deg, of QUAD4 cells, as an Exodus II mesh.

usage: make_mesh.py OUT.e --inner a --outer b --radial NR --hoop NT

NR cells in r (uniform spacing (b - a) / NR), NT cells in theta (uniform, 90 / NT degrees).
Nodes lie on the circles; cell sides are straight chords. Sets:
  node sets  xaxis (theta = 0, the y = 0 edge), yaxis (theta = 90 deg, the x = 0 edge; x is
             written as exactly 0 there)
  side sets  inner (r = a), outer (r = b)

The file is written with netCDF4 (classic 64-bit-offset format) in the layout that libexodus
(and efg's `efg mesh`) writes: the variables src/io/ExodusReader.cpp reads through
ex_get_init / ex_get_coord / ex_get_block / ex_get_conn / ex_get_set / ex_get_names.
Node numbering: node (i, j) (i radial 0..NR, j hoop 0..NT) is j (NR + 1) + i + 1. Cell (i, j)
has nodes (i, j), (i+1, j), (i+1, j+1), (i, j+1): counter-clockwise, so Exodus QUAD4 side 2 is
r = r_(i+1) and side 4 is r = r_i.
"""
import argparse

import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from exodus_mesh import write_exodus  # noqa: E402



def annulus(a, b, nr, nt):
    r = np.linspace(a, b, nr + 1)
    theta = np.linspace(0.0, 0.5 * np.pi, nt + 1)
    rr, tt = np.meshgrid(r, theta)  # [j, i]
    x = (rr * np.cos(tt)).ravel()
    y = (rr * np.sin(tt)).ravel()
    x[nt * (nr + 1):] = 0.0  # theta = 90 deg exactly on the axis
    y[: nr + 1] = 0.0

    def node(i, j):
        return j * (nr + 1) + i + 1

    conn = np.array([[node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]
                     for j in range(nt) for i in range(nr)], dtype=np.int32)

    def cell(i, j):
        return j * nr + i + 1

    node_sets = {
        "xaxis": np.array([node(i, 0) for i in range(nr + 1)], dtype=np.int32),
        "yaxis": np.array([node(i, nt) for i in range(nr + 1)], dtype=np.int32),
    }
    side_sets = {
        "inner": (np.array([cell(0, j) for j in range(nt)], dtype=np.int32),
                  np.full(nt, 4, dtype=np.int32)),
        "outer": (np.array([cell(nr - 1, j) for j in range(nt)], dtype=np.int32),
                  np.full(nt, 2, dtype=np.int32)),
    }
    return x, y, conn, node_sets, side_sets


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("out")
    p.add_argument("--inner", type=float, required=True)
    p.add_argument("--outer", type=float, required=True)
    p.add_argument("--radial", type=int, required=True)
    p.add_argument("--hoop", type=int, required=True)
    args = p.parse_args()
    if not (0 < args.inner < args.outer) or args.radial < 1 or args.hoop < 1:
        p.error("need 0 < inner < outer, radial >= 1, hoop >= 1")
    x, y, conn, ns, ss = annulus(args.inner, args.outer, args.radial, args.hoop)
    write_exodus(args.out, "thick cylinder quarter annulus a=%g b=%g %dx%d"
                 % (args.inner, args.outer, args.radial, args.hoop), [x, y], conn, "QUAD4", ns, ss,
                 block_name="annulus")
    print("%s: %d nodes, %d QUAD4 cells" % (args.out, len(x), len(conn)))


if __name__ == "__main__":
    main()
