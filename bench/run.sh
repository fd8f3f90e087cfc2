#!/usr/bin/env bash
# Runs the benchmarks (after building) and prints their tables. Not part of the test suite.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh"
"${EFG_BUILD_DIR:-$here/build}/bench/efg_bench_discretization" "$@"
"${EFG_BUILD_DIR:-$here/build}/bench/efg_bench_explicit"
"${EFG_BUILD_DIR:-$here/build}/bench/efg_bench_materials"
"${EFG_BUILD_DIR:-$here/build}/bench/efg_bench_contact"
"${EFG_BUILD_DIR:-$here/build}/bench/efg_bench_expressions"
"${EFG_BUILD_DIR:-$here/build}/bench/efg_bench_shells"
