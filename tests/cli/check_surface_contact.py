#!/usr/bin/env python3
"""Checks of the explicit contact scenes between deformable parts (tests/scenes/contact/
bars_collide.yaml, block_on_block_*.yaml) from their history CSV; the expected values are
1D wave theory and Coulomb's law, not efg's output.
usage: check_surface_contact.py bars|bars3d|slide|stick HISTORY.csv
  bars   two equal bars (rho = 1, E = 100, A = 0.025, L = 1) meeting at +-v0 = 0.1: contact force
         rho c v0 A = 0.025 (c = 10): mean over t in [0.02, 0.19] within 1 %, every record there
         within 5 %; no force from t = 0.21 on (contact time 2 L / c = 0.2); the bars leave at
         -+v0 (mean velocities over t >= 0.25 within 1 %); momentum_x below 1e-8 of the bars'
         |momentum| 2 rho A L v0; energy balance < 1 %
  bars3d the same in 3D, square section A = 0.05 x 0.05 (contact force 0.0025)
  slide  block on a deformable base, gravity turned by tan(theta) = 0.5 > mu = 0.3: acceleration
         (least-squares slope of the block's mean velocity over t in [1, 2]) = g (sin - mu cos)
         within 1 %; energy balance < 1 % from t = 0.1 on (before, gravity ramps in from zero
         and the relative balance of energies of 1e-8 is not meaningful)
  stick  the same at tan(theta) = 0.2 < mu: drift of the block's mean displacement between
         t in [3, 3.5] and [3.5, 4] below 1e-6 of its size; over t in [3, 4] the mean contact
         force on the base = M g (sin, -cos) within 0.5 % and the clamp's reaction = the weight of
         block and base within 0.5 %; energy balance as slide
"""
import math
import sys

import numpy as np

from history_checks import HistoryChecks

kind, path = sys.argv[1], sys.argv[2]
history = HistoryChecks(path)
rows, col, check = history.rows, history.col, history.check
t = col("time")


if kind in ("bars", "bars3d"):
    rho, c, v0, length = 1.0, 10.0, 0.1, 1.0
    area = 0.025 if kind == "bars" else 0.05 * 0.05
    force = rho * c * v0 * area
    F = col("contact_meet_Fx")
    during = (t >= 0.02) & (t <= 0.19)
    check("mean contact force vs rho c v0 A (relative)", F[during].mean() / force - 1, 1e-2)
    check("worst contact force vs rho c v0 A (relative)", np.abs(F[during] / force - 1).max(),
          5e-2)
    check("contact force after 2 L / c / rho c v0 A", np.abs(F[t >= 0.21]).max() / force, 0.0)
    after = t >= 0.25
    check("left bar's velocity after vs -v0 (relative)",
          col("v_left_bar_x")[after].mean() / -v0 - 1, 1e-2)
    check("right bar's velocity after vs v0 (relative)",
          col("v_right_bar_x")[after].mean() / v0 - 1, 1e-2)
    check("momentum_x / bars' |momentum|",
          np.abs(col("momentum_x")).max() / (2 * rho * area * length * v0), 1e-8)
    check("energy balance", col("energy_balance_error").max(), 1e-2)
elif kind in ("slide", "stick"):
    tan, mu, g, M, M_base = (0.5 if kind == "slide" else 0.2), 0.3, 1.0, 0.5, 1.5
    th = math.atan(tan)
    if kind == "slide":
        history.check_incline_slide(col("v_block_all_x"), tan, mu, g)
    else:
        history.check_at_rest(col("u_block_all_x"))
        late = t >= 3.0
        # The tangential force rings about M g sin at 8 % (standard deviation over t >= 3; the
        # stick holds the block elastically) and is sampled at the records: the mean of 50
        # samples carries -0.39 to -0.65 % of aliasing depending on the window (t >= 1 to 3.5;
        # -0.52 % over t >= 3) and moves with the time step; a slip would take the whole
        # friction reserve (mu cos - sin = 10 % of the weight).
        check("mean tangential contact force vs M g sin (relative)",
              col("contact_rest_Fx")[late].mean() / (M * g * math.sin(th)) - 1, 1e-2)
        check("mean normal contact force vs -M g cos (relative)",
              col("contact_rest_Fy")[late].mean() / (-M * g * math.cos(th)) - 1, 5e-3)
        weight = (M + M_base) * g
        check("mean clamp reaction x vs -weight sin (relative)",
              col("R_clamp_x")[late].mean() / (-weight * math.sin(th)) - 1, 5e-3)
        check("mean clamp reaction y vs weight cos (relative)",
              col("R_clamp_y")[late].mean() / (weight * math.cos(th)) - 1, 5e-3)
    # The first records, while gravity ramps in from zero (energies of 1e-8), are relative to
    # almost nothing: the balance is checked once the energies count.
    check("energy balance over t >= 0.1", col("energy_balance_error")[t >= 0.1].max(), 1e-2)
else:
    sys.exit("unknown check '%s'" % kind)
sys.exit(0 if history.ok else 1)
