#!/usr/bin/python3
"""A nearly incompressible rubber bar (nu = 0.4999, mixed_up) thrown at a rigid wall, explicit
(tests/scenes/mixed/rubber_bar_wall.yaml; issue 17). Checks:
  - energy balance error below 1 % at every record, with the work the cells' bulk viscosity
    dissipated (history column bulk_viscosity_work, positive: the impact's ringing is damped);
  - the stable step follows the bulk wave: dt within [0.2, 2] h / c_p with
    c_p = sqrt((kappa + 4 mu / 3) / rho) (h the cell size; the shear wave would allow 70 x more);
  - the bar rebounds: mean x velocity at the end above 0.8 v0.
  - the particle field `pressure` (the volume-weighted mean of the cells around each particle,
    the pressure output of issue 17) carries no checkerboard: on every 2 x 2 block of particles
    the alternating sum (p1 - p2 + p3 - p4) / 4 stays below 10 % of the largest |p| of the run
    (measured 6.6 %, at the wall when the bar leaves it; a particle taking one neighbouring
    cell's pressure instead carries the cells' 34 %).
Prints, without asserting it, the same measure on the cell pressures (measured 23 %, the open
item of docs/mixed.md, "Explicit pressure").
The same bar with pressure_cells: patch (2 x 2 cells per pressure): energy balance below 1 %, and
both measures below those of one pressure per cell (measured 13.8 % vs 23.4 % on the cell
pressures, 3.5 % vs 6.6 % on the particles): the impact's ringing, not the spurious mode, is most
of what remains.
usage: check_rubber_bar.py EFG OUTDIR      (exit 1 when a check fails)
"""
import csv
import json
import math
import os
import subprocess
import sys

import netCDF4
import numpy as np
import yaml

efg, out = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(__file__))
scene = os.path.join(here, "..", "scenes", "mixed", "rubber_bar_wall.yaml")
failures = []


def check(ok, text):
    print(("ok    " if ok else "FAIL  ") + text)
    if not ok:
        failures.append(text)


run = subprocess.run([efg, "run", scene, "-o", out], capture_output=True, text=True)
if run.returncode != 0:
    sys.exit("efg run failed (exit %d):\n%s" % (run.returncode, run.stdout[-3000:] + run.stderr))

# The scene's constants (rubber_bar_wall.yaml): E = 100, nu = 0.4999, rho = 1, cells 40 x 8 on 1 x 0.2.
E, NU, RHO, H, V0 = 100.0, 0.4999, 1.0, 1.0 / 40, 1.0
mu = E / (2 * (1 + NU))
kappa = E / (3 * (1 - 2 * NU))
c_p = math.sqrt((kappa + 4 * mu / 3) / RHO)

report = json.load(open(os.path.join(out, "rubber_bar_wall.e.report.json")))
history = list(csv.DictReader(open(os.path.join(out, "rubber_bar_wall.csv"))))
worst = max(abs(float(r["energy_balance_error"])) for r in history)
check(worst < 0.01 and abs(report["energy_balance_error"]) < 0.01,
      f"energy balance error: largest {worst:.2%} over the records (< 1 %)")
dts = [float(r["time_step"]) for r in history]
damping = [float(r["bulk_viscosity_work"]) for r in history]
check(damping[-1] > 0 and all(b >= a - 1e-12 for a, b in zip(damping, damping[1:])),
      f"bulk viscosity work {damping[-1]:.4g} > 0, never decreasing")
check(max(dts) <= 2 * H / c_p and min(dts) >= 0.2 * H / c_p,
      f"stable step {min(dts):.3g} .. {max(dts):.3g} within [0.2, 2] h / c_p = {H / c_p:.3g} "
      f"(c_p = {c_p:.0f}; the shear wave would allow {H / math.sqrt(mu / RHO):.3g})")
v_end = float(history[-1]["v_all_x"])
check(v_end > 0.8 * V0, f"rebound: mean x velocity at the end {v_end:.3f} > 0.8 v0")


def checkerboard(p, ij):
    """Largest |p1 - p2 + p3 - p4| / 4 over 2 x 2 blocks of a structured grid of cells."""
    grid = np.zeros((ij[:, 0].max() + 1, ij[:, 1].max() + 1))
    grid[ij[:, 0], ij[:, 1]] = p
    alt = grid[:-1, :-1] - grid[1:, :-1] + grid[1:, 1:] - grid[:-1, 1:]
    return np.abs(alt).max() / 4


