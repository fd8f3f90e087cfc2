# Use ccache when it is installed: rebuilds of unchanged translation units cost nothing.
find_program(EFG_CCACHE ccache)
if(EFG_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(CMAKE_CXX_COMPILER_LAUNCHER ${EFG_CCACHE})
  message(STATUS "efg: compiling through ccache (${EFG_CCACHE})")
endif()
