# Every C++ file of the project is formatted as .clang-format says (clang-format --dry-run
# --Werror prints each difference as an error). Arguments: -DCLANG_FORMAT, -DSOURCE_DIR.
if(NOT CLANG_FORMAT)
  message(FATAL_ERROR "clang-format not found: scripts/setup.sh installs Debian's clang-format")
endif()
file(GLOB_RECURSE files RELATIVE ${SOURCE_DIR}
  ${SOURCE_DIR}/include/*.h ${SOURCE_DIR}/source/*.cc ${SOURCE_DIR}/tests/*.h
  ${SOURCE_DIR}/tests/*.cc ${SOURCE_DIR}/benchmarks/*.cc ${SOURCE_DIR}/benchmarks/*.h)
list(LENGTH files n_files)
if(n_files LESS 10)
  message(FATAL_ERROR "only ${n_files} C++ files found under ${SOURCE_DIR}")
endif()
execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror ${files}
                WORKING_DIRECTORY ${SOURCE_DIR}
                RESULT_VARIABLE status ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "files not formatted by .clang-format (run: clang-format -i FILE):\n"
                      "${errors}")
endif()
message(STATUS "${n_files} files formatted")
