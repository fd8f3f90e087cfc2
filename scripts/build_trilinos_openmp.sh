#!/usr/bin/env bash
# Builds Trilinos 13.2 from Debian's trilinos *source* package with Kokkos OpenMP + Serial, MPI
# on, and only the packages efg uses, into a cache prefix outside the repository:
#   ${EFG_CACHE:-/var/cache/efg}/trilinos-openmp
# and prints that prefix. Idempotent: when the prefix holds a finished install made with the
# same options (stamp file), it only prints the path. The default efg build and CI stay on
# Debian's Serial Trilinos packages; `scripts/build.sh --threads` (or
# cmake -DEFG_TRILINOS_PREFIX=<prefix>) builds efg against this one (docs/threads.md).
#
# Choices (../shared/reference/toolchain.md, "Threads and GPUs"):
#   - packages Kokkos, KokkosKernels, Teuchos, Tpetra, Belos, Ifpack2, Amesos2, Thyra,
#     Stratimikos, NOX (with its LAPACK group), Zoltan2, MueLu, Anasazi, Sacado; Epetra explicitly off
#     (Thyra and NOX would pull it in);
#   - explicit instantiation for scalar double, local int, global long long, the OpenMP node only
#     (Tpetra's default node is then Kokkos::Compat::KokkosOpenMPWrapperNode);
#   - Release, shared libraries, C++17, tests and examples off;
#   - compiled through ccache with its own cache folder ($EFG_CACHE/ccache-trilinos, 6 GB), so
#     a rebuild after a lost prefix or a changed option takes minutes, not 45.
# Measured on the 2-core development machine (docs/threads.md): source download and unpack 9 s,
# configure 5 s, build 35 min at -j2 from an empty ccache (1,181 steps), 147 MB installed,
# ccache folder 89 MB.
# Environment: EFG_CACHE (default /var/cache/efg), EFG_JOBS (default 2, at most 2 is used).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
cache="${EFG_CACHE:-/var/cache/efg}"
prefix="$cache/trilinos-openmp"
say() { echo "efg build_trilinos_openmp: $*" >&2; }
sudo_cmd=""
if [ "$(id -u)" -ne 0 ]; then sudo_cmd="sudo"; fi
# shellcheck source=lib/trilinos_source.sh
source "$here/lib/trilinos_source.sh"

multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || echo x86_64-linux-gnu)
options=(
  -G Ninja
  -DCMAKE_BUILD_TYPE=Release
  -DCMAKE_INSTALL_PREFIX="$prefix"
  -DCMAKE_INSTALL_RPATH="$prefix/lib"
  -DBUILD_SHARED_LIBS=ON
  -DCMAKE_CXX_STANDARD=17
  -DCMAKE_C_COMPILER=mpicc
  -DCMAKE_CXX_COMPILER=mpicxx
  -DTrilinos_ENABLE_Fortran=OFF
  -DTrilinos_ENABLE_TESTS=OFF
  -DTrilinos_ENABLE_EXAMPLES=OFF
  -DTrilinos_ENABLE_ALL_PACKAGES=OFF
  -DTrilinos_ENABLE_ALL_OPTIONAL_PACKAGES=OFF
  -DTrilinos_ENABLE_SECONDARY_TESTED_CODE=ON
  -DTrilinos_ENABLE_Kokkos=ON
  -DTrilinos_ENABLE_KokkosKernels=ON
  -DTrilinos_ENABLE_Teuchos=ON
  -DTrilinos_ENABLE_Tpetra=ON
  -DTrilinos_ENABLE_Belos=ON
  -DTrilinos_ENABLE_Ifpack2=ON
  -DTrilinos_ENABLE_Amesos2=ON
  -DTrilinos_ENABLE_Thyra=ON
  -DTrilinos_ENABLE_ThyraTpetraAdapters=ON
  -DTrilinos_ENABLE_Stratimikos=ON
  -DTrilinos_ENABLE_NOX=ON
  -DTrilinos_ENABLE_Zoltan2=ON
  -DTrilinos_ENABLE_MueLu=ON
  -DTrilinos_ENABLE_Anasazi=ON
  -DTrilinos_ENABLE_Sacado=ON
  -DAnasazi_ENABLE_Tpetra=ON
  -DNOX_ENABLE_ABSTRACT_IMPLEMENTATION_LAPACK=ON
  -DTrilinos_ENABLE_Epetra=OFF
  -DStratimikos_ENABLE_Belos=ON
  -DStratimikos_ENABLE_Ifpack2=ON
  -DStratimikos_ENABLE_Amesos2=ON
  -DBelos_ENABLE_Tpetra=ON
  -DBelos_ENABLE_Thyra=ON
  -DIfpack2_ENABLE_Amesos2=ON
  -DAmesos2_ENABLE_KLU2=ON
  -DMueLu_ENABLE_Amesos2=ON
  -DMueLu_ENABLE_Ifpack2=ON
  -DMueLu_ENABLE_Belos=ON
  -DMueLu_ENABLE_Thyra=ON
  -DMueLu_ENABLE_Stratimikos=ON
  -DNOX_ENABLE_Stratimikos=ON
  -DNOX_ENABLE_Belos=ON
  -DNOX_ENABLE_Ifpack2=ON
  -DNOX_ENABLE_ABSTRACT_IMPLEMENTATION_THYRA=ON
  -DNOX_ENABLE_LOCA=OFF
  -DTrilinos_ENABLE_OpenMP=ON
  -DKokkos_ENABLE_OPENMP=ON
  -DKokkos_ENABLE_SERIAL=ON
  -DTrilinos_ENABLE_EXPLICIT_INSTANTIATION=ON
  -DTpetra_INST_DOUBLE=ON
  -DTpetra_INST_COMPLEX_DOUBLE=OFF
  -DTpetra_INST_FLOAT=OFF
  -DTpetra_INST_INT_INT=OFF
  -DTpetra_INST_INT_LONG=OFF
  -DTpetra_INST_INT_LONG_LONG=ON
  -DTpetra_INST_INT_UNSIGNED=OFF
  -DTpetra_INST_INT_UNSIGNED_LONG=OFF
  -DTpetra_INST_SERIAL=OFF
  -DTpetra_INST_OPENMP=ON
  -DKokkosKernels_INST_EXECSPACE_SERIAL=OFF
  -DKokkosKernels_INST_EXECSPACE_OPENMP=ON
  -DKokkosKernels_INST_MEMSPACE_HOSTSPACE=ON
  -DKokkosKernels_INST_DOUBLE=ON
  -DKokkosKernels_INST_COMPLEX_DOUBLE=OFF
  -DKokkosKernels_INST_COMPLEX_FLOAT=OFF
  -DKokkosKernels_INST_FLOAT=OFF
  -DKokkosKernels_INST_ORDINAL_INT=ON
  -DKokkosKernels_INST_ORDINAL_INT64_T=OFF
  -DKokkosKernels_INST_OFFSET_SIZE_T=ON
  -DKokkosKernels_INST_OFFSET_INT=OFF
  -DKokkosKernels_INST_LAYOUTLEFT=ON
  -DKokkosKernels_INST_LAYOUTRIGHT=OFF
  -DTPL_ENABLE_MPI=ON
  -DTPL_ENABLE_BLAS=ON
  -DTPL_ENABLE_LAPACK=ON
  -DTPL_ENABLE_Pthread=OFF
  -DTPL_ENABLE_Boost=OFF
  -DTPL_ENABLE_Netcdf=OFF
  -DTPL_ENABLE_HDF5=OFF
  -DTPL_ENABLE_ParMETIS=OFF
  -DTPL_ENABLE_METIS=OFF
  -DTPL_ENABLE_Scotch=OFF
  -DTPL_ENABLE_SuperLU=OFF
  -DTPL_ENABLE_Matio=OFF
  -DTPL_ENABLE_X11=OFF
  -DTPL_ENABLE_yaml-cpp=OFF
  "-DTPL_BLAS_LIBRARIES=/usr/lib/$multiarch/libblas.so"
  "-DTPL_LAPACK_LIBRARIES=/usr/lib/$multiarch/liblapack.so"
)
stamp_value=$(printf '%s\n' "${options[@]}" | sha256sum | cut -c1-16)
stamp="$prefix/.efg-build-stamp"
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$stamp_value" ] && [ -f "$prefix/lib/cmake/Trilinos/TrilinosConfig.cmake" ]; then
  echo "$prefix"
  exit 0
fi

t0=$(date +%s)
efg_prepare_source_tools dpkg-dev cmake ninja-build g++ ccache libopenmpi-dev openmpi-bin \
  libblas-dev liblapack-dev
$sudo_cmd mkdir -p "$cache"
if [ -n "$sudo_cmd" ]; then $sudo_cmd chown "$(id -u):$(id -g)" "$cache"; fi
work="$cache/trilinos-openmp-work"
efg_fetch_trilinos_source "$work"
t_src=$(date +%s)

jobs="${EFG_JOBS:-2}"
if [ "$jobs" -gt 2 ]; then jobs=2; fi
export CCACHE_DIR="$cache/ccache-trilinos" CCACHE_BASEDIR="$work" CCACHE_NOHASHDIR=1
ccache --max-size=6G >/dev/null
say "configuring (log: $work/configure.log)"
cmake -S "$work/trilinos" -B "$work/build" "${options[@]}" \
  -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache \
  >"$work/configure.log" 2>&1 || { say "configure failed, see $work/configure.log"; exit 1; }
grep -E "^Final set of enabled (SE )?packages|^Final set of enabled top-level packages" \
  "$work/configure.log" | head -3 >&2 || true
t_conf=$(date +%s)
say "building with $jobs job(s) (about 35 minutes at -j2 from an empty ccache; log: $work/build.log)"
cmake --build "$work/build" --parallel "$jobs" >"$work/build.log" 2>&1 \
  || { say "build failed, see $work/build.log"; tail -20 "$work/build.log" >&2; exit 1; }
t_build=$(date +%s)
rm -rf "$prefix"
cmake --install "$work/build" >"$work/install.log" 2>&1 \
  || { say "install failed, see $work/install.log"; exit 1; }
grep -q "KOKKOS_ENABLE_OPENMP" "$prefix/include/KokkosCore_config.h" \
  || { say "the installed Kokkos has no OpenMP backend"; exit 1; }
echo "$stamp_value" >"$stamp"
t_install=$(date +%s)
rm -rf "$work"
say "source $((t_src - t0)) s, configure $((t_conf - t_src)) s, build $((t_build - t_conf)) s," \
  "install $((t_install - t_build)) s; $(du -sh "$prefix" | cut -f1) in $prefix"
echo "$prefix"
