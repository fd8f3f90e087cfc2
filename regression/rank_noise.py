#!/usr/bin/python3
"""Measures the 1- vs N-rank noise of a regression case, to choose the floors of its exodiff.cmd
(docs/regression.md, "Tolerances"). For every nodal and global variable of two efg results of the
same scene: the largest |value| (the field's scale; stress components share one, as do strains and
reactions), the largest |a - b|, that difference as a fraction of the scale, and the smallest floor
(as a fraction of the scale) at which the noise stays 10 x below relative 1e-8.

Usage: /usr/bin/python3 regression/rank_noise.py ONE_RANK.e TWO_RANKS.e
(Debian's python3-netcdf4; a pyenv python3 on PATH may not see it.)
"""
import sys

import netCDF4
import numpy as np


def names(ds, var):
    if var not in ds.variables:
        return []
    raw = np.ma.getdata(ds.variables[var][:]).astype("S1")
    return [b"".join(row).decode().rstrip("\x00 ") for row in raw]


def family(name):
    if name.startswith("R_"):
        return "reaction"
    if name == "strain_energy":
        return name
    return name.rsplit("_", 1)[0] if name.count("_") else name


def main():
    a, b = netCDF4.Dataset(sys.argv[1]), netCDF4.Dataset(sys.argv[2])
    rows = []
    for i, n in enumerate(names(a, "name_nod_var")):
        key = "vals_nod_var%d" % (i + 1)
        rows.append((n, np.array(a.variables[key][:]), np.array(b.variables[key][:])))
    for i, n in enumerate(names(a, "name_glo_var")):
        rows.append((n, np.array(a.variables["vals_glo_var"][:, i]), np.array(b.variables["vals_glo_var"][:, i])))
    scale = {}
    for n, x, _ in rows:
        scale[family(n)] = max(scale.get(family(n), 0.0), float(np.abs(x).max()))
    print("%-22s %11s %11s %11s %11s %12s" % ("variable", "max |value|", "scale", "max |a-b|", "of scale", "floor needed"))
    for n, x, y in rows:
        s = scale[family(n)]
        d = float(np.abs(x - y).max())
        frac = d / s if s > 0 else 0.0
        print("%-22s %11.3e %11.3e %11.3e %11.1e %12.1e" % (n, np.abs(x).max(), s, d, frac, frac * 1e9))


if __name__ == "__main__":
    main()
