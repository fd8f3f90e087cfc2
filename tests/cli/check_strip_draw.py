#!/usr/bin/env python3
"""U-channel-like strip draw with damping (input/strip_draw.yaml; issue 56, "quasi-static forming
has no damping"): the scene is run at its punch speed v and at v/2, each a damped explicit draw
followed by an implicit springback, and checked:
  - the end of forming is at rest: kinetic / internal energy at the forming stage's end <= 5 %
    (the run report's kinetic_to_internal_end), both speeds;
  - the springback angle theta1 (bottom wall to side wall, NUMISHEET'93's measure, lines fitted
    through the mid-surface) changes by <= 0.3 degrees when the punch speed halves (issue 56);
    theta2 (side wall to flange) likewise;
  - physical sanity from hand estimates (rigid-plastic plane-strain bending, the Swift law of the
    scene's steel, isotropic hardening):
      * the internal energy at the end of forming within 15 % of the plastic work of the formed
        section: the two wrapped corners bent once, the side wall bent and unbent over the die
        shoulder, W(kappa) = int over the thickness of int sigma d eps_eq (plane strain:
        sigma_x d eps_x = sigma_eq d eps_eq, eps_eq = 2 / sqrt(3) |z| kappa);
      * the drawing force dE_int / d(stroke) over the last third of the stroke (the side wall
        growing by the stroke, each millimetre bent and unbent over the die shoulder) within
        15 % of the bend-unbend work per unit length drawn (Swift 1948's energy argument for
        drawing over a radius; the damping's drag on the strip moving with the tools is reacted
        by the tools and does not enter it);
      * the tools' work = internal energy + kinetic energy + damping work within 1 % (columns of
        the history; the report's energy balance error below 1 %);
      * springback opens the channel: theta1 grows by between 0.5 and 2 times the elastic
        unbending of the punch corner from its fully plastic moment, M_p R_m (pi / 2) / (E' I)
        (the side wall's curl adds to it);
  - with --undamped (the contrast): the same pair with damping 0 must break a limit (the angle
    change above 0.3 degrees or K/I above 5 %): the test fails when it does not.
usage: check_strip_draw.py EFG OUTDIR [--undamped]   (exit 1 when a check fails)"""
import csv
import json
import math
import os
import subprocess
import sys
import time

import netCDF4
import numpy as np
import yaml

efg, out = sys.argv[1], sys.argv[2]
undamped = "--undamped" in sys.argv[3:]
scene = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "input",
                     "strip_draw.yaml")
doc = yaml.safe_load(open(scene))
P = doc["parameters"]
h, wp, rp, rd, c, stroke, v = (float(P[k]) for k in ("h", "wp", "rp", "rd", "c", "stroke", "v"))
E, nu, K, e0, n = (float(P[k]) for k in ("E", "nu", "K", "e0", "n"))
wd = wp + c
Ep = E / (1 - nu**2)
# the scene's damping, 2 omega_1 of the free blank (its comment says why), for the log
alpha_scene = 2 * 22.373 / (2 * float(P["Lh"])) ** 2 * math.sqrt(
    Ep * h**2 / 12 / (float(P["rho"]) * float(P["s"])))
failures = []


def check(ok, text):
    print(("ok    " if ok else "FAIL  ") + text)
    if not ok:
        failures.append(text)


