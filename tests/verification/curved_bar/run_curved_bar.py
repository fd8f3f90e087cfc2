#!/usr/bin/python3
"""Curved bar of Timoshenko & Goodier sec. 31 written wholly in a scene (issue 19), three levels
by `efg study`. Checks:
  - the scene's expressions are exactly the ones exact_solution_check.py verifies (constants,
    exact displacement and stress, end traction);
  - the displacement of both probes (MLS at the point: the middle of the loaded end and the
    middle of the ring) within 1 % of T&G's polar formulas on the finest level, errors falling;
  - fitted rates of the relative error norms from the study CSV: L2 >= 1.9, energy >= 0.9.
usage: run_curved_bar.py EFG OUTDIR     (exit 1 when a check fails)
"""
import json
import math
import os
import subprocess
import sys

import numpy as np
import yaml

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
import exact_solution_check as exact  # noqa: E402

efg, out = sys.argv[1], sys.argv[2]
scene_path = os.path.join(here, "curved_bar.yaml")
scene = yaml.safe_load(open(scene_path))
failures = []


def check(ok, text):
    print(("ok    " if ok else "FAIL  ") + text)
    if not ok:
        failures.append(text)


# 1. The scene says what the independent check verified.
params = scene["parameters"]
for name, expr in exact.CONSTANTS:
    check(str(params[name]) == expr, f"parameter {name} = {params[name]} is the verified '{expr}'")
user = scene["verification"]["user_solution"]
check(user["displacement"] == [exact.FIELDS["u_x"], exact.FIELDS["u_y"]], "exact displacement")
check([user["stress"][k] for k in ("xx", "yy", "xy")] ==
      [exact.FIELDS[k] for k in ("sxx", "syy", "sxy")], "exact stress")
check(scene["loads"][0]["value"][0] == exact.TRACTION["t_x"], "end traction")

# 2. Three levels.
os.makedirs(out, exist_ok=True)
run = subprocess.run([efg, "study", scene_path, "-o", out, "--levels", "3"], capture_output=True,
                     text=True)
if run.returncode != 0:
    sys.exit("efg study failed (exit %d):\n%s" % (run.returncode, run.stdout[-3000:] + run.stderr))
rows = [line.split(",") for line in open(os.path.join(out, "curved_bar_study.csv"))]
header, rows = rows[0], rows[1:]
col = {k: header.index(k) for k in ("h", "dofs", "l2_rel_error", "energy_rel_error")}

# T&G's polar displacement at the probes, in Cartesian components.
c = exact.constants_for({k: float(params[k]) for k in ("a", "b", "P", "E", "nu")})
r0 = c["r0"]
points = {"end": (r0, 0.0), "mid": (r0 * math.cos(math.pi / 4), r0 * math.sin(math.pi / 4))}
print("level  dofs   L2 error    energy error  " + "  ".join(
    f"{p}_{k} (rel. error)" for p in points for k in ("ux", "uy")))
probe_errors = []
for level, row in enumerate(rows):
    report = json.load(open(os.path.join(out, f"curved_bar_L{level}.e.report.json")))
    errors = []
    for name, (x, y) in points.items():
        r, th = math.hypot(x, y), math.atan2(y, x)
        ur, ut = exact.polar_displacement(c, r, th)
        u = (ur * math.cos(th) - ut * math.sin(th), ur * math.sin(th) + ut * math.cos(th))
        for k, axis in enumerate(("x", "y")):
            value = report["probes"][f"probe_{name}_u{axis}"]
            errors.append((value, u[k], abs(value - u[k]) / abs(u[k])))
    probe_errors.append([e[2] for e in errors])
    print(f"{level:5d}  {row[col['dofs']]:>5}  {float(row[col['l2_rel_error']]):.4e}  "
          f"{float(row[col['energy_rel_error']]):.4e}    " +
          "  ".join(f"{v:.6e} vs {u:.6e} ({100 * e:.3f} %)" for v, u, e in errors))
for k in range(4):
    check(probe_errors[-1][k] < 0.01, f"probe component {k}: {100 * probe_errors[-1][k]:.3f} % < 1 % "
          "on the finest level")
    check(probe_errors[-1][k] < probe_errors[0][k], f"probe component {k}: error falls with "
          "refinement")


def rate(key):
    x = np.log([float(r[col["h"]]) for r in rows])
    y = np.log([float(r[col[key]]) for r in rows])
    return np.polyfit(x, y, 1)[0]


l2, energy = rate("l2_rel_error"), rate("energy_rel_error")
check(l2 >= 1.9, f"fitted L2 rate {l2:.3f} >= 1.9")
check(energy >= 0.9, f"fitted energy rate {energy:.3f} >= 0.9")
if failures:
    sys.exit(f"{len(failures)} check(s) failed")
print("curved bar verified")
