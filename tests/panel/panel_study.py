#!/usr/bin/env python3
"""Cook's tapered panel (issue 12's membrane) on refined levels, 1 and 2 ranks, two Poisson ratios,
along two paths:
  default   - default section and solver settings (SCNI; the direct solver at these sizes);
  iterative - `solver: iterative` (GMRES + smoothed-aggregation multigrid on the Jacobian) with
              `integration: scni_subcells` and `spacing: edges` (the supports sized by the rows of
              the panel's sheared cells: with the cells' extents they span up to 7.5 rows and
              multigrid stalls, docs/implicit.md).
Fails when a level does not converge, when 1 and 2 ranks differ by more than 1e-7 (default) or
1e-8 (iterative) of the largest displacement, when the Krylov iterations of the iterative path
grow by more than 1.5x from one level to the next or by more than 1.5x from 1 to 2 ranks (from
64 x 64 cells on), or when the nu = 1/3 panel misses the
literature value. (1 vs 2 ranks: the assembled matrices differ in their last bits, and the direct
solutions by about cond(K) x 1e-16: measured 5e-12 at 32 x 32, 2-3e-8 at 128 x 128; the iterative
ones, solved to 1e-10 of the residual, by up to 4e-11.)

Cook's membrane (Cook 1974): trapezoid (0,0), (48,44), (48,60), (0,44), plane stress, E = 1,
thickness 1, clamped at x = 0, a vertical shear of total 1 on x = 48. For nu = 1/3 the vertical
displacement of the loaded edge's midpoint (48, 52) converges to 23.96 (Simo & Rifai 1990;
Q9 finite elements give 23.965 at 64 x 64).

usage: panel_study.py EFG MPIRUN2 WORKDIR [LEVELS...]   (MPIRUN2: the mpirun prefix for 2 ranks,
                                                           words separated by '|')
Prints a Markdown table of the runs (docs/implicit.md).
"""
import json
import os
import subprocess
import sys

import netCDF4
import numpy as np

REFERENCE_MIDPOINT = 23.96  # u_y(48, 52), nu = 1/3
PATHS = {
    "default": {"integration": "scni", "spacing": "", "solver": "", "ranks_tolerance": 1e-7},
    "iterative": {"integration": "scni_subcells", "spacing": ", spacing: edges",
                  "solver": ", solver: iterative", "ranks_tolerance": 1e-8},
}
MAX_ITERATION_GROWTH = 1.5
# Two ranks against one on the iterative path from 64 x 64 on (multigrid's coarse levels moved
# onto fewer ranks: measured 1.27x and 1.15x; 1.9x while each rank solved its own coarse rows).
MAX_RANKS_RATIO, RANKS_RATIO_FROM = 1.5, 64
SCENE = """title: Cook's tapered panel, {n} x {n}, nu = {nu}
mesh:
  file: {mesh}
parts:
  - name: panel
    blocks: [block_1]
    material: m
    plane: stress
    section: {{basis: linear, integration: {integration}, dilation: 2.0{spacing}}}
materials:
  - {{name: m, model: linear_elastic, youngs_modulus: 1.0, poissons_ratio: {nu}}}
boundary_conditions:
  - {{name: clamp, type: displacement, node_set: xmin, x: 0, y: 0}}
loads:
  - {{name: shear, type: traction, side_set: xmax, value: [0, 0.0625]}}
stages:
  - {{name: load, driver: implicit, end_time: 1{solver}}}
output:
  fields: [displacement]
"""
SQUARE = """title: unit square
mesh:
  generate: {{element: quad4, lower: [0, 0], upper: [1, 1], cells: [{n}, {n}]}}
parts:
  - {{name: p, blocks: [block_1], material: m, plane: stress}}
materials:
  - {{name: m, model: linear_elastic, youngs_modulus: 1, poissons_ratio: 0.3}}
"""


def run(command, log):
    with open(log, "w") as out:
        return subprocess.run(command, stdout=out, stderr=subprocess.STDOUT).returncode


def displacement(path):
    with netCDF4.Dataset(path) as d:
        names = ["".join(c.decode() for c in row if c) for row in d.variables["name_nod_var"][:]]
        x, y = d.variables["coordx"][:], d.variables["coordy"][:]
        ux = d.variables["vals_nod_var%d" % (names.index("displacement_x") + 1)][-1]
        uy = d.variables["vals_nod_var%d" % (names.index("displacement_y") + 1)][-1]
    return np.asarray(x), np.asarray(y), np.column_stack([ux, uy])