def run(tag, speed, alpha=None):
    """The scene with the punch's mean speed (and damping) overridden, run in OUTDIR/tag."""
    variant = yaml.safe_load(open(scene))
    variant["parameters"]["v"] = speed
    if alpha is not None:
        variant["parameters"]["alpha"] = alpha
    folder = os.path.join(out, tag)
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, "strip_draw.yaml")
    with open(path, "w") as f:
        yaml.safe_dump(variant, f, sort_keys=False)
    start = time.time()
    r = subprocess.run([efg, "run", path, "-o", folder], capture_output=True, text=True)
    seconds = time.time() - start
    if r.returncode != 0:
        sys.exit("efg failed (%s, exit %d):\n%s" % (tag, r.returncode, (r.stdout + r.stderr)[-3000:]))
    report = json.load(open(os.path.join(folder, "strip_draw.e.report.json")))
    form = report["explicit_stages"][0]
    rows = [{k: float(x) for k, x in row.items()}
            for row in csv.DictReader(open(os.path.join(folder, "history.csv")))]
    T = stroke / speed + float(P["settle"])
    result = {"tag": tag, "seconds": seconds, "steps": form["steps"],
              "ki_end": form["kinetic_to_internal_end"], "ki_mean": form["kinetic_to_internal_mean"],
              "balance": form["worst_energy_balance_error"], "T": T}
    formed_rows = [row for row in rows if row["time"] <= T * (1 + 1e-9)]
    end = formed_rows[-1]
    result.update(E_int=end["internal_energy"], E_kin=end["kinetic_energy"],
                  W_tools=end["wall_work"], W_damp=end.get("mass_damping_work", 0.0))
    # drawing force from the energy: slope of E_int over the punch travel, last third of the stroke
    travel = np.array([-row["rb_punch_corner_uy"] for row in formed_rows])
    energy = np.array([row["internal_energy"] for row in formed_rows])
    window = (travel > 2 * stroke / 3) & (travel < stroke - 0.5) & (np.diff(np.r_[-1.0, travel]) > 1e-9)
    result["draw_force"] = np.polyfit(travel[window], energy[window], 1)[0] if window.sum() >= 4 else math.nan
    result["window"] = int(window.sum())
    tool_force = [row["rb_punch_corner_Fy"] + row["rb_punch_bottom_Fy"] + row["rb_punch_side_Fy"]
                  + row["rb_counter_pad_Fy"] for row in formed_rows if 2 * stroke / 3 < -row["rb_punch_corner_uy"] < stroke - 0.5]
    result["tool_force"] = float(np.mean(tool_force))
    result.update(angles(os.path.join(folder, "strip_draw.e"), T))
    damping = alpha_scene if alpha is None else alpha
    print(f"{tag}: v = {speed:g} mm/s, damping {damping:.1f} /s, {result['steps']} steps, "
          f"{seconds:.1f} s; K/I end {result['ki_end']:.3g}, mean {result['ki_mean']:.3g}; E_int "
          f"{result['E_int']:.1f}, tools' work {result['W_tools']:.1f}, damping work {result['W_damp']:.1f}; "
          f"dE_int/ds {result['draw_force']:.2f} ({result['window']} records), mean tool force "
          f"{result['tool_force']:.2f} (inertia and the damping's drag included); theta1 "
          f"{result['theta1_formed']:.3f} -> {result['theta1']:.3f}, theta2 {result['theta2_formed']:.3f} -> "
          f"{result['theta2']:.3f} deg")
    return result


def angles(exodus, T):
    """theta1, theta2 at the end of forming and after springback: the mid-surface (the mean of
    the bottom and top surface nodes at each x) split into the bottom wall (under the punch's flat),
    the side wall (between the two wrapped corners, 1.5 clear of each) and the flange (beyond the
    die shoulder), chosen in the formed state and followed as the same material points."""
    d = netCDF4.Dataset(exodus)
    names = ["".join(ch.decode() for ch in row if ch) for row in d["name_nod_var"][:].data]
    X, Y = np.asarray(d["coordx"][:]), np.asarray(d["coordy"][:])
    ux = np.asarray(d["vals_nod_var%d" % (names.index("displacement_x") + 1)][:])
    uy = np.asarray(d["vals_nod_var%d" % (names.index("displacement_y") + 1)][:])
    times = np.asarray(d["time_whole"][:])
    bottom = np.where(abs(Y) < 1e-9)[0]
    top = np.where(abs(Y - h) < 1e-9)[0]
    bottom, top = bottom[np.argsort(X[bottom])], top[np.argsort(X[top])]

    def mid(rec):
        return (0.5 * (X[bottom] + ux[rec, bottom] + X[top] + ux[rec, top]),
                0.5 * (Y[bottom] + uy[rec, bottom] + Y[top] + uy[rec, top]))

    def direction(x, y):
        p = np.c_[x, y] - np.c_[x, y].mean(0)
        return np.linalg.eigh(p.T @ p)[1][:, -1]

    formed = int(np.argmin(abs(times - T)))
    x, y = mid(formed)
    # (mid-surface heights: the bottom at -stroke + h/2, the die's top at +h/2)
    wall_of = {"bottom": x < wp - rp - 1.0,
               "side": (y > -stroke + h + rp + 1.5) & (y < -rd - 1.5),
               "flange": x > wd + rd + 1.0}
    result = {}
    for rec, suffix in ((formed, "_formed"), (len(times) - 1, "")):
        x, y = mid(rec)
        b, s, f = (direction(x[m], y[m]) for m in (wall_of["bottom"], wall_of["side"], wall_of["flange"]))
        b = b if b[0] < 0 else -b  # towards the symmetry plane
        s = s if s[1] > 0 else -s  # up the side wall
        f = f if f[0] > 0 else -f  # out along the flange
        result["theta1" + suffix] = math.degrees(math.acos(np.clip(b @ s, -1, 1)))
        result["theta2" + suffix] = math.degrees(math.acos(np.clip(-s @ f, -1, 1)))
    result["side_points"] = int(wall_of["side"].sum())
    return result


