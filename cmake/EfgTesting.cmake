# Test helpers. MPI tests run the whole test binary under mpiexec with N ranks; as root Open MPI
# needs --allow-run-as-root, and more ranks than cores need --oversubscribe.
find_package(GTest REQUIRED)
include(GoogleTest)

set(EFG_MPIEXEC ${MPIEXEC_EXECUTABLE})
set(EFG_MPIEXEC_FLAGS --oversubscribe)
execute_process(COMMAND id -u OUTPUT_VARIABLE _efg_uid OUTPUT_STRIP_TRAILING_WHITESPACE)
if(_efg_uid STREQUAL "0")
  list(APPEND EFG_MPIEXEC_FLAGS --allow-run-as-root)
endif()

# efg_add_mpi_test(NAME name TARGET exe RANKS n [LABELS ...])
function(efg_add_mpi_test)
  cmake_parse_arguments(T "" "NAME;TARGET;RANKS" "LABELS" ${ARGN})
  add_test(NAME ${T_NAME}
    COMMAND ${EFG_MPIEXEC} ${EFG_MPIEXEC_FLAGS} ${MPIEXEC_NUMPROC_FLAG} ${T_RANKS} $<TARGET_FILE:${T_TARGET}>)
  set_tests_properties(${T_NAME} PROPERTIES PROCESSORS ${T_RANKS} LABELS "mpi;${T_LABELS}" TIMEOUT 300)
endfunction()
