# Finite rotations and curved references of shells (issue 18, docs/shells.md "Finite rotations",
# "Curved references"; included from CMakeLists.txt after its helper functions).

# Runs of `scene` with its text `from` replaced by "cells: [C, C2]" for each C of `levels`
# (written at configure time), named cli.<name>_<C>, results <dir>/<stem>_<C>.e; `out` gets the
# list of result files in order. `second`: the second cell count ("" for square levels).
function(efg_shell_levels name scene from second levels text out)
  get_filename_component(stem ${scene} NAME_WE)
  file(READ ${PROJECT_SOURCE_DIR}/${scene} original)
  set(results "")
  foreach(cells ${levels})
    if(second)
      set(to "cells: [${cells}, ${second}]")
    else()
      set(to "cells: [${cells}, ${cells}]")
    endif()
    string(REPLACE "${from}" "${to}" level "${original}")
    file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/${stem}_${cells}.yaml "${level}")
    set(dir ${EFG_CLI_TMP}/${name}_${cells})
    efg_cli_test(NAME cli.${name}_${cells}
      COMMAND "${efg}|run|${CMAKE_CURRENT_BINARY_DIR}/${stem}_${cells}.yaml|-o|${dir}"
      EXIT 0 TEXT "${text}" FILE ${dir}/${stem}_${cells}.e)
    set_tests_properties(cli.${name}_${cells} PROPERTIES FIXTURES_SETUP ${name}_${cells})
    list(APPEND results ${dir}/${stem}_${cells}.e)
  endforeach()
  set(${out} ${results} PARENT_SCOPE)
endfunction()

# The rolled strip: a cantilever strip under an end moment 2 pi E I / L in 10 Newton load steps
# follows the elastica's arcs and closes into a circle (end within 1 % of L of the clamp),
# Newton's tail quadratic, the closure error falling over 24, 48 and 96 cells; 1 vs 2 ranks
# (1e-8: the twisting moment, zero by symmetry, is the round-off of 110 Newton iterations; the
# other columns agree to 1e-12). tests/cli/check_shell_rolled.py.
efg_scene_on_ranks(shell_rolled tests/scenes/shells/strip_rolled.yaml
  "stage 'roll' done: 10 steps, 0 cutbacks" "")
efg_shell_same_on_ranks(shell_rolled strip_rolled.e 1e-8
  displacement_x displacement_z rotation_y moment_xx)
efg_shell_levels(shell_rolled tests/scenes/shells/strip_rolled.yaml "cells: [48, 2]" 2 "24;96"
  "stage 'roll' done: 10 steps" rolled_levels)
add_test(NAME cli.shell_rolled_check COMMAND /usr/bin/python3
  ${CMAKE_CURRENT_SOURCE_DIR}/check_shell_rolled.py ${EFG_CLI_TMP}/shell_rolled_np1/strip_rolled.e
  --levels ${rolled_levels})
set_tests_properties(cli.shell_rolled_check PROPERTIES LABELS cli
  FIXTURES_REQUIRED "shell_rolled_np1;shell_rolled_24;shell_rolled_96")

# shell_edge_load in a linear stage: the same strip with small rotations, one solve. Beam theory
# (hand values): the end moment m per width turns the end by m L / (E I) = 2 pi and deflects it
# by -m L^2 / (2 E I) = -12 pi = -37.69911184 (printed to 10 digits; 1e-8 and 3e-9 here).
file(READ ${PROJECT_SOURCE_DIR}/tests/scenes/shells/strip_rolled.yaml rolled)
string(REPLACE ", formulation: total_lagrangian" "" linear "${rolled}")
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/strip_end_moment_linear.yaml "${linear}")
efg_cli_test(NAME cli.shell_edge_moment_linear
  COMMAND "${efg}|run|${CMAKE_CURRENT_BINARY_DIR}/strip_end_moment_linear.yaml|-o|${EFG_CLI_TMP}/shell_edge_moment_linear"
  EXIT 0 TEXT "probe_tip_ry = 6.2831853|probe_tip_uz = -37.6991118")

