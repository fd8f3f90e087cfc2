#!/usr/bin/env python3
"""1 vs 2 ranks of one explicit run: every history column of every record, and the listed nodal
fields of the last record, agree to TOL relative to each column's (field's) largest magnitude
(history columns of quantities that vanish by symmetry, below 1e-4 of the largest column - the
cross components of a symmetry plane's reaction, the sideways force on a centered impactor -
hold only the round-off of sums of terms of order 1 and are compared against that floor; the
energy balance error, a fraction, against 1; a rigid body's contact moment rb_<body>_M*, a sum
of terms r x F_J with arms r up to the model's size L, against its largest force column x L
(L the largest extent of ONE.e's coordinates), the scale of those terms: a moment that vanishes
by symmetry holds their round-off (1.5e-13 F L on the flat punch; against 1e-4 of the largest
force column, a floor in the wrong units, that was 1.5e-9).
usage: check_same_on_ranks.py TOL ONE/history.csv TWO/history.csv ONE.e TWO.e FIELD [FIELD ...]
A results file written one file per rank (output.files: per_rank, as a distributed read writes)
is named by its base, TWO.e: its pieces TWO.e.<ranks>.<rank> are joined here by their node id maps
(the nodes on a cut appear in two pieces with the same values).
"""
import csv
import glob
import os
import re
import sys

import netCDF4
import numpy as np

tol = float(sys.argv[1])
a = list(csv.DictReader(open(sys.argv[2])))
b = list(csv.DictReader(open(sys.argv[3])))
worst, where = 0.0, ""
if len(a) != len(b):
    sys.exit("records: %d on 1 rank, %d on 2" % (len(a), len(b)))
floor = 1e-4 * max(abs(float(r[n])) for r in a for n in a[0])


def model_size(path):
    pieces = [path] if os.path.exists(path) else sorted(glob.glob(path + ".*.*"))
    d = netCDF4.Dataset(pieces[0])
    return max(float(np.ptp(d[c][:])) for c in ("coordx", "coordy", "coordz") if c in d.variables)


def moment_floor(name):
    m = re.fullmatch(r"(rb_.*)_M[xyz]", name)
    if not m:
        return 0.0
    forces = [n for n in a[0] if re.fullmatch(re.escape(m.group(1)) + r"_F[xyz]", n)]
    largest = max((abs(float(r[n])) for r in a for n in forces), default=0.0)
    return largest * model_size(sys.argv[4])


for name in a[0]:
    x = np.array([float(r[name]) for r in a])
    y = np.array([float(r[name]) for r in b])
    scale = max(np.abs(x).max(), np.abs(y).max(), floor, moment_floor(name), 1e-300,
                1.0 if name == "energy_balance_error" else 0.0)
    diff = np.abs(x - y).max() / scale
    if diff > worst:
        worst, where = diff, name


def last_of_file(path, field):
    d = netCDF4.Dataset(path)
    names = [b"".join(c for c in row if c).decode() for row in d["name_nod_var"][:]]
    values = np.array(d["vals_nod_var%d" % (names.index(field) + 1)][-1])
    ids = np.array(d["node_num_map"][:]) if "node_num_map" in d.variables else \
        np.arange(1, len(values) + 1)
    return ids, values


def last(path, field):
    pieces = [path] if os.path.exists(path) else sorted(
        p for p in glob.glob(path + ".*.*") if re.fullmatch(r"\.\d+\.\d+", p[len(path):]))
    if not pieces:
        sys.exit("no results file %s (nor pieces %s.<ranks>.<rank>)" % (path, path))
    joined = {}
    for piece in pieces:
        ids, values = last_of_file(piece, field)
        joined.update(zip(ids.tolist(), values.tolist()))
    if sorted(joined) != list(range(1, len(joined) + 1)):
        sys.exit("%s: the pieces' node ids are not 1..%d" % (path, len(joined)))
    return np.array([joined[i] for i in range(1, len(joined) + 1)])


for field in sys.argv[6:]:
    x, y = last(sys.argv[4], field), last(sys.argv[5], field)
    diff = np.abs(x - y).max() / max(np.abs(x).max(), 1e-300)
    if diff > worst:
        worst, where = diff, field
print("1 vs 2 ranks: largest relative difference %.3g (%s)" % (worst, where))
sys.exit(0 if worst <= tol else 1)
