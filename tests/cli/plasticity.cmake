# Plasticity command-line and verification tests (docs/plasticity.md), included by
# tests/cli/CMakeLists.txt (its helpers and variables: efg, EFG_CLI_TMP, EFG_MPIRUN2).
# J2 plasticity (docs/plasticity.md): a homogeneous uniaxial tension block (loading, then elastic
# unloading) against the closed form at every record to round-off, on 1 and 2 ranks, and 1 vs 2
# ranks; the same at finite strain (stretch 1.5).
efg_cli_test(NAME cli.j2_tension COMMAND "${efg}|run|tests/scenes/plasticity/j2_tension.yaml|-o|${EFG_CLI_TMP}/j2_tension"
  EXIT 0 TEXT "stage 'stretch' done: 8 steps, 0 cutbacks" FILE ${EFG_CLI_TMP}/j2_tension/j2_tension.e)
efg_cli_test(NAME cli.j2_tension_np2 COMMAND "${EFG_MPIRUN2}|${efg}|run|tests/scenes/plasticity/j2_tension.yaml|-o|${EFG_CLI_TMP}/j2_tension_np2"
  EXIT 0 TEXT "stage 'stretch' done: 8 steps, 0 cutbacks" FILE ${EFG_CLI_TMP}/j2_tension_np2/j2_tension.e RANKS 2)
add_test(NAME cli.j2_tension_closed_form COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/check_j2_tension.py
  ${EFG_CLI_TMP}/j2_tension/j2_tension.e ${EFG_CLI_TMP}/j2_tension_np2/j2_tension.e)
set_tests_properties(cli.j2_tension_closed_form PROPERTIES LABELS cli FIXTURES_REQUIRED j2_tension)
set_tests_properties(cli.j2_tension cli.j2_tension_np2 PROPERTIES FIXTURES_SETUP j2_tension)
# Mixed u-p J2 (issue 17) at nu = 0.4999: the small-strain block (tolerance 1e-6: round-off grows
# with kappa / mu, measured 3.7e-8) and the finite-strain block (tolerance 1e-7, measured 4e-9;
# the output stress missed the cells' pressure for path-dependent parts, 1.4 sigma_y).
foreach(kind mixed finite_mixed)
  efg_cli_test(NAME cli.j2_tension_${kind} COMMAND "${efg}|run|tests/scenes/plasticity/j2_tension_${kind}.yaml|-o|${EFG_CLI_TMP}/j2_tension_${kind}"
    EXIT 0 TEXT "stage 'stretch' done: 8 steps, 0 cutbacks" FILE ${EFG_CLI_TMP}/j2_tension_${kind}/j2_tension_${kind}.e)
  set_tests_properties(cli.j2_tension_${kind} PROPERTIES FIXTURES_SETUP j2_tension_${kind})
endforeach()
add_test(NAME cli.j2_tension_mixed_closed_form COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/check_j2_tension.py
  --nu 0.4999 --tolerance 1e-6 ${EFG_CLI_TMP}/j2_tension_mixed/j2_tension_mixed.e)
add_test(NAME cli.j2_tension_finite_mixed_closed_form COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/check_j2_tension.py
  --finite --nu 0.4999 --tolerance 1e-7 ${EFG_CLI_TMP}/j2_tension_finite_mixed/j2_tension_finite_mixed.e)
foreach(kind mixed finite_mixed)
  set_tests_properties(cli.j2_tension_${kind}_closed_form PROPERTIES LABELS cli FIXTURES_REQUIRED j2_tension_${kind})
endforeach()
efg_cli_test(NAME cli.j2_tension_finite COMMAND "${efg}|run|tests/scenes/plasticity/j2_tension_finite.yaml|-o|${EFG_CLI_TMP}/j2_tension_finite"
  EXIT 0 TEXT "stage 'stretch' done: 8 steps, 0 cutbacks" FILE ${EFG_CLI_TMP}/j2_tension_finite/j2_tension_finite.e)
# (Without the extrapolated predictor the second load step's Newton path depended on the linear
# solver's round-off: 0 cutbacks with UMFPACK and KLU2, 1 with MUMPS; docs/implicit.md.)
add_test(NAME cli.j2_tension_finite_closed_form COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/check_j2_tension.py
  --finite ${EFG_CLI_TMP}/j2_tension_finite/j2_tension_finite.e)
set_tests_properties(cli.j2_tension_finite_closed_form PROPERTIES LABELS cli FIXTURES_REQUIRED j2_tension_finite)
set_tests_properties(cli.j2_tension_finite PROPERTIES FIXTURES_SETUP j2_tension_finite)
# J2 with SCNI subcells (a history per piece of each nodal domain): small strain on 1 and 2 ranks,
# finite strain; the closed form to round-off.
foreach(kind subcells finite_subcells)
  efg_cli_test(NAME cli.j2_tension_${kind} COMMAND "${efg}|run|tests/scenes/plasticity/j2_tension_${kind}.yaml|-o|${EFG_CLI_TMP}/j2_tension_${kind}"
    EXIT 0 TEXT "stage 'stretch' done: 8 steps, 0 cutbacks" FILE ${EFG_CLI_TMP}/j2_tension_${kind}/j2_tension_${kind}.e)
  set_tests_properties(cli.j2_tension_${kind} PROPERTIES FIXTURES_SETUP j2_tension_${kind})
