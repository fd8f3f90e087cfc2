#!/usr/bin/python3
"""Markdown tables of the study CSV files in a folder (scripts/verification_docs.sh)."""
import csv
import glob
import math
import os
import sys


def rate(rows, key):
    x = [math.log(float(r["h"])) for r in rows]
    y = [math.log(float(r[key])) for r in rows]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)


for path in sorted(glob.glob(os.path.join(sys.argv[1], "*_study.csv"))):
    rows = list(csv.DictReader(open(path)))
    keys = [k for k in rows[0] if "." in k]
    print(f"\n### {os.path.basename(path)}\n")
    print("| " + " | ".join(k.split(".")[-1] for k in keys) + " | dofs | L2 error | energy error | seconds |")
    print("|" + "---|" * (len(keys) + 4))
    groups = {}
    for r in rows:
        groups.setdefault(tuple(r[k] for k in keys), []).append(r)
        print("| " + " | ".join(r[k] for k in keys) +
              f" | {r['dofs']} | {float(r['l2_rel_error']):.3e} | {float(r['energy_rel_error']):.3e} | {float(r['total_seconds']):.2f} |")
    print("\nFitted rates in h (least squares over the levels):\n")
    for g, rs in groups.items():
        print(f"- {', '.join(g)}: L2 {rate(rs, 'l2_rel_error'):.2f}, energy {rate(rs, 'energy_rel_error'):.2f}")
