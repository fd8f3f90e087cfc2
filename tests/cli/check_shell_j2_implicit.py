#!/usr/bin/env python3
"""J2 shells in implicit stages (tests/scenes/shells/strip_j2_implicit.yaml and
strip_j2_implicit_collapse.yaml): a simply supported plate strip in cylindrical bending (L = 1,
t = 0.01, E = 1000, nu = 0.3, sigma_y = 0.1, perfectly plastic, 12 Gauss layers).

Loaded to q = 0.985 q_c (t = 1), q_c = 8 M_p / L^2, M_p = (2 / sqrt 3) sigma_y t^2 / 4:
  * yielded at the middle (plastic strain > 0 there);
  * moments of the particles in the middle half on statics, M = -q x (L - x) / 2, within 3 % of
    M_p (the beam is statically determinate: whatever the material does).
Unloaded to zero (t = 2): unloading is elastic (a rectangular section does not yield in reverse)
and the beam determinate, so
  * the plastic strain is left as it was (to 1e-12);
  * the moments return to zero (within 1 % of M_p);
  * the deflection recovered, w(1) - w(2), is the elastic Timoshenko beam's under q,
    q x (L^3 - 2 L x^2 + x^3) / (24 D) + q x (L - x) / (2 k G t), D = E t^3 / (12 (1 - nu^2)),
    k = 5/6, within 1 % of its largest value at every particle.
--collapse COLLAPSE.e: the run asked for 1.04 q_c stopped (exit 3) with its last converged state
written: its load factor lies between the 12-layer rule's limit (sum_k w_k |xi_k| = 1.0053 of
q_c: the discrete limit of the displacement method is above it) and 1 % above that (24 x 2 cells:
1.010).
--clamped CLAMPED.e ELASTIC.e: the strip clamped at both ends (strip_j2_clamped.yaml) pressed to
0.95 of its collapse load and released, and its elastic twin under the same load: hinges have
formed at the clamps (plastic strain > 0 there), unloading left the plastic strain unchanged (to
1e-12), and the deflection and moments it recovered, w(1) - w(2) and M(1) - M(2), equal the
elastic twin's to 1e-6 of their largest (the unloading is elastic; the clamps' moments come
from the edge points' own J2 layers: without their history it fails by 1e-3 and 1e-2).
--springback SPRINGBACK.e DIRECT.e: the clamped strip released by a springback stage (the
forces out of balance released over 4 load steps) and by an ordinary stage at once: the same end
state (deflection, rotation, moments) to 1e-8 of the largest values, plastic strain unchanged.
--quasistatic EXPLICIT.e IMPLICIT.e: the strip pressed to 0.9 q_c explicitly along a smooth
ramp and held (strip_j2_quasistatic_explicit.yaml), and statically (its implicit twin): the held
explicit state (mean over the records from t = 60) has the static deflection within 1 % of its
largest, plastic strain within 2 % of its largest, moments within 0.01 M_p.
usage: check_shell_j2_implicit.py IMPLICIT.e [--collapse COLLAPSE.e] [--clamped CLAMPED.e ELASTIC.e]
                                  [--springback SPRINGBACK.e DIRECT.e]
                                  [--quasistatic EXPLICIT.e IMPLICIT.e]
"""
import argparse
import math

import netCDF4
import numpy as np

L, t, E, nu, sigma_y = 1.0, 0.01, 1000.0, 0.3, 0.1
M_p = 2 / math.sqrt(3) * sigma_y * t * t / 4
q_c = 8 * M_p / L**2
q = 0.985 * q_c
D = E * t**3 / (12 * (1 - nu**2))
kGt = 5.0 / 6.0 * E / (2 * (1 + nu)) * t
xi, w = np.polynomial.legendre.leggauss(12)
rule_limit = float(np.sum(w * np.abs(xi)))  # fully plastic moment of the rule / M_p


