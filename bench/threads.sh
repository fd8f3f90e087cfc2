#!/usr/bin/env bash
# Thread scaling (docs/threads.md): efg_bench_threads of the threaded build (build-openmp/,
# scripts/build.sh --threads) with 1 thread, 2 threads, and 2 MPI ranks x 1 thread, back to
# back on the same machine, then the ratios. Extra arguments go to the bench
# (--cells N: N^3 hex cells, (N+1)^3 particles, default 48 = 117,649; --repeats R).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bench="${EFG_BUILD_DIR:-$here/build-openmp}/bench/efg_bench_threads"
[ -x "$bench" ] || { echo "bench/threads.sh: $bench missing: run scripts/build.sh --threads" >&2; exit 2; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_PROC_BIND=false
one=$(OMP_NUM_THREADS=1 "$bench" --threads 1 "$@")
two=$(OMP_NUM_THREADS=2 "$bench" --threads 2 "$@")
ranks=$(OMP_NUM_THREADS=1 mpirun -np 2 --bind-to core "$bench" --threads 1 "$@")
/usr/bin/python3 - "$one" "$two" "$ranks" <<'PY'
import sys
runs = []
for line in sys.argv[1:]:
    f = line.split()
    runs.append({f[i]: f[i + 1] for i in range(0, len(f) - 1, 2)})
names = ["1 rank x 1 thread", "1 rank x 2 threads", "2 ranks x 1 thread"]
print("particles: %s (3D block, hex8 cells, linear basis, SCNI, dilation 1.2)" % runs[0]["particles"])
print("%-20s %14s %14s %14s" % ("configuration", "shape funcs s", "explicit step s", "tangent s"))
for n, r in zip(names, runs):
    print("%-20s %14.4f %14.5f %14.4f" % (n, float(r["shape_s"]), float(r["step_s"]), float(r["tangent_s"])))
print("%-20s %14s %14s %14s" % ("speedup", "shape funcs", "explicit step", "tangent"))
for label, i, j in (("2 threads vs 1", 0, 1), ("2 ranks vs 1", 0, 2), ("2 threads vs 2 ranks", 2, 1)):
    print("%-20s %14.2f %14.2f %14.2f" % (label, *(float(runs[i][k]) / float(runs[j][k]) for k in ("shape_s", "step_s", "tangent_s"))))
for k in ("force_norm", "tangent_norm"):
    values = [float(r[k]) for r in runs]
    print("%s: %s (largest relative spread %.1e)" % (k, ", ".join(r[k] for r in runs), (max(values) - min(values)) / max(values)))
PY
