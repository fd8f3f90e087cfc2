#!/usr/bin/env python3
"""A cantilever strip under a uniform pressure (tests/scenes/shells/strip_follower_pressure.yaml
and its dead twin): L = 1, t = 0.01, E = 1000, nu = 0 (E I = E t^3 / 12 per width), q = 1e-3.

Reference: the inextensible elastica (Euler-Bernoulli; the shear and membrane strains of this
thin strip are below 1e-4), arc length s from the clamp, tangent angle phi from +x towards +z,
m = E I phi' the bending moment, F(s) the resultant of the load beyond s:
  phi' = m / (E I),  m' = -(cos phi F_z - sin phi F_x),  F' = -p,  (x, z)' = (cos phi, sin phi)
with p = q (-sin phi, cos phi) per length for the follower pressure (along the deformed normal)
and p = (0, q) for the dead one; phi(0) = 0, m(L) = F(L) = 0. Solved by shooting on the tip angle
(scipy solve_ivp, rtol 1e-12, and brentq); at small q it gives the linear beam's q L^3 / (6 E I)
and q L^4 / (8 E I) (checked here). Checked: the tip particle's position (x, z) within 1 % of L
and its rotation (-phi about y) within 1 % of the reference, for both loads.
usage: check_shell_follower.py FOLLOWER.e DEAD.e
"""
import math
import sys

import netCDF4
import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

L, W, E, t, q = 1.0, 1.0 / 6, 1000.0, 0.01, 1e-3
EI = E * t**3 / 12


def shoot(load, follower, tip_angle):
    def rhs(s, y):
        phi, m, fx, fz, _, _ = y
        px, pz = (-load * math.sin(phi), load * math.cos(phi)) if follower else (0.0, load)
        return [m / EI, -(math.cos(phi) * fz - math.sin(phi) * fx), -px, -pz, math.cos(phi),
                math.sin(phi)]
    return solve_ivp(rhs, [L, 0], [tip_angle, 0, 0, 0, 0, 0], rtol=1e-12, atol=1e-14).y[:, -1]


def elastica(load, follower):
    """Tip angle and tip position (x, z) of the elastica."""
    clamp_angle = lambda a: shoot(load, follower, a)[0]
    grid = np.linspace(1e-9, 3.0, 301)
    values = [clamp_angle(a) for a in grid]
    for i in range(len(grid) - 1):
        if values[i] * values[i + 1] < 0:
            a = brentq(clamp_angle, grid[i], grid[i + 1], xtol=1e-14)
            y = shoot(load, follower, a)
            return a, -y[4], -y[5]
    raise RuntimeError("no elastica found")


def tip(path):
    f = netCDF4.Dataset(path)
    names = list(netCDF4.chartostring(f.variables["name_nod_var"][:]))
    X = np.asarray(f.variables["coordx"][:])
    Y = np.asarray(f.variables["coordy"][:])
    k = int(np.argmin(np.hypot(X - L, Y - W / 2)))
    value = lambda n: float(f.variables["vals_nod_var%d" % (names.index(n) + 1)][-1][k])
    return L + value("displacement_x"), value("displacement_z"), value("rotation_y")


def main():
    errors = []
    small = 1e-6
    a, x, z = elastica(small, True)
    linear = (small * L**3 / (6 * EI), small * L**4 / (8 * EI))
    if abs(a / linear[0] - 1) > 1e-5 or abs(z / linear[1] - 1) > 1e-5:
        errors.append("the shooting solution misses the linear beam at small loads")
    for path, follower in ((sys.argv[1], True), (sys.argv[2], False)):
        angle, x_ref, z_ref = elastica(q, follower)
        x, z, rotation = tip(path)
        position = math.hypot(x - x_ref, z - z_ref) / L
        turn = abs(-rotation - angle) / angle
        print("%s pressure: tip (%.5f, %.5f) vs the elastica's (%.5f, %.5f): %.2e L; rotation "
              "%.5f vs %.5f: %.2e" % ("follower" if follower else "dead", x, z, x_ref, z_ref,
                                      position, -rotation, angle, turn))
        if position > 0.01 or turn > 0.01:
            errors.append("%s pressure: tip off the elastica (%.3g L, %.3g)"
                          % ("follower" if follower else "dead", position, turn))
    for e in errors:
        print("FAIL: " + e)
    sys.exit(1 if errors else 0)


if __name__ == "__main__":
    main()
