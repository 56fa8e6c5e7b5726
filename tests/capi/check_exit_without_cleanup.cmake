# Runs `capi_c_test exit_without_cleanup` RUNS times: a process that exits without cleaning up (one thesis job
# idle, one computing, and a handle API analyzer computing) must end, and end cleanly, every time. Each run has
# its own time limit, so a hang at exit fails here in seconds rather than holding the test until ctest's limit.
# Why exit could hang: platform::ProcessWide.
# cmake "-DEMULATOR=..." -DTEST=capi_c_test -DRUNS=N -P check_exit_without_cleanup.cmake
# Output goes to files, not pipes: a wineserver started by a run inherits the pipes and would hold each run
# open for the seconds it lingers.
set(log ${CMAKE_CURRENT_BINARY_DIR}/exit_without_cleanup)
foreach(run RANGE 1 ${RUNS})
  execute_process(COMMAND ${EMULATOR} ${TEST} exit_without_cleanup
                  RESULT_VARIABLE rc OUTPUT_FILE ${log}.out ERROR_FILE ${log}.err TIMEOUT 60)
  file(READ ${log}.out out)
  file(READ ${log}.err err)
  if(NOT rc STREQUAL "0" OR NOT out MATCHES "exit_without_cleanup: passed")
    message(FATAL_ERROR "run ${run} of ${RUNS}: exit status '${rc}' (a time-out reads 'Process terminated due to timeout')\n${out}\n${err}")
  endif()
endforeach()
message(STATUS "${RUNS} runs ended cleanly")
