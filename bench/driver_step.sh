#!/usr/bin/env bash
# The whole driver's explicit step against the kernel's (issue 56, item 6), side by side in one
# run: `efg run` on the explicit block of bench/scale.sh (input/block_explicit.yaml refined to
# NX x 0.35 NX x 0.35 NX hex8 cells, dilation 1.2; NX = 95: 110,976 particles, about 100 steps)
# and efg_bench_step on the same scene's model (one internal force and the velocity-Verlet
# updates, bench/ExplicitStep.hpp) for as many steps, alternately, --rounds times. Prints per
# round and as medians: the driver's `explicit time steps` phase per particle-step (its timer
# holds the steps only: stable-step estimates are the `stable time step` phase, printed apart),
# the kernel's, their ratio (issue 56's target: <= 1.2), and setup (scene and mesh, partition,
# neighbour search, shape functions and integration: the phases of bench/scale.sh) in the
# driver's steps (target: <= 20), with the setup phases one by one. Not part of the test suite.
#   bench/driver_step.sh [--cells NX] [--rounds R] [--driver EFG]   (EFG: another build's efg,
#                                                                      e.g. an older one)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EFG_BUILD_DIR:-$here/build}"
efg="$build/efg"
kernel="$build/bench/efg_bench_step"
nx=95
rounds=3
while [ $# -gt 0 ]; do
  case "$1" in
    --cells) nx="$2"; shift 2 ;;
    --rounds) rounds="$2"; shift 2 ;;
    --driver) efg="$2"; shift 2 ;;
    *) echo "bench/driver_step.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
for x in "$efg" "$kernel"; do
  [ -x "$x" ] || { echo "bench/driver_step.sh: $x missing: run scripts/build.sh" >&2; exit 2; }
done
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$here/bench/block_scene.py" "$work/block.yaml" "$nx" explicit

for r in $(seq 1 "$rounds"); do
  rm -rf "$work/out"
  "$efg" run "$work/block.yaml" -o "$work/out" >"$work/log.$r" 2>&1 ||
    { echo "bench/driver_step.sh: efg run failed:" >&2; tail -5 "$work/log.$r" >&2; exit 1; }
  cp "$work"/out/*.report.json "$work/report.$r.json"
  steps=$(sed -n "s/.*stage '[^']*' done: \([0-9]*\) steps.*/\1/p" "$work/log.$r" | head -1)
  "$kernel" --scene "$work/block.yaml" --steps "$steps" >"$work/kernel.$r"
done

/usr/bin/python3 - "$work" "$rounds" <<'PY'
import json, re, statistics, sys
work, rounds = sys.argv[1], int(sys.argv[2])
setup_phases = ("scene and mesh", "partition (Zoltan2 RCB)",
                "neighbour search (ghosts, particles)", "shape functions and integration")
rows = []
for r in range(1, rounds + 1):
    rep = json.load(open("%s/report.%d.json" % (work, r)))
    ph = {k: (max(v) if isinstance(v, list) else v) for k, v in rep["phase_seconds"].items()}
    log = open("%s/log.%d" % (work, r)).read()
    steps = int(re.search(r"stage '[^']*' done: (\d+) steps", log).group(1))
    f = open("%s/kernel.%d" % (work, r)).read().split()
    k = {f[i]: f[i + 1] for i in range(0, len(f) - 1, 2)}
    n = rep["particles"]
    driver = ph["explicit time steps"] / steps
    kernel = float(k["step_s"])
    setup = sum(ph[p] for p in setup_phases)
    rows.append(dict(n=n, kn=int(k["particles"]), steps=steps, driver=driver, kernel=kernel,
                     ratio=driver / kernel, setup=setup, setup_steps=setup / driver,
                     stable=ph["stable time step"], phases={p: ph[p] for p in setup_phases},
                     # (internal force: inside the steps' and the estimate's phases)
                     rest=rep["total_seconds"] - sum(v for p, v in ph.items()
                                                     if p != "internal force")))
print("particles %d (driver) / %d (kernel), %d steps" % (rows[0]["n"], rows[0]["kn"], rows[0]["steps"]))
print("| round | driver ns/particle-step | kernel ns/particle-step | ratio | setup s | setup in steps | stable-step estimate s |")
print("|---|---|---|---|---|---|---|")
ns = lambda s, n: 1e9 * s / n
for i, x in enumerate(rows):
    print("| %d | %.1f | %.1f | %.3f | %.2f | %.0f | %.2f |" % (
        i + 1, ns(x["driver"], x["n"]), ns(x["kernel"], x["kn"]), x["ratio"], x["setup"],
        x["setup_steps"], x["stable"]))
med = lambda key: statistics.median(x[key] for x in rows)
print("| median | %.1f | %.1f | %.3f | %.2f | %.0f | %.2f |" % (
    ns(med("driver"), rows[0]["n"]), ns(med("kernel"), rows[0]["kn"]), med("ratio"), med("setup"),
    med("setup_steps"), med("stable")))
print("setup phases (median s, in driver steps):")
for p in setup_phases:
    s = statistics.median(x["phases"][p] for x in rows)
    print("  %-40s %7.3f  %6.1f" % (p, s, s / med("driver")))
print("  %-40s %7.3f  %6.1f" % ("untimed (operators, mass, checks)", med("rest"), med("rest") / med("driver")))
PY
