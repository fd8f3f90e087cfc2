#!/usr/bin/env bash
# Memory and setup at scale (issue 20): the explicit 3D cantilever block of input/block_explicit.yaml
# (hex8 cells of aspect 1, box supports of dilation 1.2, SCNI, linear elastic steel) at about
# 1e4, 1e5 and 1e6 particles, 100 explicit steps each, and the same block with an implicit stage
# (the stiffness matrix and its preconditioner) at 1e4 and 1e5 (the 1e5 one came back with the
# Gauss-Seidel smoother of the 31st session: with ILU(0) its multigrid ran 500 GMRES iterations
# per Newton iteration, over 20 min). Prints, per run, the bytes per
# particle the run keeps (the log's memory account, all phases) and its high-water mark, the
# setup time (scene, partition, search, shape functions and integration points) and the time
# per explicit step, and setup in explicit steps (issue 20's target: 3), each size also with
# `smoothing_quadrature: split` (4 triangles per SCNI facet: the default before the 34th session;
# the default in 3D is now one point per flat facet). Runs longer than
# EFG_BENCH_TIMEOUT seconds (default 1200) are stopped. Not part of the test suite.
#   bench/scale.sh [--max-particles N]     default 1100000 (the 1e6 run needs about 6 GB, 4 min)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh" >/dev/null
efg="${EFG_BUILD_DIR:-$here/build}/efg"
limit="${EFG_BENCH_TIMEOUT:-1200}"
max=1100000
if [ "${1:-}" = "--max-particles" ]; then max="$2"; fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# scene OUT NX DRIVER: the block with NX x 0.35 NX x 0.35 NX cells (bench/block_scene.py).
scene() { /usr/bin/python3 "$here/bench/block_scene.py" "$1" "$2" "$3"; }

row() {  # row NAME SCENE
  local out="$work/out"
  rm -rf "$out"
  if timeout "$limit" "$efg" run "$2" -o "$out" >"$work/log" 2>&1; then
    /usr/bin/python3 - "$out"/*.report.json "$1" "$work/log" <<'PY'
import json, re, sys
r = json.load(open(sys.argv[1]))
ph = r["phase_seconds"]
one = lambda v: max(v) if isinstance(v, list) else v
setup = sum(one(ph.get(k, 0)) for k in ("scene and mesh", "partition (Zoltan2 RCB)",
            "neighbour search (ghosts, particles)", "shape functions and integration"))
n = r["particles"]
kept = sum(p["bytes"] for p in r["memory_by_phase"]) / n
peak = r["memory_high_water_bytes"] / n
log = open(sys.argv[3]).read()
m = re.search(r"stage '[^']*' done: (\d+) steps", log)
steps = int(m.group(1)) if m and "explicit time steps" in ph else 0
step_s = one(ph.get("explicit time steps", 0)) / steps if steps else 0
ratio = "%.0f" % (setup / step_s) if step_s else ""
print("| %s | %d | %.0f | %.0f | %.1f | %s | %s | %s |" % (
    sys.argv[2], n, kept, peak, setup, steps or "", "%.3f" % step_s if step_s else "", ratio))
PY
  else
    echo "| $1 | | (stopped or failed) | | > $limit | | | |"
  fi
}

echo "| run | particles | kept B/particle | peak B/particle | setup s | steps | s/step | setup in steps |"
echo "|---|---|---|---|---|---|---|---|"
for nx in 43 95 200; do  # about 1.1e4, 1.1e5, 1.0e6 particles
  particles=$(( (nx + 1) * ( $(/usr/bin/python3 -c "print(max(1, round($nx * 0.35)))") + 1 ) ** 2 ))
  if [ "$particles" -gt "$max" ]; then continue; fi
  scene "$work/explicit.yaml" "$nx" explicit
  row "explicit, 100 steps" "$work/explicit.yaml"
  # The same with the split rule on the SCNI facets inside the cells (4 points per facet).
  sed 's/dilation: 1.2}/dilation: 1.2, smoothing_quadrature: split}/' "$work/explicit.yaml" \
    >"$work/split.yaml"
  row "explicit, split facets" "$work/split.yaml"
  if [ "$nx" -le 95 ]; then  # the implicit stage at 1e4 and 1e5 particles
    scene "$work/implicit.yaml" "$nx" implicit
    row "implicit (matrix + preconditioner)" "$work/implicit.yaml"
  fi
done
