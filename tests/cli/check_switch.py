#!/usr/bin/env python3
"""Stage switch (tests/scenes/switch_nitsche.yaml, switch_transformation.yaml): over the explicit stage the
kinetic energy stays below 1e-8 of the strain energy (the implicit solution is an equilibrium of
the same discrete forces), the tip deflection does not move (1e-9 relative), and the final
implicit stage ends where the first did.
usage: check_switch.py history.csv"""
import csv
import sys

rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(sys.argv[1]))]
static = next(r for r in rows if abs(r["time"] - 1.0) < 1e-12)
dynamic = [r for r in rows if 1.0 < r["time"] < 2.0]  # the explicit stage, between t = 1 and 2
final = rows[-1]
ratio = max(r["kinetic_energy"] / static["strain_energy"] for r in dynamic)
drift = max(abs(r["u_xmax_z"] - static["u_xmax_z"]) for r in dynamic + [final]) / abs(static["u_xmax_z"])
print(f"strain energy {static['strain_energy']:.6g}, tip u_z {static['u_xmax_z']:.9g}; "
      f"explicit records {len(dynamic)}: kinetic / strain energy up to {ratio:.3e}, "
      f"tip drift {drift:.3e} (final implicit stage included)")
ok = len(dynamic) >= 5 and static["strain_energy"] > 0 and ratio < 1e-8 and drift < 1e-9
sys.exit(0 if ok else 1)
