#!/usr/bin/env python3
"""The Scordelis-Lo roof (tests/scenes/shells/scordelis_lo.yaml) on 8, 12, 16 and 24 cells per
side: the vertical displacement at the middle of the free edge, scaled back from the load factor
1e-4, against 0.3024 (MacNeal & Harder 1985; benchmarks.md section 8). Checked: within 2 % on
16 x 16 and 1 % on 24 x 24, the error falling from 12 to 16 to 24; the table of error and run
time per level is printed (docs/verification.md).
usage: check_shell_scordelis.py L8.e L12.e L16.e L24.e (their .report.json beside them)
"""
import json
import sys

reference, factor = 0.3024, 1e-4


def main():
    errors, rows = [], []
    for cells, path in zip((8, 12, 16, 24), sys.argv[1:5]):
        report = json.load(open(path + ".report.json"))
        w = -report["probes"]["probe_free_edge_uz"] / factor
        seconds = report["seconds"]
        rows.append((cells, w, w / reference - 1, seconds))
        print("%2d x %2d: w = %.5f, error %+.2f %%, run %.2f s"
              % (cells, cells, w, 100 * (w / reference - 1), seconds))
    err = {cells: abs(e) for cells, _, e, _ in rows}
    if err[16] > 0.02:
        errors.append("16 x 16 misses the reference by %.2f %%" % (100 * err[16]))
    if err[24] > 0.01:
        errors.append("24 x 24 misses the reference by %.2f %%" % (100 * err[24]))
    if not err[12] > err[16] > err[24]:
        errors.append("the error does not fall from 12 to 16 to 24 cells")
    for e in errors:
        print("FAIL: " + e)
    sys.exit(1 if errors else 0)


if __name__ == "__main__":
    main()