def main():
    efg, mpirun2, work = sys.argv[1], sys.argv[2].split("|"), sys.argv[3]
    levels = [int(a) for a in sys.argv[4:]] or [16, 32, 64, 128]
    here = os.path.dirname(os.path.abspath(__file__))
    os.makedirs(work, exist_ok=True)
    failures, rows = [], []
    midpoint_errors = {path: [] for path in PATHS}
    krylov = {}  # (path, nu, ranks) -> [(level, largest Krylov count of a Newton iteration)]
    for n in levels:
        square = os.path.join(work, "square%d.yaml" % n)
        mesh = os.path.join(work, "panel%d.exo" % n)
        with open(square, "w") as f:
            f.write(SQUARE.format(n=n))
        if run([efg, "mesh", square, mesh], mesh + ".log") != 0:
            sys.exit("efg mesh failed for level %d" % n)
        subprocess.run(["/usr/bin/python3", os.path.join(here, "make_panel.py"), mesh], check=True)
        for path, settings in PATHS.items():
            for nu in ("0.3333333333333333", "0.49"):
                scene = os.path.join(work, "panel%d_nu%s_%s.yaml" % (n, nu[:4], path))
                with open(scene, "w") as f:
                    f.write(SCENE.format(n=n, nu=nu, mesh=mesh, **{
                        k: v for k, v in settings.items() if k != "ranks_tolerance"}))
                results = {}
                for ranks in (1, 2):
                    out = os.path.join(work, "out_%d_%s_%s_np%d" % (n, nu[:4], path, ranks))
                    prefix = mpirun2 if ranks == 2 else []
                    code = run(prefix + [efg, "run", scene, "-o", out], out + ".log")
                    name = os.path.splitext(os.path.basename(scene))[0]
                    if code != 0:
                        failures.append("%s path, level %d nu %s on %d rank(s): exit %d (log %s.log)"
                                        % (path, n, nu, ranks, code, out))
                        continue
                    with open(os.path.join(out, name + ".e.report.json")) as f:
                        report = json.load(f)
                    stage = report["implicit_stages"][0]
                    its = [i for s in stage["newton_solves"] for i in s["linear_iterations"]]
                    krylov.setdefault((path, nu[:4], ranks), []).append((n, max(its)))
                    x, y, u = displacement(os.path.join(out, name + ".e"))
                    mid = int(np.argmin((x - 48) ** 2 + (y - 52) ** 2))
                    results[ranks] = u
                    rows.append("| %s | %d | %d | %s | %d | %s | %d | %s | %.2f | %.2f | %.4f |" % (
                        path, n, (n + 1) ** 2, nu[:4], ranks, stage["linear_solver"].split(" (")[0],
                        stage["newton_iterations"], "/".join(str(int(i)) for i in its),
                        stage["linear_setup_seconds"], report["total_seconds"], u[mid, 1]))
                    if nu.startswith("0.33") and ranks == 1:
                        midpoint_errors[path].append(
                            (n, abs(u[mid, 1] - REFERENCE_MIDPOINT) / REFERENCE_MIDPOINT))
                if len(results) == 2:
                    scale = np.max(np.abs(results[1]))
                    diff = np.max(np.abs(results[1] - results[2])) / scale
                    print("%s path, level %d nu %s: 1 vs 2 ranks differ by %.2e of the largest "
                          "displacement" % (path, n, nu[:4], diff))
                    if not diff <= settings["ranks_tolerance"]:
                        failures.append("%s path, level %d nu %s: 1 and 2 ranks differ by %.3g of "
                                        "the largest displacement" % (path, n, nu, diff))
    print("| path | cells per side | particles | nu | ranks | linear solver | Newton its |"
          " linear its | solver setup s | run s | u_y(48, 52) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(r)
    for path, errors in midpoint_errors.items():
        for n, e in errors:
            print("%s path, nu = 1/3, %d x %d: u_y(48, 52) off the reference 23.96 by %.3f %%"
                  % (path, n, n, 100 * e))
        # The literature value, within 1 % from 32 x 32 on.
        for n, e in errors:
            if n >= 32 and not e < 0.01:
                failures.append("%s path, nu = 1/3, %d x %d: u_y(48, 52) is %.2f %% off 23.96"
                                % (path, n, n, 100 * e))
    # SCNI approaches it monotonically from above on these levels.
    errors = midpoint_errors["default"]
    for k in range(1, len(errors)):
        if not errors[k][1] < errors[k - 1][1]:
            failures.append("default path, nu = 1/3: the error does not decrease from %d to %d "
                            "cells per side" % (errors[k - 1][0], errors[k][0]))
    # A scalable iterative path: the Krylov iterations nearly flat under refinement.
    for (path, nu, ranks), counts in sorted(krylov.items()):
        if path != "iterative":
            continue
        print("iterative path, nu %s, %d rank(s): Krylov iterations %s" % (
            nu, ranks, " / ".join(str(c) for _, c in counts)))
        for (n0, c0), (n1, c1) in zip(counts, counts[1:]):
            if c1 > MAX_ITERATION_GROWTH * c0:
                failures.append("iterative path, nu %s, %d rank(s): %d Krylov iterations at %d "
                                "cells per side after %d at %d (more than %.1fx)"
                                % (nu, ranks, c1, n1, c0, n0, MAX_ITERATION_GROWTH))
    for (path, nu, ranks), counts in sorted(krylov.items()):
        if path != "iterative" or ranks != 2:
            continue
        one = dict(krylov.get((path, nu, 1), []))
        for n, c in counts:
            if n >= RANKS_RATIO_FROM and n in one and c > MAX_RANKS_RATIO * one[n]:
                failures.append("iterative path, nu %s, %d x %d: %d Krylov iterations on 2 ranks "
                                "against %d on one (more than %.1fx)"
                                % (nu, n, n, c, one[n], MAX_RANKS_RATIO))
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        sys.exit(1)
    print("panel study passed")


if __name__ == "__main__":
    main()
