#!/usr/bin/python3
"""Plots an `efg study` table: relative errors against dofs and against wall time, log-log, with
least-squares rates in the legend (rates against h for the dofs plot). Usage:
plot_study.py STUDY.csv OUTPUT_PREFIX -> OUTPUT_PREFIX_error_vs_dofs.png, _error_vs_time.png"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def slope(xs, ys):
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    n = len(lx)
    mx, my = sum(lx) / n, sum(ly) / n
    den = sum((a - mx) ** 2 for a in lx)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / den if den > 0 else float("nan")


def main(table, prefix):
    rows = list(csv.DictReader(open(table)))
    fixed = {"level", "h", "dofs", "l2_rel_error", "energy_rel_error", "max_nodal_error", "pressure_rel_error",
             "total_seconds"}
    sweep_keys = [k for k in rows[0].keys() if k not in fixed and not k.endswith("_seconds")]
    series = {}
    for r in rows:
        if not r["l2_rel_error"]:
            continue
        label = ", ".join(f"{k.split('.')[-1]}={r[k]}" for k in sweep_keys) or "efg"
        series.setdefault(label, []).append(r)
    for x_key, x_label, name in (("dofs", "degrees of freedom", "error_vs_dofs"), ("total_seconds", "wall time [s]", "error_vs_time")):
        fig, ax = plt.subplots(figsize=(7, 5))
        for label, rs in series.items():
            x = [float(r[x_key]) for r in rs]
            h = [float(r["h"]) for r in rs]
            for err, style in (("l2_rel_error", "o-"), ("energy_rel_error", "s--")):
                y = [float(r[err]) for r in rs]
                rate = slope(h, y) if len(rs) > 1 else float("nan")
                ax.loglog(x, y, style, label=f"{label}: {err.replace('_rel_error', '')} (rate in h {rate:.2f})")
        ax.set_xlabel(x_label)
        ax.set_ylabel("relative error")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(f"{prefix}_{name}.png", dpi=110)
        plt.close(fig)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
