#!/usr/bin/env python3
"""Checks of the explicit contact scenes (tests/scenes/contact/*.yaml) from their history CSV.
usage: check_contact.py impact|punch|slide|stick HISTORY.csv
  impact  free rigid disc on a free block: momentum of particles + disc constant to 1e-8
          relative, energy balance < 1 %, the rebound velocity after separation from momentum
          and energy conservation with the measured vibration energy of the block within 1 %
  punch   prescribed flat punch on a clamped block: R_base_y = rb_punch_Fy at every record
          within 0.5 % of the largest, energy balance < 1e-4
  slide   block on an incline, tan(theta) = 0.5 > mu = 0.3: acceleration of the center of mass
          (least-squares slope of momentum_x / M over t in [1, 2]) = g (sin - mu cos) within 1 %
  stick   tan(theta) = 0.2 < mu: drift of the bottom's mean displacement between t in [3, 3.5]
          and [3.5, 4] below 1e-6 of the block size; the plane carries the weight within 0.5 %
  rest    free rigid box (weight 5) settled on a clamped block: over t in [3, 4] contact force
          on the box and base reaction = weight within 0.5 %, box speed < 1e-4, balance < 1 %,
          no contact moment about the centred box
  roll    free disc spinning at omega0 on an elastic block with friction: angular momentum about
          the contact point conserved (mean over t >= 0.5 within 1 %, every record within 6 %),
          mean rolling speed and -omega R over t >= 0.5 = -omega0 R / 3 within 2 %
  pressed the same with an applied force 5 instead of the weight and the box's centre 0.2 off
          the block's axis: contact moment about it -1 within 0.5 %
  driven  a roll spinning at a prescribed omega = -4 (R = 0.25) pulls a strip on a frictionless
          floor: the strip's mean velocity over t in [1.6, 2] = omega R within 3 %, energy
          balance < 1 %, the roll's spin as prescribed
  tumble  free rigid box (mass 0.5, v = -1, omega0 = 3) on a free block (mass 1): momentum of
          particles + box constant to 1e-8 relative; energy balance < 1 %; the spin changed by
          the contact by more than 0.1; the box left the block (no contact force at the end)
  tumble3d  the same in 3D (box 0.4 x 0.2 x 0.2, omega0 = (0.5, 3, 0)): momentum (z, and x, y
          against it) to 1e-8; energy balance < 1 %; the spin about y changed by more than 0.1;
          the box left the block
  precession  free box 0.2 x 0.2 x 0.6 (m = 1) spinning in space at omega0 = (1, 0, 2): the
          angular velocity keeps its length and its component along L = (I1, 0, 2 I3) to 1e-6,
          and turns about L at |L| / I1 (phase within 1e-3 rad over 3 time units); the kinetic
          energy omega . L / 2 constant to 1e-6
  drag_implicit  punch pressed (t <= 0.5) then dragged over a clamped block, implicit, Coulomb
          mu = 0.3: F_x = 0 while pressing; partial slip while the drag builds up
          (|F_x| < mu F_y at t = 0.6, 0.7); F_x = -mu F_y for t >= 1 (all slipping); the base's
          reaction equals the contact force in both directions; all to 1e-8 of F_y
  punch_implicit  prescribed punch on a block on rollers, implicit: force E* delta within 0.5 %
          at every record (delta = 0.01 t), base reaction = contact force to 1e-8, the punch's
          travel 0.01 t to 1e-12
  punch_force  the same punch free, force-controlled by F t (F = E* 0.01): its place
          u_y = -t (0.01 + F h / (100 E (W + h))) within 1e-4 of 0.01 t (by hand: the block's
          uniaxial shortening and the top's uniform penetration, 8.5e-4 of the place; the
          particles' contact forces, a nodal quadrature of the pressure, bend the top by
          4e-5 of it), its contact force = -F t and the base's reaction = F t, both to 1e-8 of
          F; with the history of the prescribed punch (flat_punch_implicit.yaml) as a third
          argument, the place where the prescribed run's force F_p(t) moved it 0.01 t, scaled
          by F / F_p (the discrete problem is linear), to 1e-9 of 0.01
  lbody   free L-shaped body of two boxes (tests/scenes/contact/l_body_spin.yaml) spinning in
          space: omega(t) . L0 / 2 (L0 = J omega0, J by hand from the two boxes and the
          parallel-axis theorem) constant to 1e-5 relative (measured 7e-7 at dt 0.002; 0.58 with
          the product of inertia I_xy left out)
  curved_tool  a rigid cylinder pressed 0.02 into a clamped block, implicit: HISTORY the
          analytic cylinder's, then the runs with the cylinder a ring of 64 and of 128 mesh
          cells (the inscribed N-gon): the 128-gon's force within 0.1 % of the cylinder's, the
          error falling by at least 2x from 64 to 128 cells, no sideways force (|F_x| below
          1e-10 F_y: the polygon is symmetric)
  spin_implicit  a prescribed roll (R = 0.25) pressed into a clamped block while spinning,
          implicit, mu = 0.3: every contact particle slips, its friction mu F_n along the
          surface's motion, tangent to the roll: the moment about the roll's centre
          M_z = mu sum rho_J F_n,J ~ mu R F_y within 1 % (rho_J = R less the penetration, the
          patch's tilt), F_x along +x (the surface at the bottom moves along -x; F_x / F_y is
          0.27 - 0.30, not mu: the friction drags the patch sideways, the normal forces' tilt
          does not cancel); the base's reaction = the contact force to
          1e-6 of it (Newton's tolerance with the nonsymmetric slip tangent)
  stacked  two elastic blocks stacked (contact between deformable parts, implicit, two-way,
          2D plane strain): the contact force of the top on the base equals the floor's reaction
          and minus the press's to 1e-9 of it; its size P = delta / ((H_base + H_top) / E* +
          1 / K) (the blocks' uniaxial compliance and the penalty's, K by hand in the scene's
          header: 10.98375) within 1e-4 (measured 4.4e-5; without the penalty's compliance
          4.8e-4 off)
  stacked3d  the same in 3D (uniaxial stress, hex8 faces cut into triangles): P = 9.98984
          within 1e-3 (measured 5.5e-4: between non-matching faces the penetration is not
          uniform, the top's coarser face indents the base between its particles)
          Both: at most 8 Newton iterations over the 2 load steps (the run's report JSON next
          to the history; 6 measured with the full tangent)
  drag_parts  an elastic block pressed (t <= 0.5) then dragged over an elastic base, implicit,
          friction between deformable parts (mu = 0.3): |F_x| < mu |F_y| while the drag builds
          up (t in (0.5, 0.75)); F_x = mu |F_y| within 5e-3 for t >= 1.2 (all slipping; measured
          3.1e-3: the dragged block rocks, its leading edge bears more, and the contact normals
          tilt by about 1e-3 rad, F_x / |F_y| = mu + tilt (1 + mu^2)); the clamp's reactions equal the contact force to 1e-8
  foam    a foam block (E = 1, nu = 0.3: K = 0.8333) 600 x 600 x 240 on a fixed floor, a free
          1 t plate dropped on by its weight W = 9810 at default contact settings: the plate's
          peak contact force 2 W (a suddenly applied load, the block's mass negligible) within
          5 %; the largest penetration of each contact (contact_top_pen, contact_bottom_pen)
          <= 0.10 of the spacing and within 10 % of 2 W / (K L^2) = 0.0654 (every top particle
          sinks alike into the flat plate, k_J = K A_J / h, sum A_J = L^2); energy balance < 1 %;
          the run report's contact_penetration equals the history's largest
  ignore  a free disc starting 0.05 deep in a free block, initial_penetration: ignore: energy
          balance < 1 % at every record, momentum of particles + disc constant to 1e-8
          relative, the disc turned back by the block (its velocity > 0 at the end), the depth
          beyond the initial one < 0.5 of the spacing
usage: check_contact.py KIND HISTORY.csv [TWIN_HISTORY.csv] [...]
"""
import math
import sys

