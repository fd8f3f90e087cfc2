# Finite rotations of shells (issue 18, docs/shells.md "Finite rotations"; included from
# CMakeLists.txt after its helper functions). The rolled strip: a cantilever strip under an end
# moment 2 pi E I / L in 10 Newton load steps follows the elastica's arcs and closes into a
# circle (end within 1 % of L of the clamp), Newton's tail quadratic, the closure error falling
# over 24, 48 and 96 cells; 1 vs 2 ranks (1e-8: the twisting moment, zero by symmetry, is the
# round-off of 110 Newton iterations; the other columns agree to 1e-12).
foreach(ranks 1 2)
  efg_launcher(launcher ${ranks})
  set(dir ${EFG_CLI_TMP}/shell_rolled_np${ranks})
  efg_cli_test(NAME cli.shell_rolled_np${ranks}
    COMMAND "${launcher}|run|tests/scenes/shells/strip_rolled.yaml|-o|${dir}"
    EXIT 0 TEXT "stage 'roll' done: 10 steps, 0 cutbacks"
    FILE ${dir}/history.csv RANKS ${ranks})
  set_tests_properties(cli.shell_rolled_np${ranks} PROPERTIES FIXTURES_SETUP shell_rolled_np${ranks})
endforeach()
efg_shell_same_on_ranks(shell_rolled strip_rolled.e 1e-8
  displacement_x displacement_z rotation_y moment_xx)
# the coarser and finer levels: the scene with its cells replaced, written at configure time
file(READ ${PROJECT_SOURCE_DIR}/tests/scenes/shells/strip_rolled.yaml rolled)
foreach(cells 24 96)
  string(REPLACE "cells: [48, 2]" "cells: [${cells}, 2]" level "${rolled}")
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/strip_rolled_${cells}.yaml "${level}")
  set(dir ${EFG_CLI_TMP}/shell_rolled_${cells})
  efg_cli_test(NAME cli.shell_rolled_${cells}
    COMMAND "${efg}|run|${CMAKE_CURRENT_BINARY_DIR}/strip_rolled_${cells}.yaml|-o|${dir}"
    EXIT 0 TEXT "stage 'roll' done: 10 steps" FILE ${dir}/strip_rolled_${cells}.e)
  set_tests_properties(cli.shell_rolled_${cells} PROPERTIES FIXTURES_SETUP shell_rolled_${cells})
endforeach()
add_test(NAME cli.shell_rolled_check COMMAND /usr/bin/python3
  ${CMAKE_CURRENT_SOURCE_DIR}/check_shell_rolled.py ${EFG_CLI_TMP}/shell_rolled_np1/strip_rolled.e
  --levels ${EFG_CLI_TMP}/shell_rolled_24/strip_rolled_24.e
  ${EFG_CLI_TMP}/shell_rolled_96/strip_rolled_96.e)
set_tests_properties(cli.shell_rolled_check PROPERTIES LABELS cli
  FIXTURES_REQUIRED "shell_rolled_np1;shell_rolled_24;shell_rolled_96")
# shell_edge_load in a linear stage: the same strip with small rotations, one solve. Beam theory
# (hand values): the end moment m per width turns the end by m L / (E I) = 2 pi and deflects it
# by -m L^2 / (2 E I) = -12 pi = -37.69911184 (printed to 10 digits; 1e-8 and 3e-9 here).
string(REPLACE ", formulation: total_lagrangian" "" linear "${rolled}")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/strip_end_moment_linear.yaml "${linear}")
efg_cli_test(NAME cli.shell_edge_moment_linear
  COMMAND "${efg}|run|${CMAKE_CURRENT_BINARY_DIR}/strip_end_moment_linear.yaml|-o|${EFG_CLI_TMP}/shell_edge_moment_linear"
  EXIT 0 TEXT "probe_tip_ry = 6.2831853|probe_tip_uz = -37.6991118")
# Finite rotations in an explicit stage: a strip bent to a half circle by a slowly raised end
# moment and held; its implicit twin (the stage replaced by Newton load steps): the same state.
file(READ ${PROJECT_SOURCE_DIR}/tests/scenes/shells/strip_half_roll_explicit.yaml half)
string(REPLACE "{name: bend, driver: explicit, end_time: rise + 20, output_interval: 0.5}"
  "{name: bend, driver: implicit, end_time: rise, load_steps: 10}" half_implicit "${half}")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/strip_half_roll_implicit.yaml "${half_implicit}")
