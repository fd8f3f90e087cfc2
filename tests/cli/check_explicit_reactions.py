#!/usr/bin/env python3
"""Reactions of velocity and displacement conditions in an explicit history (issue 14, item 8:
they were 0). A unit square (plane strain, E, nu) held at its base and pressed at its top by a
prescribed velocity to a strain eps, slowly (quasi-static): the two reactions balance, and the
press force lies between the hand-computed bounds of a laterally free specimen,
E / (1 - nu^2) eps, and a laterally confined one, E (1 - nu) / ((1 + nu)(1 - 2 nu)) eps.

usage: check_explicit_reactions.py HISTORY.csv E NU EPS
"""
import csv
import sys

path, E, nu, eps = sys.argv[1], *map(float, sys.argv[2:5])
with open(path) as f:
    last = list(csv.DictReader(f))[-1]
base, press = float(last["R_base_y"]), float(last["R_press_y"])
low = E / (1 - nu * nu) * eps
high = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) * eps
print("t = %s: R_base_y %.6g, R_press_y %.6g, bounds [%.6g, %.6g]" % (last["time"], base, press, low, high))
if not (low <= base <= high and low <= -press <= high):
    sys.exit("the reactions are outside the hand-computed bounds")
if abs(base + press) > 0.02 * base:
    sys.exit("the base and press reactions do not balance to 2 %")
