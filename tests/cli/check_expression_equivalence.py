#!/usr/bin/env python3
"""The Timoshenko cantilever written with expressions (tests/scenes/expressions) against the
built-in exact solution's scene (input/timoshenko_beam.yaml), issue 19: the displacement and
stress fields of the last record and the error norms of the two run reports agree to 1e-12
relative (the same closed forms evaluated by muParser instead of C++: round-off only).
usage: check_expression_equivalence.py BUILTIN.e BUILTIN.report.json EXPRESSIONS.e EXPRESSIONS.report.json
"""
import json
import sys

import netCDF4
import numpy as np

TOL = 1e-12


def last(path, field):
    d = netCDF4.Dataset(path)
    names = [b"".join(c for c in row if c).decode() for row in d["name_nod_var"][:]]
    return np.array(d["vals_nod_var%d" % (names.index(field) + 1)][-1])


worst = 0.0
for field in ("displacement_x", "displacement_y", "stress_xx", "stress_xy", "stress_yy"):
    a, b = last(sys.argv[1], field), last(sys.argv[3], field)
    diff = np.abs(a - b).max() / np.abs(a).max()
    print(f"{field}: largest difference {diff:.3e} of its largest magnitude")
    worst = max(worst, diff)
ra, rb = (json.load(open(p))["errors"] for p in (sys.argv[2], sys.argv[4]))
assert ra["exact_solution"] == "timoshenko_beam" and rb["exact_solution"] == "user", (ra, rb)
for key in ("l2_rel_error", "energy_rel_error", "max_nodal_error"):
    diff = abs(ra[key] - rb[key]) / abs(ra[key])
    print(f"{key}: {ra[key]:.12e} (built-in) vs {rb[key]:.12e} (expressions), {diff:.3e}")
    worst = max(worst, diff)
if not worst <= TOL:
    sys.exit(f"FAILED: differences up to {worst:.3e} > {TOL}")
print(f"equal to {worst:.3e} <= {TOL}")
