#!/usr/bin/env bash
# Builds SEACAS exodiff (and epu) from Debian's trilinos *source* package into a cache prefix
# outside the repository, ${EFG_CACHE:-/var/cache/efg}/seacas, and prints the path of exodiff.
# Idempotent: when exodiff is already there it only prints its path (the regression suite,
# regression/CMakeLists.txt, finds it in the same place). Progress messages go to stderr, the
# path to stdout, so `scripts/build_exodiff.sh >/dev/null` is silent when nothing is to be done.
#
# Steps (as root, or through sudo for the apt parts):
#   1. enable a deb-src stanza for Debian bookworm main if none is present
#      (/etc/apt/sources.list.d/efg-deb-src.sources), apt-get update, install dpkg-dev if missing;
#   2. apt-get source trilinos (13.2.0-4: 166 MB download, 828 MB unpacked) into a work folder;
#   3. two known fixes (docs/regression.md, /work/shared/reference/toolchain.md):
#      - netCDF 4.9 defines NC_SZIP_NN as a macro, which breaks the line
#        `const int NC_SZIP_NN = 32;` of packages/seacas/libraries/exodus/src/ex_utils.c:
#        guarded with #ifndef in the unpacked copy;
#      - the netCDF library list must also name the serial HDF5 library (Debian's libnetcdf is
#        built on HDF5; TPL_Netcdf_LIBRARIES = libnetcdf.so;hdf5/serial/libhdf5.so below);
#   4. a SEACAS-only configure of the Trilinos tree (all packages off, SEACASExodiff and
#      SEACASEpu on, which pull in SEACASExodus, SuplibC and SuplibCpp; no MPI, no Fortran,
#      netCDF from Debian), build with at most 2 jobs, install, remove the work folder.
#
# Measured on the 2-core development machine (Debian 12, g++ 12.2), two clean runs:
#   deb-src stanza + apt-get update + download of the source package (166 MB): 2-3 s (fast mirror
#   here; budget a minute elsewhere); unpack (828 MB) 5 s; configure 2 s; build 86-89 s at -j2;
#   install < 1 s; removing the work folder 8 s. Whole first run 1 min 44 s on an idle machine,
#   2 min 24 s while another build shared the 2 cores. Installed prefix 9.0 MB (exodiff 0.8 MB,
#   libexodus, suplib, epu, Exodus Python modules). A second run: 2 ms (prints the path only);
#   scripts/setup.sh with everything present: 0.2 s.
# Environment: EFG_CACHE (default /var/cache/efg), EFG_JOBS (default 2, at most 2 is used).
set -euo pipefail

cache="${EFG_CACHE:-/var/cache/efg}"
prefix="$cache/seacas"
exodiff="$prefix/bin/exodiff"

if [ -x "$exodiff" ] && [ -x "$prefix/bin/epu" ]; then
  echo "$exodiff"
  exit 0
fi

say() { echo "efg build_exodiff: $*" >&2; }
sudo_cmd=""
if [ "$(id -u)" -ne 0 ]; then sudo_cmd="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
t0=$(date +%s)

# 1 + 2. deb-src for bookworm main, the tools, the source package unpacked in a work folder.
# shellcheck source=lib/trilinos_source.sh
source "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/lib/trilinos_source.sh"
efg_prepare_source_tools dpkg-dev cmake ninja-build g++ libnetcdf-dev libhdf5-dev
$sudo_cmd mkdir -p "$cache"
if [ -n "$sudo_cmd" ]; then $sudo_cmd chown "$(id -u):$(id -g)" "$cache"; fi
work="$cache/seacas-work"
efg_fetch_trilinos_source "$work"
t_dl=$(date +%s)
t_unpack=$t_dl

# 3a. NC_SZIP_NN fix.
utils="$work/trilinos/packages/seacas/libraries/exodus/src/ex_utils.c"
grep -q '^ *const int NC_SZIP_NN = 32;' "$utils" || { say "ex_utils.c: NC_SZIP_NN line not found"; exit 1; }
sed -i 's|^\( *\)const int NC_SZIP_NN = 32;\(.*\)$|#ifndef NC_SZIP_NN /* a macro since netCDF 4.9 */\n\1const int NC_SZIP_NN = 32;\2\n#endif|' "$utils"

# 3b + 4. SEACAS-only configure; the netCDF library list names the serial HDF5 library too.
multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || echo x86_64-linux-gnu)
netcdf_lib="/usr/lib/$multiarch/libnetcdf.so"
hdf5_lib="/usr/lib/$multiarch/hdf5/serial/libhdf5.so"
for f in "$netcdf_lib" "$hdf5_lib"; do
  [ -f "$f" ] || { say "missing $f"; exit 1; }
done
jobs="${EFG_JOBS:-2}"
if [ "$jobs" -gt 2 ]; then jobs=2; fi
say "configuring SEACAS (exodiff, epu)"
cmake -S "$work/trilinos" -B "$work/build" -G Ninja \
  -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_INSTALL_PREFIX="$prefix" \
  -DBUILD_SHARED_LIBS=ON \
  -DCMAKE_INSTALL_RPATH="$prefix/lib" \
  -DTrilinos_ENABLE_ALL_PACKAGES=OFF \
  -DTrilinos_ENABLE_ALL_OPTIONAL_PACKAGES=OFF \
  -DTrilinos_ENABLE_SECONDARY_TESTED_CODE=OFF \
  -DTrilinos_ENABLE_Fortran=OFF \
  -DTrilinos_ENABLE_TESTS=OFF \
  -DTrilinos_ENABLE_EXAMPLES=OFF \
  -DTrilinos_ENABLE_SEACASExodiff=ON \
  -DTrilinos_ENABLE_SEACASEpu=ON \
  -DTPL_ENABLE_MPI=OFF \
  -DTPL_ENABLE_Netcdf=ON \
  -DTPL_ENABLE_HDF5=OFF \
  -DTPL_ENABLE_Pnetcdf=OFF \
  -DTPL_ENABLE_Matio=OFF \
  -DTPL_ENABLE_X11=OFF \
  -DTPL_ENABLE_Pthread=OFF \
  -DNetcdf_ALLOW_PREFIND=OFF \
  -DTPL_Netcdf_INCLUDE_DIRS=/usr/include \
  "-DTPL_Netcdf_LIBRARIES=$netcdf_lib;$hdf5_lib" \
  >"$work/configure.log" 2>&1 || { say "configure failed, see $work/configure.log"; exit 1; }
t_conf=$(date +%s)
say "building with $jobs job(s) (about 2 minutes at -j2)"
cmake --build "$work/build" --parallel "$jobs" >"$work/build.log" 2>&1 \
  || { say "build failed, see $work/build.log"; exit 1; }
t_build=$(date +%s)
cmake --install "$work/build" >"$work/install.log" 2>&1 \
  || { say "install failed, see $work/install.log"; exit 1; }
t_install=$(date +%s)
[ -x "$exodiff" ] && [ -x "$prefix/bin/epu" ] || { say "exodiff or epu not installed in $prefix/bin"; exit 1; }
"$exodiff" -version >/dev/null 2>&1 || { say "$exodiff does not run"; exit 1; }
rm -rf "$work"
t_end=$(date +%s)
say "source download and unpack $((t_dl - t0)) s, configure $((t_conf - t_unpack)) s," \
  "build $((t_build - t_conf)) s, install $((t_install - t_build)) s, clean-up $((t_end - t_install)) s;" \
  "$(du -sh "$prefix" | cut -f1) in $prefix"
echo "$exodiff"
