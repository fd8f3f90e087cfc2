#!/usr/bin/env python3
"""Erosion (tests/scenes/plasticity/plastic_wave_erosion.yaml): at the last record, the particles
flagged `eroded` are exactly those whose effective plastic strain reached the failure strain
(an eroded particle's state is frozen at failure, so its plastic strain is at or above it; an
intact one is below it), some particles eroded, every eroded particle carries zero stress, the history reports a positive eroded energy no
larger than the internal energy, and the energy balance error of every record stays below
ENERGY (the stress of a failing particle drops to zero in one step: the balance is looser than
without erosion, 1.2 % against 0.5 % measured).
usage: check_erosion.py RESULTS.e HISTORY.csv FAILURE_STRAIN ENERGY
"""
import csv
import sys

import netCDF4
import numpy as np

results, history, failure, energy = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
d = netCDF4.Dataset(results)
names = [b"".join(c for c in row if c).decode() for row in d["name_nod_var"][:]]
get = lambda n: np.array(d["vals_nod_var%d" % (names.index(n) + 1)][-1])
eroded, plastic = get("eroded") > 0.5, get("plastic_strain")
stress = np.abs(np.stack([get(n) for n in names if n.startswith("stress_")]))
rows = list(csv.DictReader(open(history)))
last = rows[-1]
worst = max(float(r["energy_balance_error"]) for r in rows)
eroded_energy, internal = float(last["eroded_energy"]), float(last["internal_energy"])
print("largest stress of an eroded particle %.3g" % stress[:, eroded].max())
print("eroded %d of %d particles; eroded plastic strain >= %.4g, intact <= %.4g; eroded energy %.4g "
      "of internal %.4g; worst energy balance error %.3g"
      % (eroded.sum(), len(eroded), plastic[eroded].min() if eroded.any() else float("nan"),
         plastic[~eroded].max(), eroded_energy, internal, worst))
ok = (eroded.any() and (plastic[eroded] >= failure).all() and (plastic[~eroded] < failure).all()
      and (stress[:, eroded] == 0).all() and 0 < eroded_energy <= internal and worst <= energy)
sys.exit(0 if ok else 1)
