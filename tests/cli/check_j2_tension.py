#!/usr/bin/env python3
"""J2 uniaxial tension (tests/scenes/plasticity/j2_tension.yaml): every record's stress_xx and
plastic_strain at every particle against the closed form of uniaxial stress with linear
isotropic hardening (Simo & Hughes, Computational Inelasticity, 1998, sec. 1.4):
  eps <= sigma_y / E:  sigma = E eps,  eps_p = 0
  beyond:              sigma = sigma_y + E H / (E + H) (eps - sigma_y / E),  eps_p = eps - sigma / E
with eps = 0.01 c(t), c rising linearly to 1 at t = 0.5 and falling to 0.8 at t = 1; the fall is
elastic from the peak: sigma = sigma_peak - E (eps_peak - eps), eps_p = eps_p,peak (the history
must have been carried from step to step for this to hold). The supports are the default
transformation method, whose boundary terms carry their own plastic history: the homogeneous
state is exact, so the tolerance is round-off (1e-8 relative; measured 2e-11, finite strain 3e-9).
With --finite (tests/scenes/plasticity/j2_tension_finite.yaml): the same law in the logarithmic
strain eps = ln(1 + 0.5 c(t)) for the Kirchhoff stress tau (Simo 1992: the exponential return of
the Hencky law is the small-strain return in principal log strains); the output Cauchy stress is
tau / J with J = exp((1 - 2 nu) tau / E) (elastic volume change only).
With --nu X the scene's Poisson's ratio is X instead of 0.3 (finite strain: J depends on it);
--tolerance T replaces 1e-8 (round-off grows with kappa / mu: the mixed u-p block at nu = 0.4999,
tests/scenes/plasticity/j2_tension_mixed.yaml, measured 3.7e-8).
usage: check_j2_tension.py [--finite] [--nu X] [--tolerance T] RESULTS.e [OTHER_RANKS.e]
       (second file: equal to 1e-9 of the scale)
"""
import math
import sys

import netCDF4
import numpy as np

E, NU, H, SIGMA_Y = 200000.0, 0.3, 2000.0, 250.0
FINITE = "--finite" in sys.argv
ARGS = [a for a in sys.argv[1:] if a != "--finite"]
TOLERANCE = 1e-8
for flag in ("--nu", "--tolerance"):
    if flag in ARGS:
        at = ARGS.index(flag)
        if flag == "--nu":
            NU = float(ARGS[at + 1])
        else:
            TOLERANCE = float(ARGS[at + 1])
        del ARGS[at:at + 2]
PULL = 0.5 if FINITE else 0.01
STRAIN = math.log(1 + PULL) if FINITE else PULL
C_END = 0.988 if FINITE else 0.8  # the curve's last value (elastic unloading)


def fields(path):
    d = netCDF4.Dataset(path)
    names = [b"".join(c for c in row if c).decode() for row in d["name_nod_var"][:]]
    t = np.array(d["time_whole"][:])
    get = lambda n: np.array(d["vals_nod_var%d" % (names.index(n) + 1)][:])
    return t, get("stress_xx"), get("plastic_strain")


def strain(c):  # the strain measure at curve value c
    return math.log(1 + PULL * c) if FINITE else PULL * c


t, sxx, ep = fields(ARGS[0])
worst_s = worst_p = 0.0
def loading(eps):
    if E * eps <= SIGMA_Y:
        return E * eps, 0.0
    sigma = SIGMA_Y + E * H / (E + H) * (eps - SIGMA_Y / E)
    return sigma, eps - sigma / E


for k, time in enumerate(t):
    c = 2 * time if time <= 0.5 else 1 - (1 - C_END) * (time - 0.5) / 0.5
    if time <= 0.5:
        sigma, plastic = loading(strain(c))
    else:
        peak, plastic = loading(STRAIN)
        sigma = peak - E * (STRAIN - strain(c))
    if FINITE:
        sigma /= math.exp((1 - 2 * NU) * sigma / E)
    worst_s = max(worst_s, np.abs(sxx[k] - sigma).max() / SIGMA_Y)
    worst_p = max(worst_p, np.abs(ep[k] - plastic).max() / (STRAIN - SIGMA_Y / E))
print("records %d: largest stress error %.3g of sigma_y, plastic strain error %.3g of the final"
      % (len(t), worst_s, worst_p))
ok = len(t) == 9 and worst_s < TOLERANCE and worst_p < TOLERANCE
if len(ARGS) > 1:
    t2, sxx2, ep2 = fields(ARGS[1])
    diff = max(np.abs(sxx2 - sxx).max() / SIGMA_Y, np.abs(ep2 - ep).max() / STRAIN)
    print("1 vs 2 ranks: %.3g" % diff)
    ok = ok and diff < 1e-9
sys.exit(0 if ok else 1)
