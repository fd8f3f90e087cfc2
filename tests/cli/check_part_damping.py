#!/usr/bin/env python3
"""Per-part mass damping (tests/scenes/explicit_part_damping.yaml): the damped block's velocity
follows the scheme's exact v0 r^n, r = (1 - a dt/2) / (1 + a dt/2), to 1e-10; the undamped
block keeps v0 to 1e-12; the energy balance error stays below 1e-10.
usage: check_part_damping.py history.csv [alpha dt] (the scene's 20 and 1e-3 by default)"""
import csv
import sys

rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(sys.argv[1]))]
alpha, dt = (float(sys.argv[2]), float(sys.argv[3])) if len(sys.argv) > 3 else (20.0, 1e-3)
r = (1 - 0.5 * alpha * dt) / (1 + 0.5 * alpha * dt)
damped = max(abs(row["v_in_a_x"] - r ** round(row["time"] / dt)) for row in rows)
free = max(abs(row["v_in_b_x"] - 1.0) for row in rows)
balance = max(row["energy_balance_error"] for row in rows)
print(f"damped block: worst {damped:.2e} from v0 r^n (at the end {rows[-1]['v_in_a_x']:.9g}); "
      f"undamped block: worst {free:.2e} from v0; energy balance {balance:.2e}")
ok = len(rows) >= 10 and rows[-1]["v_in_a_x"] < 0.2 and damped < 1e-10 and free < 1e-12 and \
    balance < 1e-10
sys.exit(0 if ok else 1)