# A scene and its twin (its text `from` replaced by `to`, written at configure time): runs
# cli.<name> and cli.<name>_twin (fixtures of the same names) expecting `text` and `twin_text`;
# `out` gets their result files.
function(efg_shell_twins name scene from to text twin_text out)
  get_filename_component(stem ${scene} NAME_WE)
  file(READ ${PROJECT_SOURCE_DIR}/${scene} original)
  string(REPLACE "${from}" "${to}" twin "${original}")
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/${stem}_twin.yaml "${twin}")
  foreach(kind "" _twin)
    set(dir ${EFG_CLI_TMP}/${name}${kind})
    if(kind)
      set(file ${CMAKE_CURRENT_BINARY_DIR}/${stem}_twin.yaml)
      set(expect "${twin_text}")
    else()
      set(file ${scene})
      set(expect "${text}")
    endif()
    efg_cli_test(NAME cli.${name}${kind} COMMAND "${efg}|run|${file}|-o|${dir}" EXIT 0
      TEXT "${expect}" FILE ${dir}/${stem}${kind}.e)
    set_tests_properties(cli.${name}${kind} PROPERTIES FIXTURES_SETUP ${name}${kind})
  endforeach()
  set(${out} ${EFG_CLI_TMP}/${name}/${stem}.e ${EFG_CLI_TMP}/${name}_twin/${stem}_twin.e
      PARENT_SCOPE)
endfunction()

# Finite rotations in an explicit stage: a strip bent to a half circle by a slowly raised end
# moment (half_roll) or turned there by its end's prescribed rotation (half_turn; each explicit
# step's rows hold the rotation's change over the step), held; its implicit twin (the stage
# replaced by Newton load steps): the same state (check_shell_rolled.py --quasistatic).
foreach(drive roll turn)
  efg_shell_twins(shell_half_${drive} tests/scenes/shells/strip_half_${drive}_explicit.yaml
    "{name: bend, driver: explicit, end_time: rise + 20, output_interval: 0.5}"
    "{name: bend, driver: implicit, end_time: rise, load_steps: 10}"
    "stage 'bend' (shells, explicit) done" "stage 'bend' done: 10 steps, 0 cutbacks" twins)
  add_test(NAME cli.shell_half_${drive}_check COMMAND /usr/bin/python3
    ${CMAKE_CURRENT_SOURCE_DIR}/check_shell_rolled.py ${EFG_CLI_TMP}/shell_rolled_np1/strip_rolled.e
    --quasistatic ${twins})
  set_tests_properties(cli.shell_half_${drive}_check PROPERTIES LABELS cli
    FIXTURES_REQUIRED "shell_rolled_np1;shell_half_${drive};shell_half_${drive}_twin")
endforeach()
# and the explicit stage on 1 vs 2 ranks (the round-off of 33,726 steps, 1e-8; measured 5.6e-9
# on the tip rotation about x, zero by symmetry)
efg_scene_on_ranks(shell_half_roll_explicit tests/scenes/shells/strip_half_roll_explicit.yaml
  "stage 'bend' (shells, explicit) done" "")
efg_shell_same_on_ranks(shell_half_roll_explicit strip_half_roll_explicit.e 1e-8
  displacement_x displacement_z rotation_y moment_xx)

# A follower pressure and its dead twin on a cantilever strip, each against the elastica's
# shooting solution (tests/cli/check_shell_follower.py).
efg_shell_twins(shell_follower tests/scenes/shells/strip_follower_pressure.yaml
  ", follower: true" "" "stage 'bend' done: 20 steps, 0 cutbacks"
  "stage 'bend' done: 20 steps, 0 cutbacks" follower_pair)
add_test(NAME cli.shell_follower_check COMMAND /usr/bin/python3
  ${CMAKE_CURRENT_SOURCE_DIR}/check_shell_follower.py ${follower_pair})
set_tests_properties(cli.shell_follower_check PROPERTIES LABELS cli
  FIXTURES_REQUIRED "shell_follower;shell_follower_twin")

