#!/usr/bin/env python3
"""Hertz contact of an elastic cylinder on a rigid flat, implicit (README.md of this folder).

Quarter model (make_mesh.py): radius R = 1, plane strain, E = 1000, nu = 0.3; symmetry u_x = 0
on x = 0; the cut through the center (y = R) pressed down by DELTA in LOAD_STEPS load steps;
the fixed rigid plane y = 0 (`rigid_bodies`, frictionless `contacts`, implicit penalty
beta = alpha E / h). Per level: the total load per unit length of the whole cylinder P = 2 x the
contact force on the plane (rb_flat_Fy of the last record), and from the contact particles
(physical position inside the plane) their pressures p_J = alpha E (-gap_J) / h_J (h_J: the
longest boundary edge at the particle, as efg's ImplicitContact); Hertz's elliptic profile
p = p0 sqrt(1 - x^2 / b^2) is fitted by least squares to p^2 against x^2 (x the deformed
position), giving the half-width b and the peak p0, compared with Johnson (Contact Mechanics,
1985, sec. 4.2): b = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi b), E* = E / (1 - nu^2).
Exit 1 when the finest level is off by more than 5 % in b or p0, an error does not fall from
the coarsest to the finest level, or on any level the cut's reaction differs from the contact
force (or the symmetry plane carries a force) by more than 1e-8 of it.
With --force P the flat is a free rigid body pressed up by P / 2 (the quarter's share of the
load P per unit length, ramped by the curve) onto the cylinder whose cut is held (force
control, drivers/BodyForceBalance): the same checks, and the contact force on the flat equal to
P / 2 to 1e-8.
With --mirror the flat is the cylinder's mirror image in y = 0, a second deformable part
(`target_parts`: contact between deformable parts, two-way, contact/ImplicitSurfaceContact),
its cut held at y = -R, the first cylinder's cut pressed down by 2 DELTA. Two equal cylinders
are Hertz's case with 1/R* = 2/R and 1/E* = 2 (1 - nu^2)/E (Johnson, sec. 4.2), which gives the
same b and p0 for the same P as one cylinder on a rigid flat; by symmetry the interface is the
plane y = -DELTA, and a contact particle's pressure is both sides' penalty forces, p_J =
2 alpha E (-g_J) / h_J with the gap to the other surface g_J = 2 (y_J - (-DELTA)). The same
checks on the errors falling and the reactions (both cuts carry the contact force), and a twin:
each level is also run on the rigid flat, and P, b and p0 of the two runs must agree to
TWIN_TOL (the symmetry argument: the mirror plays the rigid flat; an independent code path,
contact/ImplicitContact against contact/ImplicitSurfaceContact). The 5 % bound on the finest
level holds from 80 cells (docs/contact.md); the test runs 20 and 40.
usage: run_hertz.py EFG OUTDIR [--radial N N N] [--penalty ALPHA] [--force P | --mirror]
"""
import argparse
import math
import os
import subprocess
import sys
import time

import netCDF4
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from make_mesh import quarter_cylinder  # noqa: E402
sys.path.insert(0, os.path.join(HERE, ".."))
from exodus_mesh import write_exodus  # noqa: E402

R, E, NU, DELTA, LOAD_STEPS = 1.0, 1000.0, 0.3, 0.03, 5
GRADING = 0.3  # contact-point spacing / uniform spacing (make_mesh.graded)
TOL = 0.05
TWIN_TOL = 0.002

# The scene of a level: the cylinder and its supports, then what it is pressed against (the
# rigid flat, or the mirror image as a second part), then loading and output.
SCENE_HEAD = """title: {title}, {nr} cells across the radius
mesh: {{file: {mesh}}}
parts:
  - {{name: cyl, blocks: [cylinder], material: m, plane: strain}}{more_parts}
materials:
  - {{name: m, model: linear_elastic, youngs_modulus: {E!r}, poissons_ratio: {nu!r}}}
boundary_conditions:
  - {{name: sym, type: displacement, node_set: sym, x: 0}}
  - {{name: top, type: displacement, node_set: top, y: {d!r}, curve: load}}
"""
FLAT = """rigid_bodies:
  - {{name: flat, shape: plane, point: [0, 0], normal: [0, 1]{flat}}}
contacts:
  - {{name: touch, rigid_body: flat, parts: [cyl], implicit_penalty: {alpha!r}}}
"""
MIRROR = """  - {{name: bottom, type: displacement, node_set: bottom, y: 0}}
contacts:
  - {{name: touch, parts: [cyl], target_parts: [mirror], implicit_penalty: {alpha!r}}}
"""
SCENE_TAIL = """curves:
  - {{name: load, time: [0, 1], value: [0, 1]}}
stages:
  - {{name: press, driver: implicit, end_time: 1, load_steps: {steps}}}
output:
  fields: [displacement]
  history: history.csv
"""