import numpy as np

from history_checks import HistoryChecks

kind, path = sys.argv[1], sys.argv[2]
history = HistoryChecks(path)
rows, col, check = history.rows, history.col, history.check
t = col("time")


if kind == "impact":
    m_disc, m_block = 2.0 * math.pi * 0.09, 1.0
    v0 = -1.0
    p = col("momentum_y")
    check("momentum drift (relative)", np.abs(p - m_disc * v0).max() / abs(m_disc * v0), 1e-8)
    check("energy balance", col("energy_balance_error").max(), 1e-2)
    F, v1 = col("rb_disc_Fy"), col("rb_disc_vy")
    touched = np.nonzero(F != 0)[0]
    after = touched[-1] + 1 if len(touched) else len(t)
    if after >= len(t) - 1:
        sys.exit("the disc never left the block")
    # After separation: the block's translation from momentum, the rest of its energy is
    # vibration; the relative velocity follows from the energy left for the two-body motion.
    e0 = 0.5 * m_disc * v0 * v0
    ke, ie = col("kinetic_energy")[after:], col("internal_energy")[after:]
    vd = v1[after:]
    V = (m_disc * v0 - m_disc * vd) / m_block
    vib = (ke - 0.5 * m_disc * vd ** 2 - 0.5 * m_block * V ** 2) + ie
    mu = m_disc * m_block / (m_disc + m_block)
    v_rel = np.sqrt(np.maximum(0.0, v0 * v0 - 2.0 * vib / mu))  # |v_disc - V| after
    vc = (m_disc * v0) / (m_disc + m_block)  # center of mass velocity
    predicted = vc + m_block / (m_disc + m_block) * v_rel  # the disc moves back up
    print("after t = %.4g: disc %.6f, predicted %.6f, vibration energy %.3g of %.3g"
          % (t[after], vd[-1], predicted[-1], vib[-1], e0))
    check("rebound velocity (relative)", np.abs(vd - predicted).max() / abs(predicted[-1]), 1e-2)
