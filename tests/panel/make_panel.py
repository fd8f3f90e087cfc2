#!/usr/bin/env python3
"""Maps the unit-square Exodus mesh written by `efg mesh` onto Cook's tapered panel, in place.

Cook's membrane (Cook 1974; Simo & Rifai 1990): the trapezoid (0,0), (48,44), (48,60), (0,44),
clamped on x = 0 and sheared on x = 48. A point (s, t) of the unit square goes to
x = 48 s, y = y_bottom(x) + t (y_top(x) - y_bottom(x)) with y_bottom = 44 s, y_top = 44 + 16 s,
so the square's node and side sets xmin / xmax become the clamped and the loaded edge.

usage: make_panel.py MESH.exo
"""
import sys

import netCDF4

with netCDF4.Dataset(sys.argv[1], "r+") as d:
    s = d.variables["coordx"][:]
    t = d.variables["coordy"][:]
    d.variables["coordx"][:] = 48.0 * s
    d.variables["coordy"][:] = 44.0 * s + t * (44.0 + 16.0 * s - 44.0 * s)