def boundary_edge_sizes(x, y, conn):
    """Longest boundary edge at each node (edges used by one cell only)."""
    count = {}
    for q in conn - 1:
        for k in range(4):
            e = tuple(sorted((q[k], q[(k + 1) % 4])))
            count[e] = count.get(e, 0) + 1
    h = np.zeros(len(x))
    for (a, b), c in count.items():
        if c == 1:
            length = math.hypot(x[a] - x[b], y[a] - y[b])
            h[a], h[b] = max(h[a], length), max(h[b], length)
    return h


def write_mirrored(mesh, nr, x, y, conn, sets):
    """The quarter and its mirror image in y = 0 (nodes of its own, cells turned back to
    counterclockwise order): blocks `cylinder` and `mirror`; node sets sym (both x = 0), top
    (y = R), bottom (y = -R), arc (the first quarter's surface)."""
    n = len(x)
    mirror_conn = conn[:, ::-1] + n
    both = {"sym": np.concatenate([sets["sym"], sets["sym"] + n]), "top": sets["top"],
            "bottom": sets["top"] + n, "arc": sets["arc"]}
    write_exodus(mesh, "Hertz two quarter cylinders %d" % nr,
                 [np.concatenate([x, x]), np.concatenate([y, -y])], conn, "QUAD4", both,
                 block_name="cylinder", more_blocks=[("mirror", mirror_conn, "QUAD4")])


