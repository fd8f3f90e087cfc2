#!/usr/bin/env python3
"""A free rigid impactor (mass m, moving along z) on a free elastic block (mass M), explicit
(tests/scenes/contact/hollow_impactor_mesh.yaml), from the history CSV:
- the energy balance error at every record <= 1 %;
- the force on the impactor: its impulse (trapezoidal rule of rb_imp_Fz over the records) equals
  its momentum change m (v_end - v0) within 1 %, and the block's momentum change (momentum_z
  less the impactor's m v) is the opposite within 1 % (the block's reaction);
- the impactor came off the block (it moves up at the end, no contact force);
- the block's top corner outside the impactor's footprint (probe `corner`) moves with the
  block: its displacement within 10 mm (a quarter of the impactor's radius) of the block's
  centre-of-mass travel (its velocity from momentum, integrated); the reported defect moved such
  a particle 131 mm. The block rings elastically: 1.6 mm under the mass-rule contact penalty,
  6.7 mm under the stiffer material rule (the default since issue 56: a shorter, harder impact).
usage: check_impactor.py history.csv [m M]  (the scene's 0.314 and 1.0 by default)"""
import csv
import sys

import numpy as np

rows = list(csv.DictReader(open(sys.argv[1])))
m, M = (float(sys.argv[2]), float(sys.argv[3])) if len(sys.argv) > 3 else (0.314, 1.0)


def col(name):
    return np.array([float(r[name]) for r in rows])


t, F, v = col("time"), col("rb_imp_Fz"), col("rb_imp_vz")
dp = m * (v[-1] - v[0])
impulse = float(np.sum(0.5 * (F[1:] + F[:-1]) * np.diff(t)))
block = col("momentum_z") - m * v
V = block / M
travel = np.concatenate([[0.0], np.cumsum(0.5 * (V[1:] + V[:-1]) * np.diff(t))])
corner = np.abs(col("probe_corner_uz") - travel).max()
balance = col("energy_balance_error").max()
print("records %d; energy balance %.3g; impactor dv %.6g, impulse %.6g, m dv %.6g, block dp %.6g; "
      "corner off the block's travel by %.3g (travel %.3g)"
      % (len(t), balance, v[-1] - v[0], impulse, dp, block[-1] - block[0], corner, travel[-1]))
failures = []
if len(t) < 20:
    failures.append("fewer than 20 records")
if not balance <= 1e-2:
    failures.append("energy balance %.3g > 1 %%" % balance)
if not abs(impulse - dp) <= 1e-2 * abs(dp):
    failures.append("impulse %.6g against m dv %.6g" % (impulse, dp))
if not abs((block[-1] - block[0]) + dp) <= 1e-2 * abs(dp):
    failures.append("block's momentum change %.6g against %.6g" % (block[-1] - block[0], -dp))
if not (v[-1] > 0 and F[-1] == 0):
    failures.append("the impactor did not come off the block (v %.4g, F %.4g)" % (v[-1], F[-1]))
if not corner <= 10.0:
    failures.append("the corner moved %.3g off the block's travel" % corner)
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
