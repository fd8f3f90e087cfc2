#!/usr/bin/python3
"""A nearly incompressible neo-Hookean block squeezed to half its height (issue 17;
tests/scenes/mixed/block_compressed.yaml): plane strain, rollers on x = 0 and y = 0, the top
moved down by 0.5, the right side free. The state is homogeneous, F = diag(lambda_1, 1/2, 1),
and the mixed law (isochoric neo-Hookean + U(J) = kappa/2 (ln J)^2 on the cells) gives

  sigma = mu J^(-5/3) dev(b) + kappa ln J / J I,   b = diag(lambda_1^2, 1/4, 1),  J = lambda_1 / 2,

with lambda_1 from sigma_11 = 0 (bisection here, independent of efg). Checks on 1 or 2 ranks:
the right side's displacement lambda_1 - 1 and the top reaction sigma_22 lambda_1 (per unit
thickness) to 1e-10, the reactions in equilibrium (bottom = -top, left = 0) to 1e-10, every cell pressure -kappa ln J / J to 1e-10 (homogeneous: no checkerboard),
and Newton converging quadratically in every load step (best measured order >= 1.8).
With SOLVER = iterative: the same checks on the saddle-point path of the bulk stiffness
(operators/BulkSplit.hpp, finite strain: B's rows F_c^-T b_c at the Newton state), whose inner
GMRES iterations are printed and their total bounded by 4,000 (measured: 38 solves of 14-26
iterations on 1 rank, 39 of 54-85 on 2; with B's rows left at b_c, 729 solves of up to 100).
usage: check_compressed_block.py EFG OUTDIR [MPIRUN2] [SOLVER]   (exit 1 when a check fails)
"""
import csv
import math
import os
import re
import subprocess
import sys

import netCDF4
import numpy as np

efg, out = sys.argv[1], sys.argv[2]
mpirun = sys.argv[3].split("|") if len(sys.argv) > 3 and sys.argv[3] else []
scene = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes", "mixed",
                     "block_compressed.yaml")
solver = sys.argv[4] if len(sys.argv) > 4 else ""
failures = []
if solver:
    import yaml

    variant = yaml.safe_load(open(scene))
    variant["stages"][0]["solver"] = solver
    os.makedirs(out, exist_ok=True)
    scene = os.path.join(out, "block_compressed.yaml")
    yaml.safe_dump(variant, open(scene, "w"), sort_keys=False)


def check(ok, text):
    print(("ok    " if ok else "FAIL  ") + text)
    if not ok:
        failures.append(text)


run = subprocess.run(mpirun + [efg, "run", scene, "-o", out], capture_output=True, text=True)
if run.returncode != 0:
    sys.exit("efg run failed (exit %d):\n%s" % (run.returncode, run.stdout[-3000:] + run.stderr))

E, NU, L2 = 10.0, 0.4999, 0.5  # the scene's material and the final height ratio
mu, kappa = E / (2 * (1 + NU)), E / (3 * (1 - 2 * NU))


def sigma(l1, i):
    J, I1 = l1 * L2, l1 * l1 + L2 * L2 + 1
    lam = (l1, L2)[i]
    return mu * J ** (-5 / 3) * (lam * lam - I1 / 3) + kappa * math.log(J) / J


lo, hi = 1.0, 4.0
for _ in range(200):
    mid = 0.5 * (lo + hi)
    if sigma(lo, 0) * sigma(mid, 0) <= 0:
        hi = mid
    else:
        lo = mid
l1 = 0.5 * (lo + hi)
J = l1 * L2
force = sigma(l1, 1) * l1
pressure = -kappa * math.log(J) / J

last = list(csv.DictReader(open(os.path.join(out, "block_compressed.csv"))))[-1]
u = float(last["u_xmax_x"])
check(abs(u - (l1 - 1)) <= 1e-10 * (l1 - 1), f"right side u_x {u:.12g} vs lambda_1 - 1 = {l1 - 1:.12g}")
r = float(last["R_top_y"])
check(abs(r - force) <= 1e-10 * abs(force), f"top reaction {r:.12g} vs sigma_22 lambda_1 = {force:.12g}")
# Equilibrium (no loads but the conditions): the bottom rollers carry the top's force back, the
# left rollers nothing (the right side is free); the same 1e-10 as the Newton state's (measured
# 0 and 1.5e-11 of the force).
bottom, left = float(last["R_bottom_y"]), float(last["R_left_x"])
check(abs(bottom + r) <= 1e-10 * abs(force) and abs(left) <= 1e-10 * abs(force),
      f"reactions in equilibrium: bottom + top {bottom + r:.3g}, left {left:.3g}")
d = netCDF4.Dataset(os.path.join(out, "block_compressed.e"))
names = ["".join(c.decode() for c in n if c) for n in d["name_elem_var"][:]]
p = np.asarray(d["vals_elem_var%deb1" % (names.index("cell_pressure") + 1)][-1])
# Round-off of kappa ln J at kappa / mu = 5000 (nu = 0.4999): 1.0e-10 measured (the Newton test
# in force units; a tighter residual_tolerance does not reduce it).
worst = np.abs(p - pressure).max() / abs(pressure)
check(worst < 3e-10, f"cell pressures {p.min():.10g} .. {p.max():.10g} vs -kappa ln J / J = {pressure:.10g} (worst {worst:.2g})")
steps, step = [], None
for line in run.stdout.splitlines():
    if re.match(r"\s+Newton 0:", line):
        step = []
        steps.append(step)
    m = re.search(r"order ([0-9.e+-]+)\)", line)
    if m and step is not None:
        step.append(float(m.group(1)))
best = [max(s) for s in steps if s]
check(len(best) == 10 and min(best) >= 1.8,
      "Newton: best convergence order per load step " + ", ".join(f"{b:.2f}" for b in best) +
      " (>= 1.8: the consistent tangent)")
if solver == "iterative":
    inner = [int(n) for n in re.findall(r"saddle point: (\d+) GMRES iterations", run.stdout)]
    check(bool(inner) and sum(inner) <= 4000,
          f"saddle-point path: {len(inner)} inner solves of {min(inner or [0])}..{max(inner or [0])} "
          f"GMRES iterations, {sum(inner)} in all (<= 4000)")
print("%d checks failed" % len(failures) if failures else "all checks passed")
sys.exit(1 if failures else 0)
