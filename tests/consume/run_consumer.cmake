# Drives one step of a packaging test: configure, build and then either
# install (MODE=install) or run the consumer executable (MODE=consume).
#
# Invoked by CTest as  cmake -DMODE=... -DPROJECT_DIR=... ... -P run_consumer.cmake
#
#   MODE                  install | consume
#   PROJECT_DIR           source tree to configure
#   BINARY_DIR            build tree (wiped first, so every run is fresh)
#   GENERATOR             CMake generator of the parent build (optional)
#   GENERATOR_PLATFORM    ... and its platform / toolset (optional)
#   GENERATOR_TOOLSET
#   MAKE_PROGRAM          CMAKE_MAKE_PROGRAM of the parent build (optional)
#   CXX_COMPILER          CMAKE_CXX_COMPILER of the parent build (optional)
#   BUILD_TYPE            configuration of the parent build (optional)
#   MULTI_CONFIG          whether GENERATOR is a multi-config generator
#   INSTALL_PREFIX        install prefix (MODE=install)
#   PREFIX_PATH           CMAKE_PREFIX_PATH for the consumer (optional)
#   SPINSLIDE_SOURCE_DIR  spinslide source tree for the consumer (optional)
#   FAIL_ON_WARNINGS      fail if configure/build output has warnings (default ON)
cmake_minimum_required(VERSION 3.16)

foreach(var MODE PROJECT_DIR BINARY_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_consumer.cmake: ${var} must be set")
  endif()
endforeach()
if(NOT MODE MATCHES "^(install|consume)$")
  message(FATAL_ERROR "run_consumer.cmake: MODE must be install or consume, not '${MODE}'")
endif()
if(NOT DEFINED FAIL_ON_WARNINGS)
  set(FAIL_ON_WARNINGS ON)
endif()

# Runs a command; prints its output and stops with FATAL_ERROR if it fails or,
# when asked, if its output contains compiler or CMake warnings.
function(run_step what check_warnings)
  string(REPLACE ";" " " pretty "${ARGN}")
  message(STATUS "[${what}] ${pretty}")
  execute_process(
    COMMAND ${ARGN}
    RESULT_VARIABLE result
    OUTPUT_VARIABLE output
    ERROR_VARIABLE output)
  message("${output}")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "[${what}] failed (exit status: ${result})")
  endif()
  if(check_warnings AND FAIL_ON_WARNINGS
     AND output MATCHES "(warning:|CMake Warning|CMake Deprecation Warning)")
    message(FATAL_ERROR "[${what}] produced warnings (see output above)")
  endif()
endfunction()

set(configure_args -S "${PROJECT_DIR}" -B "${BINARY_DIR}")
if(GENERATOR)
  list(APPEND configure_args -G "${GENERATOR}")
endif()
if(GENERATOR_PLATFORM)
  list(APPEND configure_args -A "${GENERATOR_PLATFORM}")
endif()
if(GENERATOR_TOOLSET)
  list(APPEND configure_args -T "${GENERATOR_TOOLSET}")
endif()
if(MAKE_PROGRAM)
  list(APPEND configure_args "-DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}")
endif()
if(CXX_COMPILER)
  list(APPEND configure_args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif()
if(BUILD_TYPE AND NOT MULTI_CONFIG)
  list(APPEND configure_args "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}")
endif()

set(config_args)
if(BUILD_TYPE)
  set(config_args --config "${BUILD_TYPE}")
endif()

file(REMOVE_RECURSE "${BINARY_DIR}")

if(MODE STREQUAL "install")
  if(NOT INSTALL_PREFIX)
    message(FATAL_ERROR "run_consumer.cmake: INSTALL_PREFIX must be set for MODE=install")
  endif()
  file(REMOVE_RECURSE "${INSTALL_PREFIX}")
  run_step(configure TRUE "${CMAKE_COMMAND}" ${configure_args}
    -DSPINSLIDE_BUILD_TESTS=OFF
    -DSPINSLIDE_BUILD_EXAMPLES=OFF
    -DSPINSLIDE_BUILD_BENCHMARKS=OFF
    -DSPINSLIDE_BUILD_PYTHON=OFF  # pip installs the Python package, not CMake
    "-DCMAKE_INSTALL_PREFIX=${INSTALL_PREFIX}")
  run_step(build TRUE "${CMAKE_COMMAND}" --build "${BINARY_DIR}" ${config_args})
  run_step(install FALSE "${CMAKE_COMMAND}" --install "${BINARY_DIR}" ${config_args})
  return()
endif()

# MODE=consume
if(PREFIX_PATH)
  list(APPEND configure_args "-DCMAKE_PREFIX_PATH=${PREFIX_PATH}")
endif()
if(SPINSLIDE_SOURCE_DIR)
  list(APPEND configure_args "-DSPINSLIDE_SOURCE_DIR=${SPINSLIDE_SOURCE_DIR}")
endif()
# Put the executable at a known place (multi-config generators add a
# per-configuration subdirectory, hence the search below).
list(APPEND configure_args "-DCMAKE_RUNTIME_OUTPUT_DIRECTORY=${BINARY_DIR}/bin")

run_step(configure TRUE "${CMAKE_COMMAND}" ${configure_args})
run_step(build TRUE "${CMAKE_COMMAND}" --build "${BINARY_DIR}" ${config_args})

file(GLOB_RECURSE apps LIST_DIRECTORIES FALSE "${BINARY_DIR}/bin/app" "${BINARY_DIR}/bin/app.exe")
list(LENGTH apps n_apps)
if(NOT n_apps EQUAL 1)
  message(FATAL_ERROR "expected exactly one consumer executable under ${BINARY_DIR}/bin, "
                      "found: '${apps}'")
endif()
run_step(run FALSE "${apps}")