endforeach()
efg_cli_test(NAME cli.j2_tension_subcells_np2 COMMAND "${EFG_MPIRUN2}|${efg}|run|tests/scenes/plasticity/j2_tension_subcells.yaml|-o|${EFG_CLI_TMP}/j2_tension_subcells_np2"
  EXIT 0 TEXT "stage 'stretch' done: 8 steps, 0 cutbacks" FILE ${EFG_CLI_TMP}/j2_tension_subcells_np2/j2_tension_subcells.e RANKS 2)
set_tests_properties(cli.j2_tension_subcells_np2 PROPERTIES FIXTURES_SETUP j2_tension_subcells)
add_test(NAME cli.j2_tension_subcells_closed_form COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/check_j2_tension.py
  ${EFG_CLI_TMP}/j2_tension_subcells/j2_tension_subcells.e ${EFG_CLI_TMP}/j2_tension_subcells_np2/j2_tension_subcells.e)
add_test(NAME cli.j2_tension_finite_subcells_closed_form COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/check_j2_tension.py
  --finite ${EFG_CLI_TMP}/j2_tension_finite_subcells/j2_tension_finite_subcells.e)
foreach(kind subcells finite_subcells)
  set_tests_properties(cli.j2_tension_${kind}_closed_form PROPERTIES LABELS cli FIXTURES_REQUIRED j2_tension_${kind})
endforeach()
# The same on perturbed particles (it stalled near a stretch of 1.25 before the predictor).
efg_cli_test(NAME cli.j2_tension_finite_perturbed COMMAND "${efg}|run|tests/scenes/plasticity/j2_tension_finite_perturbed.yaml|-o|${EFG_CLI_TMP}/j2_tension_finite_perturbed"
  EXIT 0 TEXT "stage 'stretch' done: 8 steps, 0 cutbacks" FILE ${EFG_CLI_TMP}/j2_tension_finite_perturbed/j2_tension_finite_perturbed.e)
set_tests_properties(cli.j2_tension_finite_perturbed PROPERTIES FIXTURES_SETUP j2_tension_finite_perturbed)
add_test(NAME cli.j2_tension_finite_perturbed_closed_form COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/check_j2_tension.py
  --finite ${EFG_CLI_TMP}/j2_tension_finite_perturbed/j2_tension_finite_perturbed.e)
set_tests_properties(cli.j2_tension_finite_perturbed_closed_form PROPERTIES LABELS cli FIXTURES_REQUIRED j2_tension_finite_perturbed)
# On 2 ranks the line search met det F <= 0 at one rank's boundary point only: that rank left
# for the failure reduction while the other waited in the residual's export, forever (found with
# MUMPS). Failures among one rank's points are now agreed before every export.
efg_cli_test(NAME cli.j2_tension_finite_np2 COMMAND "${EFG_MPIRUN2}|${efg}|run|tests/scenes/plasticity/j2_tension_finite.yaml|-o|${EFG_CLI_TMP}/j2_tension_finite_np2"
  EXIT 0 TEXT "stage 'stretch' done: 8 steps, 0 cutbacks" RANKS 2)
set_tests_properties(cli.j2_tension_finite_np2 PROPERTIES TIMEOUT 120)
# Erosion: the plastic zone of the wall impact fails at 5 % plastic strain (check_erosion.py;
# every step recorded: each particle erodes in the step that takes it past the failure strain).
# The stable step is re-estimated as points erode (the stiffness falls; a small-strain part's
# elastic probe does not change with strain), unlike a linear elastic stage's.
efg_cli_test(NAME cli.j2_erosion COMMAND "${efg}|run|tests/scenes/plasticity/plastic_wave_erosion.yaml|-o|${EFG_CLI_TMP}/erosion"
  EXIT 0 TEXT "stage 'impact' done|stable-step re-estimates" FILE ${EFG_CLI_TMP}/erosion/plastic_wave_erosion.e)
add_test(NAME cli.j2_erosion_flags COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/check_erosion.py
  ${EFG_CLI_TMP}/erosion/plastic_wave_erosion.e ${EFG_CLI_TMP}/erosion/history.csv 0.05 0.02)
set_tests_properties(cli.j2_erosion_flags PROPERTIES LABELS cli FIXTURES_REQUIRED erosion)
set_tests_properties(cli.j2_erosion PROPERTIES FIXTURES_SETUP erosion)
# The same on 2 ranks: history and fields (plastic strain, erosion flags) equal to 1 rank.
efg_cli_test(NAME cli.j2_erosion_np2 COMMAND "${EFG_MPIRUN2}|${efg}|run|tests/scenes/plasticity/plastic_wave_erosion.yaml|-o|${EFG_CLI_TMP}/erosion_np2"
  EXIT 0 TEXT "stage 'impact' done" FILE ${EFG_CLI_TMP}/erosion_np2/history.csv RANKS 2)
