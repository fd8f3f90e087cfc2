#!/usr/bin/env python3
"""The rolled strip (tests/scenes/shells/strip_rolled.yaml): a cantilever strip, L = 12, t = 0.1,
E = 1.2e6, nu = 0, end moment m = lambda 2 pi E t^3 / (12 L) per width in 10 load steps.

Exact (the elastica under a constant moment): at load lambda the strip is an arc of curvature
k = 2 pi lambda / L, the particle at X on the mid-surface goes to
  (sin(k X) / k, (1 - cos(k X)) / k) in the (x, -z) plane, its rotation about y is k X,
its moment m_xx = lambda m. Checked at every load step:
  * positions of every particle within 1 % of L (at lambda = 1: the end back at the clamp);
  * rotation_y of every particle within 1 % of the end's rotation k L (wrapped into (-pi, pi]);
  * moment_xx of the particles away from the ends (2 spacings) within 1 % of lambda m;
  * Newton (the run report's residuals): every step converged within 12 iterations; ||r|| is
    dominated by the membrane rows, (L/t)^2 stiffer than the bending ones, and rises when an
    iteration removes a bending residual (its second-order membrane forces); after its last
    rise every iteration reduces it by 1e3 or more until it is below 1e-8 of the step's largest
    (the quadratic tail; the orders are printed).
--levels COARSE.e FINE.e: the same strip on 24 and 96 cells: the end's distance from the clamp
at the full load falls with refinement (coarse > this > fine).
--quasistatic EXPLICIT.e IMPLICIT.e: the strip_half_roll_explicit.yaml strip bent to a half circle
by an end moment raised slowly in an explicit stage and held, and statically by Newton: the held
explicit state (mean over the records from t = 40) matches the static one, positions within 0.2 %
of L, rotations within 0.2 % of pi, moments within 1 % of the largest; the explicit stage's
energy balance error below 1 %.
--tail-from-step N: the quadratic tail checked from step N on (strip_rolled_by_rotation.yaml: its
first step imposes 0.63 rad on the flat strip's end at once; its tail falls by 660, 54, 2e4; from
step 2 on by 1e5 per iteration), the 12-iteration bound on every step.
usage: check_shell_rolled.py RESULTS.e [--levels COARSE.e FINE.e] [--quasistatic EXPLICIT.e
                             IMPLICIT.e] [--tail-from-step N]
"""
import argparse
import json
import math
import sys

import netCDF4
import numpy as np

L, t, E = 12.0, 0.1, 1.2e6
m_full = 2 * math.pi * E * t**3 / 12 / L


def closure(path):
    """The end's largest distance from the clamp at the last record, over L."""
    f = netCDF4.Dataset(path)
    names = list(netCDF4.chartostring(f.variables["name_nod_var"][:]))
    X = np.asarray(f.variables["coordx"][:])
    ux = np.asarray(f.variables["vals_nod_var%d" % (names.index("displacement_x") + 1)][-1])
    uz = np.asarray(f.variables["vals_nod_var%d" % (names.index("displacement_z") + 1)][-1])
    end = X > L - 1e-9
    return np.hypot(X[end] + ux[end], uz[end]).max() / L


