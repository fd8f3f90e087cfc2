#!/usr/bin/env python3
"""Uniform mass scaling of an explicit stage (issue 21, item 4; stage key mass_scale): the bar of
tests/scenes/impact/small_strain_impact_v1.yaml (rho A v0^2 / 2 = 0.0125 of kinetic energy at
t = 0) run with mass_scale 1 and 4. Exact consequences of scaling M by s: the initial kinetic
energy is s times (1e-12) and the stable time step sqrt(s) times (omega^2 of M^-1 K scales by
1/s; within 1e-5, the estimate adding its own residual bound: measured 3.7e-6).
usage: check_mass_scale.py EFG OUTDIR   (exit 1 when a check fails)"""
import csv
import os
import re
import subprocess
import sys

import yaml

efg, out = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(__file__))
base = yaml.safe_load(open(os.path.join(here, "..", "scenes", "impact", "small_strain_impact_v1.yaml")))
failures = []


def check(ok, text):
    print(("ok    " if ok else "FAIL  ") + text)
    if not ok:
        failures.append(text)


def run(scale):
    scene = dict(base)
    scene["stages"] = [{"name": "impact", "driver": "explicit", "end_time": 0.002,
                        "output_interval": 0.001, "mass_scale": scale}]
    scene["output"] = {"history": "history.csv"}
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, "scale%g.yaml" % scale)
    yaml.safe_dump(scene, open(path, "w"), sort_keys=False)
    r = subprocess.run([efg, "run", path, "-o", os.path.join(out, "scale%g" % scale)],
                       capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("efg failed (exit %d):\n%s" % (r.returncode, (r.stdout + r.stderr)[-3000:]))
    dt = float(re.search(r"stable time step ([0-9.eE+-]+)", r.stdout).group(1))
    rows = [{k: float(v) for k, v in row.items()}
            for row in csv.DictReader(open(os.path.join(out, "scale%g" % scale, "history.csv")))]
    return dt, rows[0]["kinetic_energy"], r.stdout


dt1, ke1, _ = run(1)
dt4, ke4, log = run(4)
check(abs(ke1 - 0.0125) < 1e-12 and abs(ke4 - 4 * 0.0125) < 1e-12,
      f"initial kinetic energy {ke1:.12g} and {ke4:.12g} (rho A v0^2 / 2 = 0.0125, x 4)")
check(abs(dt4 / dt1 - 2) < 1e-5, f"stable time step {dt1:.8g} -> {dt4:.8g} (ratio {dt4 / dt1:.8f}, "
      "expected 2)")
check("masses scaled by 4" in log, "the log says the masses are scaled")
sys.exit(1 if failures else 0)
