#!/usr/bin/env python3
"""The cantilever block under a suddenly applied tip force (input/block_explicit.yaml), checked
against hand results (issue 13, item 9: the test only checked that files exist):
- it oscillates about the static deflection of a Timoshenko beam, P L^3 / (3 E I) + P L / (k G A)
  (k = 10 (1 + nu) / (12 + 11 nu), Cowper), within 5 % (3D clamp and discretization);
- the dynamic amplification of a step load on an undamped structure is 2: the largest deflection
  is twice the centre of the oscillation, within 5 %;
- the energy account balances to 1 % at every record.

usage: check_block_explicit.py HISTORY.csv
"""
import csv
import sys

P, L, b, h, E, nu = 100.0, 10.0, 2.0, 2.0, 2.1e5, 0.3
I, A, G = b * h ** 3 / 12, b * h, E / (2 * (1 + nu))
k = 10 * (1 + nu) / (12 + 11 * nu)
static = P * L ** 3 / (3 * E * I) + P * L / (k * G * A)
with open(sys.argv[1]) as f:
    rows = list(csv.DictReader(f))[1:]
u = [-float(r["u_xmax_z"]) for r in rows]
centre = 0.5 * (max(u) + min(u))
print("static (beam) %.5g, oscillation centre %.5g, largest %.5g" % (static, centre, max(u)))
failed = []
if abs(centre - static) > 0.05 * static:
    failed.append("the oscillation centre is not the static deflection")
if abs(max(u) / centre - 2) > 0.1:
    failed.append("the dynamic amplification is not 2")
worst = max(float(r["energy_balance_error"]) for r in rows)
if worst > 0.01:
    failed.append("energy balance error %.3g" % worst)
if failed:
    sys.exit("; ".join(failed))
