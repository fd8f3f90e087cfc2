#!/usr/bin/env python3
"""A flat rigid punch pressed onto a plate and dragged across it with Coulomb friction
mu = 0.3 (tests/scenes/shells/plate_drag.yaml): the punch's force F (the mean over each output
interval) satisfies
- while pressing (t <= 5): F_x = 0 to 1e-12 of F_z (no drag, no friction force);
- once everything slips (t in [6, 7.5]: the punch has moved 0.005 to 0.02, less than the next
  particle row ahead of its leading edge, which it then starts to plough): F_x = -mu F_z to
  1e-3 (Coulomb's law summed over the particles under the punch: every normal is -z);
- and never more than mu F_z (stick below the cap: |F_x| <= mu F_z (1 + 1e-9) for t < 7.5).
usage: check_shell_drag.py history.csv
"""
import sys

import numpy as np

from history_checks import HistoryChecks

mu = 0.3
history = HistoryChecks(sys.argv[1])
col, check = history.col, history.check
t, Fx, Fz = col("time"), col("rb_punch_Fx"), col("rb_punch_Fz")

press = (t > 0) & (t <= 5 + 1e-9)
slip = (t >= 6 - 1e-9) & (t <= 7.5 + 1e-9)
before = (t > 0) & (t <= 7.5 + 1e-9)
check("F_x / F_z while pressing", np.abs(Fx[press] / Fz[press]).max(), 1e-12)
check("sliding: |F_x / (-mu F_z) - 1|", np.abs(Fx[slip] / (-mu * Fz[slip]) - 1).max(), 1e-3)
check("|F_x| above mu F_z (relative, below 0)",
      max(0.0, (np.abs(Fx[before]) / (mu * Fz[before]) - 1).max()), 1e-9)
sys.exit(0 if history.ok else 1)
