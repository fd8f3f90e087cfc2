#!/usr/bin/env bash
# Configures (once) and builds efg in build/ (override with EFG_BUILD_DIR). Quiet when up to date.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EFG_BUILD_DIR:-$here/build}"
jobs="${EFG_JOBS:-$(nproc)}"
# ccache: paths under the checkout hashed relative to it, so that clones share the cache.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$here}"
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE="${EFG_BUILD_TYPE:-Release}" >/dev/null
fi
cmake --build "$build" --parallel "$jobs" | grep -v "^ninja: no work to do" || true
test -x "$build/efg"