def open_results(path):
    f = netCDF4.Dataset(path)
    names = list(netCDF4.chartostring(f.variables["name_nod_var"][:]))
    times = np.asarray(f.variables["time_whole"][:])

    def field(name, k):
        return np.asarray(f.variables["vals_nod_var%d" % (names.index(name) + 1)][k])
    return np.asarray(f.variables["coordx"][:]), times, field


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("implicit")
    ap.add_argument("--collapse")
    ap.add_argument("--clamped", nargs=2)
    ap.add_argument("--springback", nargs=2)
    ap.add_argument("--quasistatic", nargs=2)
    args = ap.parse_args()
    errors = []
    x, times, field = open_results(args.implicit)
    loaded = int(np.argmin(np.abs(times - 1.0)))
    unloaded = int(np.argmin(np.abs(times - 2.0)))
    if abs(times[loaded] - 1.0) > 1e-12 or abs(times[unloaded] - 2.0) > 1e-12:
        errors.append("records at t = 1 and 2 expected, found %s" % list(times))
    middle = np.abs(x - L / 2) < 1e-9
    middle_half = (x > 0.25 - 1e-9) & (x < 0.75 + 1e-9)
    eps_loaded = field("plastic_strain", loaded)
    print("loaded: plastic strain at the middle %s" % eps_loaded[middle])
    if not np.all(eps_loaded[middle] > 0):
        errors.append("the middle has not yielded at 0.985 q_c")
    statics = -q * x * (L - x) / 2
    worst = np.abs(field("moment_xx", loaded) - statics)[middle_half].max() / M_p
    print("loaded: moments in the middle half vs statics: worst %.4f M_p" % worst)
    if worst > 0.03:
        errors.append("loaded: moments off statics by %.3f M_p" % worst)
    w_loaded = field("displacement_z", loaded)
    # unloaded
    change = np.abs(field("plastic_strain", unloaded) - eps_loaded).max()
    residual = np.abs(field("moment_xx", unloaded)).max() / M_p
    recovered = w_loaded - field("displacement_z", unloaded)
    beam = -(q * x * (L**3 - 2 * L * x**2 + x**3) / (24 * D) + q * x * (L - x) / (2 * kGt))
    elastic = np.abs(recovered - beam).max() / np.abs(beam).max()
    print("unloaded: plastic strain change %.2e, largest moment %.2e M_p, recovered deflection "
          "vs the elastic beam %.3e of its largest (middle: %.6e vs %.6e)"
          % (change, residual, elastic, recovered[middle][0], beam[middle][0]))
    if change > 1e-12:
        errors.append("unloading changed the plastic strain by %.3g" % change)
    if residual > 0.01:
        errors.append("moments left after unloading: %.3g M_p" % residual)
    if elastic > 0.01:
        errors.append("the deflection recovered on unloading is off the elastic beam by %.3g"
                      % elastic)
    if args.collapse:
        f = netCDF4.Dataset(args.collapse)
        last = float(f.variables["time_whole"][-1])
        factor = 1.04 * last
        print("collapse: last converged load %.5f q_c (the 12-layer rule's limit %.5f)"
              % (factor, rule_limit))
        if not rule_limit <= factor <= 1.01 * rule_limit:
            errors.append("collapse: last converged load %.5f q_c outside [%.5f, %.5f]"
                          % (factor, rule_limit, 1.01 * rule_limit))
    if args.clamped:
        xc, tc, fc = open_results(args.clamped[0])
        _, _, fe = open_results(args.clamped[1])
        ends = (np.abs(xc) < 1e-9) | (np.abs(xc - L) < 1e-9)
        eps = fc("plastic_strain", 1)
        change = np.abs(fc("plastic_strain", 2) - eps).max()
        gaps = []
        for name in ("displacement_z", "moment_xx"):
            recovered = fc(name, 1) - fc(name, 2)
            twin = fe(name, 1)
            gaps.append(np.abs(recovered - twin).max() / np.abs(twin).max())
        print("clamped: plastic strain at the clamps %.3e, changed by unloading %.2e; recovered "
              "vs the elastic twin: deflection %.2e, moments %.2e"
              % (eps[ends].min(), change, gaps[0], gaps[1]))
        if not np.all(eps[ends] > 0):
            errors.append("clamped: no hinge at the clamps")
        if change > 1e-12:
            errors.append("clamped: unloading changed the plastic strain by %.3g" % change)
        if max(gaps) > 1e-6:
            errors.append("clamped: the unloading is not the elastic twin's response (%.3g, %.3g)"
                          % tuple(gaps))
    if args.springback:
        _, ts, fs = open_results(args.springback[0])
        _, _, fd = open_results(args.springback[1])
        last = len(ts) - 1
        gap = max(np.abs(fs(n, last) - fd(n, last)).max() / np.abs(fd(n, last)).max()
                  for n in ("displacement_z", "rotation_y", "moment_xx"))
        change = np.abs(fs("plastic_strain", last) - fs("plastic_strain", 1)).max()
        left = np.abs(fs("moment_xx", last)).max() / M_p
        print("springback: end state vs the release at once %.2e; plastic strain changed by "
              "%.1e; moments left %.3f M_p (statics: 0; the odd-even pattern, docs/shells.md)"
              % (gap, change, left))
        if gap > 1e-8 or change > 1e-12:
            errors.append("springback: the gradual release differs from the release at once")
    if args.quasistatic:
        _, te, fe = open_results(args.quasistatic[0])
        _, ti, fi = open_results(args.quasistatic[1])
        held = [k for k in range(len(te)) if te[k] >= 60 - 1e-9]
        static = len(ti) - 1
        gaps = {}
        for name in ("displacement_z", "plastic_strain", "moment_xx"):
            mean = np.mean([fe(name, k) for k in held], axis=0)
            scale = M_p if name == "moment_xx" else np.abs(fi(name, static)).max()
            gaps[name] = np.abs(mean - fi(name, static)).max() / scale
        print("quasi-static: explicit (held mean) vs implicit: deflection %.2e of its largest, "
              "plastic strain %.2e of its largest, moments %.2e M_p"
              % (gaps["displacement_z"], gaps["plastic_strain"], gaps["moment_xx"]))
        if gaps["displacement_z"] > 0.01 or gaps["plastic_strain"] > 0.02 or \
                gaps["moment_xx"] > 0.01:
            errors.append("quasi-static: the explicit and implicit J2 shells disagree")
    if errors:
        print("FAILED:\n  " + "\n  ".join(errors))
        raise SystemExit(1)
    print("J2 shells in implicit stages: checks passed")


if __name__ == "__main__":
    main()
