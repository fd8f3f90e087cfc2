#!/usr/bin/env python3
"""Mesh for the one-sided rigid tool check (tests/scenes/contact/flat_punch_skin_3d.yaml): block
`block`, the unit cube of 4 x 4 x 4 hex8 cells (node sets `base` z = 0, `left` x = 0, `front`
y = 0), and block `skin`, a 2 x 2 quad4 surface at z = 1 over [-0.5, 1.5]^2 (nodes of its own),
its nodes ordered so that the right-hand normal points down (-z), to the cube: the bottom face
of flat_punch_3d.yaml's analytic box as a surface.
usage: make_skin_punch.py  (writes skin_punch.exo here)"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "verification"))
from exodus_mesh import write_exodus  # noqa: E402

n = 4
grid = [(i / n, j / n, k / n) for k in range(n + 1) for j in range(n + 1) for i in range(n + 1)]
node = lambda i, j, k: k * (n + 1) ** 2 + j * (n + 1) + i + 1  # noqa: E731
hexes = [[node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
          node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)]
         for k in range(n) for j in range(n) for i in range(n)]
sets = {"base": [node(i, j, 0) for j in range(n + 1) for i in range(n + 1)],
        "left": [node(0, j, k) for k in range(n + 1) for j in range(n + 1)],
        "front": [node(i, 0, k) for k in range(n + 1) for i in range(n + 1)]}
first = len(grid) + 1
skin = [(-0.5 + i, -0.5 + j, 1.0) for j in range(3) for i in range(3)]
snode = lambda i, j: first + j * 3 + i  # noqa: E731
quads = [[snode(i, j), snode(i, j + 1), snode(i + 1, j + 1), snode(i + 1, j)]  # normal -z
         for j in range(2) for i in range(2)]
xyz = np.array(grid + skin)
write_exodus(os.path.join(HERE, "skin_punch.exo"), "cube and a rigid skin above it",
             [xyz[:, 0], xyz[:, 1], xyz[:, 2]], np.array(hexes), "HEX8", sets,
             block_name="block", more_blocks=[("skin", np.array(quads), "QUAD4")])