def plastic_work(R, passes):
    """Rigid-plastic work per unit length (per unit width) of bending the strip to the mid-surface
    radius R (passes = 1) or bending and unbending it (passes = 2): eps_eq accumulates
    passes x 2 / sqrt(3) |z| / R (isotropic hardening), W = int K (e0 + e)^n de."""
    z = np.linspace(0.0, h / 2, 4001)
    e = passes * 2 / math.sqrt(3) * z / R
    w = K / (n + 1) * ((e0 + e) ** (n + 1) - e0 ** (n + 1))
    return 2 * np.trapz(w, z)


# The formed section by hand: bottom flat, the punch corner wrapped (mid radius Rp), the side wall
# the common inner tangent of the two mid-surface circles, the die shoulder wrapped (Rd).
Rp, Rd = rp + h / 2, rd + h / 2
cp = np.array([wp - rp, h + rp - stroke])  # punch corner centre at the end of the stroke
cd = np.array([wd + rd, -rd])              # die shoulder centre
D = float(np.linalg.norm(cd - cp))
side_length = math.sqrt(D**2 - (Rp + Rd) ** 2)
wrap = math.atan2(cd[1] - cp[1], cd[0] - cp[0]) + math.asin((Rp + Rd) / D)  # side wall from horizontal
W_bu, W_p, W_d = plastic_work(Rd, 2), plastic_work(Rp, 1), plastic_work(Rd, 1)
E_hand = W_p * Rp * wrap + W_d * Rd * wrap + W_bu * side_length
z = np.linspace(0.0, h / 2, 4001)
M_p = 2 * np.trapz(2 / math.sqrt(3) * K * (e0 + 2 / math.sqrt(3) * z / Rp) ** n * z, z)
springback_hand = math.degrees(M_p / (Ep * h**3 / 12) * Rp * math.pi / 2)
print(f"hand: side wall {side_length:.3f} long at {math.degrees(wrap):.2f} deg; bend work "
      f"{W_p:.2f} (punch), {W_d:.2f} (die), bend-unbend {W_bu:.2f} per mm; formed section {E_hand:.1f}; "
      f"punch corner M_p {M_p:.2f}, elastic unbending {springback_hand:.3f} deg")

fast = run("undamped_v" if undamped else "v", v, 0.0 if undamped else None)
slow = run("undamped_v2" if undamped else "v2", v / 2, 0.0 if undamped else None)
change1 = abs(fast["theta1"] - slow["theta1"])
change2 = abs(fast["theta2"] - slow["theta2"])
worst_ki = max(fast["ki_end"], slow["ki_end"])
if undamped:
    # The contrast: without damping the draw must break one of the limits the damped draw meets.
    check(change1 > 0.3 or change2 > 0.3 or worst_ki > 0.05,
          f"undamped: a limit broken: theta1 changes by {change1:.3f} deg, theta2 by {change2:.3f} "
          f"deg (limit 0.3), K/I at the end {worst_ki:.3g} (limit 0.05)")
    sys.exit(1 if failures else 0)
for r in (fast, slow):
    tag = r["tag"]
    check(r["ki_end"] <= 0.05, f"{tag}: kinetic / internal energy at the end of forming {r['ki_end']:.3g} <= 0.05")
    check(abs(r["E_int"] / E_hand - 1) <= 0.15,
          f"{tag}: internal energy {r['E_int']:.1f} vs formed section by hand {E_hand:.1f} "
          f"({100 * (r['E_int'] / E_hand - 1):+.1f} %)")
    check(abs(r["draw_force"] / W_bu - 1) <= 0.15,
          f"{tag}: drawing force dE_int/ds {r['draw_force']:.2f} vs bend-unbend work {W_bu:.2f} "
          f"({100 * (r['draw_force'] / W_bu - 1):+.1f} %)")
    books = r["E_int"] + r["E_kin"] + r["W_damp"]
    check(abs(r["W_tools"] - books) <= 0.01 * r["W_tools"] and r["balance"] < 0.01,
          f"{tag}: tools' work {r['W_tools']:.2f} = E_int + E_kin + damping work {books:.2f} "
          f"(worst balance error {r['balance']:.2g})")
    opened = r["theta1"] - r["theta1_formed"]
    check(0.5 * springback_hand <= opened <= 2 * springback_hand,
          f"{tag}: springback opens theta1 by {opened:.3f} deg (punch corner's elastic unbending "
          f"{springback_hand:.3f}; 0.5x to 2x)")
check(change1 <= 0.3, f"theta1 after springback {fast['theta1']:.3f} (v) vs {slow['theta1']:.3f} (v/2): "
      f"changes by {change1:.3f} deg <= 0.3")
check(change2 <= 0.3, f"theta2 after springback {fast['theta2']:.3f} (v) vs {slow['theta2']:.3f} (v/2): "
      f"changes by {change2:.3f} deg <= 0.3")
sys.exit(1 if failures else 0)
