# Runs one LAMMPS input twice, with -var model A and -var model B, in DIR
# (serially, or on NP MPI ranks when NP > 1), and compares the two dumps
# (<DIR>/ab_<model>.dump: the inputs' variable `out` is set so) with
# compare_dumps at TOL.
#   cmake -DLMP=... -DPLUGIN=... -DINPUT=... -DA=stock -DB=uncoupled -DCOMPARE=...
#         -DDIR=... [-DNP=2 -DMPIEXEC=mpirun] [-DTOL=0] [-DVARS="name value|..."]
#         -P run_ab.cmake
include("${CMAKE_CURRENT_LIST_DIR}/lammps_run.cmake")
foreach(var LMP PLUGIN INPUT A B COMPARE DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_ab.cmake: pass -D${var}=...")
  endif()
endforeach()
if(NOT DEFINED TOL)
  set(TOL 0)
endif()
file(MAKE_DIRECTORY "${DIR}")
lammps_launcher(launcher)
lammps_var_args(extra)
foreach(model IN ITEMS ${A} ${B})
  execute_process(
    COMMAND ${launcher} "${LMP}" -in "${INPUT}" -var model ${model} -var plugin "${PLUGIN}"
            -var out ab_${model} ${extra} -log "log.${model}" -screen none
    WORKING_DIRECTORY "${DIR}" RESULT_VARIABLE ran)
  if(NOT ran EQUAL 0)
    message(FATAL_ERROR "run_ab.cmake: LAMMPS failed for model ${model} (${DIR}/log.${model})")
  endif()
endforeach()
execute_process(COMMAND "${COMPARE}" "ab_${A}.dump" "ab_${B}.dump" ${TOL}
                WORKING_DIRECTORY "${DIR}" RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "run_ab.cmake: models ${A} and ${B} differ beyond ${TOL}")
endif()
