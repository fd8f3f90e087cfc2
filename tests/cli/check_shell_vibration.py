#!/usr/bin/env python3
"""Free vibration of the simply supported plate of tests/scenes/shells/plate_vibration.yaml
(a = 1, t = 0.02, E = 1000, nu = 0.3, rho = 1; released at rest from its static deflection at
t = 1): the period of the centre deflection, from its zero crossings over ten periods, within 2 %
of Mindlin's plate theory (and of Kirchhoff's, 0.07 % apart here), and the energy balance
E_kin + E_strain - W_ext = E_0 within 1 % at every record.

Reference: for the mode sin(pi x / a) sin(pi y / a), k^2 = 2 pi^2 / a^2, Mindlin's equations
(Mindlin, J. Appl. Mech. 18, 1951; the simply supported case separates, Leissa, "Vibration of
Plates", NASA SP-160, 1969) give omega^2 as the lower root of
  (k_s G t k^2 - rho t omega^2)(D k^2 + k_s G t - rho t^3/12 omega^2) = (k_s G t k)^2,
which tends to Kirchhoff's omega = k^2 sqrt(D / (rho t)) as t -> 0. The zero crossings of the
centre time the first mode alone: the static shape's other modes (m, n odd) run at
(m^2 + n^2) / 2 = 5, 9, 13, ... times its frequency and vanish with it at the crossings.
usage: check_shell_vibration.py history.csv
"""
import csv
import math
import sys

a, t, E, nu, rho, ks = 1.0, 0.02, 1000.0, 0.3, 1.0, 5.0 / 6.0
released = 1.0
rows = [r for r in csv.DictReader(open(sys.argv[1])) if float(r["time"]) >= released - 1e-12]
time = [float(r["time"]) for r in rows]
w = [float(r["probe_centre_uz"]) for r in rows]
errors = []

D = E * t**3 / (12 * (1 - nu**2))
G = E / (2 * (1 + nu))
k2 = 2 * math.pi**2 / a**2
kirchhoff = k2 * math.sqrt(D / (rho * t))
# the quadratic A x^2 + B x + C = 0 in x = omega^2
S, J, m = ks * G * t, rho * t**3 / 12, rho * t
A = m * J
B = -(m * (D * k2 + S) + J * S * k2)
C = S * k2 * (D * k2 + S) - S * S * k2
mindlin = math.sqrt((-B - math.sqrt(B * B - 4 * A * C)) / (2 * A))

crossings = []
for i in range(len(w) - 1):
    if w[i] * w[i + 1] < 0:
        crossings.append(time[i] - w[i] * (time[i + 1] - time[i]) / (w[i + 1] - w[i]))
if len(crossings) < 20:
    sys.exit("only %d zero crossings of the centre deflection (ten periods give 21)" % len(crossings))
period = 2 * (crossings[-1] - crossings[0]) / (len(crossings) - 1)
error = period / (2 * math.pi / mindlin) - 1
print("period %.6f: %+.3f %% vs Mindlin %.6f, %+.3f %% vs Kirchhoff %.6f (%d crossings)"
      % (period, 100 * error, 2 * math.pi / mindlin,
         100 * (period / (2 * math.pi / kirchhoff) - 1), 2 * math.pi / kirchhoff, len(crossings)))
if abs(error) > 0.02:
    errors.append("period %g is %.2f %% off Mindlin's %g" % (period, 100 * error, 2 * math.pi / mindlin))

E0 = float(rows[0]["strain_energy"]) + float(rows[0]["kinetic_energy"])
worst = 0.0
for r in rows:
    balance = float(r["strain_energy"]) + float(r["kinetic_energy"]) - float(r["external_work"])
    worst = max(worst, abs(balance - E0) / E0)
print("energy balance: worst %.2e of the initial energy %.6g over %d records" % (worst, E0, len(rows)))
if worst > 0.01:
    errors.append("energy balance error %.3g > 1 %%" % worst)
# the kinetic energy must take the whole energy at the crossings: it vibrates, not creeps
if max(float(r["kinetic_energy"]) for r in rows) < 0.9 * E0:
    errors.append("the kinetic energy never reaches 90 % of the initial energy")

if errors:
    sys.exit("\n".join(errors))
print("ok")