efg_cli_test(NAME cli.shell_half_roll_explicit
  COMMAND "${efg}|run|tests/scenes/shells/strip_half_roll_explicit.yaml|-o|${EFG_CLI_TMP}/shell_half_roll_explicit"
  EXIT 0 TEXT "stage 'bend' (shells, explicit) done" FILE ${EFG_CLI_TMP}/shell_half_roll_explicit/strip_half_roll_explicit.e)
set_tests_properties(cli.shell_half_roll_explicit PROPERTIES FIXTURES_SETUP shell_half_roll_explicit)
efg_cli_test(NAME cli.shell_half_roll_implicit
  COMMAND "${efg}|run|${CMAKE_CURRENT_BINARY_DIR}/strip_half_roll_implicit.yaml|-o|${EFG_CLI_TMP}/shell_half_roll_implicit"
  EXIT 0 TEXT "stage 'bend' done: 10 steps, 0 cutbacks" FILE ${EFG_CLI_TMP}/shell_half_roll_implicit/strip_half_roll_implicit.e)
set_tests_properties(cli.shell_half_roll_implicit PROPERTIES FIXTURES_SETUP shell_half_roll_implicit)
add_test(NAME cli.shell_half_roll_check COMMAND /usr/bin/python3
  ${CMAKE_CURRENT_SOURCE_DIR}/check_shell_rolled.py ${EFG_CLI_TMP}/shell_rolled_np1/strip_rolled.e
  --quasistatic ${EFG_CLI_TMP}/shell_half_roll_explicit/strip_half_roll_explicit.e
  ${EFG_CLI_TMP}/shell_half_roll_implicit/strip_half_roll_implicit.e)
set_tests_properties(cli.shell_half_roll_check PROPERTIES LABELS cli
  FIXTURES_REQUIRED "shell_rolled_np1;shell_half_roll_explicit;shell_half_roll_implicit")
# A follower pressure and its dead twin on a cantilever strip, each against the elastica's
# shooting solution (tests/cli/check_shell_follower.py).
file(READ ${PROJECT_SOURCE_DIR}/tests/scenes/shells/strip_follower_pressure.yaml follower)
string(REPLACE ", follower: true" "" dead "${follower}")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/strip_dead_pressure.yaml "${dead}")
efg_cli_test(NAME cli.shell_follower_pressure
  COMMAND "${efg}|run|tests/scenes/shells/strip_follower_pressure.yaml|-o|${EFG_CLI_TMP}/shell_follower_pressure"
  EXIT 0 TEXT "stage 'bend' done: 20 steps, 0 cutbacks" FILE ${EFG_CLI_TMP}/shell_follower_pressure/strip_follower_pressure.e)
set_tests_properties(cli.shell_follower_pressure PROPERTIES FIXTURES_SETUP shell_follower_pressure)
efg_cli_test(NAME cli.shell_dead_pressure
  COMMAND "${efg}|run|${CMAKE_CURRENT_BINARY_DIR}/strip_dead_pressure.yaml|-o|${EFG_CLI_TMP}/shell_dead_pressure"
  EXIT 0 TEXT "stage 'bend' done: 20 steps, 0 cutbacks" FILE ${EFG_CLI_TMP}/shell_dead_pressure/strip_dead_pressure.e)
set_tests_properties(cli.shell_dead_pressure PROPERTIES FIXTURES_SETUP shell_dead_pressure)
add_test(NAME cli.shell_follower_check COMMAND /usr/bin/python3
  ${CMAKE_CURRENT_SOURCE_DIR}/check_shell_follower.py
  ${EFG_CLI_TMP}/shell_follower_pressure/strip_follower_pressure.e
  ${EFG_CLI_TMP}/shell_dead_pressure/strip_dead_pressure.e)
set_tests_properties(cli.shell_follower_check PROPERTIES LABELS cli
  FIXTURES_REQUIRED "shell_follower_pressure;shell_dead_pressure")
