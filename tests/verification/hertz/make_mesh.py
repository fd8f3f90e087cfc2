#!/usr/bin/env python3
"""Quarter of an elastic cylinder for the Hertz contact benchmark (README.md): the lower-right
quarter of a disc of radius R centered at (0, R), so that its lowest point touches the plane
y = 0 at the origin. The O-grid of ../taylor_bar/make_mesh.py (core square + two outer patches,
every cell convex), mirrored in y. QUAD4, one block `cylinder`; node sets `sym` (x = 0),
`top` (y = R, the cut through the center), `arc` (the surface r = R).
With --grading a < 1 the nodes are pulled towards the contact point (graded(): spacing a times
the uniform one there).
usage: make_mesh.py OUT.e --radial NR [--radius R] [--grading A]
"""
import argparse
import importlib.util
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))
from exodus_mesh import write_exodus  # noqa: E402

# The O-grid of the Taylor bar's mesh script (a module of the same file name, loaded by path).
_spec = importlib.util.spec_from_file_location(
    "taylor_make_mesh", os.path.join(HERE, "..", "taylor_bar", "make_mesh.py"))
_taylor = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_taylor)
section = _taylor.section


def graded(x, y, radius, a):
    """Nodes pulled towards the contact point (0, 0) by a smooth map of the quarter disc onto
    itself: about the center (0, R), with angle t from the downward axis and distance r,
    t' = t (a + (1 - a) t / (pi/2)) and R - r' = (R - r) (a + (1 - a) (R - r) / R): slopes a at
    the contact point (spacing a times the uniform one), 2 - a at the center and the cut; the
    axis, the cut and the arc map onto themselves."""
    dy = y - radius
    r = np.hypot(x, dy)
    t = np.arctan2(x, -dy)
    t2 = t * (a + (1 - a) * t / (0.5 * math.pi))
    s = radius - r
    r2 = radius - s * (a + (1 - a) * s / radius)
    return r2 * np.sin(t2), radius - r2 * np.cos(t2)


def quarter_cylinder(radius, nr, grading=1.0):
    xy, quads = section(radius, nr)
    x, y = xy[:, 0], radius - xy[:, 1]      # mirror: the arc's top point becomes the contact point
    if grading != 1.0:
        x, y = graded(x, y, radius, grading)
    quads = quads[:, ::-1]                   # mirrored cells keep counter-clockwise order
    tol = 1e-9 * radius
    r = np.hypot(x, y - radius)
    sets = {
        "sym": np.nonzero(np.abs(x) < tol)[0] + 1,
        "top": np.nonzero(np.abs(y - radius) < tol)[0] + 1,
        "arc": np.nonzero(np.abs(r - radius) < 1e-6 * radius)[0] + 1,
    }
    return x, y, quads + 1, sets


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--radial", type=int, required=True)
    ap.add_argument("--radius", type=float, default=1.0)
    ap.add_argument("--grading", type=float, default=1.0)
    a = ap.parse_args()
    x, y, conn, sets = quarter_cylinder(a.radius, a.radial, a.grading)
    write_exodus(a.out, "Hertz quarter cylinder %d" % a.radial, [x, y], conn, "QUAD4", sets,
                 block_name="cylinder")
    print("%s: %d nodes, %d cells" % (a.out, len(x), len(conn)))


if __name__ == "__main__":
    main()
