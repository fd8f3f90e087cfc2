#!/usr/bin/env python3
"""Mass-proportional damping (tests/scenes/explicit_mass_damping.yaml): a rigidly moving free
block's kinetic energy follows the scheme's exact solution E_0 r^(2n), r = (1 - a dt/2) /
(1 + a dt/2), to 1e-10 at every record, the continuous exp(-2 a t) to the scheme's O((a dt)^2)
(within 1e-3 here), and kinetic energy + damping work = E_0 (energy balance error < 1e-10).
usage: check_mass_damping.py history.csv alpha dt"""
import csv
import math
import sys

rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(sys.argv[1]))]
alpha, dt = float(sys.argv[2]), float(sys.argv[3])
r = (1 - 0.5 * alpha * dt) / (1 + 0.5 * alpha * dt)
e0 = rows[0]["kinetic_energy"]
worst_scheme = worst_continuous = worst_balance = 0.0
for row in rows:
    n = round(row["time"] / dt)
    scheme = e0 * r ** (2 * n)
    worst_scheme = max(worst_scheme, abs(row["kinetic_energy"] - scheme) / e0)
    worst_continuous = max(worst_continuous,
                           abs(row["kinetic_energy"] - e0 * math.exp(-2 * alpha * row["time"])) / e0)
    worst_balance = max(worst_balance,
                        abs(row["kinetic_energy"] + row["mass_damping_work"] - e0) / e0,
                        row["energy_balance_error"])
last = rows[-1]
print(f"E_0 {e0:.6g}; at t = {last['time']:.4g}: E_kin {last['kinetic_energy']:.9g} (scheme "
      f"{e0 * r ** (2 * round(last['time'] / dt)):.9g}, exp {e0 * math.exp(-2 * alpha * last['time']):.9g}); "
      f"worst: scheme {worst_scheme:.2e}, continuous {worst_continuous:.2e}, balance {worst_balance:.2e}")
ok = (len(rows) >= 10 and last["kinetic_energy"] < 0.05 * e0 and worst_scheme < 1e-10
      and worst_continuous < 1e-3 and worst_balance < 1e-10)
sys.exit(0 if ok else 1)