add_test(NAME cli.j2_erosion_ranks COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/check_same_on_ranks.py 1e-9
  ${EFG_CLI_TMP}/erosion/history.csv ${EFG_CLI_TMP}/erosion_np2/history.csv
  ${EFG_CLI_TMP}/erosion/plastic_wave_erosion.e ${EFG_CLI_TMP}/erosion_np2/plastic_wave_erosion.e
  plastic_strain eroded stress_xx displacement_x)
set_tests_properties(cli.j2_erosion_ranks PROPERTIES LABELS "cli;mpi" FIXTURES_REQUIRED "erosion;erosion_np2")
set_tests_properties(cli.j2_erosion_np2 PROPERTIES FIXTURES_SETUP erosion_np2)
# Taylor bar (tests/verification/taylor_bar): explicit finite-strain J2 impact at 227 m/s with
# efg's default time-step settings (dt_scale 0.9; re-estimates from step 1, interval doubling to
# 100 and halving when the stable step falls: the step falls > 10x during the impact). The impact
# face held on the wall plane, free to slide (the references' condition): final length within 1 %
# of 21.43 mm and footprint within 2 % of 7.22 mm (Foulk et al. 2021; Simo 1992 7.12; README.md
# for the sources), energy balance < 1 %. The penalty-wall variant overshoots the footprint (README).
add_test(NAME verification.taylor_bar
  COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/verification/taylor_bar/run_taylor.py
          --radial 4 --impact clamp ${efg} ${EFG_CLI_TMP}/taylor_bar)
set_tests_properties(verification.taylor_bar PROPERTIES LABELS verification TIMEOUT 600)
# The same with erosion on (failure_strain 2.0: the particles near the impact face fail): no
# inverted point, energy balance < 1 % with the eroded energy; lengths reported only.
add_test(NAME verification.taylor_bar_erosion
  COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/verification/taylor_bar/run_taylor.py
          --radial 4 --impact clamp --failure-strain 2.0
          ${efg} ${EFG_CLI_TMP}/taylor_bar_erosion)
set_tests_properties(verification.taylor_bar_erosion PROPERTIES LABELS verification TIMEOUT 600)
# Thick-walled cylinder under internal pressure, plane strain (tests/verification/thick_cylinder):
# elastic against Lame; elastic-perfectly plastic J2 against Hill (1950) and an exact radial J2
# reference, up to collapse (2/sqrt 3) sigma_y ln(b/a), approached from below.
foreach(kind elastic plastic)
  add_test(NAME verification.thick_cylinder_${kind}
    COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/verification/thick_cylinder/run_cylinder.py
            --material ${kind} ${efg} ${EFG_CLI_TMP}/thick_cylinder_${kind})
  set_tests_properties(verification.thick_cylinder_${kind} PROPERTIES LABELS verification TIMEOUT 600)
endforeach()
# Nearly incompressible J2 (nu = 0.4999) with the cell pressure (formulation mixed_up; issue 17):
# against Hill, exact as nu -> 1/2, c within 0.33 % and u(b) within 0.30 % up to 0.98 p_L, checked
# to 0.5 %. The displacement formulation on the same tube misses the plastic radius by 7.5 % (it
# locks); keeping the bulk modulus at the J2 points as well as in the cells gives u(b) -1.03 %.
add_test(NAME verification.thick_cylinder_plastic_mixed
  COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/verification/thick_cylinder/run_cylinder.py
          --material plastic --poissons-ratio 0.4999 --formulation mixed_up --plastic-tolerance 0.005
          ${efg} ${EFG_CLI_TMP}/thick_cylinder_plastic_mixed)
set_tests_properties(verification.thick_cylinder_plastic_mixed PROPERTIES LABELS verification TIMEOUT 600)
# The same with SCNI subcells (the J2 history at each piece of a nodal domain; output the
# volume-weighted mean of a particle's pieces): u(b) within 0.03 % of Hill at every load up to
# 0.98 p_L (default SCNI: 0.30 %), checked to 0.1 %; c within 0.72 %, checked to 1 % (a
# particle whose domain is partly plastic shows a positive mean: the averaged boundary of the
# plastic zone moves out by up to half a ring, 2.5 mm of 105..177).
add_test(NAME verification.thick_cylinder_plastic_mixed_subcells
  COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/tests/verification/thick_cylinder/run_cylinder.py
          --material plastic --poissons-ratio 0.4999 --formulation mixed_up --integration scni_subcells
          --plastic-tolerance 0.001 --c-tolerance 0.01 ${efg} ${EFG_CLI_TMP}/thick_cylinder_plastic_mixed_subcells)
set_tests_properties(verification.thick_cylinder_plastic_mixed_subcells PROPERTIES LABELS verification TIMEOUT 600)
