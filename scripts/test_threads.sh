#!/usr/bin/env bash
# The whole test suite against the OpenMP Trilinos (docs/threads.md): builds the default
# (Serial) efg and the threaded one (scripts/build.sh --threads, which builds Trilinos with
# OpenMP first when missing: about 45 min once), then runs every test of build-openmp/ with
# OMP_NUM_THREADS=1 and again with OMP_NUM_THREADS=2, the thread-agreement tests (label threads:
# 1 vs 2 threads, and the 1-thread result vs the Serial build's, to 1e-12) included in both.
# Prints one CTest summary per thread count; exits non-zero when either run fails.
# Extra arguments go to ctest, e.g. scripts/test_threads.sh -L threads
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
start=$(date +%s)
"$here/scripts/setup.sh"
"$here/scripts/build.sh" --threads
built=$(date +%s)
echo "efg threaded tests: setup and builds took $((built - start)) s"
# The MPI tests put up to 3 ranks x 2 threads on 2 cores: threads must sleep, not spin, when
# they wait (OMP_WAIT_POLICY=passive), or those tests run many times slower (docs/threads.md).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_PROC_BIND=false OMP_WAIT_POLICY=passive
cd "${EFG_BUILD_DIR:-$here/build-openmp}"
status=0
for n in 1 2; do
  echo "=== OMP_NUM_THREADS=$n ==="
  t0=$(date +%s)
  OMP_NUM_THREADS=$n ctest --output-on-failure -j "${EFG_JOBS:-$(nproc)}" "$@" || status=1
  echo "OMP_NUM_THREADS=$n: $(( $(date +%s) - t0 )) s"
done
exit $status
