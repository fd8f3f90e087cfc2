#!/usr/bin/env bash
# Implicit solve time, today's default solver against the previous defaults, side by side in one
# run (docs/implicit.md): the Timoshenko beam at 8,514 dofs (default MUMPS, the previous direct
# default UMFPACK, the first default GMRES + Ifpack2 ILU(2)), at 33,410 and 132,354 dofs on 1 and
# 2 ranks (MUMPS; UMFPACK on 1; with SCNI subcells multigrid and MUMPS on 1 and 2), the
# cantilever block at about 10,000 and 75,000 particles (multigrid with the Gauss-Seidel smoother
# against ILU(0), 1 and 2 ranks), and the block with SCNI subcells at 30,927 dofs (auxiliary space against multigrid on the Jacobian).
# Prints, per model and solver, the Newton phase (linear solver setup + Krylov + assembly inside
# Newton), the setup share and the linear iterations. Runs longer than EFG_BENCH_TIMEOUT seconds
# (default 600) are stopped and shown as "> limit". Not part of the test suite.
#   bench/solvers.sh [--quick]     --quick: the 8,514- and 33,410-dof beams and the 10k block
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

run() {  # run NAME SCENE [RANKS] -> prints one row
  local name="$1" file="$2" ranks="${3:-1}" out="$work/out_${1// /_}"
  local launch=()
  if [ "$ranks" -gt 1 ]; then
    launch=(mpirun -np "$ranks")
    if [ "$(id -u)" -eq 0 ]; then launch+=(--allow-run-as-root); fi
  fi
  if timeout "$limit" "${launch[@]}" "$efg" run "$file" -o "$out" >"$work/$name.log" 2>&1; then
    /usr/bin/python3 - "$out"/*.report.json "$name" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
st = r["implicit_stages"][0]
newton = r["phase_seconds"]["Newton iterations"]
newton = max(newton) if isinstance(newton, list) else newton
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
scene "$here/input/timoshenko_beam.yaml" "$work/beam_umf.yaml" "128, 32" ", preconditioner: {Type: direct, solver: UMFPACK}"
scene "$here/input/timoshenko_beam.yaml" "$work/beam_old.yaml" "128, 32" ", preconditioner: {Type: Ifpack2}"
run "beam 8514 dofs, default" "$work/beam.yaml"
run "beam 8514 dofs, UMFPACK" "$work/beam_umf.yaml"
run "beam 8514 dofs, ILU(2)" "$work/beam_old.yaml"
beams=("256, 64")                     # 33,410 dofs
if [ $quick -eq 0 ]; then beams+=("512, 128"); fi  # 132,354 dofs
for cells in "${beams[@]}"; do
  tag="beam ${cells// /}"
  scene "$here/input/timoshenko_beam.yaml" "$work/beam.yaml" "$cells" ", solver: direct"
  scene "$here/input/timoshenko_beam.yaml" "$work/beam_umf.yaml" "$cells" ", preconditioner: {Type: direct, solver: UMFPACK}"
  run "$tag, default" "$work/beam.yaml"
  run "$tag, default, 2 ranks" "$work/beam.yaml" 2
  run "$tag, UMFPACK" "$work/beam_umf.yaml"
  # The iterative path on the same beam with SCNI subcells (multigrid on the Jacobian, its coarse
  # levels gathered onto fewer ranks): issue 12's two-rank speedup, side by side with MUMPS.
  scene "$here/input/timoshenko_beam.yaml" "$work/beam_mg.yaml" "$cells" ", solver: iterative"
  sed -i 's/integration: scni/integration: scni_subcells/' "$work/beam_mg.yaml"
  scene "$here/input/timoshenko_beam.yaml" "$work/beam_sub.yaml" "$cells" ", solver: direct"
  sed -i 's/integration: scni/integration: scni_subcells/' "$work/beam_sub.yaml"
  run "$tag subcells, multigrid" "$work/beam_mg.yaml"
  run "$tag subcells, multigrid, 2 ranks" "$work/beam_mg.yaml" 2
  run "$tag subcells, MUMPS" "$work/beam_sub.yaml"
  run "$tag subcells, MUMPS, 2 ranks" "$work/beam_sub.yaml" 2
done
models=("45, 14, 14")                 # 46 x 15 x 15 = 10,350 particles
if [ $quick -eq 0 ]; then models+=("100, 26, 26"); fi  # 101 x 27 x 27 = 73,629 particles
for cells in "${models[@]}"; do
  tag="block ${cells// /}"
  scene "$here/input/block.yaml" "$work/block.yaml" "$cells" ""
  scene "$here/input/block.yaml" "$work/block_old.yaml" "$cells" "
    preconditioner: {Type: Ifpack2}"
  # The multigrid's smoother: symmetric Gauss-Seidel (default in 3D) against ILU(0) (the
  # default before the 31st session), 1 and 2 ranks.
  scene "$here/input/block.yaml" "$work/block_ilu.yaml" "$cells" "
    preconditioner: {Type: MueLu, \"smoother: type\": RILUK, \"smoother: params\": {\"fact: iluk level-of-fill\": 0}}"
  run "$tag, default" "$work/block.yaml"
  run "$tag, default, 2 ranks" "$work/block.yaml" 2
  run "$tag, ILU(0) smoother" "$work/block_ilu.yaml"
  run "$tag, ILU(0) smoother, 2 ranks" "$work/block_ilu.yaml" 2
  run "$tag, previous" "$work/block_old.yaml"
done
# The auxiliary space (docs/implicit.md): the block with SCNI subcells above the direct limit,
# the default (multigrid on the background cells' finite elements) against multigrid on the
# Jacobian, side by side.
subcells() {  # subcells FILE CELLS STAGE_EXTRA
  scene "$here/input/block.yaml" "$1" "$2" "$3"
  sed -i 's/integration: scni/integration: scni_subcells/' "$1"
}
subcells "$work/aux.yaml" "60, 12, 12" ""
subcells "$work/aux_jacobian.yaml" "60, 12, 12" "
    preconditioner: {Type: MueLu}"
run "block 60x12x12 subcells, default (auxiliary space)" "$work/aux.yaml"
run "block 60x12x12 subcells, multigrid on the Jacobian" "$work/aux_jacobian.yaml"
