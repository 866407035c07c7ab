# Fails when doc/parameters.md differs from what the program prints now.
# Regenerate with: build/slidewave --print-parameters markdown > doc/parameters.md
execute_process(COMMAND ${EXECUTABLE} --print-parameters markdown
  OUTPUT_FILE ${OUTPUT} RESULT_VARIABLE _status)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "slidewave --print-parameters markdown failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUTPUT} ${DOCUMENT}
  RESULT_VARIABLE _different)
if(_different)
  message(FATAL_ERROR "doc/parameters.md is out of date; regenerate it with\n"
    "  build/slidewave --print-parameters markdown > doc/parameters.md")
endif()
