#!/usr/bin/python3
"""The iterative path of nearly incompressible mixed u-p parts (issue 17, item 2): the condensed
Jacobian solved through the saddle point of its bulk stiffness above nu = 1/4 (block triangular,
multigrid on the rest; operators/BulkSplit.hpp), on Lame's cylinder (lame_mixed.yaml, perturbed
particles), pressure_cells: patch, integration: scni_subcells, section.spacing: edges, levels
16 x 32, 32 x 64, 64 x 128 cells, nu = 0.3, 0.4999, 0.499999. Checks:
  1. every run converges (exit 0) on the saddle-point path;
  2. the inner GMRES iterations per Newton step (all inner iterations of the step's linear
     solve: the outer GMRES takes one iteration when its tolerance reaches Belos, see
     NewtonSolver's linear tolerance) at nu = 0.4999 and 0.499999 are at most 2x those at
     nu = 0.3 on the same level (they do not grow with nu: the point of the block
     preconditioner); printed with their growth per level;
  3. the L2 displacement error equals the direct solver's within 1 %;
  4. 2 ranks (every level, with MPIRUN2): the check of 2, and the same displacements as 1 rank
     to 1e-10 of the largest at every nu (the issue's bound; measured 2.6e-13 at most: A
     assembled at kappa_0, not as K - C^T D_1 B, and the outer fixed point, which adds the inner
     solution unscaled: operators/BulkTangent.hpp, LinearSolverPlan).
usage: saddle_iterations.py EFG OUTDIR [MPIRUN2]      (exit 1 when a check fails)
"""
import json
import os
import re
import subprocess
import sys

import netCDF4
import numpy as np
import yaml

here = os.path.dirname(os.path.abspath(__file__))
efg, out = sys.argv[1], sys.argv[2]
mpirun = sys.argv[3].split("|") if len(sys.argv) > 3 and sys.argv[3] else []
os.makedirs(out, exist_ok=True)
LEVELS = [(16, 32), (32, 64), (64, 128)]
NUS = [0.3, 0.4999, 0.499999]
failures = []


def check(ok, text):
    print(("ok    " if ok else "FAIL  ") + text)
    if not ok:
        failures.append(text)


def variant(cells, nu, solver):
    s = yaml.safe_load(open(os.path.join(here, "lame_mixed.yaml")))
    s["mesh"]["generate"]["cells"] = list(cells)
    s["parameters"]["nu"] = nu
    s["parts"][0]["pressure_cells"] = "patch"
    s["parts"][0]["section"].update({"integration": "scni_subcells", "spacing": "edges"})
    s["stages"][0]["solver"] = solver
    name = "cyl_%dx%d_%s_%s" % (cells[0], cells[1], nu, solver)
    path = os.path.join(out, name + ".yaml")
    yaml.safe_dump(s, open(path, "w"), sort_keys=False)
    return path, name


def run(cells, nu, solver, prefix=(), tag=""):
    path, name = variant(cells, nu, solver)
    folder = os.path.join(out, name + tag)
    r = subprocess.run(list(prefix) + [efg, "run", path, "-o", folder], capture_output=True,
                       text=True)
    log = r.stdout + r.stderr
    inner = [int(n) for n in re.findall(r"saddle point: (\d+) GMRES iterations", log)]
    newton = [int(n) for n in re.findall(r"(\d+) Newton iterations", log)]
    report = json.load(open(os.path.join(folder, name + ".e.report.json"))) if r.returncode == 0 else {}
    return {"rc": r.returncode, "inner": inner, "newton": sum(newton), "log": log,
            "report": report, "exo": os.path.join(folder, name + ".e")}


def l2(res):
    return res["report"]["errors"]["l2_rel_error"]


def displacement(f):
    d = netCDF4.Dataset(f)
    names = ["".join(c.decode() for c in n if c) for n in d["name_nod_var"][:]]
    return np.array([d["vals_nod_var%d" % (names.index(k) + 1)][-1]
                     for k in ("displacement_x", "displacement_y")])


def per_newton_step(res):
    return sum(res["inner"]) / max(res["newton"], 1)


print("cells    nu        inner per solve   per Newton step   L2 error (direct)")
per_step, one_rank = {}, {}
for cells in LEVELS:
    base = None
    for nu in NUS:
        it = run(cells, nu, "iterative")
        check(it["rc"] == 0 and it["inner"], f"{cells} nu = {nu}: converged on the saddle-point path"
              f" (exit {it['rc']})")
        if it["rc"] != 0 or not it["inner"]:
            print(it["log"][-2000:])
            continue
        direct = run(cells, nu, "direct")
        step = per_newton_step(it)
        per_step[(cells, nu)] = step
        one_rank[(cells, nu)] = it
        print(f"{cells[0]:2d}x{cells[1]:<3d}  {nu:<9} {max(it['inner']):4d}              "
              f"{step:6.1f}            {l2(it):.4e} ({l2(direct):.4e})")
        if nu == 0.3:
            base = step
        else:
            check(step <= 2 * base, f"{cells} nu = {nu}: {step:.0f} inner iterations per Newton "
                  f"step <= 2 x {base:.0f} (nu = 0.3)")
        check(abs(l2(it) - l2(direct)) <= 0.01 * l2(direct),
              f"{cells} nu = {nu}: L2 error {l2(it):.4e} equals the direct solver's {l2(direct):.4e} within 1 %")
for nu in NUS:
    steps = [per_step.get((c, nu)) for c in LEVELS]
    if all(steps):
        print(f"nu = {nu}: inner iterations per Newton step over the levels: "
              + " / ".join(f"{s:.0f}" for s in steps)
              + "  (growth per level " + ", ".join(f"{b / a:.2f}" for a, b in zip(steps, steps[1:])) + ")")

if mpirun:
    print("2 ranks: cells    nu        per Newton step   1 vs 2 ranks (of the largest displacement)")
    for cells in LEVELS:
        base = None
        for nu in NUS:
            two = run(cells, nu, "iterative", mpirun, "_np2")
            check(two["rc"] == 0 and two["inner"], f"2 ranks {cells} nu = {nu}: converged on the "
                  f"saddle-point path (exit {two['rc']})")
            one = one_rank.get((cells, nu))
            if two["rc"] != 0 or not two["inner"] or not one:
                continue
            step = per_newton_step(two)
            u1, u2 = displacement(one["exo"]), displacement(two["exo"])
            diff = np.abs(u1 - u2).max() / np.abs(u1).max()
            print(f"         {cells[0]:2d}x{cells[1]:<3d}  {nu:<9} {step:6.1f}            {diff:.1e}")
            if nu == 0.3:
                base = step
            elif base:
                check(step <= 2 * base, f"2 ranks {cells} nu = {nu}: {step:.0f} inner iterations per "
                      f"Newton step <= 2 x {base:.0f} (nu = 0.3)")
            check(diff < 1e-10, f"2 ranks {cells} nu = {nu}: largest displacement difference from "
                  f"1 rank {diff:.1e} of the largest (< 1e-10)")

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("all checks passed")
