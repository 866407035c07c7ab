# Checkpoint on two MPI ranks, resume on one (tests/common/restart_column.prm, checkpoints
# every 150 steps): the resumed run's statistics rows after step 300 must equal those of the
# uninterrupted two-rank run, except the load_imbalance column (which depends on the ranks).
# Arguments: -DMPIEXEC, -DNUMPROC_FLAG, -DEXECUTABLE, -DSCENE, -DDIRECTORY.
file(REMOVE_RECURSE ${DIRECTORY})
execute_process(
  COMMAND ${MPIEXEC} ${NUMPROC_FLAG} 2 --oversubscribe ${EXECUTABLE}
          --set "Output directory=${DIRECTORY}" ${SCENE}
  OUTPUT_VARIABLE full RESULT_VARIABLE status_full)
execute_process(
  COMMAND ${EXECUTABLE} --set "Output directory=${DIRECTORY}" --resume ${SCENE}
  OUTPUT_VARIABLE resumed RESULT_VARIABLE status_resumed)
if(NOT status_full EQUAL 0 OR NOT status_resumed EQUAL 0)
  message(FATAL_ERROR "runs failed: ${status_full} ${status_resumed}\n${full}\n${resumed}")
endif()
foreach(step 350 400)
  string(REGEX MATCH "time=[^\n]* step=${step} [^\n]*" row_full "${full}")
  string(REGEX MATCH "time=[^\n]* step=${step} [^\n]*" row_resumed "${resumed}")
  string(REGEX REPLACE " load_imbalance=.*" "" row_full "${row_full}")
  string(REGEX REPLACE " load_imbalance=.*" "" row_resumed "${row_resumed}")
  if(row_full STREQUAL "" OR NOT row_full STREQUAL row_resumed)
    message(FATAL_ERROR "step ${step}: 2 ranks: '${row_full}'\n1 rank resumed: '${row_resumed}'")
  endif()
  message(STATUS "step ${step} equal: ${row_resumed}")
endforeach()