elif kind == "punch":
    F, R = col("rb_punch_Fy"), col("R_base_y")
    check("|R_base_y - rb_punch_Fy| / max", np.abs(F - R).max() / np.abs(F).max(), 5e-3)
    check("energy balance", col("energy_balance_error").max(), 1e-4)
elif kind == "roll":
    m, R, w0 = 0.5, 0.25, -4.0
    inertia = 0.5 * m * R * R
    vx, w = col("rb_disc_vx"), col("rb_disc_wz")
    L0 = inertia * w0
    late = t >= 0.5
    L = (inertia * w - m * R * vx) / L0 - 1
    # the bounce on the elastic ground moves the contact patch: L oscillates by about 5 %
    check("angular momentum about the contact point, largest deviation", np.abs(L).max(), 6e-2)
    check("angular momentum about the contact point, mean over t >= 0.5", L[late].mean(), 1e-2)
    v_roll = -w0 * R / 3
    check("mean rolling speed vs -omega0 R / 3 (relative)", vx[late].mean() / v_roll - 1, 2e-2)
    check("mean -omega R vs -omega0 R / 3 (relative)", (-w[late] * R).mean() / v_roll - 1, 2e-2)
    check("energy balance", col("energy_balance_error").max(), 1e-2)
elif kind in ("rest", "pressed"):
    late = t >= 3.0
    if kind == "pressed":  # resultant at the block's axis x = 0.5, box centre at x = 0.7
        check("contact moment about the box centre vs (0.5 - 0.7) x 5 (relative)",
              np.abs(col("rb_box_Mz")[late] / -1.0 - 1).max(), 5e-3)
    else:  # box centred over the block: no moment
        check("contact moment about the box centre / (weight x box width)",
              np.abs(col("rb_box_Mz")[late]).max() / (5.0 * 1.4), 1e-6)
    weight = 0.5 * 10.0
    check("contact force on the box vs weight (relative)",
          np.abs(col("rb_box_Fy")[late] / weight - 1).max(), 5e-3)
    check("base reaction vs weight (relative)", np.abs(col("R_base_y")[late] / weight - 1).max(),
          5e-3)
    check("box speed", np.abs(col("rb_box_vy")[late]).max(), 1e-4)
    check("energy balance", col("energy_balance_error").max(), 1e-2)
