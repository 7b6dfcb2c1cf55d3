# Serial against MPI on a pour of 2000 spheres (engines/lammps/examples/in.pour_mpi,
# docs/lammps.md): for each coupling in COUPLINGS, runs the input
# serially and on NP ranks in DIR, and compares the two logs with
# compare_statistics:
#  - early in the pour (the EARLY lines up to step 2500), where the runs
#    still agree to rounding: the contact and sliding counts exactly, the
#    sums of |F_t| and |M| to relative 1e-8;
#  - the statistics averaged over the last 2000 of 12000 steps, when the
#    runs have long diverged: within the tolerances of
#    pour_statistics_tolerances.txt (3 sqrt(2) times the standard deviation
#    of five serial runs with other seeds).
#   cmake -DLMP=... -DPLUGIN=... -DINPUT=... -DMPIEXEC=mpirun -DCOMPARE=...
#         -DTOLERANCES=... -DDIR=... [-DNP=2] [-DCOUPLINGS="yes;no"] -P pour_statistics.cmake
foreach(var LMP PLUGIN INPUT MPIEXEC COMPARE TOLERANCES DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "pour_statistics.cmake: pass -D${var}=...")
  endif()
endforeach()
if(NOT DEFINED NP)
  set(NP 2)
endif()
if(NOT DEFINED COUPLINGS)
  set(COUPLINGS yes no)
endif()
file(MAKE_DIRECTORY "${DIR}")
set(failed "")
foreach(coupling IN LISTS COUPLINGS)
  foreach(run serial mpi)
    set(launcher "")
    if(run STREQUAL mpi)
      # as run_ab.cmake: root (CI) needs --allow-run-as-root; --oversubscribe
      # lets NP ranks run where fewer cores are free
      set(launcher "${MPIEXEC}" --allow-run-as-root --oversubscribe -np ${NP})
    endif()
    string(TIMESTAMP t0 "%s")
    execute_process(
      COMMAND ${launcher} "${LMP}" -in "${INPUT}" -var plugin "${PLUGIN}" -var coupling ${coupling}
              -log "log.${coupling}.${run}" -screen none
      WORKING_DIRECTORY "${DIR}" RESULT_VARIABLE ran)
    string(TIMESTAMP t1 "%s")
    math(EXPR secs "${t1} - ${t0}")
    if(NOT ran EQUAL 0)
      message(FATAL_ERROR "pour_statistics.cmake: LAMMPS failed (${DIR}/log.${coupling}.${run})")
    endif()
    message(STATUS "coupling ${coupling}, ${run}: ${secs} s")
  endforeach()
  message(STATUS "coupling ${coupling}: serial (A) against ${NP} ranks (B)")
  execute_process(
    COMMAND "${COMPARE}" "log.${coupling}.serial" "log.${coupling}.mpi" "${TOLERANCES}" ${coupling}
            2500 1e-8
    WORKING_DIRECTORY "${DIR}" RESULT_VARIABLE same)
  if(NOT same EQUAL 0)
    list(APPEND failed ${coupling})
  endif()
endforeach()
if(failed)
  message(FATAL_ERROR "pour_statistics.cmake: serial and MPI differ beyond the tolerances (coupling ${failed})")
endif()