# Curved references, the obstacle course on four levels each (tests/cli/check_shell_obstacle.py):
# the Scordelis-Lo roof against 0.3024 and the pinched cylinder (a shell_point_load) against
# 1.8248e-5; 1 vs 2 ranks on 16 x 16: the roof to 1e-6 (Newton ends at the round-off floor of
# the internal force, 2e-6 of the residual's start under its load scaled by 1e-4; the
# displacements agree to 3e-11, the twisting moment on the symmetry line to 1.6e-7), the
# cylinder to 1e-9 (measured 1e-13; its point load applied by the rank evaluating the point).
# The obstacle-course case `case` of check_shell_obstacle.py: `scene` on `levels`, checked.
function(efg_shell_obstacle name case scene levels)
  efg_shell_levels(${name} ${scene} "cells: [16, 16]" "" "${levels}"
    "stage 'load' done: 1 steps, 0 cutbacks" results)
  set(fixtures "")
  foreach(cells ${levels})
    list(APPEND fixtures ${name}_${cells})
  endforeach()
  add_test(NAME cli.${name}_check COMMAND /usr/bin/python3
    ${CMAKE_CURRENT_SOURCE_DIR}/check_shell_obstacle.py ${case} ${results})
  set_tests_properties(cli.${name}_check PROPERTIES LABELS cli FIXTURES_REQUIRED "${fixtures}")
  efg_scene_on_ranks(${name} ${scene} "stage 'load' done" "")
endfunction()
efg_shell_obstacle(shell_scordelis roof tests/scenes/shells/scordelis_lo.yaml "8;12;16;24")
efg_shell_same_on_ranks(shell_scordelis scordelis_lo.e 1e-6 displacement_x displacement_z)
efg_shell_obstacle(shell_pinched pinched tests/scenes/shells/pinched_cylinder.yaml "8;16;24;32")
efg_shell_same_on_ranks(shell_pinched pinched_cylinder.e 1e-9 displacement_x displacement_z)
# The pinched hemisphere (a latitude-longitude map, no isometry: the strains' metric) against
# 0.093 on 12, 16, 24 and 32 cells; 1 vs 2 ranks on 16 x 16 to 1e-7 (measured 1.0e-8, in the
# bending moment at the load point: Newton stops at its round-off floor, 2e-4 of the residual's
# start under the load scaled by 1e-4, with a membrane to bending stiffness ratio (R/t)^2 = 6e4).
efg_shell_obstacle(shell_hemisphere hemisphere tests/scenes/shells/pinched_hemisphere.yaml
  "12;16;24;32")
efg_shell_same_on_ranks(shell_hemisphere pinched_hemisphere.e 1e-7 displacement_x displacement_y
  displacement_z)

# Shell surfaces read as 3D Exodus meshes (SHELL4; tests/verification/shell_surface/run_surface.py
# writes the meshes and scenes): the roof on 8, 12, 16, 24 cells within 2 % from 16 on (as its
# 2D-chart twin above: +0.79 / +0.15 % at 16 / 24 against +0.74 / +0.13 %), the hemisphere on 16,
# 24, 32 within 3 %, the finest within 2 % (measured +2.71 / +2.00 / +1.53 %: the projection chart
# converges more slowly than the latitude-longitude one); 1 vs 2 ranks on 12 x 12 to 2e-6
# (measured: displacements 6e-9 / 2e-8, moments 6e-7; both runs end at Newton's round-off floor,
# 1.4e-4 of the residual's start, their first iterates already apart by 3e-5 in the residual:
# the projection chart's stiffness is worse conditioned than the latitude-longitude one's).
string(REPLACE ";" " " efg_mpirun2_words "${EFG_MPIEXEC};${EFG_MPIEXEC_FLAGS};${MPIEXEC_NUMPROC_FLAG};2")
set(efg_run_surface /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/verification/shell_surface/run_surface.py ${efg})
add_test(NAME verification.shell_surface_roof
  COMMAND ${efg_run_surface} ${EFG_CLI_TMP}/shell_surface_roof roof --levels 8,12,16,24)
add_test(NAME verification.shell_surface_hemisphere
  COMMAND ${efg_run_surface} ${EFG_CLI_TMP}/shell_surface_hemisphere hemisphere --levels 16,24,32
          --bound 0.03 --final-bound 0.02)