elif kind == "punch_implicit":
    e_star = 1000.0 / (1 - 0.3 ** 2)
    F, R, u = col("rb_punch_Fy"), col("R_base_y"), col("rb_punch_uy")
    late = t > 0
    check("travel error", np.abs(u + 0.01 * t).max(), 1e-12)
    check("force vs E* delta (relative)",
          np.abs(F[late] / (e_star * 0.01 * t[late]) - 1).max(), 5e-3)
    check("|R_base_y - rb_punch_Fy| / max", np.abs(F - R).max() / np.abs(F).max(), 1e-8)
    if kind == "punch_implicit":
        # The uniform pressure's resultant acts at the middle of the top in its current place,
        # x = 0.5 (1 + eps_xx), eps_xx = nu / (1 - nu) x 0.01 t (plane strain, sigma_xx = 0, the
        # block free to widen); the punch's centre is at x = 1.
        x_f = 0.5 * (1 + 0.3 / 0.7 * 0.01 * t)
        check("contact moment vs (x_F - 1) F (relative to max F)",
              np.abs(col("rb_punch_Mz") - (x_f - 1.0) * F).max() / np.abs(F).max(), 1e-4)
elif kind in ("stacked", "stacked3d"):
    up = "Fy" if kind == "stacked" else "Fz"
    axis = up[-1].lower()
    F = col("contact_stack_" + up)
    floor, press = col("R_floor_" + axis), col("R_press_" + axis)
    P = np.abs(F).max()
    check("|contact force + floor reaction| / P", np.abs(F + floor).max() / P, 1e-9)
    check("|contact force - press reaction| / P", np.abs(F - press).max() / P, 1e-9)
    E, nu, delta = 1000.0, 0.3, 0.01
    if kind == "stacked":  # plane strain; K = 100 E (9 x 1.1 + 12 x (1 + 1/12))
        stiff, K = E / (1 - nu ** 2), 100 * E * (9 * 1.1 + 12 * (1 + 1.0 / 12))
    else:  # uniaxial stress; K = 100 E (4 x (1 + 1/3) + 3 x 1.5)
        stiff, K = E, 100 * E * (4 * (1 + 1.0 / 3) + 3 * 1.5)
    hand = delta / (1.0 / stiff + 1.0 / K)
    check("|P / P_hand - 1|", abs(-F[-1] / hand - 1), 1e-4 if kind == "stacked" else 1e-3)
    # The consistent tangent: 6 Newton iterations over the 2 load steps (the first iterate
    # without contact, then a contraction by about 1e-3 per iteration; with the facet's nodes
    # held in the tangent, as against a rigid surface, it takes NEWTON_WITH_FIXED_FACETS).
    import glob
    import json
    import os
    reports = glob.glob(os.path.join(os.path.dirname(path), "*.report.json"))
    stage = json.load(open(reports[0]))["implicit_stages"][0]
    check("Newton iterations over the stage", stage["newton_iterations"], 8)
