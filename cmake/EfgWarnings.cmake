# Warnings for efg's own code only; third-party headers come in as SYSTEM includes.
add_library(efg_warnings INTERFACE)
target_compile_options(efg_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wold-style-cast -Wnon-virtual-dtor)
if(EFG_WARNINGS_AS_ERRORS)
  target_compile_options(efg_warnings INTERFACE -Werror)
endif()
