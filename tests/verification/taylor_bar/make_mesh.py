#!/usr/bin/env python3
"""Quarter cylinder x >= 0, y >= 0, 0 <= z <= L of HEX8 cells (O-grid section), as Exodus II.

usage: make_mesh.py OUT.e [--radius R] [--length L] --radial NR --axial NZ [--core F]

Section (the quarter disk of radius R), an O-grid of three structured patches, so that no cell
degenerates at the axis or on the rim:
  core   the square [0, a]^2, a = R * ceil(NR/2) / NR, n x n cells, n = ceil(NR/2)
  right  between the core's edge x = a and the arc 0 <= theta <= 45 deg: n cells along the arc,
         m = NR - n cells outward (straight lines from the edge to the arc)
  upper  the same between the edge y = a and the arc 45 <= theta <= 90 deg
NR is the number of cells along a symmetry edge (x axis: n in the core + m outside); the arc has
2 n cells. NZ uniform layers in z. Per layer (n+1)^2 + m (2n+1) nodes.

Exodus II written with netCDF4 (classic 64-bit-offset format) in the layout libexodus writes
(the same writer as tests/verification/thick_cylinder/make_mesh.py, here 3D); one block `rod`,
node sets:
  xsym    x = 0 (written as exactly 0)     ysym    y = 0 (exactly 0)
  impact  z = 0                              top     z = L
  all     every node (file meshes have no automatic `all` set; initial velocities use it)
HEX8 cells: the section quad counter-clockwise seen from +z at z_k, then the same at z_(k+1),
so every cell has a positive Jacobian (checked here).
"""
import argparse
import math

import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from exodus_mesh import write_exodus  # noqa: E402



def section(radius, nr):
    """2D nodes (x, y) and counter-clockwise quads of the quarter-disk O-grid."""
    n = (nr + 1) // 2
    m = nr - n
    if m < 1:
        raise ValueError("need at least 2 cells across the radius")
    a = radius * n / nr
    pts = []
    index = {}

    def add(key, x, y):
        index[key] = len(pts)
        pts.append((x, y))

    for j in range(n + 1):
        for i in range(n + 1):
            add(("A", i, j), a * i / n, a * j / n)
    for r in range(1, m + 1):
        t = r / m
        for j in range(n + 1):  # right patch, theta from 0 to 45 deg
            th = 0.25 * math.pi * j / n
            x = (1 - t) * a + t * radius * math.cos(th)
            y = (1 - t) * a * j / n + t * radius * math.sin(th)
            add(("B", r, j), x, 0.0 if j == 0 else y)
        for i in range(n):  # upper patch, theta from 90 down to (not including) 45 deg
            th = 0.5 * math.pi - 0.25 * math.pi * i / n
            x = (1 - t) * a * i / n + t * radius * math.cos(th)
            y = (1 - t) * a + t * radius * math.sin(th)
            add(("C", r, i), 0.0 if i == 0 else x, y)

    def A(i, j):
        return index[("A", i, j)]

    def B(r, j):
        return A(n, j) if r == 0 else index[("B", r, j)]

    def C(r, i):
        if r == 0:
            return A(i, n)
        return B(r, n) if i == n else index[("C", r, i)]

    quads = []
    for j in range(n):
        for i in range(n):
            quads.append((A(i, j), A(i + 1, j), A(i + 1, j + 1), A(i, j + 1)))
    for r in range(m):
        for j in range(n):
            quads.append((B(r, j), B(r + 1, j), B(r + 1, j + 1), B(r, j + 1)))
    for r in range(m):
        for i in range(n):
            quads.append((C(r, i), C(r, i + 1), C(r + 1, i + 1), C(r + 1, i)))
    xy = np.array(pts)
    quads = np.array(quads, dtype=np.int64)
    # every quad counter-clockwise with positive corner cross products (no degenerate corner)
    for q in quads:
        p = xy[q]
        for k in range(4):
            e1 = p[(k + 1) % 4] - p[k]
            e0 = p[k] - p[(k - 1) % 4]
            assert e0[0] * e1[1] - e0[1] * e1[0] > 0, "non-convex or clockwise section cell"
    return xy, quads


def rod(radius, length, nr, nz):
    xy, quads = section(radius, nr)
    ns = len(xy)
    z = np.linspace(0.0, length, nz + 1)
    x = np.tile(xy[:, 0], nz + 1)
    y = np.tile(xy[:, 1], nz + 1)
    zz = np.repeat(z, ns)
    conn = []
    for k in range(nz):
        for q in quads:
            lo = [k * ns + v + 1 for v in q]
            hi = [(k + 1) * ns + v + 1 for v in q]
            conn.append(lo + hi)
    conn = np.array(conn, dtype=np.int32)
    ids = np.arange(1, len(x) + 1, dtype=np.int32)
    node_sets = {
        "xsym": ids[x == 0.0],
        "ysym": ids[y == 0.0],
        "impact": ids[:ns],
        "top": ids[nz * ns:],
        "all": ids,
    }
    return x, y, zz, conn, node_sets


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("out")
    p.add_argument("--radius", type=float, default=3.2)
    p.add_argument("--length", type=float, default=32.4)
    p.add_argument("--radial", type=int, required=True)
    p.add_argument("--axial", type=int, required=True)
    args = p.parse_args()
    if args.radius <= 0 or args.length <= 0 or args.radial < 2 or args.axial < 1:
        p.error("need radius, length > 0, radial >= 2, axial >= 1")
    x, y, z, conn, ns = rod(args.radius, args.length, args.radial, args.axial)
    write_exodus(args.out, "Taylor bar quarter cylinder R=%g L=%g %dx%d"
                 % (args.radius, args.length, args.radial, args.axial), [x, y, z], conn, "HEX8", ns,
                 block_name="rod")
    print("%s: %d nodes, %d HEX8 cells" % (args.out, len(x), len(conn)))


if __name__ == "__main__":
    main()