elif kind == "punch_force":
    E, nu, h = 1000.0, 0.3, 1.0 / 12
    F = E / (1 - nu ** 2) * 0.01
    place = -t * (0.01 + F * h / (100 * E * (1 + h)))
    check("punch place vs hand value / 0.01", np.abs(col("rb_punch_uy") - place).max() / 0.01, 1e-4)
    if len(sys.argv) > 3:
        twin = HistoryChecks(sys.argv[3])
        F_p, t_p = twin.col("rb_punch_Fy"), twin.col("time")
        late = t > 0
        if not np.array_equal(t, t_p):
            sys.exit("the two histories have different records")
        scaled = -0.01 * t[late] * (F * t[late]) / F_p[late]
        check("punch place vs the prescribed run's, scaled by F / F_p, / 0.01",
              np.abs(col("rb_punch_uy")[late] - scaled).max() / 0.01, 1e-9)
    check("|rb_punch_Fy - F t| / F", np.abs(col("rb_punch_Fy") - F * t).max() / F, 1e-8)
    check("|R_base_y - F t| / F", np.abs(col("R_base_y") - F * t).max() / F, 1e-8)
    check("punch moved across its load (u_x)", np.abs(col("rb_punch_ux")).max(), 0.0)
elif kind == "lbody":
    boxes = [((0.0, 0.0, 5.0), (0.6, 0.2, 5.2)), ((0.0, 0.2, 5.0), (0.2, 0.6, 5.2))]
    masses, centres, own = [], [], []
    for lo, hi in boxes:
        side = np.subtract(hi, lo)
        m = float(np.prod(side))  # density 1
        masses.append(m)
        centres.append(np.add(lo, hi) / 2)
        own.append(m / 12 * np.diag([side[1]**2 + side[2]**2, side[0]**2 + side[2]**2,
                                     side[0]**2 + side[1]**2]))
    M = sum(masses)
    c = sum(m * x for m, x in zip(masses, centres)) / M
    J = sum(I + m * (np.dot(x - c, x - c) * np.eye(3) - np.outer(x - c, x - c))
            for m, x, I in zip(masses, centres, own))
    w0 = np.array([1.0, 2.0, 3.0])
    L0 = J @ w0
    w = np.stack([col("rb_ell_wx"), col("rb_ell_wy"), col("rb_ell_wz")], axis=1)
    energy = 0.5 * w @ L0
    check("omega . L0 / 2 drift (relative)", np.abs(energy / (0.5 * w0 @ L0) - 1).max(), 1e-5)
    check("products of inertia present (|J_xy| / J_xx, above 0.05)", max(0.0, 0.05 - abs(J[0, 1]) / J[0, 0]), 0.0)
elif kind == "curved_tool":
    F = col("rb_tool_Fy")[-1]
    errors = []
    for path in sys.argv[3:5]:
        ring = HistoryChecks(path)
        errors.append(ring.col("rb_tool_Fy")[-1] / F - 1)
        check("|F_x| / F_y of the ring", np.abs(ring.col("rb_tool_Fx")).max() / F, 1e-10)
    print("force error of the 64-gon %.3e, of the 128-gon %.3e" % tuple(errors))
    check("force of the 128-gon vs the cylinder (relative)", abs(errors[1]), 1e-3)
    check("error reduction from 64 to 128 cells (2 - ratio, below 0)",
          max(0.0, 2.0 - abs(errors[0]) / abs(errors[1])), 0.0)
elif kind == "spin_implicit":
    mu, R = 0.3, 0.25
    late = t > 0
    Fx, Fy, Mz = col("rb_roll_Fx")[late], col("rb_roll_Fy")[late], col("rb_roll_Mz")[late]
    check("M_z / (R F_y) vs mu (relative)", np.abs(Mz / (R * Fy) / mu - 1).max(), 1e-2)
    check("the friction along the surface's motion: 0.5 - min F_x / (mu F_y), below 0",
          max(0.0, 0.5 - (Fx / (mu * Fy)).min()), 0.0)
    for axis in "xy":
        check("|R_base_%s - rb_roll_F%s| / max F_y" % (axis, axis),
              np.abs(col("R_base_" + axis) - col("rb_roll_F" + axis)).max() / np.abs(Fy).max(),
              1e-6)
