#!/usr/bin/env python3
"""Explicit -> implicit -> explicit at equilibrium (tests/scenes/switch_explicit_implicit_explicit
.yaml): over the third stage the energy balance error stays below 1e-3 and the kinetic energy
below 1e-8 of the strain energy the implicit stage left (an equilibrium of the same discrete
forces: nothing may move and no energy may appear or vanish).
usage: check_switch_back.py history.csv"""
import csv
import sys

rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(sys.argv[1]))]
static = next(r for r in rows if abs(r["time"] - 1.0) < 1e-12)
held = [r for r in rows if r["time"] > 1.0]
balance = max(r["energy_balance_error"] for r in held)
ratio = max(r["kinetic_energy"] / static["strain_energy"] for r in held)
print(f"strain energy {static['strain_energy']:.6g}; third stage: {len(held)} records, energy "
      f"balance error up to {balance:.3e}, kinetic / strain energy up to {ratio:.3e}")
ok = len(held) >= 5 and static["strain_energy"] > 0 and balance < 1e-3 and ratio < 1e-8
sys.exit(0 if ok else 1)
