#!/usr/bin/env bash
# Installs what is missing, builds, and runs a scene (default: input/block.yaml).
# Usage: scripts/run.sh [SCENE.yaml] [-o OUTDIR]   (OUTDIR default: out/)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh"
scene="${1:-$here/input/block.yaml}"
shift $(( $# > 0 ? 1 : 0 ))
if [ $# -eq 0 ]; then set -- -o "$here/out"; fi
exec "${EFG_BUILD_DIR:-$here/build}/efg" run "$scene" "$@"
