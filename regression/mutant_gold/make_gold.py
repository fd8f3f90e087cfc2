#!/usr/bin/python3
"""Writes the mutant gold: a copy of SOURCE (timoshenko_scni/gold.e) with one nodal value changed
by +0.1 %: displacement_y at the node of largest |displacement_y| (the beam tip) in the last record.
Usage: /usr/bin/python3 make_gold.py SOURCE TARGET   (Debian's python3-netcdf4; see docs/regression.md)
"""
import shutil
import sys

import netCDF4
import numpy as np


def names(ds, var):
    raw = np.ma.getdata(ds.variables[var][:]).astype("S1")
    return [b"".join(row).decode().rstrip("\x00 ") for row in raw]


def main():
    source, target = sys.argv[1], sys.argv[2]
    shutil.copyfile(source, target)
    with netCDF4.Dataset(target, "r+") as ds:
        k = names(ds, "name_nod_var").index("displacement_y") + 1
        var = ds.variables["vals_nod_var%d" % k]
        last = var.shape[0] - 1
        values = np.array(var[last, :])
        node = int(np.argmax(np.abs(values)))
        old = values[node]
        values[node] = old * 1.001
        var[last, :] = values
    print("mutant gold %s: displacement_y of node %d (1-offset) in record %d: %.10e -> %.10e (+0.1 %%)"
          % (target, node + 1, last + 1, old, old * 1.001))


if __name__ == "__main__":
    main()
