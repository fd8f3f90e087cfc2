#!/usr/bin/env python3
"""An implicit stage hands its equilibrium to an explicit stage under the same load
(tests/scenes/two_stages.yaml): the explicit stage starts at rest in equilibrium, so the tip
deflection stays at the static value (to 1e-4 of it) and the kinetic energy stays below 1e-5 of
the strain energy. A broken hand-over (displacements reset, loads dropped) moves the tip at once.

usage: check_two_stages.py HISTORY.csv
"""
import csv
import sys

with open(sys.argv[1]) as f:
    rows = list(csv.DictReader(f))
static = [r for r in rows if float(r["time"]) == 1.0][0]
u0 = float(static["u_xmax_z"])
dynamic = [r for r in rows if float(r["time"]) > 1.0]
drift = max(abs(float(r["u_xmax_z"]) - u0) for r in dynamic)
kinetic = max(float(r["kinetic_energy"]) for r in dynamic)
strain = float(static["strain_energy"])
print("static tip %.6g, largest drift %.3g, largest kinetic energy %.3g (strain %.4g), %d records"
      % (u0, drift, kinetic, strain, len(dynamic)))
if not (u0 < 0 and len(dynamic) >= 3 and drift <= 1e-4 * abs(u0) and kinetic <= 1e-5 * strain):
    sys.exit("the explicit stage does not stay in the implicit stage's equilibrium")
