#!/usr/bin/python3
"""Checks an `efg study` output folder: the CSV columns, the fitted rates of the Timoshenko beam
(L2 >= 1.8 and energy >= 0.95 over 3 coarse levels; the 4-level rates of the implicit tests are
1.93 and 1.13) and non-empty PNG plots. Usage: check_study.py OUTDIR NAME"""
import csv
import math
import os
import sys

folder, name = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader(open(os.path.join(folder, f"{name}_study.csv"))))
required = ["level", "h", "dofs", "l2_rel_error", "energy_rel_error", "max_nodal_error", "Newton_iterations_seconds",
            "tangent_assembly_seconds", "shape_functions_and_integration_seconds", "total_seconds"]
missing = [c for c in required if c not in rows[0]]
assert not missing, f"missing columns {missing}"
assert len(rows) == 3, f"expected 3 runs, found {len(rows)}"


def rate(key):
    x = [math.log(float(r["h"])) for r in rows]
    y = [math.log(float(r[key])) for r in rows]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)


l2, energy = rate("l2_rel_error"), rate("energy_rel_error")
print(f"fitted rates: L2 {l2:.3f}, energy {energy:.3f}")
assert l2 >= 1.8, l2
assert energy >= 0.95, energy
assert all(float(r["total_seconds"]) > 0 for r in rows)
for plot in ("error_vs_dofs", "error_vs_time"):
    path = os.path.join(folder, f"{name}_{plot}.png")
    assert os.path.getsize(path) > 1000, path
print("study output checked")
