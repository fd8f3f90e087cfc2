# The version string efg prints: the project version plus the git description when available.
find_package(Git QUIET)
set(EFG_GIT_DESCRIBE "unknown")
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} describe --always --dirty --tags
    WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}
    OUTPUT_VARIABLE EFG_GIT_DESCRIBE OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT EFG_GIT_DESCRIBE)
    set(EFG_GIT_DESCRIBE "unknown")
  endif()
endif()