add_test(NAME verification.shell_surface_ranks
  COMMAND ${efg_run_surface} ${EFG_CLI_TMP}/shell_surface_ranks hemisphere --levels 12
          --check-from 100 --np2 "${efg_mpirun2_words}" --rank-tol 2e-6)
# Read in slices on 2 ranks (mesh.read: distributed; the chart made from the slices,
# model/SurfaceSliceChart.hpp), against one rank with the whole mesh: the roof on 32 x 32 cells
# by efg's projection (each rank's part 76 % of the surface), the hemisphere on 24 x 24 by the
# chart given below (84 %; its loads at 3D points, and the pin's box of 3D corners, which holds
# no node of one rank's part). Measured, probes: roof 9.4e-7 (the root read on 2 ranks: 2.3e-6;
# both end at Newton's round-off floor, 3e-5 of the residual's start), hemisphere 7.3e-8 at 32.
add_test(NAME verification.shell_surface_distributed
  COMMAND ${efg_run_surface} ${EFG_CLI_TMP}/shell_surface_distributed roof --levels 32
          --check-from 100 --np2 "${efg_mpirun2_words}" --rank-tol 5e-6 --distributed)
add_test(NAME verification.shell_surface_distributed_chart
  COMMAND ${efg_run_surface} ${EFG_CLI_TMP}/shell_surface_distributed_chart hemisphere --levels 24
          --check-from 100 --np2 "${efg_mpirun2_words}" --rank-tol 2e-6 --distributed
          --chart "R * asin(z / R); R * atan2(y, x)")
set_tests_properties(verification.shell_surface_distributed
  verification.shell_surface_distributed_chart PROPERTIES LABELS "verification;mpi"
  PROCESSORS 2 TIMEOUT 600)
# The hemisphere's 3D mesh with the chart given (mesh.chart: latitude and longitude as arc
# lengths): the latitude-longitude convergence of the 2D-chart scene comes back.
add_test(NAME verification.shell_surface_hemisphere_chart
  COMMAND ${efg_run_surface} ${EFG_CLI_TMP}/shell_surface_hemisphere_chart hemisphere
          --levels 12,16,24,32 --chart "R * asin(z / R); R * atan2(y, x)")
set_tests_properties(verification.shell_surface_roof verification.shell_surface_hemisphere
  verification.shell_surface_hemisphere_chart PROPERTIES LABELS verification TIMEOUT 600)
set_tests_properties(verification.shell_surface_ranks PROPERTIES LABELS "verification;mpi"
  PROCESSORS 2 TIMEOUT 600)

# Prescribed rotations with finite rotations: the rolled strip driven by its end's rotation 2 pi
# (ry, rx held) instead of the moment, the same elastica (check_shell_rolled.py; the quadratic
# tail from the second step on, see there). Measured: positions 1.4e-4 L, rotations 3.5e-4 rad,
# moments 0.22 %, the end back at the clamp.
efg_run_then_check_file(shell_rolled_by_rotation tests/scenes/shells/strip_rolled_by_rotation.yaml
  "stage 'roll' done: 10 steps, 0 cutbacks" strip_rolled_by_rotation.e check_shell_rolled.py
  --tail-from-step 2)

# The 3D-mesh path from the command line (tests/scenes/shells/roof_surface_4.yaml): `efg check` and
# `efg run` report the chart; the roof's mean normal tilts by 20 degrees about y, by hand
# (sin 20, 0, cos 20) = (0.342, 0, 0.940).
efg_cli_test(NAME cli.shell_surface_check
  COMMAND "${efg}|check|tests/scenes/shells/roof_surface_4.yaml" EXIT 0
  TEXT "shell surface read in 3D (25 nodes), charted by projection onto the plane normal to (0.342, 0, 0.94)")
efg_cli_test(NAME cli.shell_surface_run
  COMMAND "${efg}|run|tests/scenes/shells/roof_surface_4.yaml|-o|${EFG_CLI_TMP}/shell_surface_run"
  EXIT 0 TEXT "charted by projection onto the plane normal to (0.342, 0, 0.94)|stage 'load' done: 1 steps"
  FILE ${EFG_CLI_TMP}/shell_surface_run/roof_surface_4.e)