d = netCDF4.Dataset(os.path.join(out, "rubber_bar_wall.e"))
names = ["".join(c.decode() for c in n if c) for n in d["name_elem_var"][:]]
column = names.index("cell_pressure") + 1
x, y = d["coordx"][:], d["coordy"][:]
conn = d["connect1"][:] - 1
cx, cy = x[conn].mean(axis=1), y[conn].mean(axis=1)
ij = np.stack([np.rint((cx - cx.min()) / H).astype(int), np.rint((cy - cy.min()) / H).astype(int)], 1)
synthetic = np.where((ij[:, 0] + ij[:, 1]) % 2 == 0, 1.0, -1.0)
check(checkerboard(synthetic, ij) > 0.9, "the measure flags a synthetic checkerboard (1.0)")
pressures = [np.asarray(d["vals_elem_var%deb1" % column][k]) for k in range(len(d["time_whole"][:]))]
largest = max(np.abs(p).max() for p in pressures)
check(largest > 0, f"cell pressures written (largest |p| {largest:.4g})")
ratio = max(checkerboard(p, ij) for p in pressures) / largest
print(f"note  checkerboard component of the cell pressures: {ratio:.1%} of the largest |p| of the run")


def patch_case():
    """The bar with pressure_cells: patch: (energy balance, cell and particle checkerboard)."""
    s = yaml.safe_load(open(scene))
    s["parts"][0]["pressure_cells"] = "patch"
    s["output"]["history"] = "rubber_bar_patch.csv"
    folder = os.path.join(out, "patch")
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, "rubber_bar_patch.yaml")
    yaml.safe_dump(s, open(path, "w"), sort_keys=False)
    r = subprocess.run([efg, "run", path, "-o", folder], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("efg run failed (exit %d):\n%s" % (r.returncode, r.stdout[-3000:] + r.stderr))
    rows = list(csv.DictReader(open(os.path.join(folder, "rubber_bar_patch.csv"))))
    balance = max(abs(float(row["energy_balance_error"])) for row in rows)
    e = netCDF4.Dataset(os.path.join(folder, "rubber_bar_patch.e"))
    steps = range(len(e["time_whole"][:]))
    cells = [np.asarray(e["vals_elem_var%deb1" % column][k]) for k in steps]
    nodes = [np.asarray(e["vals_nod_var%d" % node_column][k]) for k in steps]
    big = max(np.abs(p).max() for p in cells)
    return (balance, max(checkerboard(p, ij) for p in cells) / big,
            max(checkerboard(p, nij) for p in nodes) / big)


node_names = ["".join(c.decode() for c in n if c) for n in d["name_nod_var"][:]]
node_column = node_names.index("pressure") + 1
nij = np.stack([np.rint((x - x.min()) / H).astype(int), np.rint((y - y.min()) / H).astype(int)], 1)
check(checkerboard(np.where((nij[:, 0] + nij[:, 1]) % 2 == 0, 1.0, -1.0), nij) > 0.9,
      "the measure flags a synthetic checkerboard of particle values (1.0)")
particle = [np.asarray(d["vals_nod_var%d" % node_column][k]) for k in range(len(d["time_whole"][:]))]
node_ratio = max(checkerboard(p, nij) for p in particle) / largest
check(node_ratio < 0.10,
      f"checkerboard component of the particle pressure: {node_ratio:.1%} of the largest cell |p| (< 10 %)")

balance, patch_ratio, patch_node_ratio = patch_case()
check(balance < 0.01, f"patch: energy balance error: largest {balance:.2%} over the records (< 1 %)")
check(patch_ratio < ratio, f"patch: checkerboard component of the cell pressures {patch_ratio:.1%} "
      f"below one pressure per cell's {ratio:.1%}")
check(patch_node_ratio < node_ratio, f"patch: checkerboard component of the particle pressure "
      f"{patch_node_ratio:.1%} below one pressure per cell's {node_ratio:.1%}")
print("%d checks failed" % len(failures) if failures else "all checks passed")
sys.exit(1 if failures else 0)
