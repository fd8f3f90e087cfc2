#!/usr/bin/env python3
"""A moving support in an explicit shell stage (tests/scenes/shells/strip_pressed.yaml): the half
of a plate strip in cylindrical bending (L = 1, W = 1/3, t = 0.01, E = 1000, nu = 0.3),
simply supported at x = 0, its middle edge pressed to w = -delta = -0.01 over t in [0, 10] and
held until 12.66, then the same delta held by an implicit stage.
Kirchhoff's beam with D = E t^3 / (12 (1 - nu^2)) per unit width (Mindlin's shear adds 3e-4
of the deflection at t/L = 0.01, the shear stabilization about 3e-3): the middle edge's force
on the strip -P W / 2 = -24 D delta W / L^3, the simple support's +P W / 2, the deflection at
x = L/4 of 11/16 delta. Checked over the held time (records averaged, the support forces being
means over each output interval): both forces within 1 %, their sum within the bound the strip's
momentum sets (equilibrium), the explicit and the implicit
deflection at x = L/4 within 0.5 % of 11/16 delta and within 0.1 % of each other, the kinetic
energy below 1e-3 of the strain energy, and the energy balance E_kin + E_strain = W (the moving
support's work) within 1 % of the final strain energy at every record.
usage: check_shell_pressed_strip.py history.csv
"""
import csv
import sys

L, W, t, E, nu, delta = 1.0, 1.0 / 3.0, 0.01, 1000.0, 0.3, 0.01
rise, held_until = 10.0, 10.0 + 2 * 1.33
rows = list(csv.DictReader(open(sys.argv[1])))
explicit = [r for r in rows if float(r["time"]) <= held_until + 1e-9]
held = [r for r in explicit if float(r["time"]) >= rise - 1e-9]
D = E * t**3 / (12 * (1 - nu**2))
force = 24 * D * delta * W / L**3
quarter = -11.0 / 16.0 * delta
errors = []


def mean(column):
    return sum(float(r[column]) for r in held) / len(held)


if len(held) < 80:
    errors.append("only %d records over the held time" % len(held))
for column, expected in (("support_press_force_z", -force), ("support_support_force_z", force)):
    value = mean(column)
    print("%s: %.6e against %.6e (%+.3f %%)" % (column, value, expected, 100 * (value / expected - 1)))
    if abs(value / expected - 1) > 0.01:
        errors.append("%s off by %.2f %%" % (column, 100 * (value / expected - 1)))
# Equilibrium: nothing else loads the strip in z (the sides hold y and rx only, whose terms do no
# work on w), so over the held time the two supports' mean forces sum to the change of the z
# momentum over that time, |sum| <= 2 max |p_z| / T_held, and by Cauchy-Schwarz with the lumped
# translational masses p_z^2 <= (sum m) (sum m v_z^2) <= 2 M E_kin, M = rho t L/2 W (rho = 1).
# Measured: -0.49 % of the load (multipliers, bound 2.0 %), +0.08 % (nitsche, bound 1.2 %).
# The supports' forces are written as means over each record's interval (the multipliers', and
# since issue 56 the nitsche supports' too): the press edge rings, and instantaneous samples
# aliased (with k_s = 1 instead of 5/6 its force swings +-8.5e-5, 11 times the load, and 101
# samples summed to +246 % of the load; at a 4.6 % smaller time step the press force came out
# 3.1 % off and this sum 2.8 times its bound): this assertion fails on such samples.
mass = 1.0 * t * L / 2 * W
held_time = float(held[-1]["time"]) - float(held[0]["time"])
kinetic_max = max(float(r["kinetic_energy"]) for r in held)
bound = 2 * (2 * mass * kinetic_max) ** 0.5 / held_time
total = mean("support_press_force_z") + mean("support_support_force_z")
print("equilibrium: supports sum to %.3e (%+.3f %% of the load), momentum bound %.3e (%.3f %%)"
      % (total, 100 * total / force, bound, 100 * bound / force))
if abs(total) > bound:
    errors.append("the supports' forces sum to %.3e, above the momentum bound %.3e: not in "
                  "equilibrium" % (total, bound))
w_explicit, w_implicit = mean("probe_quarter_uz"), float(rows[-1]["probe_quarter_uz"])
print("deflection at L/4: explicit %.6e, implicit %.6e, Kirchhoff %.6e (%+.3f %%, %+.3f %%)"
      % (w_explicit, w_implicit, quarter, 100 * (w_explicit / quarter - 1),
         100 * (w_implicit / quarter - 1)))
for name, w in (("explicit", w_explicit), ("implicit", w_implicit)):
    if abs(w / quarter - 1) > 5e-3:
        errors.append("%s deflection at L/4 off by %.3f %%" % (name, 100 * (w / quarter - 1)))
if abs(w_explicit / w_implicit - 1) > 1e-3:
    errors.append("explicit and implicit differ by %.3f %%" % (100 * (w_explicit / w_implicit - 1)))
ratio = max(float(r["kinetic_energy"]) / float(r["strain_energy"]) for r in held)
final = float(explicit[-1]["strain_energy"])
balance = max(abs(float(r["strain_energy"]) + float(r["kinetic_energy"]) -
                  float(r["external_work"])) for r in explicit) / final
print("kinetic / strain energy while held: at most %.2e; energy balance %.2e of the final "
      "strain energy" % (ratio, balance))
if ratio > 1e-3:
    errors.append("kinetic / strain energy %.2e while held: not quasi-static" % ratio)
if balance > 0.01:
    errors.append("energy balance error %.3g > 1 %%" % balance)
if errors:
    sys.exit("\n".join(errors))
print("ok")
