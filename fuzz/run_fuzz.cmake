# One short, repeatable fuzz run for CTest: the repository's seed corpus is read only, new inputs
# and any crash reproducer go to WORK (in the build tree); a fixed seed and a fixed number of
# runs, no re-reading of the output folder, and address randomisation off through LAUNCHER
# (fuzz/CMakeLists.txt), so the inputs tried are the same on a fast and on a slow machine.
# cmake -DFUZZER=... -DCORPUS=... -DWORK=... -DRUNS=... [-DLAUNCHER="setarch x86_64 -R"] -P run_fuzz.cmake
separate_arguments(launcher UNIX_COMMAND "${LAUNCHER}")
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/new)
execute_process(
  COMMAND ${launcher} ${FUZZER} -seed=1 -runs=${RUNS} -reload=0 -timeout=20 -rss_limit_mb=2048
          -print_final_stats=1 -artifact_prefix=${WORK}/ ${WORK}/new ${CORPUS}
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${FUZZER} failed (${rc}); the reproducer is in ${WORK}/")
endif()
