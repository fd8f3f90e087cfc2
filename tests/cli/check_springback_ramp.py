#!/usr/bin/env python3
"""Springback release on a linear problem (tests/scenes/springback_ramp.yaml): the load acts in
stage 'load' only, and the springback stage releases it linearly over pseudo-time 1..2, so the
tip deflection is (2 - t) u(1) at every record of the stage and 0 at its end (1e-9 relative).
usage: check_springback_ramp.py history.csv"""
import csv
import sys

rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(sys.argv[1]))]
loaded = next(r for r in rows if abs(r["time"] - 1.0) < 1e-12)["u_xmax_y"]
released = [r for r in rows if r["time"] > 1.0 + 1e-12]
worst = max(abs(r["u_xmax_y"] - (2 - r["time"]) * loaded) for r in released) / abs(loaded)
print(f"tip u_y at t = 1: {loaded:.9g}; {len(released)} springback records, largest departure "
      f"from (2 - t) u(1): {worst:.3e} of u(1); at t = 2: {released[-1]['u_xmax_y']:.3e}")
ok = loaded < -1e-3 and len(released) == 4 and worst < 1e-9
sys.exit(0 if ok else 1)
