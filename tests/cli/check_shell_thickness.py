#!/usr/bin/env python3
"""The thickness output of shells (tests/scenes/shells/strip_j2_thinning.yaml): at every particle
the thickness at t = 1 (elastic) is t0 (1 - nu sigma / E) and at t = 2 (plastic) t0 (1 - nu sigma /
E - alpha / 2), alpha = (sigma - sigma_y) / H, hand values of uniaxial plane stress; checked to
1e-9 of t0, the plastic strain to 1e-6 of alpha, and the stress xx at the top, middle and
bottom equal to sigma = N / t to 1e-8 (yy and xy to 1e-8 of sigma).
usage: check_shell_thickness.py RESULTS.e
"""
import sys

import netCDF4
import numpy as np

T0, E, NU, SY, H = 0.01, 1000.0, 0.3, 1.0, 100.0


def main():
    f = netCDF4.Dataset(sys.argv[1])
    names = [netCDF4.chartostring(n) for n in f.variables["name_nod_var"][:]]
    field = lambda name: np.asarray(f.variables["vals_nod_var%d" % (names.index(name) + 1)][:])  # noqa: E731
    times = list(np.asarray(f.variables["time_whole"][:]))
    thickness, plastic = field("thickness"), field("plastic_strain")
    errors = []
    for time, sigma in ((1.0, 0.5), (2.0, 1.2)):
        k = times.index(time)
        alpha = max(0.0, (sigma - SY) / H)
        expected = T0 * (1 - NU * sigma / E - alpha / 2)
        off = np.abs(thickness[k] - expected).max() / T0
        print("t = %g: thickness %.10g .. %.10g, expected %.10g (largest difference %.1e t0); "
              "plastic strain %.6g, expected %.6g"
              % (time, thickness[k].min(), thickness[k].max(), expected, off, plastic[k].max(),
                 alpha))
        if off > 1e-9:
            errors.append("t = %g: the thickness is off by %.1e t0" % (time, off))
        if np.abs(plastic[k] - alpha).max() > 1e-6 * max(alpha, 1e-3):
            errors.append("t = %g: the plastic strain is not %g" % (time, alpha))
        for side in ("top", "middle", "bottom"):
            s = {c: field("stress_%s_%s" % (side, c))[k] for c in ("xx", "yy", "xy")}
            worst = max(np.abs(s["xx"] - sigma).max(), np.abs(s["yy"]).max(),
                        np.abs(s["xy"]).max()) / sigma
            print("        stress_%s: xx %.10g .. %.10g (largest difference %.1e sigma)"
                  % (side, s["xx"].min(), s["xx"].max(), worst))
            if worst > 1e-8:
                errors.append("t = %g: stress_%s is off by %.1e sigma" % (time, side, worst))
    for e in errors:
        print("FAIL: " + e)
    sys.exit(1 if errors else 0)


if __name__ == "__main__":
    main()