elif kind == "driven":
    omega, R = -4.0, 0.25
    late = t >= 1.6 - 1e-9
    check("strip speed vs omega R (relative)", col("v_all_x")[late].mean() / (omega * R) - 1,
          3e-2)
    check("energy balance", col("energy_balance_error").max(), 1e-2)
    check("roll spin vs omega", np.abs(col("rb_roll_wz") - omega).max(), 0.0)
elif kind in ("tumble", "tumble3d"):
    # the box falls along y (2D, spinning about z) or z (3D, spinning mostly about y)
    fall, spin, across = ("y", "wz", "x") if kind == "tumble" else ("z", "wy", "xy")
    m_box, v0, w0 = 0.5, -1.0, 3.0
    p = col("momentum_" + fall)
    check("momentum drift (relative)", np.abs(p - m_box * v0).max() / abs(m_box * v0), 1e-8)
    for axis in across:
        check("momentum_%s / |momentum|" % axis,
              np.abs(col("momentum_" + axis)).max() / abs(m_box * v0), 1e-8)
    check("energy balance", col("energy_balance_error").max(), 1e-2)
    w = col("rb_box_" + spin)
    check("spin unchanged by the contact (0.1 - |omega_end - omega0|, below 0)",
          max(0.0, 0.1 - abs(w[-1] - w0)), 0.0)
    check("contact force at the end", np.abs(col("rb_box_F" + fall)[-1]), 0.0)
elif kind == "precession":
    m = 1.0
    I1, I3 = m * (0.2**2 + 0.6**2) / 12, m * (0.2**2 + 0.2**2) / 12
    w0 = np.array([1.0, 0.0, 2.0])
    L = np.array([I1 * w0[0], I1 * w0[1], I3 * w0[2]])
    n = L / np.linalg.norm(L)
    w = np.stack([col("rb_box_wx"), col("rb_box_wy"), col("rb_box_wz")], axis=1)
    check("|omega| drift (relative)",
          np.abs(np.linalg.norm(w, axis=1) - np.linalg.norm(w0)).max() / np.linalg.norm(w0), 1e-6)
    check("omega . L / |L| drift (relative)",
          np.abs(w @ n - w0 @ n).max() / np.linalg.norm(w0), 1e-6)
    # the phase of omega's part across L, about L, against |L| / I1 t
    e1 = w0 - (w0 @ n) * n
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    phase = np.unwrap(np.arctan2(w @ e2, w @ e1))
    rate = np.linalg.norm(L) / I1
    print("precession: %.6f rad over %.2f against %.6f" % (phase[-1], t[-1], rate * t[-1]))
    check("phase error (rad)", np.abs(phase - rate * (t - t[0])).max(), 1e-3)
    ke = col("kinetic_energy")
    e0 = 0.5 * w0 @ L
    check("kinetic energy drift (relative)", np.abs(ke - e0).max() / e0, 1e-6)
elif kind == "drag_implicit":
    mu = 0.3
    Fx, Fy = col("rb_punch_Fx"), col("rb_punch_Fy")
    scale = np.abs(Fy).max()
    press, slip = (t > 0) & (t <= 0.5 + 1e-9), t >= 1.0 - 1e-9
    partial = (np.abs(t - 0.6) < 1e-9) | (np.abs(t - 0.7) < 1e-9)
    check("F_x while pressing / max F_y", np.abs(Fx[press]).max() / scale, 1e-8)
    check("partial slip: largest |F_x| / (mu F_y) - 1 at t = 0.6, 0.7 (below 0)",
          max(0.0, (np.abs(Fx[partial]) / (mu * Fy[partial])).max() - 1 + 1e-3), 0.0)
    check("full slip: |F_x + mu F_y| / max F_y", np.abs(Fx[slip] + mu * Fy[slip]).max() / scale,
          1e-8)
    check("|R_base_x - F_x| / max F_y", np.abs(col("R_base_x") - Fx).max() / scale, 1e-8)
    check("|R_base_y - F_y| / max F_y", np.abs(col("R_base_y") - Fy).max() / scale, 1e-8)
