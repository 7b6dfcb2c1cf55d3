# Contact statistics counted once (issue 30; engines/lammps/examples/
# in.contact_count): 648 contacts in the lattice, with newton on and off,
# serially and on NP ranks.
#   cmake -DLMP=... -DPLUGIN=... -DINPUT=... -DDIR=... [-DNP=2 -DMPIEXEC=mpirun] -P contact_count.cmake
foreach(var LMP PLUGIN INPUT DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "contact_count.cmake: pass -D${var}=...")
  endif()
endforeach()
file(MAKE_DIRECTORY "${DIR}")
set(runs serial)
if(NP AND NP GREATER 1)
  list(APPEND runs mpi)
endif()
foreach(run IN LISTS runs)
  set(launcher "")
  if(run STREQUAL mpi)
    set(launcher "${MPIEXEC}" --allow-run-as-root --oversubscribe -np ${NP})
  endif()
  foreach(newton on off)
    execute_process(
      COMMAND ${launcher} "${LMP}" -in "${INPUT}" -var plugin "${PLUGIN}" -var newton ${newton}
              -log "log.${run}.${newton}" -screen none
      WORKING_DIRECTORY "${DIR}" RESULT_VARIABLE ran)
    file(READ "${DIR}/log.${run}.${newton}" log)
    if(NOT ran EQUAL 0 OR NOT log MATCHES "\ncontacts 648\n")
      string(REGEX MATCH "\ncontacts [^\n]*" got "${log}")
      message(FATAL_ERROR "contact_count.cmake: ${run}, newton ${newton}: expected 648 contacts,${got} (${DIR}/log.${run}.${newton})")
    endif()
    message(STATUS "${run}, newton ${newton}: 648 contacts")
  endforeach()
endforeach()
