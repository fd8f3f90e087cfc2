#!/usr/bin/env python3
"""Springback of a J2 shell (tests/scenes/shells/strip_j2_springback.yaml): a plate strip in
cylindrical bending bent explicitly by end rotations to kappa = 10 kappa_y, released implicitly.
Closed form (../shared/reference/benchmarks.md, section 7; plane strain, elastic-perfectly
plastic): E' = E / (1 - nu^2), sigma_y' = 2 sigma_y / sqrt 3, kappa_y = 2 sigma_y' / (E' t),
M = sigma_y' t^2 / 4 (1 - (kappa_y / kappa)^2 / 3) per unit width, and on release the curvature
drops by M / (E' t^3 / 12).
Checks (the curvature: slope of rotation_y over x of the particles two cells or more from the
ends; the moment: their mean moment_xx):
  * end of bending (t = 70): M within 2 % of the closed form (the 12-layer rule carries 1.005 of
    the fully plastic moment; a J2 layer in plane strain reaches sigma_y' only asymptotically);
  * the curvature change on release within 3 % of the closed form M / (E' I) (the criterion of
    issue 21) and within 1 % of the bent strip's own M / (E' I) (the release is elastic);
  * released (t = 71): moments below 1 % of M_p, plastic strain unchanged (to 1e-12).
usage: check_shell_springback.py RESULTS.e
"""
import math
import sys

import netCDF4
import numpy as np

E, nu, t, sigma_y = 1000.0, 0.3, 0.01, 0.1
E1 = E / (1 - nu**2)
s1 = 2 * sigma_y / math.sqrt(3)
D = E1 * t**3 / 12
kappa_y = 2 * s1 / (E1 * t)
kappa = 10 * kappa_y
M_closed = s1 * t * t / 4 * (1 - (kappa_y / kappa) ** 2 / 3)
M_p = s1 * t * t / 4

f = netCDF4.Dataset(sys.argv[1])
names = list(netCDF4.chartostring(f.variables["name_nod_var"][:]))
times = np.asarray(f.variables["time_whole"][:])
x = np.asarray(f.variables["coordx"][:])


def field(name, k):
    return np.asarray(f.variables["vals_nod_var%d" % (names.index(name) + 1)][k])


bent, released = int(np.argmin(np.abs(times - 70))), int(np.argmin(np.abs(times - 71)))
errors = []
if abs(times[bent] - 70) > 1e-9 or abs(times[released] - 71) > 1e-9:
    errors.append("records at t = 70 and 71 expected, found %s" % list(times))
h = 1.0 / 12
inner = (x > 2 * h - 1e-9) & (x < 1 - 2 * h + 1e-9)


def curvature(k):
    return np.polyfit(x[inner], field("rotation_y", k)[inner], 1)[0]


M_bent = field("moment_xx", bent)[inner].mean()
change = curvature(bent) - curvature(released)
left = np.abs(field("moment_xx", released)).max() / M_p
plastic = np.abs(field("plastic_strain", released) - field("plastic_strain", bent)).max()
print("bent: M %.6e vs the closed form %.6e (%+.2f %%); curvature %.4f kappa_y"
      % (M_bent, M_closed, 100 * (M_bent / M_closed - 1), curvature(bent) / kappa_y))
print("released: curvature change %.6e vs M / (E' I) %.6e closed form (%+.2f %%), %.6e own "
      "(%+.2f %%); moments left %.1e M_p; plastic strain changed by %.1e"
      % (change, M_closed / D, 100 * (change * D / M_closed - 1), M_bent / D,
         100 * (change * D / M_bent - 1), left, plastic))
if abs(M_bent / M_closed - 1) > 0.02:
    errors.append("the bending moment is off the closed form")
if abs(change * D / M_closed - 1) > 0.03:
    errors.append("the springback is off the closed form by more than 3 %")
if abs(change * D / M_bent - 1) > 0.01:
    errors.append("the springback is not the elastic release of the bent strip's moment")
if left > 0.01 or plastic > 1e-12:
    errors.append("the released strip keeps moments or changed its plastic strain")
if errors:
    print("FAILED:\n  " + "\n  ".join(errors))
    sys.exit(1)
print("springback of a J2 shell: checks passed")
