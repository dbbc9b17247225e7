# cmake -P script behind the install_and_consume test:
#   1. cmake --install VISCOROLL_BINARY_DIR --prefix WORK_DIR/prefix
#   2. configure + build CONSUMER_SOURCE_DIR with CMAKE_PREFIX_PATH=WORK_DIR/prefix
#   3. run the consumer; any failure is a FATAL_ERROR (test fails).
# Arguments (-D): VISCOROLL_BINARY_DIR, CONSUMER_SOURCE_DIR, WORK_DIR, CONFIG, GENERATOR,
# CXX_COMPILER (the last three optional).
cmake_minimum_required(VERSION 3.20)

foreach(_var VISCOROLL_BINARY_DIR CONSUMER_SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "ConsumerTest.cmake: -D${_var}=... is required")
  endif()
endforeach()
if(NOT CONFIG)
  set(CONFIG Release)
endif()

set(_prefix ${WORK_DIR}/prefix)
set(_build ${WORK_DIR}/build)
# Start clean, so a header removed from include/ cannot linger in the prefix.
file(REMOVE_RECURSE ${_prefix} ${_build})

function(run_step name)
  message(STATUS "[consumer] ${name}: ${ARGN}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "[consumer] ${name} failed (${_rc}):\n${_out}")
  endif()
  set(step_output "${_out}" PARENT_SCOPE)
endfunction()

run_step(install ${CMAKE_COMMAND} --install ${VISCOROLL_BINARY_DIR} --config ${CONFIG} --prefix ${_prefix})

set(_configure ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${_build}
    -DCMAKE_PREFIX_PATH=${_prefix} -DCMAKE_BUILD_TYPE=${CONFIG})
if(GENERATOR)
  list(APPEND _configure -G ${GENERATOR})
endif()
if(CXX_COMPILER)
  list(APPEND _configure -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
endif()
run_step(configure ${_configure})
run_step(build ${CMAKE_COMMAND} --build ${_build} --config ${CONFIG})

# Single-config generators put it in the build dir, multi-config ones in a <CONFIG>/ subdir.
find_program(_consumer NAMES viscoroll_consumer PATHS ${_build} ${_build}/${CONFIG} NO_DEFAULT_PATH
             NO_CACHE)
if(NOT _consumer)
  message(FATAL_ERROR "[consumer] built, but viscoroll_consumer not found under ${_build}")
endif()
run_step(run ${_consumer})
message(STATUS "[consumer] output: ${step_output}")
