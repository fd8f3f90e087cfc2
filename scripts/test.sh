#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite (unit, MPI on 1-3 ranks, CLI).
# Extra arguments go to ctest, e.g. scripts/test.sh -L mpi
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
start=$(date +%s)
"$here/scripts/setup.sh"
built=$(date +%s)
cd "${EFG_BUILD_DIR:-$here/build}"
# Open MPI as root (CI containers) needs these; harmless otherwise.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
echo "efg tests: setup and build took $((built - start)) s"
# ctest's summary stays the last output (CI reads it); the regression suite's total time is in
# build/regression/summary.txt, written by its last test (regression.total_time).
exec ctest --output-on-failure -j "${EFG_JOBS:-$(nproc)}" "$@"
