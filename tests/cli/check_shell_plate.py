#!/usr/bin/env python3
"""Clamped square plate (tests/scenes/shells/clamped_plate.yaml): the centre deflection of the
last record against Kirchhoff's w_c = 0.00126532 q a^4 / D (Timoshenko & Woinowsky-Krieger 1959,
table 35; Taylor & Govindjee 2004) within 1 % (16 x 16 particles, t/a = 1e-3: +0.57 % measured),
the rotations at the centre zero by symmetry (1e-9 of w / a), no in-plane motion, and the slope
at the quarter point of the right sign (the plate bends down toward the clamp at x = 0: theta_y
of a deflection rising with x is -dw/dx < 0), and the centre moments M_xx = M_yy = 0.022905 q a^2
(tests/verification/shells/clamped_plate_fd.py) within 1 %, M_xy = 0.
usage: check_shell_plate.py history.csv
"""
import csv
import sys

E, NU, T, Q, A = 1000.0, 0.3, 0.001, 1.0, 1.0
D = E * T ** 3 / (12 * (1 - NU ** 2))
KIRCHHOFF = 0.00126532 * Q * A ** 4 / D

last = list(csv.DictReader(open(sys.argv[1])))[-1]
w = float(last["probe_centre_uz"])
errors = []
rel = w / KIRCHHOFF - 1
print("centre deflection %.6g, Kirchhoff %.6g: %+.3f %%" % (w, KIRCHHOFF, 100 * rel))
if abs(rel) > 0.01:
    errors.append("centre deflection off by %+.3f %% (limit 1 %%)" % (100 * rel))
for c in ("rx", "ry", "ux", "uy"):
    v = float(last["probe_centre_" + c])
    if abs(v) > 1e-9 * abs(w):
        errors.append("centre %s = %g, expected 0 by symmetry" % (c, v))
ry = float(last["probe_quarter_ry"])
print("quarter-point theta_y %.6g" % ry)
if not ry < 0:
    errors.append("theta_y at the quarter point %g: expected < 0 (w rises with x there)" % ry)
M = 0.022905 * Q * A ** 2
for c in ("mxx", "myy"):
    m = float(last["probe_centre_" + c])
    print("centre %s %.6g vs %.6g: %+.3f %%" % (c, m, M, 100 * (m / M - 1)))
    if abs(m / M - 1) > 0.01:
        errors.append("centre %s off by %+.3f %% (limit 1 %%)" % (c, 100 * (m / M - 1)))
if abs(float(last["probe_centre_mxy"])) > 1e-9 * M:
    errors.append("centre mxy %s, expected 0 by symmetry" % last["probe_centre_mxy"])
if float(last["strain_energy"]) <= 0:
    errors.append("strain energy not positive")
if errors:
    sys.exit("FAILED: " + "; ".join(errors))
print("ok")
