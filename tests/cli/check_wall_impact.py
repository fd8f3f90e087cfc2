#!/usr/bin/env python3
"""A bar pressing on a rigid wall: the mean wall force of the history records from T_FROM on
equals the 1D wave theory's value within REL, every record within 6 % (the penalty wall rings
by about 4 %), and the energy balance error of every record stays below ENERGY (tests/scenes/impact/bar_wall_in_contact.yaml, tests/scenes/plasticity/plastic_wave_impact.yaml).
usage: check_wall_impact.py HISTORY.csv FORCE REL ENERGY T_FROM
"""
import csv
import sys

path, force, rel, energy, t_from = sys.argv[1], *map(float, sys.argv[2:6])
rows = list(csv.DictReader(open(path)))
forces = [float(r["wall_wall_force"]) for r in rows if float(r["time"]) >= t_from]
worst_f = max(abs(f - force) / force for f in forces)
mean_f = abs(sum(forces) / len(forces) - force) / force
worst_e = max(float(r["energy_balance_error"]) for r in rows)
last = rows[-1]
print("records %d, last t = %s: wall force %s (expected %g), worst force error %.3g, worst energy "
      "balance error %.3g, mean force error %.3g" % (len(rows), last["time"], last["wall_wall_force"],
                                               force, worst_f, worst_e, mean_f))
sys.exit(0 if mean_f <= rel and worst_f <= 0.06 and worst_e <= energy else 1)
