#!/usr/bin/env python3
"""The rigid wall's penetration column (issue 56: per-contact penetration in the history and the
report, walls included) on input/bar_wall_impact.yaml: a bar (E = 100, rho = 1, c = 10, spacing
h = 0.005) at v = 1 against a wall at x = -1e-4 (normal +x), mass-rule penalty p = 0.5.

Checks, each from an independent source:
- geometry: at every record the history's wall_wall_pen (the deepest particle over its spacing
  since the previous record) is at least the deepest particle behind the wall in the Exodus
  displacements at that record (x = X + u_x), and it is 0 once the bar has left the wall
  (contact lasts 2 L / c = 0.2);
- the report's wall_penetration is the largest of the history's values;
- a hand bound on the peak: the front particle (mass m = rho h^2) on the wall's spring
  k = p m / dt^2 carries the bar's stopping force sigma h, sigma = rho c v, statically at
  x_s = sigma h / k; reaching it at speed v it overshoots to at most
  x_s + sqrt(x_s^2 + m v^2 / k) (a spring loaded suddenly by a constant force and an impact).
  The peak lies between x_s and that, over h.
usage: check_wall_penetration.py OUTDIR/bar_wall_impact.csv
"""
import csv
import glob
import json
import math
import os
import sys

import netCDF4

out = os.path.dirname(os.path.abspath(sys.argv[1]))
rho, E, v, h, p, wall_x = 1.0, 100.0, 1.0, 0.005, 0.5, -1e-4
c = math.sqrt(E / rho)
rows = list(csv.DictReader(open(glob.glob(out + "/*.csv")[0])))
report = json.load(open(glob.glob(out + "/*.report.json")[0]))
exodus = netCDF4.Dataset(glob.glob(out + "/*.e")[0])
names = [netCDF4.chartostring(n) for n in exodus.variables["name_nod_var"][:]]
ux = exodus.variables["vals_nod_var%d" % (list(names).index("displacement_x") + 1)][:]
X = exodus.variables["coordx"][:]
times = exodus.variables["time_whole"][:]
failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        failures.append(what)


column = [float(r["wall_wall_pen"]) for r in rows]
history_times = [float(r["time"]) for r in rows]
check(len(column) == len(times), "%d history rows, %d Exodus records" % (len(column), len(times)))
worst_gap = 0.0
for k, t in enumerate(times):
    depth = max(0.0, max(wall_x - (X + ux[k]))) / h
    worst_gap = max(worst_gap, depth - column[k])
    if abs(history_times[k] - t) > 1e-12 * max(1.0, t):
        check(False, "record %d at t = %g in the history, %g in Exodus" % (k, history_times[k], t))
# (1e-9: the records hold the positions to round-off)
check(worst_gap <= 1e-9,
      "the column is at least the deepest particle of each record (worst shortfall %.2e)" % worst_gap)
after = [col for t, col in zip(history_times, column) if t > 2.0 / c * 1.05]
check(len(after) > 0 and max(after) == 0.0,
      "0 after the bar has left the wall (%d records after t = %.3f)" % (len(after), 2.0 / c * 1.05))
peak = max(column)
reported = report["explicit_stages"][0]["wall_penetration"]["wall"]
check(abs(reported - peak) <= 1e-9 * peak,
      "report's wall_penetration %.10g = the history's largest %.10g" % (reported, peak))
dt = report["explicit_stages"][0]["largest_dt"]
m = rho * h * h
k = p * m / dt**2
x_s = rho * c * v * h / k
x_max = x_s + math.sqrt(x_s**2 + m * v * v / k)
check(x_s / h <= peak <= x_max / h,
      "peak %.4f of the spacing between the static %.4f and the overshoot bound %.4f (dt %.4g)" %
      (peak, x_s / h, x_max / h, dt))
sys.exit(1 if failures else 0)
