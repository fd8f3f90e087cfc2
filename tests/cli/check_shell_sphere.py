#!/usr/bin/env python3
"""A rigid sphere (R = 0.05) pressed into the centre of a simply supported square plate
(tests/scenes/shells/plate_pressed_by_sphere.yaml: a = 1, t = 0.02, E = 1000, nu = 0.3), explicit,
quasi-static: the sphere travels delta = 0.01 over t in [0, 10], then holds until 13.33.
Checked over the held time after half a period (record means; the supports' and the sphere's
forces are means over each output interval):
- equilibrium: the contact force on the sphere equals the supports' reaction within 1 %;
- the sphere sets the deflection: the centre's deflection within 1 % of delta (the penalty's
  penetration, F / k, is 0.4 % of it);
- the plate's stiffness under the concentrated load: P against Kirchhoff's point load,
  w = 0.0116 P a^2 / D (Timoshenko & Woinowsky-Krieger 1959, sec. 34, nu = 0.3), within 10 %
  (measured -8.7 % at 16 x 16 cells, -7.9 % at 32 x 32: the Reissner-Mindlin plate is more
  flexible under a concentrated load, its shear deflection growing like ln(a / r) as the contact
  patch r shrinks, and the shear stabilization softens it at these spacings; the same plate
  under a point load of the contact's force, implicit, deflects within 0.05 % of the contact
  run);
- quasi-static: kinetic energy below 1e-3 of the strain energy; energy balance within 1 %.
usage: check_shell_sphere.py history.csv
"""
import sys

import numpy as np

from history_checks import HistoryChecks

a, t, E, nu, delta = 1.0, 0.02, 1000.0, 0.3, 0.01
rise, period = 10.0, 1.6631
history = HistoryChecks(sys.argv[1])
rows, check = history.rows, history.check
held = history.col("time") >= rise + 0.5 * period
col = lambda name: history.col(name)[held]  # noqa: E731
P = col("rb_ball_Fz").mean()
supports = sum(col("support_%s_force_z" % n) for n in ("ss_x0", "ss_x1", "ss_y0", "ss_y1")).mean()
w = -col("probe_centre_uz").mean()
D = E * t**3 / (12 * (1 - nu**2))
kirchhoff = w * D / (0.0116 * a**2)
kinetic = (col("kinetic_energy") / col("strain_energy")).max()
work = np.array([float(r["external_work"]) for r in rows])
energy = np.array([float(r["strain_energy"]) + float(r["kinetic_energy"]) for r in rows])
balance = np.abs(energy - work).max() / np.abs(energy).max()

print("P = %.6e, supports %.6e, centre deflection %.6e, Kirchhoff's P for it %.6e"
      % (P, supports, w, kirchhoff))
check("sphere force against the supports' reaction", abs(P / supports - 1), 0.01)
check("centre deflection against the sphere's travel", abs(w / delta - 1), 0.01)
check("P against Kirchhoff's point load", abs(P / kirchhoff - 1), 0.10)
check("kinetic / strain energy while held", kinetic, 1e-3)
check("energy balance", balance, 0.01)
sys.exit(0 if history.ok else 1)
