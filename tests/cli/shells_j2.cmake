# J2 shells in implicit stages (issue 18, docs/shells.md "J2 shells"; included from
# CMakeLists.txt after its helper functions). A simply supported plate strip pressed statically to
# 0.985 q_c by Newton load steps and released: moments on statics, the plastic strain left by the
# elastic unloading unchanged, the deflection recovered that of the elastic beam, 1 vs 2 ranks;
# and beyond the collapse load the run stops with its last converged load between the 12-layer
# rule's limit and 1 % above (tests/cli/check_shell_j2_implicit.py).
foreach(ranks 1 2)
  efg_launcher(launcher ${ranks})
  set(dir ${EFG_CLI_TMP}/shell_j2_implicit_np${ranks})
  efg_cli_test(NAME cli.shell_j2_implicit_np${ranks}
    COMMAND "${launcher}|run|tests/scenes/shells/strip_j2_implicit.yaml|-o|${dir}"
    EXIT 0 TEXT "stage 'press' done: 10 steps, 0 cutbacks|stage 'release' done: 2 steps, 0 cutbacks"
    FILE ${dir}/history.csv RANKS ${ranks})
  set_tests_properties(cli.shell_j2_implicit_np${ranks} PROPERTIES
    FIXTURES_SETUP shell_j2_implicit_np${ranks})
endforeach()
# (rotation_x is round-off in cylindrical bending: the fields compared are those that carry it)
efg_shell_same_on_ranks(shell_j2_implicit strip_j2_implicit.e 1e-9
  displacement_z rotation_y plastic_strain moment_xx)
# The same held by penalty supports (their boundary terms and tangent in Newton).
efg_run_then_check_file(shell_j2_implicit_penalty tests/scenes/shells/strip_j2_implicit_penalty.yaml
  "stage 'press' done: 10 steps, 0 cutbacks|stage 'release' done: 2 steps, 0 cutbacks"
  strip_j2_implicit_penalty.e check_shell_j2_implicit.py)
efg_cli_test(NAME cli.shell_j2_implicit_collapse
  COMMAND "${efg}|run|tests/scenes/shells/strip_j2_implicit_collapse.yaml|-o|${EFG_CLI_TMP}/shell_j2_implicit_collapse"
  EXIT 3 TEXT "the tangent is singular (a mechanism)|is reached (beyond a limit load, no equilibrium exists)"
  FILE ${EFG_CLI_TMP}/shell_j2_implicit_collapse/strip_j2_implicit_collapse.e.part)
set_tests_properties(cli.shell_j2_implicit_collapse PROPERTIES FIXTURES_SETUP shell_j2_implicit_collapse)
# Clamped at both ends: hinges at the clamps, whose moments come from the edge points' own J2
# layers; the unloading recovers the elastic twin's response to round-off. Clamps and load
# released by a springback stage: the end state of the release at once. Explicit and implicit
# J2 shells on a quasi-static plastic loading (0.9 q_c, smooth ramp): the same state.
foreach(scene strip_j2_clamped strip_elastic_clamped strip_j2_springback_release
        strip_j2_direct_release strip_j2_quasistatic_explicit strip_j2_quasistatic_implicit)
  efg_cli_test(NAME cli.shell_${scene}
    COMMAND "${efg}|run|tests/scenes/shells/${scene}.yaml|-o|${EFG_CLI_TMP}/shell_${scene}"
    EXIT 0 TEXT "stage 'press'" FILE ${EFG_CLI_TMP}/shell_${scene}/${scene}.e)
  set_tests_properties(cli.shell_${scene} PROPERTIES FIXTURES_SETUP shell_${scene})
endforeach()
add_test(NAME cli.shell_j2_implicit_check COMMAND /usr/bin/python3
  ${CMAKE_CURRENT_SOURCE_DIR}/check_shell_j2_implicit.py
  ${EFG_CLI_TMP}/shell_j2_implicit_np1/strip_j2_implicit.e
  --collapse ${EFG_CLI_TMP}/shell_j2_implicit_collapse/strip_j2_implicit_collapse.e.part
  --clamped ${EFG_CLI_TMP}/shell_strip_j2_clamped/strip_j2_clamped.e
            ${EFG_CLI_TMP}/shell_strip_elastic_clamped/strip_elastic_clamped.e
  --springback ${EFG_CLI_TMP}/shell_strip_j2_springback_release/strip_j2_springback_release.e
               ${EFG_CLI_TMP}/shell_strip_j2_direct_release/strip_j2_direct_release.e
  --quasistatic ${EFG_CLI_TMP}/shell_strip_j2_quasistatic_explicit/strip_j2_quasistatic_explicit.e
                ${EFG_CLI_TMP}/shell_strip_j2_quasistatic_implicit/strip_j2_quasistatic_implicit.e)
set_tests_properties(cli.shell_j2_implicit_check PROPERTIES LABELS cli FIXTURES_REQUIRED
  "shell_j2_implicit_np1;shell_j2_implicit_collapse;shell_strip_j2_clamped;shell_strip_elastic_clamped;shell_strip_j2_springback_release;shell_strip_j2_direct_release;shell_strip_j2_quasistatic_explicit;shell_strip_j2_quasistatic_implicit")
# Runs tests/scenes/shells/<scene>.yaml as cli.<name> (expecting `text`), then checks its results
# with tests/cli/<check> as cli.<name>_check.
function(efg_shell_run_and_check name scene text check)
  set(dir ${EFG_CLI_TMP}/${name})
  efg_cli_test(NAME cli.${name}
    COMMAND "${efg}|run|tests/scenes/shells/${scene}.yaml|-o|${dir}"
    EXIT 0 TEXT "${text}" FILE ${dir}/${scene}.e)
  set_tests_properties(cli.${name} PROPERTIES FIXTURES_SETUP ${name})
  add_test(NAME cli.${name}_check
    COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/${check} ${dir}/${scene}.e)
  set_tests_properties(cli.${name}_check PROPERTIES LABELS cli FIXTURES_REQUIRED ${name})
endfunction()
# Springback of a J2 shell (issues 18 and 21): bent explicitly by end rotations to 10 kappa_y,
# released implicitly (the layers' history handed from the explicit stage to the Newton stage):
# the curvature springs back by the closed form M / (E' I) (3 %) and by the bent strip's own
# moment over E' I (1 %).
efg_shell_run_and_check(shell_j2_springback strip_j2_springback
  "stage 'bend' (shells, explicit) done: 34499 steps|stage 'release' done: 1 steps, 0 cutbacks"
  check_shell_springback.py)
# The thickness output: a J2 strip pulled elastically, then past yield; every particle's
# thickness against the hand values of uniaxial plane stress (tests/cli/check_shell_thickness.py).
efg_shell_run_and_check(shell_j2_thinning strip_j2_thinning
  "stage 'plastic' done: 4 steps, 0 cutbacks" check_shell_thickness.py)
