#!/usr/bin/env python3
"""Energy account of an explicit run from its history CSV: at the last record the work put in
(external_work, which includes the supports of prescribed motions, plus wall_work) must equal
the kinetic plus internal energy to 1e-3 of it, and must be positive (the crush did work).

usage: check_energy_balance.py HISTORY.csv
"""
import csv
import sys

with open(sys.argv[1]) as f:
    rows = list(csv.DictReader(f))
last = rows[-1]
work = float(last["external_work"]) + float(last["wall_work"])
energy = float(last["kinetic_energy"]) + float(last["internal_energy"])
print("t = %s: work in %.6g, kinetic + internal %.6g" % (last["time"], work, energy))
if not (work > 0 and abs(work - energy) <= 1e-3 * work):
    sys.exit("the energy account does not balance")
