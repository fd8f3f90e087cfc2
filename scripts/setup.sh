#!/usr/bin/env bash
# Installs every Debian package efg needs (idempotent: silent when all are present) and builds efg.
# Usage: scripts/setup.sh [--no-build]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

packages=(
  build-essential cmake ninja-build ccache pkg-config
  trilinos-all-dev libopenmpi-dev openmpi-bin
  libptscotch-dev libscotch-dev  # Debian's Trilinos CMake config links them without depending on them
  libexodusii-dev libnetcdf-dev
  libyaml-cpp-dev libgtest-dev python3-yaml
  libmuparser-dev        # expressions in scene values (issue 19)
  libsuitesparse-dev     # UMFPACK, the one-process direct solver
  libmumps-dev           # MUMPS, the distributed direct solver (the build Trilinos links)
  libopenblas0-serial    # one-thread optimized BLAS: UMFPACK's frontal matrices 1.7x faster than reference
  python3-netcdf4 python3-matplotlib python3-numpy
  python3-scipy          # tests/verification/shells/clamped_plate_fd.py (the plate reference values)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -gt 0 ]; then
  echo "efg setup: installing ${#missing[@]} missing package(s): ${missing[*]}"
  sudo_cmd=""
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -qq
  $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# SEACAS exodiff for the regression suite (docs/regression.md): built once from Debian's trilinos
# source package into ${EFG_CACHE:-/var/cache/efg}/seacas (about 2.5 minutes); silent when present.
"$here/scripts/build_exodiff.sh" >/dev/null

if [ "${1:-}" != "--no-build" ]; then
  "$here/scripts/build.sh"
fi
