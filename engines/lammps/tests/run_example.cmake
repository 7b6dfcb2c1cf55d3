# One of LAMMPS' own granular examples, converted (issue 30;
# engines/lammps/examples/convert_example.cmake) and run with -var model
# stock (LAMMPS' own styles, the original input), uncoupled (the plugin with
# the coupling off) and coupled, serially or on NP MPI ranks: stock and
# uncoupled must give the same dump at TOL (0: bit for bit), and the
# coupled run must finish with finite numbers throughout its dump.
#   cmake -DLMP=... -DPLUGIN=... -DEXAMPLE=<lammps>/examples/granular/in.pour.drum
#         -DCONVERT=.../convert_example.cmake -DCOMPARE=... -DDIR=...
#         [-DNP=2 -DMPIEXEC=mpirun] [-DTOL=0] [-DVARS="run1 2000|run2 1500"] -P run_example.cmake
include("${CMAKE_CURRENT_LIST_DIR}/lammps_run.cmake")
foreach(var LMP PLUGIN EXAMPLE CONVERT COMPARE DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_example.cmake: pass -D${var}=...")
  endif()
endforeach()
if(NOT DEFINED TOL)
  set(TOL 0)
endif()
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
set(input "${DIR}/converted.in")
execute_process(COMMAND "${CMAKE_COMMAND}" "-DIN=${EXAMPLE}" "-DOUT=${input}" -P "${CONVERT}"
                RESULT_VARIABLE converted)
if(NOT converted EQUAL 0)
  message(FATAL_ERROR "run_example.cmake: the conversion of ${EXAMPLE} failed")
endif()
lammps_launcher(launcher)
lammps_var_args(extra)
foreach(model IN ITEMS stock uncoupled coupled)
  execute_process(
    COMMAND ${launcher} "${LMP}" -in "${input}" -var model ${model} -var plugin "${PLUGIN}"
            -var out ${model} ${extra} -log "log.${model}" -screen none
    WORKING_DIRECTORY "${DIR}" RESULT_VARIABLE ran)
  if(NOT ran EQUAL 0)
    message(FATAL_ERROR "run_example.cmake: LAMMPS failed for model ${model} (${DIR}/log.${model})")
  endif()
endforeach()
execute_process(COMMAND "${COMPARE}" stock.dump uncoupled.dump ${TOL} WORKING_DIRECTORY "${DIR}"
                RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "run_example.cmake: stock and uncoupled differ beyond ${TOL}")
endif()
file(READ "${DIR}/coupled.dump" dump)
string(TOLOWER "${dump}" dump)
if(dump MATCHES "nan|inf")
  message(FATAL_ERROR "run_example.cmake: the coupled run's dump holds nan or inf (${DIR}/coupled.dump)")
endif()
file(READ "${DIR}/log.coupled" log)
if(log MATCHES "ERROR")
  message(FATAL_ERROR "run_example.cmake: the coupled run reported an error (${DIR}/log.coupled)")
endif()
message(STATUS "run_example.cmake: stock and uncoupled agree at ${TOL}; the coupled run is finite")
