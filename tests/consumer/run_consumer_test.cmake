# ctest consumer_find_package: install the acdplan build tree into a scratch prefix, then
# configure, build and run tests/consumer against it with find_package(acdplan).
#
# Run with cmake -P and these variables:
#   ACDPLAN_BINARY_DIR  the acdplan build tree to install
#   CONSUMER_SOURCE_DIR tests/consumer (or another consumer project)
#   CONSUMER_PROGRAM    the executable it builds and that must exit 0
#   WORK_DIR            scratch folder (wiped first)
#   CONSUMER_CXX_COMPILER, CONSUMER_CXX_FLAGS, CONSUMER_BUILD_TYPE  passed to the consumer build,
#                       so that a sanitizer build links the same runtime as the library.
#   CONSUMER_CMAKE_ARGS  more arguments for the consumer's configure step (a ;-list), optional
#   ACDPLAN_SOURCE_DIR  the acdplan source tree: no installed file may name it (optional)
foreach(var ACDPLAN_BINARY_DIR CONSUMER_SOURCE_DIR CONSUMER_PROGRAM WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_consumer_test.cmake: ${var} is not set")
  endif()
endforeach()

set(prefix "${WORK_DIR}/prefix")
set(build "${WORK_DIR}/build")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "consumer_find_package: ${what} failed (status ${status})")
  endif()
endfunction()

run_step("cmake --install" "${CMAKE_COMMAND}" --install "${ACDPLAN_BINARY_DIR}" --prefix "${prefix}")

# Installed files must not point back into the source tree (the package must work once the
# sources are gone).
if(ACDPLAN_SOURCE_DIR)
  file(GLOB_RECURSE installed LIST_DIRECTORIES false "${prefix}/*.cmake" "${prefix}/*.h")
  foreach(f IN LISTS installed)
    file(READ "${f}" text)
    string(FIND "${text}" "${ACDPLAN_SOURCE_DIR}/" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "consumer_find_package: ${f} names the source tree ${ACDPLAN_SOURCE_DIR}")
    endif()
  endforeach()
endif()

set(configure_args -S "${CONSUMER_SOURCE_DIR}" -B "${build}" "-DCMAKE_PREFIX_PATH=${prefix}")
if(CONSUMER_CXX_COMPILER)
  list(APPEND configure_args "-DCMAKE_CXX_COMPILER=${CONSUMER_CXX_COMPILER}")
endif()
if(CONSUMER_BUILD_TYPE)
  list(APPEND configure_args "-DCMAKE_BUILD_TYPE=${CONSUMER_BUILD_TYPE}")
endif()
if(CONSUMER_CXX_FLAGS)
  list(APPEND configure_args "-DCMAKE_CXX_FLAGS=${CONSUMER_CXX_FLAGS}")
endif()
list(APPEND configure_args ${CONSUMER_CMAKE_ARGS})
run_step("configuring ${CONSUMER_SOURCE_DIR}" "${CMAKE_COMMAND}" ${configure_args})
run_step("building ${CONSUMER_SOURCE_DIR}" "${CMAKE_COMMAND}" --build "${build}")
run_step("running ${CONSUMER_PROGRAM}" "${build}/${CONSUMER_PROGRAM}")
