#!/usr/bin/python3
"""Measures the 1- vs N-rank noise of a regression case, to choose the floors of its exodiff.cmd
(docs/regression.md, "Tolerances"). For every nodal and global variable of two efg results of the
same scene: the largest |value| (the field's scale; stress components share one, as do strains and
reactions), the largest |a - b|, that difference as a fraction of the scale, and the smallest floor
(as a fraction of the scale) at which the noise stays 10 x below relative 1e-8.

Usage: /usr/bin/python3 regression/rank_noise.py ONE_RANK.e TWO_RANKS.e [--max-fraction X]
(Debian's python3-netcdf4; a pyenv python3 on PATH may not see it.)
With --max-fraction it is a check (the thread-agreement tests, tests/threads): exit 1 when the
files differ in variables or records, or any variable differs by more than X of its scale.
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
    args = sys.argv[1:]
    limit = None
    if "--max-fraction" in args:
        i = args.index("--max-fraction")
        limit = float(args[i + 1])
        del args[i:i + 2]
    a, b = netCDF4.Dataset(args[0]), netCDF4.Dataset(args[1])
    for var in ("name_nod_var", "name_glo_var"):
        if names(a, var) != names(b, var):
            print("different %s: %s vs %s" % (var, names(a, var), names(b, var)))
            return 1
    if a.variables["time_whole"].shape != b.variables["time_whole"].shape:
        print("different record counts: %d vs %d" % (a.variables["time_whole"].shape[0], b.variables["time_whole"].shape[0]))
        return 1
    rows = [("time", np.array(a.variables["time_whole"][:]), np.array(b.variables["time_whole"][:]))]
    for i, n in enumerate(names(a, "name_nod_var")):
        key = "vals_nod_var%d" % (i + 1)
        rows.append((n, np.array(a.variables[key][:]), np.array(b.variables[key][:])))
    for i, n in enumerate(names(a, "name_glo_var")):
        rows.append((n, np.array(a.variables["vals_glo_var"][:, i]), np.array(b.variables["vals_glo_var"][:, i])))
    scale = {}
    for n, x, _ in rows:
        scale[family(n)] = max(scale.get(family(n), 0.0), float(np.abs(x).max()))
    print("%-22s %11s %11s %11s %11s %12s" % ("variable", "max |value|", "scale", "max |a-b|", "of scale", "floor needed"))
    worst = 0.0
    for n, x, y in rows:
        s = scale[family(n)]
        d = float(np.abs(x - y).max()) if x.size else 0.0
        frac = d / s if s > 0 else (0.0 if d == 0 else float("inf"))
        if not np.all(np.isfinite(y)):
            frac = float("inf")
        worst = max(worst, frac)
        print("%-22s %11.3e %11.3e %11.3e %11.1e %12.1e" % (n, np.abs(x).max() if x.size else 0.0, s, d, frac, frac * 1e9))
    if limit is not None:
        print("largest difference: %.2e of its variable's scale (allowed %.1e)" % (worst, limit))
        return 0 if worst <= limit else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
