#!/usr/bin/env python3
"""The benchmarks' 3D block (bench/scale.sh, bench/output.sh): input/block_explicit.yaml with
NX x NY x NY hex8 cells of edge h = 10 / NX (NY = 35 % of NX, the block 10 x NY h x NY h), box
supports of dilation 1.2.

  block_scene.py OUT NX explicit [RECORDS]   100 explicit steps (dt is about 1.79e-7 h here, 0.9
                                              of the stable step); RECORDS records after the
                                              first (default: none but the last)
  block_scene.py OUT NX implicit              one implicit step, clamped by displacement
"""
import os
import sys

here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
out, nx, driver = sys.argv[1], int(sys.argv[2]), sys.argv[3]
records = int(sys.argv[4]) if len(sys.argv) > 4 else 0
s = open(here + "/input/block_explicit.yaml").read()
ny = max(1, round(nx * 0.35))
h = 10.0 / nx
s = s.replace("upper: [10, 2, 2], cells: [20, 4, 4]",
              "upper: [10, %g, %g], cells: [%d, %d, %d]" % (ny * h, ny * h, nx, ny, ny))
s = s.replace("dilation: 1.5", "dilation: 1.2")
if driver == "explicit":
    end = 100 * 1.79e-7 * h
    s = s.replace("end_time: 2.0e-4, output_interval: 1.0e-5",
                  "end_time: %g, output_interval: %s" % (end, "%g" % (end / records) if records else "1.0"))
else:
    s = s.replace("driver: explicit, end_time: 2.0e-4, output_interval: 1.0e-5",
                  "driver: implicit, end_time: 1.0")
    s = s.replace("type: velocity", "type: displacement")
open(out, "w").write(s)
