#!/usr/bin/env python3
"""Hertz contact of an elastic sphere on a rigid flat, 3D, implicit (the 3D case of ../hertz).

An eighth of a ball of radius R = 1 centred at (0, 0, R): the unit cube [0, 1]^3 of n^3 HEX8
cells mapped onto the ball's octant x, y >= 0, z <= R by p -> R p |p|_inf / |p|_2 (the cube's
faces x, y = 1 and z = 1 go to the sphere), then pulled towards the contact point (0, 0, 0) by
the map of ../hertz/make_mesh.py's graded() applied about the centre in the meridian plane
(polar angle from the downward axis and depth below the sphere, azimuth kept). E = 1000,
nu = 0.3; symmetry u_x = 0 on x = 0 and u_y = 0 on y = 0; the cut z = R pressed down by DELTA in
LOAD_STEPS load steps onto the fixed rigid plane z = 0 (frictionless, implicit penalty
beta = alpha E / h). Per level: the whole sphere's load P = 4 x the contact force on the plane,
the contact particles' pressures p_J = alpha E (-gap_J) / h_J (h_J the longest edge of the
boundary faces at the particle, as efg's), and Hertz's profile p = p0 sqrt(1 - r^2 / a^2)
fitted to p^2 against r^2 (r the deformed distance from the axis), compared with Johnson
(Contact Mechanics, 1985, sec. 4.2): a = (3 P R / (4 E*))^(1/3), p0 = 3 P / (2 pi a^2),
E* = E / (1 - nu^2).
Exit 1 when the finest level is off by more than TOL in a or p0, when an error does not fall
from the coarsest level to the finest, or when the cut's reaction differs from the contact
force (or a symmetry plane carries a normal force) by more than 1e-8 of it.
usage: run_hertz_sphere.py EFG OUTDIR [--cells N N ...] [--penalty ALPHA] [--grading A]
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import time

import netCDF4
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))
sys.path.insert(0, os.path.join(HERE, "..", "hertz"))
from exodus_mesh import write_exodus  # noqa: E402
from make_mesh import graded  # noqa: E402
from run_hertz import finish  # noqa: E402

R, E, NU, DELTA, LOAD_STEPS = 1.0, 1000.0, 0.3, 0.02, 4
GRADING = 0.35
TOL = 0.05

SCENE = """title: Hertz sphere on a rigid flat, {n} cells across the radius
mesh: {{file: {mesh}}}
parts:
  - {{name: ball, blocks: [ball], material: m}}
materials:
  - {{name: m, model: linear_elastic, youngs_modulus: {E!r}, poissons_ratio: {nu!r}}}
boundary_conditions:
  - {{name: sym_x, type: displacement, node_set: sym_x, x: 0}}
  - {{name: sym_y, type: displacement, node_set: sym_y, y: 0}}
  - {{name: top, type: displacement, node_set: top, z: {d!r}, curve: load}}
rigid_bodies:
  - {{name: flat, shape: plane, point: [0, 0, 0], normal: [0, 0, 1]}}
contacts:
  - {{name: touch, rigid_body: flat, parts: [ball], implicit_penalty: {alpha!r}}}
curves:
  - {{name: load, time: [0, 1], value: [0, 1]}}
stages:
  - {{name: press, driver: implicit, end_time: 1, load_steps: {steps}}}
output:
  fields: [displacement]
  history: history.csv