elif kind == "drag_parts":
    mu = 0.3
    Fx, Fy = col("contact_rub_Fx"), col("contact_rub_Fy")  # the block's force on the base
    scale = np.abs(Fy).max()
    slip, building = t >= 1.2 - 1e-9, (t > 0.5 + 1e-9) & (t < 0.75)
    check("building up: largest F_x / (mu |F_y|) - 1 (below 0)",
          max(0.0, (np.abs(Fx[building]) / (mu * np.abs(Fy[building]))).max() - 1 + 1e-3), 0.0)
    check("full slip: |F_x / (mu |F_y|) - 1|", np.abs(Fx[slip] / (mu * np.abs(Fy[slip])) - 1).max(),
          5e-3)
    check("|R_clamp_x + F_x| / max |F_y|", np.abs(col("R_clamp_x") + Fx).max() / scale, 1e-8)
    check("|R_clamp_y + F_y| / max |F_y|", np.abs(col("R_clamp_y") + Fy).max() / scale, 1e-8)
elif kind == "foam":
    W, K, L = 9810.0, 1.0 / (3 * (1 - 2 * 0.3)), 600.0
    exact = 2 * W / (K * L * L)
    check("peak plate force / 2 W - 1", col("rb_plate_Fz").max() / (2 * W) - 1, 0.05)
    for name in ("contact_top_pen", "contact_bottom_pen"):
        largest = col(name).max()
        print("%s largest %.4f, by hand %.4f" % (name, largest, exact))
        check(name + " largest (fraction of the spacing)", largest, 0.10)
        check(name + " largest / by hand - 1", largest / exact - 1, 0.10)
    check("energy balance", col("energy_balance_error").max(), 1e-2)
    # The run report's explicit_stages[].contact_penetration: the largest over the stage, which
    # the history's per-record peaks (the largest since the previous record) hold as well.
    import glob
    import json
    import os
    report = json.load(open(glob.glob(os.path.join(os.path.dirname(path), "*.report.json"))[0]))
    stage = report["explicit_stages"][0]["contact_penetration"]
    for name in ("top", "bottom"):
        check("report contact_penetration." + name + " vs the history's largest",
              stage[name] - col("contact_%s_pen" % name).max(), 1e-9)
elif kind == "ignore":
    p = col("momentum_y")
    check("momentum drift (relative)", np.abs(p - p[0]).max() / abs(p[0]), 1e-8)
    check("energy balance", col("energy_balance_error").max(), 1e-2)
    v_end = col("rb_disc_vy")[-1]
    print("disc velocity at the end %.4f" % v_end)
    check("disc not turned back (v_end <= 0)", 0.0 if v_end > 0 else 1.0, 0.0)
    check("depth beyond the initial one", col("contact_hit_pen").max(), 0.5)
elif kind in ("slide", "stick"):
    tan, mu, g, M = (0.5 if kind == "slide" else 0.2), 0.3, 1.0, 0.5
    th = math.atan(tan)
    if kind == "slide":
        history.check_incline_slide(col("momentum_x") / M, tan, mu, g)
    else:
        history.check_at_rest(col("u_ymin_x"))
        late = t >= 3.0
        fx, fy = col("rb_incline_Fx")[late], col("rb_incline_Fy")[late]
        check("tangential support vs M g sin (relative)",
              np.abs(fx - M * g * math.sin(th)).max() / (M * g * math.sin(th)), 5e-3)
        check("normal support vs M g cos (relative)",
              np.abs(-fy - M * g * math.cos(th)).max() / (M * g * math.cos(th)), 5e-3)
sys.exit(0 if history.ok else 1)