# Curved references: the Scordelis-Lo roof on four levels against 0.3024
# (tests/cli/check_shell_obstacle.py), 1 vs 2 ranks on 16 x 16 (1e-6: Newton ends at the
# round-off floor of the internal force, 2e-6 of the residual's start under the load scaled by
# 1e-4; the displacements agree to 3e-11, the twisting moment on the symmetry line to 1.6e-7).
file(READ ${PROJECT_SOURCE_DIR}/tests/scenes/shells/scordelis_lo.yaml roof)
set(roof_results "")
foreach(cells 8 12 16 24)
  string(REPLACE "cells: [16, 16]" "cells: [${cells}, ${cells}]" level "${roof}")
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/scordelis_lo_${cells}.yaml "${level}")
  set(dir ${EFG_CLI_TMP}/shell_scordelis_${cells})
  efg_cli_test(NAME cli.shell_scordelis_${cells}
    COMMAND "${efg}|run|${CMAKE_CURRENT_BINARY_DIR}/scordelis_lo_${cells}.yaml|-o|${dir}"
    EXIT 0 TEXT "stage 'load' done: 1 steps, 0 cutbacks" FILE ${dir}/scordelis_lo_${cells}.e)
  set_tests_properties(cli.shell_scordelis_${cells} PROPERTIES FIXTURES_SETUP shell_scordelis_${cells})
  list(APPEND roof_results ${dir}/scordelis_lo_${cells}.e)
endforeach()
add_test(NAME cli.shell_scordelis_check COMMAND /usr/bin/python3
  ${CMAKE_CURRENT_SOURCE_DIR}/check_shell_obstacle.py roof ${roof_results})
set_tests_properties(cli.shell_scordelis_check PROPERTIES LABELS cli
  FIXTURES_REQUIRED "shell_scordelis_8;shell_scordelis_12;shell_scordelis_16;shell_scordelis_24")
foreach(ranks 1 2)
  efg_launcher(launcher ${ranks})
  set(dir ${EFG_CLI_TMP}/shell_scordelis_np${ranks})
  efg_cli_test(NAME cli.shell_scordelis_np${ranks}
    COMMAND "${launcher}|run|tests/scenes/shells/scordelis_lo.yaml|-o|${dir}"
    EXIT 0 TEXT "stage 'load' done" FILE ${dir}/history.csv RANKS ${ranks})
  set_tests_properties(cli.shell_scordelis_np${ranks} PROPERTIES FIXTURES_SETUP shell_scordelis_np${ranks})
endforeach()
efg_shell_same_on_ranks(shell_scordelis scordelis_lo.e 1e-6 displacement_x displacement_z)
# The pinched cylinder on four levels against 1.8248e-5 (a point load, shell_point_load).
file(READ ${PROJECT_SOURCE_DIR}/tests/scenes/shells/pinched_cylinder.yaml pinched)
set(pinched_results "")
foreach(cells 8 16 24 32)
  string(REPLACE "cells: [16, 16]" "cells: [${cells}, ${cells}]" level "${pinched}")
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/pinched_cylinder_${cells}.yaml "${level}")
  set(dir ${EFG_CLI_TMP}/shell_pinched_${cells})
  efg_cli_test(NAME cli.shell_pinched_${cells}
    COMMAND "${efg}|run|${CMAKE_CURRENT_BINARY_DIR}/pinched_cylinder_${cells}.yaml|-o|${dir}"
    EXIT 0 TEXT "stage 'load' done: 1 steps, 0 cutbacks" FILE ${dir}/pinched_cylinder_${cells}.e)
  set_tests_properties(cli.shell_pinched_${cells} PROPERTIES FIXTURES_SETUP shell_pinched_${cells})
  list(APPEND pinched_results ${dir}/pinched_cylinder_${cells}.e)
endforeach()
add_test(NAME cli.shell_pinched_check COMMAND /usr/bin/python3
  ${CMAKE_CURRENT_SOURCE_DIR}/check_shell_obstacle.py pinched ${pinched_results})
set_tests_properties(cli.shell_pinched_check PROPERTIES LABELS cli
  FIXTURES_REQUIRED "shell_pinched_8;shell_pinched_16;shell_pinched_24;shell_pinched_32")
# 1 vs 2 ranks on 16 x 16: the point load applied by the rank that evaluates its point.
foreach(ranks 1 2)
  efg_launcher(launcher ${ranks})
  set(dir ${EFG_CLI_TMP}/shell_pinched_np${ranks})
  efg_cli_test(NAME cli.shell_pinched_np${ranks}
    COMMAND "${launcher}|run|tests/scenes/shells/pinched_cylinder.yaml|-o|${dir}"
    EXIT 0 TEXT "stage 'load' done" FILE ${dir}/history.csv RANKS ${ranks})
  set_tests_properties(cli.shell_pinched_np${ranks} PROPERTIES FIXTURES_SETUP shell_pinched_np${ranks})
endforeach()
efg_shell_same_on_ranks(shell_pinched pinched_cylinder.e 1e-9 displacement_x displacement_z)
