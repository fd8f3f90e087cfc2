#!/usr/bin/env python3
"""Explicit and implicit shells on one quasi-static load (tests/scenes/shells/plate_quasistatic.yaml):
the simply supported plate (a = 1, t = 0.02, E = 1000, nu = 0.3) under a uniform pressure q = 1
raised over five periods (8.3155) and held for one (1.6631) in an explicit stage, then solved
statically by an implicit stage. The explicit centre deflection averaged over the held period
(the residual vibration averages out) agrees with the implicit one within 0.3 %, and both lie
within 1 % of Navier's w_c = 0.00406235 q a^4 / D (Timoshenko & Woinowsky-Krieger 1959, table 8;
Mindlin's shear adds about 0.1 % at t/a = 0.02). The kinetic energy over the held period stays
below 1e-3 of the strain energy (quasi-static).
The explicit stage holds the supports by Lagrange multipliers, the implicit one by collocation
rows with edge terms: both consistent, so they differ by the discretization only.
usage: check_shell_quasistatic.py history.csv
"""
import csv
import sys

period, rise = 1.6631, 5 * 1.6631
t_, E, nu, q = 0.02, 1000.0, 0.3, 1.0
rows = list(csv.DictReader(open(sys.argv[1])))
held = [r for r in rows if rise - 1e-9 <= float(r["time"]) <= rise + period + 1e-9]
explicit = sum(float(r["probe_centre_uz"]) for r in held[:-1]) / len(held[:-1])
implicit = float(rows[-1]["probe_centre_uz"])
D = E * t_**3 / (12 * (1 - nu**2))
navier = 0.00406235 * q / D
errors = []
gap = explicit / implicit - 1
print("centre deflection: explicit (mean over the held period) %.6f, implicit %.6f (%+.3f %%), "
      "Navier %.6f (explicit %+.3f %%, implicit %+.3f %%)"
      % (explicit, implicit, 100 * gap, navier, 100 * (explicit / navier - 1),
         100 * (implicit / navier - 1)))
if len(held) < 40:
    errors.append("only %d records in the held period" % len(held))
if abs(gap) > 3e-3:
    errors.append("explicit and implicit differ by %.3f %%" % (100 * gap))
for name, w in (("explicit", explicit), ("implicit", implicit)):
    if abs(w / navier - 1) > 0.01:
        errors.append("%s deflection %.3f %% off Navier" % (name, 100 * (w / navier - 1)))
ratio = max(float(r["kinetic_energy"]) / float(r["strain_energy"]) for r in held)
print("kinetic / strain energy over the held period: at most %.2e" % ratio)
if ratio > 1e-3:
    errors.append("kinetic / strain energy %.2e > 1e-3: not quasi-static" % ratio)
if errors:
    sys.exit("\n".join(errors))
print("ok")
