#!/usr/bin/env python3
"""Writes the small 3D shell surface meshes (SHELL4) that scenes of tests/scenes refer to:
roof_4.exo, a Scordelis-Lo roof quarter on 4 x 4 cells (node sets crown, free, midspan,
diaphragm), and half_cylinder_16.exo, a half cylinder on 16 x 2 cells (180 degrees: its edge
cells' normals turn by 84 degrees from their mean, beyond the projection chart's 80; node sets
side_a, side_b, end_a, end_b), and tapered_strip_16.exo, the strip [0, 1] x [0, 0.2] in the plane
z = 0 on 16 x 2 SHELL4 cells whose thickness attribute is t0 (1 + x) at each cell's centre,
t0 = 0.01 (node sets xmin, xmax; tests/scenes/shells/strip_tapered_mesh.yaml), and
collapsed_cell_4.exo, a slightly curved strip on 4 x 1 cells whose second cell is collapsed
onto a line (its x = 0.5 nodes moved onto the x = 0.25 ones: zero area; node set xmin;
tests/scenes/bad/shell_surface_collapsed_cell.yaml).
Run once from this folder; the files are committed.
"""
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "..", "verification", "shell_surface"))
sys.path.insert(0, os.path.join(here, "..", "..", "..", "verification"))
from exodus_mesh import write_exodus  # noqa: E402
from run_surface import grid, roof  # noqa: E402

roof(4, os.path.join(here, "roof_4.exo"))
coords, conn, e = grid(16, 2, lambda u, v: (math.cos(u * math.pi), 10 * v, math.sin(u * math.pi)))
write_exodus(os.path.join(here, "half_cylinder_16.exo"), "half cylinder", coords, conn, "SHELL4",
             {"side_a": e["i0"], "side_b": e["i1"], "end_a": e["j0"], "end_b": e["j1"]})
coords, conn, e = grid(16, 2, lambda u, v: (u, 0.2 * v, 0.0))
centre_x = [sum(coords[0][n - 1] for n in cell) / 4 for cell in conn]
write_exodus(os.path.join(here, "tapered_strip_16.exo"), "tapered strip", coords, conn, "SHELL4",
             {"xmin": e["i0"], "xmax": e["i1"]},
             attributes={"thickness": [0.01 * (1 + x) for x in centre_x]})
coords, conn, e = grid(4, 1, lambda u, v: (u, 0.25 * v, 0.1 * u * u))
for a, b in ((3, 2), (8, 7)):  # 1-based nodes (i = 2, j) onto (i = 1, j)
    for axis in coords:
        axis[a - 1] = axis[b - 1]
write_exodus(os.path.join(here, "collapsed_cell_4.exo"), "collapsed cell", coords, conn, "SHELL4",
             {"xmin": e["i0"]})
