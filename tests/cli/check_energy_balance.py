#!/usr/bin/env python3
"""Energy account of an explicit run from its history CSV: at the last record the work put in
(external_work, which includes the supports of prescribed motions, plus wall_work) must equal
the kinetic plus internal energy gained since the first record to 1e-3 of it, and must be
positive (the crush did work). With WORK, the work must also be that hand value to 1e-3.

usage: check_energy_balance.py HISTORY.csv [WORK]
"""
import csv
import sys

with open(sys.argv[1]) as f:
    rows = list(csv.DictReader(f))
first, last = rows[0], rows[-1]
work = float(last["external_work"]) + float(last["wall_work"])
energy = (float(last["kinetic_energy"]) + float(last["internal_energy"]) -
          float(first["kinetic_energy"]) - float(first["internal_energy"]))
print("t = %s: work in %.6g, kinetic + internal %.6g" % (last["time"], work, energy))
if not (work > 0 and abs(work - energy) <= 1e-3 * work):
    sys.exit("the energy account does not balance")
if len(sys.argv) > 2 and not abs(work - float(sys.argv[2])) <= 1e-3 * float(sys.argv[2]):
    sys.exit("the work put in is not the hand value %s" % sys.argv[2])
