# Builds the LAMMPS plugin (engines/lammps) as a user does, into BINARY_DIR,
# against the LAMMPS in PREFIX (engines/lammps/build_lammps.sh) and this
# source tree's headers: the fixture of the lammps tests.
#   cmake -DSOURCE_DIR=<spinslide> -DPREFIX=<lammps prefix> -DBINARY_DIR=<dir> -P build_plugin.cmake
foreach(var SOURCE_DIR PREFIX BINARY_DIR)
  if(NOT ${var})
    message(FATAL_ERROR "build_plugin.cmake: pass -D${var}=...")
  endif()
endforeach()
execute_process(
  COMMAND "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/engines/lammps" -B "${BINARY_DIR}"
          -DCMAKE_BUILD_TYPE=Release "-DLAMMPS_SOURCE_DIR=${PREFIX}/source/src"
          "-DSPINSLIDE_INCLUDE_DIR=${SOURCE_DIR}/include"
  RESULT_VARIABLE configured)
if(NOT configured EQUAL 0)
  message(FATAL_ERROR "build_plugin.cmake: configuring engines/lammps failed")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BINARY_DIR}" -j 2 RESULT_VARIABLE built)
if(NOT built EQUAL 0)
  message(FATAL_ERROR "build_plugin.cmake: building the plugin failed")
endif()
