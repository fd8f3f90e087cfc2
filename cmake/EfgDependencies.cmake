# Third-party dependencies, all from Debian 12 packages (scripts/setup.sh installs them).
# Facts behind this file: ../shared/reference/toolchain.md.
# EFG_TRILINOS_PREFIX selects another Trilinos install, e.g. the OpenMP build of
# scripts/build_trilinos_openmp.sh (docs/threads.md); empty means Debian's packages.
set(EFG_TRILINOS_PREFIX "" CACHE PATH "Trilinos install prefix (empty: Debian's trilinos-all-dev)")
find_package(MPI REQUIRED COMPONENTS CXX)
if(EFG_TRILINOS_PREFIX)
  find_package(Trilinos 13.2 REQUIRED
    COMPONENTS Teuchos Tpetra Belos Ifpack2 MueLu NOX Stratimikos Thyra Amesos2 Zoltan2 Anasazi Sacado
    PATHS ${EFG_TRILINOS_PREFIX} NO_DEFAULT_PATH)
else()
  find_package(Trilinos 13.2 REQUIRED
    COMPONENTS Teuchos Tpetra Belos Ifpack2 MueLu NOX Stratimikos Thyra Amesos2 Zoltan2 Anasazi)
endif()
# Which Kokkos backends this Trilinos has (Debian's: Serial only).
find_file(EFG_KOKKOS_CONFIG KokkosCore_config.h PATHS ${Trilinos_INCLUDE_DIRS} NO_DEFAULT_PATH)
file(STRINGS "${EFG_KOKKOS_CONFIG}" _efg_kokkos_openmp REGEX "^#define KOKKOS_ENABLE_OPENMP")
if(_efg_kokkos_openmp)
  set(EFG_KOKKOS_OPENMP ON)
  find_package(OpenMP REQUIRED COMPONENTS CXX)
else()
  set(EFG_KOKKOS_OPENMP OFF)
endif()
message(STATUS "efg: Trilinos ${Trilinos_VERSION} from ${Trilinos_DIR}; Kokkos OpenMP: ${EFG_KOKKOS_OPENMP}")
find_package(yaml-cpp REQUIRED)

# Debian's Trilinos targets carry no include directories and no MPI: wrap them in one target.
add_library(efg_trilinos INTERFACE)
target_include_directories(efg_trilinos SYSTEM INTERFACE
  ${Trilinos_INCLUDE_DIRS} ${Trilinos_TPL_INCLUDE_DIRS})
target_link_libraries(efg_trilinos INTERFACE
  ${Trilinos_LIBRARIES} ${Trilinos_TPL_LIBRARIES} MPI::MPI_CXX)
if(EFG_KOKKOS_OPENMP)
  target_link_libraries(efg_trilinos INTERFACE OpenMP::OpenMP_CXX)
endif()

# A Debian library without a CMake config as an INTERFACE target: efg_debian_library(TARGET
# HEADER "PATH_SUFFIXES" "LIBRARY NAMES" "what" package).
function(efg_debian_library target header suffixes names what package)
  find_path(${target}_INCLUDE_DIR ${header} PATH_SUFFIXES ${suffixes})
  find_library(${target}_LIBRARY NAMES ${names})
  if(NOT ${target}_INCLUDE_DIR OR NOT ${target}_LIBRARY)
    message(FATAL_ERROR "efg: ${what} not found; run scripts/setup.sh (package ${package})")
  endif()
  add_library(${target} INTERFACE)
  target_include_directories(${target} SYSTEM INTERFACE ${${target}_INCLUDE_DIR})
  target_link_libraries(${target} INTERFACE ${${target}_LIBRARY})
endfunction()

# Exodus II (Debian's libexodusii-dev ships no CMake config).
efg_debian_library(efg_exodus exodusII.h "exodusii" "exoIIv2;exodus;exoIIv2c" "Exodus II"
                   libexodusii-dev)
# netCDF (Debian's libnetcdf-dev), Exodus II's container: the record checksums are a netCDF
# variable of their own (io/RecordChecksum).
efg_debian_library(efg_netcdf netcdf.h "" "netcdf" netCDF libnetcdf-dev)
# UMFPACK (Debian's libsuitesparse-dev): the default sparse direct solver (solvers/SparseLU).
efg_debian_library(efg_umfpack suitesparse/umfpack.h "" "umfpack" UMFPACK libsuitesparse-dev)
# MUMPS (Debian's libmumps-dev): the distributed sparse direct solver (solvers/DistributedLU).
# The build Trilinos' own link interface names (Amesos2's TPL), so it is the one the process
# binds dmumps_c to whatever is listed here: PORD, AMD, AMF and QAMD orderings, sequential
# analysis. (Sessions 10-23 asked for libmumps-ptscotch-dev here and still ran this one, the
# linker resolving dmumps_c from Trilinos' earlier libdmumps. The PT-Scotch build, put first in
# the link, was measured in session 24 and is not better: its automatic ordering is Scotch, 3.09
# GFlop against PORD's 2.39 on the 8,514-dof beam and 15.7 against 14.3 on the 9,300-dof block;
# its parallel analysis works (ICNTL(28) = 2, 29 = 1) but orders the 132,354-dof beam for 3.0e11
# flops against 1.97e11: 2 ranks 12.8 s against PORD's 11.3 s Newton phase.)
efg_debian_library(efg_mumps dmumps_c.h "" "dmumps" MUMPS libmumps-dev)

# yaml-cpp as a SYSTEM include as well.
add_library(efg_yaml INTERFACE)
get_target_property(_yaml_inc yaml-cpp INTERFACE_INCLUDE_DIRECTORIES)
if(_yaml_inc)
  target_include_directories(efg_yaml SYSTEM INTERFACE ${_yaml_inc})
endif()
target_link_libraries(efg_yaml INTERFACE yaml-cpp)

# muParser (libmuparser-dev): expressions in scene values (src/expressions).
find_package(muparser REQUIRED)
