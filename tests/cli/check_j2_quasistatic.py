#!/usr/bin/env python3
"""Explicit quasi-static J2 loading (tests/scenes/plasticity/j2_quasistatic_explicit.yaml): at
the last record every particle carries stress_xx = SIGMA within REL_STRESS and the effective
plastic strain (SIGMA - sigma_y) / H of uniaxial stress with linear hardening (the implicit
closed form) within REL_PLASTIC; the kinetic energy left is below 1e-5 of the internal energy.
usage: check_j2_quasistatic.py RESULTS.e HISTORY.csv
"""
import csv
import sys

import netCDF4
import numpy as np

SIGMA, SIGMA_Y, H = 260.0, 250.0, 2000.0
REL_STRESS, REL_PLASTIC = 2e-3, 2e-2
d = netCDF4.Dataset(sys.argv[1])
names = [b"".join(c for c in row if c).decode() for row in d["name_nod_var"][:]]
get = lambda n: np.array(d["vals_nod_var%d" % (names.index(n) + 1)][-1])
sxx, ep = get("stress_xx"), get("plastic_strain")
alpha = (SIGMA - SIGMA_Y) / H
last = list(csv.DictReader(open(sys.argv[2])))[-1]
ke, ie = float(last["kinetic_energy"]), float(last["internal_energy"])
err_s = np.abs(sxx - SIGMA).max() / SIGMA
err_p = np.abs(ep - alpha).max() / alpha
print("stress_xx %.3f..%.3f (%.2g), plastic strain %.5f..%.5f vs %.5f (%.2g), kinetic/internal %.2g"
      % (sxx.min(), sxx.max(), err_s, ep.min(), ep.max(), alpha, err_p, ke / ie))
sys.exit(0 if err_s <= REL_STRESS and err_p <= REL_PLASTIC and ke < 1e-5 * ie else 1)
