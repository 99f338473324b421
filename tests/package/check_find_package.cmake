# Installs the build into a scratch prefix, then configures, builds and runs a
# small outside project that uses find_package(mcdenoise) and links it.
# Usage: cmake -DSOURCE_DIR=... -DBUILD_DIR=... -P check_find_package.cmake
set(prefix ${BUILD_DIR}/package-test/prefix)
set(consumer_build ${BUILD_DIR}/package-test/consumer)
file(REMOVE_RECURSE ${BUILD_DIR}/package-test)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed: ${ARGN}\n${out}\n${err}")
  endif()
endfunction()

run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/package/consumer -B ${consumer_build}
    -DCMAKE_PREFIX_PATH=${prefix})
run(${CMAKE_COMMAND} --build ${consumer_build})
run(${consumer_build}/consumer)
message(STATUS "find_package(mcdenoise) consumer built and ran")
