#!/usr/bin/env bash
# The mesh read whole on rank 0 and sent to every rank (mesh.read: root) against each rank
# reading only its slice and keeping its part (mesh.read: distributed; docs/scaling.md), and the
# same for the generated mesh (generated whole on rank 0, or each rank generating its slice:
# mesh.generate with read: distributed), side by side in one run: the explicit 3D block of bench/block_scene.py at NX x 0.35 NX x 0.35 NX cells
# (NX = 100: 130,896 particles, dilation 1.2) written once with `efg mesh`, 100 steps, on 1, 2
# and 3 ranks. Prints the nodes each rank holds, the resident growth per rank of the "scene and
# mesh" and "partition" phases (a distributed read partitions while it reads), the setup (scene
# and mesh, partition, neighbour search, shape functions: the slower rank's) and each rank's
# memory high-water mark.
#   bench/distributed_read.sh [NX]      (RANKS="2" for some rank counts only; default "1 2 3")
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh" >/dev/null
efg="${EFG_BUILD_DIR:-$here/build}/efg"
nx="${1:-100}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

/usr/bin/python3 "$here/bench/block_scene.py" "$work/generated.yaml" "$nx" explicit
"$efg" mesh "$work/generated.yaml" "$work/block.exo" >/dev/null
for read in root distributed generated_root generated_distributed; do
  /usr/bin/python3 - "$work/generated.yaml" "$work/$read.yaml" "$read" <<'PY'
import re, sys
s, read = open(sys.argv[1]).read(), sys.argv[3]
if read.startswith("generated_"):
    s = re.sub(r"(mesh:\n  generate: \{[^}]*\}\n)", r"\1  read: %s\n" % read[10:], s)
else:
    s = re.sub(r"mesh:\n  generate: \{[^}]*\}\n", "mesh: {file: block.exo, read: %s}\n" % read, s)
open(sys.argv[2], "w").write(s)
PY
done

row() {  # row RANKS READ
  local out="$work/out_$1_$2" launch=()
  rm -rf "$out"
  if [ "$1" -gt 1 ]; then
    launch=(mpirun -np "$1")
    if [ "$(id -u)" -eq 0 ]; then launch+=(--allow-run-as-root --oversubscribe); fi
  fi
  "${launch[@]}" "$efg" run "$work/$2.yaml" -o "$out" >"$work/$2.log" 2>&1
  /usr/bin/python3 - "$work/$2.log" "$1" "$2" "$out/$2.e.report.json" <<'PY'
import json, re, sys
log, ranks = open(sys.argv[1]).read(), int(sys.argv[2])
r = json.load(open(sys.argv[4]))
nodes = r["particles"]
held = re.search(r"each rank holds (\d+) to (\d+) of its nodes", log)
held = "%s-%s" % held.groups() if held else "%d (whole)" % nodes
# the read with the partition: a distributed read does both in "scene and mesh"
mesh = sum(float(re.search(r"\n  %s +([0-9.]+) MiB" % phase, log).group(1))
           for phase in ("scene and mesh", "partition")) / ranks
peak = re.search(r"memory high-water mark: ([0-9.]+) MiB per rank", log).group(1)
ph = r["phase_seconds"]
one = lambda v: max(v) if isinstance(v, list) else v
setup = sum(one(ph[k]) for k in ("scene and mesh", "partition (Zoltan2 RCB)",
                                 "neighbour search (ghosts, particles)",
                                 "shape functions and integration"))
print("| %d | %s | %d | %s | %.1f | %.2f | %s |" % (ranks, sys.argv[3], nodes, held, mesh, setup,
      peak))
PY
}

echo "| ranks | mesh.read | particles | nodes per rank | mesh + partition MiB per rank | setup s | high-water MiB per rank |"
echo "|---|---|---|---|---|---|---|"
for ranks in ${RANKS:-1 2 3}; do
  for read in root distributed generated_root generated_distributed; do row "$ranks" "$read"; done
done