def quasistatic(explicit, implicit):
    fe, fi = netCDF4.Dataset(explicit), netCDF4.Dataset(implicit)
    ne = list(netCDF4.chartostring(fe.variables["name_nod_var"][:]))
    ni = list(netCDF4.chartostring(fi.variables["name_nod_var"][:]))
    te = np.asarray(fe.variables["time_whole"][:])
    held = [k for k in range(len(te)) if te[k] >= 40 - 1e-9]
    errors = []
    length, turn = 1.0, math.pi
    bounds = {"displacement_x": 0.002 * length, "displacement_z": 0.002 * length,
              "rotation_y": 0.002 * turn, "moment_xx": None}
    for name, bound in bounds.items():
        ve = np.asarray(fe.variables["vals_nod_var%d" % (ne.index(name) + 1)][:])
        vi = np.asarray(fi.variables["vals_nod_var%d" % (ni.index(name) + 1)][-1])
        if bound is None:
            bound = 0.01 * np.abs(vi).max()
        gap = np.abs(ve[held].mean(axis=0) - vi).max()
        print("quasi-static: %s explicit (held mean) vs implicit %.2e (bound %.2e)"
              % (name, gap, bound))
        if not held or gap > bound:
            errors.append("quasi-static: %s differs by %.3g" % (name, gap))
    stages = json.load(open(explicit + ".report.json"))["shell_stages"]
    balance = stages[-1]["energy_balance_error"]
    print("quasi-static: explicit energy balance error %.2e" % balance)
    if not balance < 0.01:
        errors.append("quasi-static: energy balance error %.3g" % balance)
    return errors


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("results")
    ap.add_argument("--levels", nargs=2)
    ap.add_argument("--quasistatic", nargs=2)
    ap.add_argument("--tail-from-step", type=int, default=1)
    args = ap.parse_args()
    path = args.results
    f = netCDF4.Dataset(path)
    names = list(netCDF4.chartostring(f.variables["name_nod_var"][:]))
    times = np.asarray(f.variables["time_whole"][:])
    X = np.asarray(f.variables["coordx"][:])

    def field(name, k):
        return np.asarray(f.variables["vals_nod_var%d" % (names.index(name) + 1)][k])

    errors = []
    if len(times) != 11:
        errors.append("11 records expected (t = 0, 0.1, ..., 1), found %d" % len(times))
    spacing = L / 48
    inner = (X > 2 * spacing - 1e-9) & (X < L - 2 * spacing + 1e-9)
    for k in range(1, len(times)):
        lam = float(times[k])
        kappa = 2 * math.pi * lam / L
        x_exact = np.sin(kappa * X) / kappa
        z_exact = -(1 - np.cos(kappa * X)) / kappa
        x = X + field("displacement_x", k)
        z = field("displacement_z", k)
        position = np.hypot(x - x_exact, z - z_exact).max() / L
        angle = field("rotation_y", k) - kappa * X
        angle = np.abs((angle + math.pi) % (2 * math.pi) - math.pi).max()
        moment = np.abs(field("moment_xx", k)[inner] - lam * m_full).max() / (lam * m_full)
        end = np.hypot(x[X > L - 1e-9], z[X > L - 1e-9]).max() / L
        print("lambda %.1f: positions %.2e L, rotations %.2e rad, moments %.2e, end at %.4f L "
              "from the clamp" % (lam, position, angle, moment, end))
        if position > 0.01:
            errors.append("lambda %.1f: positions off the arc by %.3g L" % (lam, position))
        if angle > 0.01 * kappa * L:
            errors.append("lambda %.1f: rotations off by %.3g rad" % (lam, angle))
        if moment > 0.01:
            errors.append("lambda %.1f: moments off by %.3g" % (lam, moment))
    if len(times) == 11 and end > 0.01:
        errors.append("the strip does not close: its end is %.3g L from the clamp" % end)
    report = json.load(open(path + ".report.json"))
    for stage in report["shell_stages"]:
        for step, r in enumerate(stage["newton_residuals"]):
            orders = ["%.2f" % (math.log(r[i + 1] / r[i]) / math.log(r[i] / r[i - 1]))
                      if r[i] != r[i - 1] else "-" for i in range(1, len(r) - 1)]
            print("step %d: %d Newton iterations, ||r|| %s, orders %s"
                  % (step + 1, len(r) - 1, " ".join("%.1e" % v for v in r), " ".join(orders)))
            if len(r) - 1 > 12:
                errors.append("step %d: %d Newton iterations" % (step + 1, len(r) - 1))
            floor = 1e-8 * max(r)
            rise = max([i for i in range(1, len(r)) if r[i] > r[i - 1]], default=0)
            for i in range(rise + 1, len(r) if step + 1 >= args.tail_from_step else 0):
                if r[i - 1] > floor and r[i] > 1e-3 * r[i - 1]:
                    errors.append("step %d: Newton iteration %d after the last rise reduced "
                                  "||r|| only from %.3g to %.3g" % (step + 1, i, r[i - 1], r[i]))
    if args.levels:
        coarse, fine = closure(args.levels[0]), closure(args.levels[1])
        this = closure(path)
        print("closure at the full load: %.4f L (coarse), %.4f L (this), %.4f L (fine)"
              % (coarse, this, fine))
        if not coarse > this > fine:
            errors.append("the closure error does not fall with refinement")
    if args.quasistatic:
        errors += quasistatic(*args.quasistatic)
    for e in errors:
        print("FAIL: " + e)
    sys.exit(1 if errors else 0)


if __name__ == "__main__":
    main()
