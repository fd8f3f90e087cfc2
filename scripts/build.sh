#!/usr/bin/env bash
# Configures (once) and builds efg in build/ (override with EFG_BUILD_DIR). Quiet when up to date.
#   scripts/build.sh            against Debian's Trilinos packages (Kokkos Serial): the default
#   scripts/build.sh --threads  against the OpenMP Trilinos of scripts/build_trilinos_openmp.sh
#                               (built first when missing: about 45 min once), in build-openmp/
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
threads=0
if [ "${1:-}" = "--threads" ]; then threads=1; shift; fi
extra=()
if [ $threads -eq 1 ]; then
  build="${EFG_BUILD_DIR:-$here/build-openmp}"
  prefix="$("$here/scripts/build_trilinos_openmp.sh")"
  extra+=("-DEFG_TRILINOS_PREFIX=$prefix")
  # The cross-build thread test compares with the Serial build's efg when there is one.
  if [ -x "$here/build/efg" ]; then extra+=("-DEFG_SERIAL_EFG=$here/build/efg"); fi
else
  build="${EFG_BUILD_DIR:-$here/build}"
fi
jobs="${EFG_JOBS:-$(nproc)}"
# ccache: paths under the checkout hashed relative to it, so that clones share the cache.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$here}"
if [ ! -f "$build/build.ninja" ] || [ ${#extra[@]} -gt 0 ]; then
  cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE="${EFG_BUILD_TYPE:-Release}" "${extra[@]}" >/dev/null
fi
# pipefail: a failed compile must fail this script (the filter alone would hide it and leave a
# stale efg behind for the tests).
set -o pipefail
cmake --build "$build" --parallel "$jobs" | { grep -v "^ninja: no work to do" || true; }
test -x "$build/efg"
