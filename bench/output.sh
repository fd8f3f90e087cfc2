#!/usr/bin/env bash
# Results output on 2 ranks, gathered onto rank 0 against one file per rank (output.files:
# per_rank, docs/scaling.md), side by side in one run: the explicit 3D block of
# input/block_explicit.yaml at 100 x 35 x 35 cells (130,896 particles, dilation 1.2), 100 steps,
# 21 records of displacement, velocity, stress and von Mises stress, each setting twice,
# alternating. Prints the output phase (the slower rank's), the whole run and each rank's memory
# high-water mark, and the per-rank files' join by SEACAS epu (scripts/build_exodiff.sh builds it).
#   bench/output.sh [NX]     NX cells along the block (default 100; 35 % of it across)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh" >/dev/null
efg="${EFG_BUILD_DIR:-$here/build}/efg"
epu="${EFG_CACHE:-/var/cache/efg}/seacas/bin/epu"
nx="${1:-100}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
launch=(mpirun -np 2)
if [ "$(id -u)" -eq 0 ]; then launch+=(--allow-run-as-root); fi

# the block of bench/block_scene.py, 100 steps, 20 records after the first, with stresses
/usr/bin/python3 "$here/bench/block_scene.py" "$work/block.yaml" "$nx" explicit 20
sed 's/fields: \[displacement, velocity, von_mises\]/fields: [displacement, velocity, stress, von_mises]/' \
  "$work/block.yaml" >"$work/gathered.yaml"
sed 's/^  history:/  files: per_rank\n  history:/' "$work/gathered.yaml" >"$work/per_rank.yaml"

row() {  # row SETTING
  local out="$work/out_$1"
  rm -rf "$out"
  "${launch[@]}" "$efg" run "$work/$1.yaml" -o "$out" >"$work/$1.log" 2>&1
  local join=""
  if [ "$1" = per_rank ] && [ -x "$epu" ]; then
    local t0 t1
    t0=$(date +%s.%N)
    (cd "$out" && "$epu" -auto "$1.e.2.0" >/dev/null 2>&1)
    t1=$(date +%s.%N)
    join=$(awk "BEGIN { printf \"%.2f\", $t1 - $t0 }")
  fi
  /usr/bin/python3 - "$out/$1.e.report.json" "$1" "$join" "$work/$1.log" <<'PY'
import json, re, sys
r = json.load(open(sys.argv[1]))
ph = r["phase_seconds"]
one = lambda v: max(v) if isinstance(v, list) else v
log = open(sys.argv[4]).read()
peak = re.search(r"memory high-water mark: ([0-9.]+) MiB per rank", log).group(1)
print("| %s | %d | %.2f | %.2f | %s | %s |" % (sys.argv[2], r["particles"], one(ph["output"]),
      r["total_seconds"], peak, sys.argv[3] or "-"))
PY
}

echo "| output, 2 ranks | particles | output phase s | whole run s | high-water MiB per rank | epu join s |"
echo "|---|---|---|---|---|---|"
for setting in gathered per_rank gathered per_rank; do row "$setting"; done
