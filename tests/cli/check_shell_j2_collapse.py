#!/usr/bin/env python3
"""The collapse load of a J2 shell, bracketed (tests/scenes/shells/strip_j2_pressure_below.yaml and
_above.yaml): a simply supported plate strip in cylindrical bending (L = 1, t = 0.01,
sigma_y = 0.1, elastic-perfectly plastic, 12 Gauss layers) under a uniform pressure raised over
t in [0, 60] and held to 90. Limit analysis: q_c = 8 M_p / L^2, M_p = (2 / sqrt 3) sigma_y t^2 / 4
in plane strain (1.0053 M_p through the 12-layer rule).
Below (q = 0.985 q_c): the strip settles (the middle's deflection changes by less than 2 % over
the last 10, the residual vibration; kinetic energy below 1e-3 of the internal energy), it has yielded (plastic
strain > 0 at the middle), and the moments of the particles in the middle half follow statics,
M = -q x (L - x) / 2, within 3 % of M_p (statics holds whatever the material does).
Above (q = 1.04 q_c): it runs away (the middle's deflection at the end more than 5 times that at
the end of the rise) while the particles at the middle carry 1.0053 M_p within 2 %, their
outermost layers (the stress_top/bottom output) in the fully plastic plane-strain state,
|sigma_xx| = 2 sigma_y / sqrt 3 and sigma_yy = sigma_xx / 2, within 2 %.
usage: check_shell_j2_collapse.py BELOW/history.csv BELOW.e ABOVE/history.csv ABOVE.e
"""
import csv
import math
import sys

import netCDF4
import numpy as np

L, t, sigma_y, rise = 1.0, 0.01, 0.1, 60.0
M_p = 2 / math.sqrt(3) * sigma_y * t * t / 4
q_c = 8 * M_p / L**2
errors = []


def fields(path):
    f = netCDF4.Dataset(path)
    names = list(netCDF4.chartostring(f.variables["name_nod_var"][:]))
    x = np.asarray(f.variables["coordx"][:])
    return x, lambda name: np.asarray(f.variables["vals_nod_var%d" % (names.index(name) + 1)][-1])


def deflection(rows, time):
    return min((abs(float(r["time"]) - time), float(r["probe_middle_uz"])) for r in rows)[1]


# below
rows = list(csv.DictReader(open(sys.argv[1])))
end = float(rows[-1]["time"])
w_end, w_before = deflection(rows, end), deflection(rows, end - 10)
ratio = float(rows[-1]["kinetic_energy"]) / float(rows[-1]["strain_energy"])
print("below: middle deflection %.6e (%.2e change over the last 10), kinetic / internal %.1e"
      % (w_end, abs(w_end / w_before - 1), ratio))
if abs(w_end / w_before - 1) > 0.02 or ratio > 1e-3:
    errors.append("below the collapse load the strip has not settled")
x, last = fields(sys.argv[2])
q = 0.985 * q_c
middle_half = (x > 0.25 - 1e-9) & (x < 0.75 + 1e-9)
statics = -q * x * (L - x) / 2
worst = np.abs(last("moment_xx") - statics)[middle_half].max() / M_p
print("below: moments in the middle half vs statics: worst %.4f M_p" % worst)
if worst > 0.03:
    errors.append("moments off statics by %.3f M_p" % worst)
yielded = last("plastic_strain")[np.abs(x - L / 2) < 1e-9]
if not np.all(yielded > 0):
    errors.append("the middle has not yielded below the collapse load: %s" % yielded)
# above
rows = list(csv.DictReader(open(sys.argv[3])))
w_rise, w_end = deflection(rows, rise), deflection(rows, float(rows[-1]["time"]))
print("above: middle deflection %.4e at the end of the rise, %.4e at the end" % (w_rise, w_end))
if not abs(w_end) > 5 * abs(w_rise):
    errors.append("above the collapse load the strip did not run away")
x, last = fields(sys.argv[4])
hinge = -last("moment_xx")[np.abs(x - L / 2) < 1e-9] / (1.0052943945513044 * M_p)
print("above: hinge moments / (1.0053 M_p): %s" % np.array2string(hinge, precision=4))
if hinge.size == 0 or np.any(np.abs(hinge - 1) > 0.02):
    errors.append("hinge moments %s, expected 1 within 2 %%" % hinge)
# the outermost layers at the hinge in the fully plastic plane-strain state: |sigma_xx| =
# 2 sigma_y / sqrt 3 and sigma_yy = sigma_xx / 2 (von Mises with eps_yy = 0 and plastic flow)
at_hinge = np.abs(x - L / 2) < 1e-9
for side in ("top", "bottom"):
    sxx, syy = last("stress_%s_xx" % side)[at_hinge], last("stress_%s_yy" % side)[at_hinge]
    print("above: %s layer at the hinge: |sigma_xx| / (2 sigma_y / sqrt 3) %s, sigma_yy / sigma_xx %s"
          % (side, np.array2string(np.abs(sxx) / (2 * sigma_y / math.sqrt(3)), precision=4),
             np.array2string(syy / sxx, precision=4)))
    if np.any(np.abs(np.abs(sxx) / (2 * sigma_y / math.sqrt(3)) - 1) > 0.02) or \
            np.any(np.abs(syy / sxx - 0.5) > 0.02):
        errors.append("the %s layer at the hinge is not in the plane-strain plastic state" % side)
if errors:
    sys.exit("\n".join(errors))
print("ok")
