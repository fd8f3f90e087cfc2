#!/usr/bin/env python3
"""A rigid impactor of mesh blocks against its analytic twin (the same run with the analytic
shape the facets are inscribed in: tests/scenes/contact/tube_side_*.yaml): the impactor's
velocity change over the run (its rebound) and the peak contact force equal the analytic run's
within TOL (2 % by default: the 48-gon of radius 40 departs from the circle by its sag,
0.086 mm, against an indentation of about 0.7 mm under the peak load - a contact half-width
a = sqrt(4 P R / (pi E*)) = 7.6 mm for P = 1.24e4 N/mm, Johnson (1985) eq. 4.43, and depth about
a^2 / 2R: the force may differ by up to the sag's share of it, 12 %, where the contact width
spans only 3 facets; measured 0.2 % on the rebound, 1.0 % on the peak), and the force's sideways components stay below 1e-3 of the peak (the
tessellation is symmetric about the impact's plane).
usage: check_impactor_twin.py mesh_history.csv analytic_history.csv [TOL]"""
import csv
import sys

import numpy as np


def load(path):
    rows = list(csv.DictReader(open(path)))
    return lambda name: np.array([float(r[name]) for r in rows])


mesh, analytic = load(sys.argv[1]), load(sys.argv[2])
tol = float(sys.argv[3]) if len(sys.argv) > 3 else 2e-2
dv = [c("rb_imp_vz")[-1] - c("rb_imp_vz")[0] for c in (mesh, analytic)]
peak = [np.abs(c("rb_imp_Fz")).max() for c in (mesh, analytic)]
side = max(np.abs(mesh(k)).max() for k in ("rb_imp_Fx", "rb_imp_Fy")) / peak[0]
print("velocity change %.6g against %.6g (%.3g); peak force %.6g against %.6g (%.3g); "
      "sideways force / peak %.3g" % (dv[0], dv[1], dv[0] / dv[1] - 1, peak[0], peak[1],
                                      peak[0] / peak[1] - 1, side))
ok = abs(dv[0] / dv[1] - 1) <= tol and abs(peak[0] / peak[1] - 1) <= tol and side <= 1e-3
sys.exit(0 if ok else 1)
