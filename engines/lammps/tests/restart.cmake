# Restart continuity (issue 30; engines/lammps/examples/in.restart): runs the
# pile in one input (two runs) and in two, the first after another pair
# style was defined, with write_restart and read_restart between them, and
# compares the dumps at the end with compare_dumps at 0 (bit for bit).  The
# reading log must say that the history fix's data was restored.  Then the
# first half again with LAMMPS' own granular styles: the reading log must
# carry granular/spinslide's warning that the file holds none of its history.
#   cmake -DLMP=... -DPLUGIN=... -DINPUT=... -DCOMPARE=... -DDIR=...
#         [-DNP=2 -DMPIEXEC=mpirun] [-DCOUPLING=yes] [-DWALL=drum]
#         [-DCOEFFS=restart] [-DMODEL=short|keywords|legacy] -P restart.cmake
# WALL=drum: the spheres in a turning drum (fix wall/gran/region/spinslide);
# the reading log must also say that the wall's contacts and the region's
# motion were restored (no run with LAMMPS' own styles then).
# COEFFS=restart: the reading input gives no pair_style and no pair_coeff
# (in.restart -var coeffs restart): the pair, its settings and coefficients
# come from the restart file, and the reading log must say so.  MODEL: the
# coefficients (in.restart -var model).  Neither with LAMMPS' own styles.
include("${CMAKE_CURRENT_LIST_DIR}/lammps_run.cmake")
foreach(var LMP PLUGIN INPUT COMPARE DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "restart.cmake: pass -D${var}=...")
  endif()
endforeach()
if(NOT DEFINED COUPLING)
  set(COUPLING yes)
endif()
if(NOT DEFINED WALL)
  set(WALL plane)
endif()
if(NOT DEFINED COEFFS)
  set(COEFFS input)
endif()
if(NOT DEFINED MODEL)
  set(MODEL short)
endif()
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
lammps_launcher(launcher)
function(lammps phase out)
  execute_process(
    COMMAND ${launcher} "${LMP}" -in "${INPUT}" -var phase ${phase} -var plugin "${PLUGIN}"
            -var coupling ${COUPLING} -var wall ${WALL} -var coeffs ${COEFFS} -var model ${MODEL}
            -var out ${out} ${ARGN} -log "log.${out}.${phase}"
            -screen none
    WORKING_DIRECTORY "${DIR}" RESULT_VARIABLE ran)
  if(NOT ran EQUAL 0)
    message(FATAL_ERROR "restart.cmake: LAMMPS failed (${DIR}/log.${out}.${phase})")
  endif()
endfunction()
lammps(full whole)
lammps(write halves -var other lj)
lammps(read halves)
execute_process(COMMAND "${COMPARE}" whole.dump halves.dump 0 WORKING_DIRECTORY "${DIR}"
                RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "restart.cmake: the restarted run differs from the whole one")
endif()
file(READ "${DIR}/log.halves.read" log)
if(NOT log MATCHES "Resetting peratom fix info from restart file:\n  fix style: NEIGH_HISTORY/SPINSLIDE, fix ID: SPINSLIDE_HISTORY\n")
  message(FATAL_ERROR "restart.cmake: the contact history was not restored (${DIR}/log.halves.read)")
endif()
if(log MATCHES "Unused restart file")
  message(FATAL_ERROR "restart.cmake: restart info left unused (${DIR}/log.halves.read)")
endif()
if(COEFFS STREQUAL "restart")
  if(NOT log MATCHES "restoring pair style granular/spinslide from restart\n")
    message(FATAL_ERROR "restart.cmake: the pair was not restored from the restart file (${DIR}/log.halves.read)")
  endif()
  if(log MATCHES "WARNING")
    message(FATAL_ERROR "restart.cmake: the restarted run warns (${DIR}/log.halves.read)")
  endif()
endif()
if(WALL STREQUAL "drum")
  foreach(kind IN ITEMS peratom global)
    if(NOT log MATCHES "Resetting ${kind} fix info from restart file:\n  fix style: wall/gran/region/spinslide, fix ID: wall\n")
      message(FATAL_ERROR "restart.cmake: the drum's ${kind} restart info was not restored (${DIR}/log.halves.read)")
    endif()
  endforeach()
  if(log MATCHES "WARNING")
    message(FATAL_ERROR "restart.cmake: the restarted drum warns (${DIR}/log.halves.read)")
  endif()
  message(STATUS "restart.cmake: the restarted drum equals the whole run bit for bit")
  return()
endif()
if(NOT COEFFS STREQUAL "input" OR NOT MODEL STREQUAL "short")
  message(STATUS "restart.cmake: the restarted run (${MODEL}, coefficients from the ${COEFFS}) equals the whole one bit for bit")
  return()
endif()
lammps(write stock -var writer stock)
lammps(read stock)
file(READ "${DIR}/log.stock.read" log)
if(NOT log MATCHES "WARNING: Pair granular/spinslide: the restart file holds no contact history")
  message(FATAL_ERROR "restart.cmake: no warning for a restart without the history (${DIR}/log.stock.read)")
endif()
message(STATUS "restart.cmake: the restarted run equals the whole one bit for bit; the warning is there")
