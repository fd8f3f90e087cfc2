#!/usr/bin/env python3
"""Plane stress: the output strain_zz must follow Hooke's law from the output stresses,
eps_zz = -nu / E (sigma_xx + sigma_yy) (sigma_zz = 0), at every particle. E and nu are the
scene's (tests/scenes/solvers/hold_stage.yaml: E = 3e7, nu = 0.3), written here by hand.

usage: check_plane_stress_strain.py RESULTS.e
"""
import sys

import netCDF4
import numpy as np

E, NU = 3.0e7, 0.3
with netCDF4.Dataset(sys.argv[1]) as d:
    names = ["".join(c.decode() for c in row if c) for row in d.variables["name_nod_var"][:]]
    value = lambda n: np.asarray(d.variables["vals_nod_var%d" % (names.index(n) + 1)][-1])
    sxx, syy, ezz = value("stress_xx"), value("stress_yy"), value("strain_zz")
expected = -NU / E * (sxx + syy)
scale = np.max(np.abs(expected))
error = np.max(np.abs(ezz - expected)) / scale
print("strain_zz vs -nu/E (sigma_xx + sigma_yy): largest difference %.3g of %.3g" % (error, scale))
if not (scale > 0 and error < 1e-9):
    sys.exit("strain_zz does not follow plane-stress Hooke's law")
