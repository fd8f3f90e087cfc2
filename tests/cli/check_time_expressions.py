#!/usr/bin/env python3
"""Values as expressions of t in an implicit stage of two load steps (issue 19): the bar pulled
by a traction 10 t has u(L) = 10 t L / E = 0.1 t and sigma_xx = 10 t; the bar pulled by a
displacement 1e-3 t has u(L) = 1e-3 t and sigma_xx = E u / L = 0.1 t (hand values, E = 1000,
L = 10, nu = 0), at t = 1 and t = 2 to 1e-3 relative (a default ramp would halve t = 1).
The explicit bar driven by v_x = a t from v_y(0) = c translates rigidly: u_x(T) = a T^2 / 2,
u_y(T) = c T at its probe, to 1e-9 relative (a = 0.01, c = 0.002, T = 0.5).
usage: check_time_expressions.py TRACTION/history.csv DISPLACEMENT/history.csv VELOCITY/history.csv"""
import csv
import sys

expected = {sys.argv[1]: {"probe_end_ux": 0.1, "probe_mid_sxx": 10.0},
            sys.argv[2]: {"probe_end_ux": 1e-3, "probe_mid_sxx": 0.1}}
bad = 0
for path, columns in expected.items():
    rows = {round(float(r["time"]), 9): r for r in csv.DictReader(open(path))}
    for t in (1.0, 2.0):
        for name, per_time in columns.items():
            value, want = float(rows[t][name]), per_time * t
            ok = abs(value - want) <= 1e-3 * abs(want)
            bad += not ok
            print(f"{'ok  ' if ok else 'FAIL'} {path}: {name} at t = {t:g}: {value:.8g} vs {want:.8g}")
last = list(csv.DictReader(open(sys.argv[3])))[-1]
T = float(last["time"])
for name, want in (("probe_p_ux", 0.01 * T * T / 2), ("probe_p_uy", 0.002 * T)):
    value = float(last[name])
    ok = abs(T - 0.5) < 1e-12 and abs(value - want) <= 1e-9 * abs(want)
    bad += not ok
    print(f"{'ok  ' if ok else 'FAIL'} {sys.argv[3]}: {name} at t = {T:g}: {value:.12g} vs {want:.12g}")
sys.exit(1 if bad else 0)
