#!/usr/bin/env python3
"""The first record of an explicit run holds the initial kinetic energy (issue 13, item 4: it was
written as 0 before the energies were computed). For a bar of density rho, area A (thickness 1)
moving rigidly at v0: E_kin = rho A v0^2 / 2, by hand.

usage: check_initial_kinetic_energy.py HISTORY.csv RHO AREA V0
"""
import csv
import sys

path, rho, area, v0 = sys.argv[1], *map(float, sys.argv[2:5])
with open(path) as f:
    first = next(csv.DictReader(f))
expected = 0.5 * rho * area * v0 * v0
found = float(first["kinetic_energy"])
print("t = %s: kinetic energy %.12g, expected %.12g" % (first["time"], found, expected))
if float(first["time"]) != 0.0 or abs(found - expected) > 1e-12 * expected:
    sys.exit("the first record does not hold the initial kinetic energy")