def run_level(efg, outdir, nr, alpha, grading, force=None, mirror=False):
    tag = "hertz_%d%s" % (nr, "_force" if force else "_mirror" if mirror else "")
    mesh = os.path.join(outdir, tag + ".e")
    x, y, conn, sets = quarter_cylinder(R, nr, grading)
    if mirror:
        write_mirrored(mesh, nr, x, y, conn, sets)
    else:
        write_exodus(mesh, "Hertz quarter cylinder %d" % nr, [x, y], conn, "QUAD4", sets,
                     block_name="cylinder")
    scene = os.path.join(outdir, tag + ".yaml")
    with open(scene, "w") as f:
        flat = (", motion: free, mass: 1.0, force: [0, %r], curve: load" % (force / 2)
                if force else "")
        scene_text = SCENE_HEAD + (MIRROR if mirror else FLAT) + SCENE_TAIL
        f.write(scene_text.format(
            title=("Hertz, two equal elastic cylinders pressed together" if mirror
                   else "Hertz cylinder on a rigid flat"),
            more_parts=("\n  - {name: mirror, blocks: [mirror], material: m, plane: strain}"
                        if mirror else ""),
            nr=nr, mesh=os.path.basename(mesh), E=E, nu=NU,
            d=-2 * DELTA if mirror else 0.0 if force else -DELTA, alpha=alpha, steps=LOAD_STEPS,
            flat=flat))
    out = os.path.join(outdir, tag + "_out")
    start = time.time()
    p = subprocess.run([efg, "run", scene, "-o", out], capture_output=True, text=True)
    seconds = time.time() - start
    if p.returncode != 0:
        sys.exit("%s: efg exit %d: %s" % (tag, p.returncode, p.stderr.strip()[-400:]))
    newton = [l for l in p.stdout.splitlines() + p.stderr.splitlines() if "Newton iterations," in l]
    with netCDF4.Dataset(os.path.join(out, tag + ".e")) as d:
        names = [str(s) for s in netCDF4.chartostring(d.variables["name_nod_var"][:])]
        ux = np.asarray(d.variables["vals_nod_var%d" % (names.index("displacement_x") + 1)][-1])
        uy = np.asarray(d.variables["vals_nod_var%d" % (names.index("displacement_y") + 1)][-1])
    ux, uy = ux[:len(x)], uy[:len(x)]  # the first quarter's (a mirror's nodes follow)
    import csv
    last = list(csv.DictReader(open(os.path.join(out, "history.csv"))))[-1]
    contact = float(last["contact_touch_Fy" if mirror else "rb_flat_Fy"])
    P = 2.0 * abs(contact)
    # Equilibrium of the quarter: the cut's reaction carries the contact force, the symmetry
    # plane (u_x only) carries no vertical share and no horizontal force (frictionless).
    reaction_error = max(abs(float(last["R_top_y"]) - contact),
                         abs(float(last["R_sym_y"])), abs(float(last["R_sym_x"]))) / (P / 2)
    if mirror:  # and the mirror's cut holds it
        reaction_error = max(reaction_error, abs(float(last["R_bottom_y"]) + contact) / (P / 2))
    h = boundary_edge_sizes(x, y, conn)
    arc = sets["arc"] - 1
    if mirror:  # the gap to the mirror surface: twice the depth below the plane of symmetry
        gap = 2 * (y[arc] + uy[arc] + DELTA)
    else:  # the flat moves under force control
        gap = y[arc] + uy[arc] - float(last["rb_flat_uy"])
    touching = gap < 0
    xs = (x[arc] + ux[arc])[touching]
    pressure = (2 if mirror else 1) * alpha * E * (-gap[touching]) / h[arc][touching]
    # p^2 = p0^2 - (p0^2 / b^2) x^2 (the quarter model's contact particles; x >= 0)
    slope, intercept = np.polyfit(xs ** 2, pressure ** 2, 1) if len(xs) > 2 else (0.0, -1.0)
    fits = intercept > 0 and slope < 0  # an ellipse: too few contact particles may not give one
    p0 = math.sqrt(intercept) if fits else float("nan")
    b = math.sqrt(-intercept / slope) if fits else float("nan")
    e_star = E / (1 - NU * NU)
    b_exact = math.sqrt(4 * P * R / (math.pi * e_star))
    p0_exact = 2 * P / (math.pi * b_exact)
    if force:  # the flat balances the applied load
        reaction_error = max(reaction_error, abs(P - force) / force)
    return dict(nr=nr, particles=len(x), seconds=seconds, P=P, touching=int(touching.sum()),
                reaction_error=reaction_error,
                b=b, b_exact=b_exact, p0=p0, p0_exact=p0_exact,
                newton=newton[-1].split("done:")[-1].strip() if newton else "")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("efg")
    ap.add_argument("outdir")
    ap.add_argument("--radial", type=int, nargs="+", default=[20, 40, 80])
    ap.add_argument("--penalty", type=float, default=100.0)
    ap.add_argument("--grading", type=float, default=GRADING)
    ap.add_argument("--force", type=float, default=None)
    ap.add_argument("--mirror", action="store_true")
    a = ap.parse_args()
    os.makedirs(a.outdir, exist_ok=True)
    efg = os.path.abspath(a.efg)
    print("| cells across R | particles | efg time | P | contact particles | b | b Hertz | b err "
          "| p0 | p0 Hertz | p0 err | reactions vs contact | steps |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    rows = []
    for nr in a.radial:
        r = run_level(efg, a.outdir, nr, a.penalty, a.grading, a.force, a.mirror)
        r["eb"] = r["b"] / r["b_exact"] - 1
        r["ep"] = r["p0"] / r["p0_exact"] - 1
        rows.append(r)
        print("| %d | %d | %.1f s | %.4f | %d | %.5f | %.5f | %+.2f %% | %.3f | %.3f | %+.2f %% "
              "| %.1e | %s |"
              % (nr, r["particles"], r["seconds"], r["P"], r["touching"], r["b"], r["b_exact"],
                 100 * r["eb"], r["p0"], r["p0_exact"], 100 * r["ep"], r["reaction_error"],
                 r["newton"]), flush=True)
    fine, coarse = rows[-1], rows[0]
    failures = []
    if a.mirror:
        for r in rows:
            flat = run_level(efg, a.outdir, r["nr"], a.penalty, a.grading)
            worst = max(abs(r[k] / flat[k] - 1) for k in ("P", "b", "p0"))
            print("%d cells: two cylinders against one on the rigid flat: P %.6f / %.6f, b %.5f /"
                  " %.5f, p0 %.3f / %.3f (largest difference %.2g)"
                  % (r["nr"], r["P"], flat["P"], r["b"], flat["b"], r["p0"], flat["p0"], worst))
            if not worst <= TWIN_TOL:
                failures.append("%d: two cylinders differ from one on the rigid flat by %.2g"
                                % (r["nr"], worst))
    if not (a.mirror and fine["nr"] < 80) and not abs(fine["eb"]) <= TOL:
        failures.append("half-width off by %+.2f %% on the finest level" % (100 * fine["eb"]))
    if not (a.mirror and fine["nr"] < 80) and not abs(fine["ep"]) <= TOL:
        failures.append("peak pressure off by %+.2f %% on the finest level" % (100 * fine["ep"]))
    if len(rows) > 1 and not abs(fine["eb"]) < abs(coarse["eb"]):
        failures.append("the half-width error does not fall with refinement")
    if len(rows) > 1 and not abs(fine["ep"]) < abs(coarse["ep"]):
        failures.append("the peak pressure error does not fall with refinement")
    finish(failures, rows, "nr")


def finish(failures, rows, level):
    """Adds the reaction check of every level (row[level] names it), prints the failures and
    exits 1 when there are any (shared with ../hertz_sphere)."""
    for r in rows:
        if not r["reaction_error"] < 1e-8:
            failures.append("%d: reactions differ from the contact force by %.2g of it"
                            % (r[level], r["reaction_error"]))
    for f in failures:
        print("FAILED: " + f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
