# Checkpoint/restart of a scene: the uninterrupted run (FULL_RANKS MPI ranks) writes its
# checkpoints, then --resume (RESUME_RANKS ranks) continues from the newest one to the end.
# - Every test-mode statistics row the resumed run prints must equal, character for
#   character, the uninterrupted run's row of the same step (columns matching IGNORE, which
#   depend on the number of ranks, removed first); at least one row must be compared.
# - FILES (paths relative to the output directory): after the resumed run they must be byte
#   for byte those of the uninterrupted run (statistics.csv, gauges: the checkpoint keeps
#   copies and the resumed run continues them from the checkpoint's step). Only when
#   FULL_RANKS equals RESUME_RANKS: on another number of ranks sums over the ranks change
#   order, which the 12-digit CSV files can show in their last digit.
# Arguments: -DMPIEXEC, -DNUMPROC_FLAG, -DEXECUTABLE, -DSCENE, -DDIRECTORY, -DFULL_RANKS,
# -DRESUME_RANKS, optional -DIGNORE (regex of one column, e.g. " load_imbalance=[^ ]*"),
# -DFILES (;-separated), optional -DSETTING ('PATH=VALUE', given to every run of the scene:
# the same scene with one parameter changed), -DOTHER_SCENE and -DOTHER_SETTING (below); -DMAPS
# (;-separated GeoTIFFs), compared pixel by pixel by
# -DCOMPARE_RASTERS (run with -DPYTHON) to -DMAP_TOLERANCE times their largest value.
file(REMOVE_RECURSE ${DIRECTORY} ${DIRECTORY}-full)
function(run_scene ranks resume output status)
  set(command ${EXECUTABLE} --set "Output directory=${DIRECTORY}")
  if(SETTING)
    list(APPEND command --set "${SETTING}")
  endif()
  if(resume)
    list(APPEND command --resume)
  endif()
  if(ranks GREATER 1)
    set(command ${MPIEXEC} ${NUMPROC_FLAG} ${ranks} --oversubscribe ${command})
  endif()
  execute_process(COMMAND ${command} ${SCENE} OUTPUT_VARIABLE out ERROR_VARIABLE err
                  RESULT_VARIABLE result)
  set(${output} "${out}${err}" PARENT_SCOPE)
  set(${status} ${result} PARENT_SCOPE)
endfunction()

run_scene(${FULL_RANKS} FALSE full status_full)
foreach(name ${FILES} ${MAPS})
  configure_file(${DIRECTORY}/${name} ${DIRECTORY}-full/${name} COPYONLY)
endforeach()
run_scene(${RESUME_RANKS} TRUE resumed status_resumed)
if(NOT status_full EQUAL 0 OR NOT status_resumed EQUAL 0)
  message(FATAL_ERROR "runs failed: ${status_full} ${status_resumed}\n${full}\n${resumed}")
endif()

string(REGEX MATCHALL "time=[^\n]*" rows_resumed "${resumed}")
list(LENGTH rows_resumed n_rows)
if(n_rows EQUAL 0)
  message(FATAL_ERROR "the resumed run printed no statistics rows:\n${resumed}")
endif()
foreach(row_resumed ${rows_resumed})
  string(REGEX MATCH " step=[0-9]+ " step "${row_resumed}")
  string(REGEX MATCH "time=[^\n]*${step}[^\n]*" row_full "${full}")
  if(IGNORE)
    string(REGEX REPLACE "${IGNORE}" "" row_full "${row_full}")
    string(REGEX REPLACE "${IGNORE}" "" row_resumed "${row_resumed}")
  endif()
  if(NOT row_full STREQUAL row_resumed)
    message(FATAL_ERROR "${step}: ${FULL_RANKS} rank(s): '${row_full}'\n"
                        "resumed on ${RESUME_RANKS}: '${row_resumed}'")
  endif()
  message(STATUS "${step}equal")
endforeach()

foreach(name ${FILES})
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${DIRECTORY}/${name}
                          ${DIRECTORY}-full/${name} RESULT_VARIABLE different)
  if(different)
    message(FATAL_ERROR "${name} of the resumed run differs from the uninterrupted run's")
  endif()
  message(STATUS "${name}: byte for byte the uninterrupted run's")
endforeach()

foreach(name ${MAPS})
  execute_process(COMMAND ${PYTHON} ${COMPARE_RASTERS} ${DIRECTORY}/${name}
                          ${DIRECTORY}-full/${name} ${MAP_TOLERANCE}
                  OUTPUT_VARIABLE compared RESULT_VARIABLE different)
  if(different)
    message(FATAL_ERROR "${name} of the resumed run differs from the uninterrupted run's: "
                        "${compared}")
  endif()
  message(STATUS "${compared}")
endforeach()

# OTHER_SCENE: resuming that scene from this scene's checkpoint must be refused (exit
# status 1) with a message naming both scenes. OTHER_SETTING ('PATH=VALUE'): the same for
# this scene with that parameter changed.
if(OTHER_SCENE)
  execute_process(COMMAND ${EXECUTABLE} --set "Output directory=${DIRECTORY}" --resume
                          ${OTHER_SCENE}
                  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
  if(NOT status EQUAL 1 OR NOT err MATCHES "is of a different scene \\(.*; this scene: .*\\)")
    message(FATAL_ERROR "resuming ${OTHER_SCENE} from this checkpoint: status ${status}\n"
                        "${out}${err}")
  endif()
  message(STATUS "another scene refused: ${err}")
endif()

if(OTHER_SETTING)
  execute_process(COMMAND ${EXECUTABLE} --set "Output directory=${DIRECTORY}" --resume
                          --set "${OTHER_SETTING}" ${SCENE}
                  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
  if(NOT status EQUAL 1 OR NOT err MATCHES "is of a different scene \\(.*; this scene: .*\\)")
    message(FATAL_ERROR "resuming with '${OTHER_SETTING}' from this checkpoint: status "
                        "${status}\n${out}${err}")
  endif()
  message(STATUS "the scene with '${OTHER_SETTING}' refused: ${err}")
endif()
