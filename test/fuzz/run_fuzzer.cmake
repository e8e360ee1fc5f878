# CTest driver of fuzz__<target>: runs FUZZER on RUNS inputs (at most SECONDS seconds) with a fixed seed, on a fresh
# working corpus WORK (new inputs go there), the seeds SEEDS and the past findings REGRESSIONS;
# crashes and failed checks are written to ARTIFACTS and fail the test.
#   cmake -DFUZZER=... -DRUNS=20000 -DSECONDS=300 -DWORK=... -DARTIFACTS=... -DSEEDS=... -DREGRESSIONS=... -P run_fuzzer.cmake
foreach(var FUZZER RUNS SECONDS WORK ARTIFACTS SEEDS REGRESSIONS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_fuzzer.cmake: ${var} is not set")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}" "${ARTIFACTS}")
get_filename_component(name "${FUZZER}" NAME)
execute_process(COMMAND "${FUZZER}" -seed=1 -runs=${RUNS} -max_total_time=${SECONDS} -timeout=60 -rss_limit_mb=2560
                        -print_final_stats=1 "-artifact_prefix=${ARTIFACTS}/${name}-"
                        "${WORK}" "${SEEDS}" "${REGRESSIONS}"
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${name} found a failing input (exit ${rc}); see the output above and ${ARTIFACTS}")
endif()
