# No source file longer than 700 lines (docs/architecture.md, "Small files"): past that a file
# holds more than one idea. Run as `cmake -DSOURCE_DIR=... -P file_length.cmake`.
cmake_minimum_required(VERSION 3.16)
set(limit 700)
file(GLOB_RECURSE files
  "${SOURCE_DIR}/src/*.cpp" "${SOURCE_DIR}/src/*.hpp" "${SOURCE_DIR}/include/*.hpp"
  "${SOURCE_DIR}/python/*.cpp" "${SOURCE_DIR}/python/*.hpp" "${SOURCE_DIR}/python/*.py"
  "${SOURCE_DIR}/tests/*.cpp" "${SOURCE_DIR}/tests/*.hpp" "${SOURCE_DIR}/tests/*.py"
  "${SOURCE_DIR}/benchmarks/*.cpp" "${SOURCE_DIR}/examples/*.py")
set(too_long "")
foreach(f IN LISTS files)
  file(READ "${f}" content)
  string(REGEX REPLACE "[^\n]" "" newlines "${content}")
  string(LENGTH "${newlines}" n)
  if(n GREATER limit)
    file(RELATIVE_PATH shown "${SOURCE_DIR}" "${f}")
    string(APPEND too_long "\n  ${shown}: ${n} lines")
  endif()
endforeach()
list(LENGTH files checked)
if(too_long)
  message(FATAL_ERROR "source files longer than ${limit} lines:${too_long}")
endif()
message(STATUS "${checked} source files, none longer than ${limit} lines")
