#!/usr/bin/env python3
"""Meshes for the curved-tool check (tests/scenes/contact/cylinder_press_mesh_*.yaml): block
`block`, the elastic block [-1, 1] x [-1, 0] of 40 x 20 quad4 cells (node set `base` at
y = -1), and block `ring`, a rigid annulus of outer radius 0.5 (inner 0.3, 2 cells across)
centred at (0, 0.5), N cells around, a node at the lowest point (0, 0) of the circle, nodes of
its own. The ring's outer boundary is the inscribed N-gon of the analytic cylinder (sag
R (1 - cos(pi / N)) midway between its corners).
usage: make_ring.py  (writes ring_64.exo and ring_128.exo here)"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "verification"))
from exodus_mesh import write_exodus  # noqa: E402

R_IN, R_OUT, LAYERS, CENTRE = 0.3, 0.5, 2, (0.0, 0.5)


def block():
    nx, ny = 40, 20
    x = [-1 + 2 * i / nx for j in range(ny + 1) for i in range(nx + 1)]
    y = [-1 + j / ny for j in range(ny + 1) for i in range(nx + 1)]
    node = lambda i, j: j * (nx + 1) + i + 1  # noqa: E731
    conn = [[node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]
            for j in range(ny) for i in range(nx)]
    return x, y, conn, [node(i, 0) for i in range(nx + 1)]


def ring(n, first):
    x, y = [], []
    for i in range(LAYERS + 1):
        r = R_IN + (R_OUT - R_IN) * i / LAYERS
        for j in range(n):
            t = -math.pi / 2 + 2 * math.pi * j / n
            x.append(CENTRE[0] + r * math.cos(t))
            y.append(CENTRE[1] + r * math.sin(t))
    node = lambda i, j: first + i * n + (j % n)  # noqa: E731
    conn = [[node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]
            for i in range(LAYERS) for j in range(n)]
    return x, y, conn


if __name__ == "__main__":
    for n in (64, 128):
        bx, by, bconn, base = block()
        rx, ry, rconn = ring(n, len(bx) + 1)
        write_exodus(os.path.join(HERE, "ring_%d.exo" % n), "block and rigid ring %d" % n,
                     [np.array(bx + rx), np.array(by + ry)], np.array(bconn), "QUAD4",
                     {"base": base}, block_name="block",
                     more_blocks=[("ring", np.array(rconn), "QUAD4")])
