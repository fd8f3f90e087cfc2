#!/usr/bin/env python3
"""A tapered cantilever strip (tests/scenes/shells/strip_tapered.yaml, strip_tapered_mesh.yaml):
t(x) = t0 (1 + x / L), t0 = 0.01, L = 1, E = 1000, nu = 0, clamped at x = 0; stage 'pull' (t = 1)
an end force q = 1e-3 per unit width along x, stage 'bend' (t = 2) an end moment m = 1e-7 per
unit width. Exact (beam theory, N = q and M = m along the strip; the end moment leaves no shear):
  u(L) = q L ln(t1 / t0) / (E (t1 - t0)),
  theta(L) = 12 m / E int_0^L t^-3 dx = 6 m L (t0^-2 - t1^-2) / (E (t1 - t0)),
  w(L) = 12 m / E int_0^L (L - x) t^-3 dx = 12 m L^2 (1 / (2 t1) + t1 / (2 t0^2) - 1 / t0)
         / (E (t1 - t0)^2),
with t1 = 2 t0. The mean thickness 0.015 everywhere misses them by -3.8 % (u) and -21 % (theta).
usage: check_shell_tapered.py history.csv TOLERANCE [--mesh MESH.exo RESULTS.e]
  TOLERANCE: the largest relative error of u, w, theta at the tip; with --mesh also the
  thickness field at every node against the mean of its cells' thickness attributes (1e-12:
  nu = 0, no membrane thinning).
"""
import csv
import math
import sys

L, t0, E, q, m = 1.0, 0.01, 1000.0, 1e-3, 1e-7
t1 = 2 * t0
exact = {
    "ux": q * L * math.log(t1 / t0) / (E * (t1 - t0)),
    "uz": 12 * m * L**2 * (0.5 / t1 + 0.5 * t1 / t0**2 - 1 / t0) / (E * (t1 - t0) ** 2),
    "ry": 6 * m * L * (t0**-2 - t1**-2) / (E * (t1 - t0)),
}
rows = {round(float(r["time"])): r for r in csv.DictReader(open(sys.argv[1]))}
tolerance = float(sys.argv[2])
errors = []
for key, stage in (("ux", 1), ("uz", 2), ("ry", 2)):
    value = abs(float(rows[stage]["probe_tip_" + key]))
    error = value / exact[key] - 1
    print("tip %s: %.6e against %.6e (%+.3f %%)" % (key, value, exact[key], 100 * error))
    if abs(error) > tolerance:
        errors.append("tip %s off by %.3f %% (> %.2f %%)" % (key, 100 * error, 100 * tolerance))

if "--mesh" in sys.argv:
    import netCDF4
    import numpy as np

    i = sys.argv.index("--mesh")
    with netCDF4.Dataset(sys.argv[i + 1]) as mesh:
        conn = np.array(mesh["connect1"][:]) - 1
        cell_t = np.array(mesh["attrib1"][:])[:, 0]
    total = np.zeros(conn.max() + 1)
    count = np.zeros_like(total)
    for cell, nodes in enumerate(conn):
        total[nodes] += cell_t[cell]
        count[nodes] += 1
    expected = total / count
    with netCDF4.Dataset(sys.argv[i + 2]) as results:
        names = [netCDF4.chartostring(n).item().strip() for n in results["name_nod_var"][:]]
        field = np.array(results["vals_nod_var%d" % (names.index("thickness") + 1)][-1])
    worst = np.max(np.abs(field - expected) / expected)
    print("thickness field against the nodes' mean cell attributes: worst %.2e" % worst)
    if worst > 1e-12:
        errors.append("thickness field off by %.2e" % worst)

for e in errors:
    print(e)
sys.exit(1 if errors else 0)
