# Runs one regression case (cmake -P): efg on RANKS ranks, then SEACAS exodiff of the result against
# the gold with the case's command file. Registered by efg_regression_case() in CMakeLists.txt.
#   -DEFG=path              the efg binary
#   -DMPIRUN="a|b|c"        the mpiexec launcher and its flags, | separated (used when RANKS > 1)
#   -DRANKS=N               number of MPI ranks
#   -DSCENE=path            scene.yaml
#   -DGOLD=path             gold.e
#   -DCOMMANDS=path         exodiff command file (per-variable tolerances)
#   -DOUTDIR=path           folder for the result (emptied first)
#   -DEXODIFF=path          exodiff (searched in EXODIFF_HINTS at run time when it does not exist)
#   -DEXODIFF_HINTS="a|b"   folders to search for exodiff
#   -DTIMES=path            folder where each run leaves its timing for the summary
#   -DTEST=name             the test name (for the timing file)
#   -DJOIN=ON               the scene writes one file per rank (output.files: per_rank): on more
#                           than one rank SEACAS epu (beside exodiff) joins them into the result
#   -DEXPECT_DIFFERENCE=regex  mutant mode, for tests registered with WILL_FAIL: the script fails
#                           (and CTest, inverting, passes) only when efg succeeded and exodiff
#                           reported different files (exit code 2) with output matching the regex.
#                           Any other outcome (efg failed, exodiff missing or crashed, files the
#                           same, text absent) ends the script normally, which WILL_FAIL turns into
#                           a failed test: a mutant only passes for the right reason.
cmake_minimum_required(VERSION 3.18)

function(now out)
  execute_process(COMMAND date +%s.%N OUTPUT_VARIABLE t OUTPUT_STRIP_TRAILING_WHITESPACE)
  set(${out} ${t} PARENT_SCOPE)
endfunction()
function(seconds_between a b out)
  execute_process(COMMAND awk "BEGIN { printf \"%.2f\", ${b} - ${a} }" OUTPUT_VARIABLE s)
  set(${out} ${s} PARENT_SCOPE)
endfunction()

# In mutant mode a wrong outcome must not fail the script (WILL_FAIL would count it as passed).
function(wrong text)
  if(EXPECT_DIFFERENCE)
    message("REGRESSION MUTANT NOT CAUGHT FOR THE RIGHT REASON (reported as a failure by WILL_FAIL):\n${text}")
    file(WRITE "${TIMES}/${TEST}.txt" "${TEST} 0 0 wrong\n")
    # Normal end of the script: exit code 0, which WILL_FAIL reports as a failed test.
    set(done TRUE PARENT_SCOPE)
  else()
    message(FATAL_ERROR "${text}")
  endif()
endfunction()

set(done FALSE)
file(MAKE_DIRECTORY "${TIMES}")
file(REMOVE "${TIMES}/${TEST}.txt")
if(NOT EXISTS "${EXODIFF}")
  string(REPLACE "|" ";" hints "${EXODIFF_HINTS}")
  find_program(found_exodiff exodiff HINTS ${hints})
  set(EXODIFF "${found_exodiff}")
endif()
foreach(f IN ITEMS "${SCENE}" "${GOLD}" "${COMMANDS}")
  if(NOT done AND NOT EXISTS "${f}")
    wrong("missing file: ${f}")
  endif()
endforeach()
if(NOT done AND NOT EXODIFF)
  wrong("exodiff not found (looked in ${EXODIFF_HINTS} and PATH): run scripts/build_exodiff.sh")
endif()

if(NOT done)
  file(REMOVE_RECURSE "${OUTDIR}")
  get_filename_component(stem "${SCENE}" NAME_WE)
  set(result "${OUTDIR}/${stem}.e")
  set(command "${EFG}" run "${SCENE}" -o "${OUTDIR}")
  if(RANKS GREATER 1)
    string(REPLACE "|" ";" launcher "${MPIRUN}")
    set(command ${launcher} ${RANKS} ${command})
  endif()
  now(t0)
  execute_process(COMMAND ${command} RESULT_VARIABLE code OUTPUT_VARIABLE log ERROR_VARIABLE log)
  now(t1)
  seconds_between(${t0} ${t1} efg_seconds)
  file(WRITE "${OUTDIR}/efg.log" "${log}")
  string(REPLACE ";" " " shown "${command}")
  message("efg on ${RANKS} rank(s): exit code ${code}, ${efg_seconds} s: ${shown}")
  if(JOIN AND RANKS GREATER 1 AND code EQUAL 0)
    # the rank zero-padded to the digits of the rank count, as SEACAS names decomposed files
    string(LENGTH "${RANKS}" digits)
    string(REPEAT "0" ${digits} first)
    get_filename_component(bin "${EXODIFF}" DIRECTORY)
    find_program(epu epu HINTS "${bin}" NO_DEFAULT_PATH)
    if(EXISTS "${result}")
      wrong("efg wrote the gathered ${result} where the scene asks for one file per rank")
    elseif(NOT epu)
      wrong("epu not found beside ${EXODIFF}: run scripts/build_exodiff.sh")
    else()
      execute_process(COMMAND "${epu}" -auto "${result}.${RANKS}.${first}"
                      WORKING_DIRECTORY "${OUTDIR}" RESULT_VARIABLE join_code
                      OUTPUT_VARIABLE join_log ERROR_VARIABLE join_log)
      file(WRITE "${OUTDIR}/epu.log" "${join_log}")
      message("epu joined ${RANKS} files: exit code ${join_code}")
    endif()
  endif()
  if(done)
  elseif(NOT code EQUAL 0 OR NOT EXISTS "${result}")
    wrong("efg failed (exit code ${code}) or wrote no ${result}; log in ${OUTDIR}/efg.log:\n${log}")
  endif()
endif()

if(NOT done)
  now(t2)
  execute_process(COMMAND "${EXODIFF}" -f "${COMMANDS}" "${GOLD}" "${result}"
                  RESULT_VARIABLE diff_code OUTPUT_VARIABLE diff_log ERROR_VARIABLE diff_log)
  now(t3)
  seconds_between(${t2} ${t3} diff_seconds)
  file(WRITE "${OUTDIR}/exodiff.log" "${diff_log}")
  # exodiff exits with 0 for the same files, 2 for different files, anything else for errors.
  string(REGEX MATCH "exodiff: Files are [a-z ]+" verdict "${diff_log}")
  message("exodiff (${diff_seconds} s), exit code ${diff_code}: ${verdict}\n  ${EXODIFF} -f ${COMMANDS} ${GOLD} ${result}")
  file(WRITE "${TIMES}/${TEST}.txt" "${TEST} ${efg_seconds} ${diff_seconds}\n")
  if(EXPECT_DIFFERENCE)
    string(REGEX MATCH "${EXPECT_DIFFERENCE}" planted "${diff_log}")
    if(diff_code EQUAL 2 AND planted)
      message(FATAL_ERROR "exodiff found the planted difference, as it must: ${planted}\n${diff_log}")
    endif()
    wrong("exodiff exit code ${diff_code}, expected 2 and output matching '${EXPECT_DIFFERENCE}':\n${diff_log}")
  elseif(NOT diff_code EQUAL 0)
    message(FATAL_ERROR "the result differs from the gold (exodiff exit code ${diff_code}); "
      "if the change is intended, regenerate the golds with scripts/update_golds.sh (docs/regression.md)\n${diff_log}")
  endif()
endif()
