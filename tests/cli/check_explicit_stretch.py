#!/usr/bin/env python3
"""Explicit quasi-static uniaxial stretch on symmetry supports (tests/scenes/
explicit_nitsche_stretch.yaml): at the last record every particle carries stress_xx = SIGMA
within REL, the lateral stresses vanish within REL x SIGMA, the reaction of the x symmetry plane
balances the load, -SIGMA x area (1), within REL_REACTION, and the energy balance holds.
usage: check_explicit_stretch.py RESULTS.e HISTORY.csv
"""
import csv
import sys

import netCDF4
import numpy as np

SIGMA, REL, REL_REACTION = 2000.0, 5e-3, 1e-3
d = netCDF4.Dataset(sys.argv[1])
names = [b"".join(c for c in row if c).decode() for row in d["name_nod_var"][:]]
get = lambda n: np.array(d["vals_nod_var%d" % (names.index(n) + 1)][-1])  # noqa: E731
sxx, syy, szz = get("stress_xx"), get("stress_yy"), get("stress_zz")
last = list(csv.DictReader(open(sys.argv[2])))[-1]
rx = float(last["R_symmetry_x_x"])
balance = float(last["energy_balance_error"])
err_x = np.abs(sxx - SIGMA).max() / SIGMA
err_lat = max(np.abs(syy).max(), np.abs(szz).max()) / SIGMA
err_r = abs(rx + SIGMA) / SIGMA
print("stress_xx %.2f..%.2f (%.2g), lateral %.2g, R_symmetry_x_x %.3f (%.2g), balance %.2g"
      % (sxx.min(), sxx.max(), err_x, err_lat, rx, err_r, balance))
ok = err_x <= REL and err_lat <= REL and err_r <= REL_REACTION and abs(balance) < 1e-4
sys.exit(0 if ok else 1)
