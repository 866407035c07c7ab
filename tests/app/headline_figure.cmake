# The README's first command ends by drawing the headline scene: this runs the same steps on
# a shortened run (the scene as shipped, 0.5 s instead of 5 s) and checks that the figure
# script writes a non-empty PNG and prints its path.
# Arguments: -DEXECUTABLE, -DPYTHON, -DSCENE, -DSCRIPT, -DDIRECTORY.
file(REMOVE_RECURSE ${DIRECTORY})
execute_process(COMMAND ${EXECUTABLE} --set "Output directory=${DIRECTORY}"
                        --set "Time/End time=0.5" ${SCENE}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the scene failed (${status}):\n${out}${err}")
endif()
set(png ${DIRECTORY}/headline.png)
execute_process(COMMAND ${PYTHON} ${SCRIPT} ${DIRECTORY} --png ${png} --times 0 0.25 0.5
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the figure script failed (${status}):\n${out}${err}")
endif()
file(SIZE ${png} size)
if(size LESS 10000)
  message(FATAL_ERROR "${png} is ${size} bytes: no figure")
endif()
if(NOT out MATCHES "wrote ${png}")
  message(FATAL_ERROR "the script did not print the figure's path:\n${out}")
endif()
message(STATUS "${png}: ${size} bytes")
