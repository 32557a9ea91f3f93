# One short, reproducible fuzz run for CTest: the repository's seed corpus is read only, new
# inputs and any crash reproducer go to WORK (in the build tree), a fixed seed and time budget.
# cmake -DFUZZER=... -DCORPUS=... -DWORK=... -DSECONDS=... -P run_fuzz.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/new)
execute_process(
  COMMAND ${FUZZER} -seed=1 -max_total_time=${SECONDS} -timeout=20 -rss_limit_mb=2048
          -print_final_stats=1 -artifact_prefix=${WORK}/ ${WORK}/new ${CORPUS}
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${FUZZER} failed (${rc}); the reproducer is in ${WORK}/")
endif()
