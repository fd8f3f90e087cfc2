#!/usr/bin/env python3
"""A free rigid ball (mass 0.05, v0 = -0.05) dropped on a clamped plate
(tests/scenes/shells/ball_on_plate.yaml):
- momentum: m (v_end - v0) equals the impulse of the plate's force on the ball, the sum of the
  history's forces (means over each output interval) times the intervals, to 1e-10 of m |v0|;
- energy: after the ball has left the plate (no force), its kinetic energy plus the plate's
  kinetic and strain energy equal m v0^2 / 2 within 1 %; the ball rebounds (v_end > 0);
- the plate's own balance, kinetic + strain = the contact's work on it, within 1 %.
usage: check_shell_ball.py history.csv
"""
import sys

import numpy as np

from history_checks import HistoryChecks

m, v0 = 0.05, -0.05
history = HistoryChecks(sys.argv[1])
col, check = history.col, history.check
t, F, v = col("time"), col("rb_ball_Fz"), col("rb_ball_vz")
kin, strain, work = col("kinetic_energy"), col("strain_energy"), col("external_work")

impulse = np.sum(F[1:] * np.diff(t))
check("momentum change against the impulse (of m |v0|)",
      abs(m * (v[-1] - v0) - impulse) / (m * abs(v0)), 1e-10)
touched = np.nonzero(F != 0)[0]
if len(touched) == 0 or touched[-1] + 1 >= len(t):
    sys.exit("the ball never touched the plate, or never left it")
after = slice(touched[-1] + 1, None)
e0 = 0.5 * m * v0 * v0
total = 0.5 * m * v[after] ** 2 + kin[after] + strain[after]
print("after separation: ball %.4e, plate %.4e of %.4e" % (0.5 * m * v[-1] ** 2,
                                                         kin[-1] + strain[-1], e0))
check("energy after separation (relative)", np.abs(total - e0).max() / e0, 0.01)
check("rebound (0 - v_end, below 0)", max(0.0, -v[-1]), 0.0)
check("plate's balance", np.abs(kin + strain - work).max() / np.abs(kin + strain).max(), 0.01)
sys.exit(0 if history.ok else 1)
