#!/usr/bin/env python3
"""Segment angles in the run report (tests/scenes/angles/pulled_square.yaml; issue 21): a square
pulled to eps_xx = 0.01 in plane strain (homogeneous, sigma_yy = 0, so eps_yy = -nu/(1 - nu)
eps_xx) and released. The diagonal from probe a (0.25, 0.25) to b (0.75, 0.75) is at
atan((1 + eps_yy) / (1 + eps_xx)) after the pull (hand computation: 44.5919173 degrees) and at 45
after the release; the reversed segment 180 degrees below. Checked to 1e-6 degrees.
usage: check_angles.py history.csv      (the report is read from the same folder)"""
import glob
import json
import math
import os
import sys

folder = os.path.dirname(os.path.abspath(sys.argv[1]))
report = json.load(open(glob.glob(os.path.join(folder, "*.report.json"))[0]))
angles = report["angles_by_stage"]
EPS, NU = 0.01, 0.3
pulled = math.degrees(math.atan2(1 - NU / (1 - NU) * EPS, 1 + EPS))
expected = {"pull": {"diagonal": pulled, "reversed": pulled - 180},
            "release": {"diagonal": 45.0, "reversed": -135.0}}
worst = 0.0
for stage, values in expected.items():
    for name, value in values.items():
        got = angles[stage][name]
        print(f"stage {stage}, angle {name}: {got:.9f} degrees, expected {value:.9f}")
        worst = max(worst, abs(got - value))
print(f"largest departure {worst:.2e} degrees")
sys.exit(0 if worst < 1e-6 and list(angles) == ["pull", "release"] else 1)