"""

# HEX8 node order of the cube's cells and their 6 faces (local node indices).
FACES = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]


def octant(n, grading):
    """Nodes (x, y, z) and HEX8 cells (1-based) of the graded ball octant, node sets."""
    g = np.linspace(0.0, 1.0, n + 1)
    i, j, k = np.meshgrid(g, g, g, indexing="ij")
    p = np.stack([i.ravel(), j.ravel(), k.ravel()], axis=1)
    two = np.linalg.norm(p, axis=1)
    inf = np.abs(p).max(axis=1)
    scale = np.where(two > 0, inf / np.where(two > 0, two, 1.0), 0.0)
    q = R * p * scale[:, None]               # the ball octant about the origin, z >= 0 upward
    x, y, z = q[:, 0], q[:, 1], R - q[:, 2]  # turned: centre at (0, 0, R), lowest point at 0
    if grading != 1.0:  # the 2D map in each meridian plane (rho, z), the azimuth kept
        az = np.arctan2(y, x)
        rho, z = graded(np.hypot(x, y), z, R, grading)
        x, y = rho * np.cos(az), rho * np.sin(az)
    m = n + 1
    node = lambda a, b, c: (a * m + b) * m + c  # noqa: E731
    cells = []
    for a in range(n):
        for b in range(n):
            for c in range(n):
                # cube cell nodes counter-clockwise in (i, j) below, then above, in k; the map
                # turns k downwards (z = R - ...), so the order is mirrored: swap the layers
                lower = [node(a, b, c), node(a + 1, b, c), node(a + 1, b + 1, c), node(a, b + 1, c)]
                upper = [node(a, b, c + 1), node(a + 1, b, c + 1), node(a + 1, b + 1, c + 1),
                         node(a, b + 1, c + 1)]
                cells.append(upper + lower)
    cells = np.array(cells)
    tol = 1e-9 * R
    r = np.sqrt(x ** 2 + y ** 2 + (z - R) ** 2)
    sets = {"sym_x": np.nonzero(np.abs(x) < tol)[0] + 1,
            "sym_y": np.nonzero(np.abs(y) < tol)[0] + 1,
            "top": np.nonzero(np.abs(z - R) < tol)[0] + 1,
            "sphere": np.nonzero(np.abs(r - R) < 1e-6 * R)[0] + 1}
    return x, y, z, cells + 1, sets


def boundary_face_sizes(x, y, z, cells):
    """Longest edge of the boundary faces (faces used by one cell) at each node."""
    count = {}
    for cell in cells - 1:
        for f in FACES:
            key = tuple(sorted(cell[list(f)]))
            count[key] = (count.get(key, (0, None))[0] + 1, [cell[v] for v in f])
    h = np.zeros(len(x))
    pts = np.stack([x, y, z], axis=1)
    for used, face in count.values():
        if used != 1:
            continue
        edges = [np.linalg.norm(pts[face[v]] - pts[face[(v + 1) % 4]]) for v in range(4)]
        for v in face:
            h[v] = max(h[v], max(edges))
    return h


def run_level(efg, outdir, n, alpha, grading):
    tag = "hertz_sphere_%d" % n
    mesh = os.path.join(outdir, tag + ".e")
    x, y, z, cells, sets = octant(n, grading)
    write_exodus(mesh, "Hertz ball octant %d" % n, [x, y, z], cells, "HEX8", sets,
                 block_name="ball")
    scene = os.path.join(outdir, tag + ".yaml")
    with open(scene, "w") as f:
        f.write(SCENE.format(n=n, mesh=os.path.basename(mesh), E=E, nu=NU, d=-DELTA,
                             alpha=alpha, steps=LOAD_STEPS))
    out = os.path.join(outdir, tag + "_out")
    start = time.time()
    p = subprocess.run([efg, "run", scene, "-o", out], capture_output=True, text=True)
    seconds = time.time() - start
    if p.returncode != 0:
        sys.exit("%s: efg exit %d: %s" % (tag, p.returncode, p.stderr.strip()[-600:]))
    newton = [l for l in p.stdout.splitlines() + p.stderr.splitlines() if "Newton iterations," in l]
    with netCDF4.Dataset(os.path.join(out, tag + ".e")) as d:
        names = [str(s) for s in netCDF4.chartostring(d.variables["name_nod_var"][:])]
        u = [np.asarray(d.variables["vals_nod_var%d" % (names.index("displacement_" + c) + 1)][-1])
             for c in "xyz"]
    last = list(csv.DictReader(open(os.path.join(out, "history.csv"))))[-1]
    contact = float(last["rb_flat_Fz"])
    P = 4.0 * abs(contact)
    reaction_error = max(abs(float(last["R_top_z"]) - contact), abs(float(last["R_sym_x_z"])),
                         abs(float(last["R_sym_y_z"]))) / abs(contact)
    h = boundary_face_sizes(x, y, z, cells)
    s = sets["sphere"] - 1
    gap = z[s] + u[2][s]
    touching = gap < 0
    rs = np.hypot(x[s] + u[0][s], y[s] + u[1][s])[touching]
    pressure = alpha * E * (-gap[touching]) / h[s][touching]
    slope, intercept = np.polyfit(rs ** 2, pressure ** 2, 1) if len(rs) > 2 else (0.0, -1.0)
    fits = intercept > 0 and slope < 0
    p0 = math.sqrt(intercept) if fits else float("nan")
    a = math.sqrt(-intercept / slope) if fits else float("nan")
    e_star = E / (1 - NU * NU)
    a_exact = (3 * P * R / (4 * e_star)) ** (1.0 / 3.0)
    p0_exact = 3 * P / (2 * math.pi * a_exact ** 2)
    return dict(n=n, particles=len(x), seconds=seconds, P=P, touching=int(touching.sum()),
                reaction_error=reaction_error, a=a, a_exact=a_exact, p0=p0, p0_exact=p0_exact,
                newton=newton[-1].split("done:")[-1].strip() if newton else "")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("efg")
    ap.add_argument("outdir")
    ap.add_argument("--cells", type=int, nargs="+", default=[8, 12, 16])
    ap.add_argument("--penalty", type=float, default=100.0)
    ap.add_argument("--grading", type=float, default=GRADING)
    args = ap.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    efg = os.path.abspath(args.efg)
    print("| cells across R | particles | efg time | P | contact particles | a | a Hertz | a err "
          "| p0 | p0 Hertz | p0 err | reactions vs contact | steps |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    rows = []
    for n in args.cells:
        r = run_level(efg, args.outdir, n, args.penalty, args.grading)
        r["ea"] = r["a"] / r["a_exact"] - 1
        r["ep"] = r["p0"] / r["p0_exact"] - 1
        rows.append(r)
        print("| %d | %d | %.1f s | %.4f | %d | %.5f | %.5f | %+.2f %% | %.3f | %.3f | %+.2f %% "
              "| %.1e | %s |"
              % (n, r["particles"], r["seconds"], r["P"], r["touching"], r["a"], r["a_exact"],
                 100 * r["ea"], r["p0"], r["p0_exact"], 100 * r["ep"], r["reaction_error"],
                 r["newton"]), flush=True)
    fine, coarse = rows[-1], rows[0]
    failures = []
    for key, name in (("ea", "contact radius"), ("ep", "peak pressure")):
        if not abs(fine[key]) <= TOL:
            failures.append("%s off by %+.2f %% on the finest level" % (name, 100 * fine[key]))
        if len(rows) > 1 and not abs(fine[key]) < abs(coarse[key]):
            failures.append("the %s error does not fall with refinement" % name)
    finish(failures, rows, "n")


if __name__ == "__main__":
    main()
