#!/usr/bin/env python3
"""Erosion (tests/scenes/plasticity/plastic_wave_erosion.yaml): at the last record, the particles
flagged `eroded` are exactly those whose effective plastic strain reached the failure strain
(an eroded particle's state is frozen at failure, so its plastic strain is at or above it; an
intact one is below it), some particles eroded, every eroded particle carries zero stress, the history reports a positive eroded energy no
larger than the internal energy, and the energy balance error of every record stays below
ENERGY (the stress of a failing particle drops to zero in one step: the balance is looser than
without erosion, 1.2 % against 0.5 % measured).
The scene records every step, so erosion is also checked where it happens: every eroded particle
was below the failure strain at the record (step) before it was flagged, i.e. its frozen strain
lies within its last step's increment above the failure strain (a particle erodes in the first
step that reaches it). Measured: eroded strains 0.0502 to 0.0827, the last increments 0.019 to
0.041, the largest strain before a flag 0.0492; eroding at 1.2 times the failure strain (0.06)
leaves particles at 0.05 to 0.06 intact for another step, and this check fails.
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
# every step recorded: no two records further apart than the largest time step
times = np.array(d["time_whole"][:])
largest_step = max(float(r["time_step"]) for r in rows)
every_step = (np.diff(times) <= largest_step * (1 + 1e-9)).all()
flags = np.array(d["vals_nod_var%d" % (names.index("eroded") + 1)][:]) > 0.5
strains = np.array(d["vals_nod_var%d" % (names.index("plastic_strain") + 1)][:])
first = flags.argmax(axis=0)  # the record at which each particle was flagged
which = np.where(eroded)[0]
before = strains[first[which] - 1, which] if eroded.any() else np.array([])
at_flag = strains[first[which], which] if eroded.any() else np.array([])
within = (eroded.any() and (first[which] > 0).all() and (before < failure).all()
          and (at_flag >= failure).all())
print("every step recorded: %s (%d records); strain at the record before a flag at most %.4g, "
      "smallest eroded %.5g = failure + %.3g, whose last increment was %.3g"
      % (every_step, len(times), before.max() if before.size else float("nan"),
         plastic[eroded].min() if eroded.any() else float("nan"),
         plastic[eroded].min() - failure if eroded.any() else float("nan"),
         (at_flag - before)[np.argmin(at_flag)] if before.size else float("nan")))
last = rows[-1]
worst = max(float(r["energy_balance_error"]) for r in rows)
eroded_energy, internal = float(last["eroded_energy"]), float(last["internal_energy"])
print("largest stress of an eroded particle %.3g" % stress[:, eroded].max())
print("eroded %d of %d particles; eroded plastic strain >= %.4g, intact <= %.4g; eroded energy %.4g "
      "of internal %.4g; worst energy balance error %.3g"
      % (eroded.sum(), len(eroded), plastic[eroded].min() if eroded.any() else float("nan"),
         plastic[~eroded].max(), eroded_energy, internal, worst))
ok = (eroded.any() and (plastic[eroded] >= failure).all() and (plastic[~eroded] < failure).all()
      and (stress[:, eroded] == 0).all() and 0 < eroded_energy <= internal and worst <= energy
      and every_step and within)
sys.exit(0 if ok else 1)
