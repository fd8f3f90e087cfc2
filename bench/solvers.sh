#!/usr/bin/env bash
# Implicit solve time, today's default solver against the previous default (GMRES + Ifpack2
# ILU(2)), side by side in one run: the Timoshenko beam at 8,514 dofs and the cantilever block
# at about 10,000 and 75,000 particles (docs/implicit.md). Prints, per model and solver, the
# Newton phase (linear solver setup + Krylov + assembly inside Newton), the setup share, the
# linear iterations and the ratio previous / default. Runs longer than EFG_BENCH_TIMEOUT seconds
# (default 600) are stopped and shown as "> limit". Not part of the test suite.
#   bench/solvers.sh [--quick]     --quick: the beam and the 10k block only
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh" >/dev/null
efg="${EFG_BUILD_DIR:-$here/build}/efg"
limit="${EFG_BENCH_TIMEOUT:-600}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
quick=0
if [ "${1:-}" = "--quick" ]; then quick=1; fi

# scene FILE NAME CELLS STAGE_EXTRA: a copy of an input scene with other cells and stage keys.
scene() {
  /usr/bin/python3 - "$1" "$2" "$3" "$4" <<'PY'
import re, sys
src, out, cells, extra = sys.argv[1:5]
s = open(src).read()
s = re.sub(r"cells: \[[^\]]*\]", "cells: [%s]" % cells, s, count=1)
s = re.sub(r"(driver: implicit)", r"\1" + extra, s, count=1)
open(out, "w").write(s)
PY
}

run() {  # run NAME SCENE -> prints one row
  local name="$1" file="$2" out="$work/out_$1"
  if timeout "$limit" "$efg" run "$file" -o "$out" >"$work/$name.log" 2>&1; then
    /usr/bin/python3 - "$out"/*.report.json "$name" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
st = r["implicit_stages"][0]
newton = r["phase_seconds"]["Newton iterations"]
print("| %s | %d | %s | %.2f | %.2f | %d |" % (sys.argv[2], r["dofs"], st["linear_solver"].split(" (")[0],
      newton, st["linear_setup_seconds"], st["linear_iterations"]))
PY
  else
    echo "| $name | | (stopped or failed) | > $limit | | |"
  fi
}

echo "| model, solver | dofs | linear solver | Newton phase s | setup s | linear its |"
echo "|---|---|---|---|---|---|"
scene "$here/input/timoshenko_beam.yaml" "$work/beam.yaml" "128, 32" ""
scene "$here/input/timoshenko_beam.yaml" "$work/beam_old.yaml" "128, 32" ", preconditioner: {Type: Ifpack2}"
run "beam 8514 dofs, default" "$work/beam.yaml"
run "beam 8514 dofs, previous" "$work/beam_old.yaml"
models=("45, 14, 14")                 # 46 x 15 x 15 = 10,350 particles
if [ $quick -eq 0 ]; then models+=("100, 26, 26"); fi  # 101 x 27 x 27 = 73,629 particles
for cells in "${models[@]}"; do
  tag="block ${cells// /}"
  scene "$here/input/block.yaml" "$work/block.yaml" "$cells" ""
  scene "$here/input/block.yaml" "$work/block_old.yaml" "$cells" "
    preconditioner: {Type: Ifpack2}"
  run "$tag, default" "$work/block.yaml"
  run "$tag, previous" "$work/block_old.yaml"
done
