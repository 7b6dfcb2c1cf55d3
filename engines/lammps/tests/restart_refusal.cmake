# A restart file's pair section that the plugin cannot read is refused with
# a message naming the problem, never misread
# (pair_granular_spinslide_restart.cpp): the first 100 steps of
# engines/lammps/examples/in.restart written to a restart file, then that
# file read back without pair_style and pair_coeff (-var coeffs restart):
#   - as written: it must be read (the pair restored, the run goes on);
#   - with the layout number after the section's magic set to 3 (a newer
#     plugin's layout) or to 1 (the layout before the `profile` keyword):
#     LAMMPS must stop with the plugin's layout error;
#   - with the magic changed: LAMMPS must stop with the plugin's marker
#     error.
# The file is patched by PYTHON (the magic 0x5350534C, little-endian on the
# machines LAMMPS' restart files are written on here, must occur once).
#   cmake -DLMP=... -DPLUGIN=... -DINPUT=... -DPYTHON=... -DDIR=... -P restart_refusal.cmake
foreach(var LMP PLUGIN INPUT PYTHON DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "restart_refusal.cmake: pass -D${var}=...")
  endif()
endforeach()
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
function(lammps phase out)
  execute_process(
    COMMAND "${LMP}" -in "${INPUT}" -var phase ${phase} -var plugin "${PLUGIN}" -var coeffs restart
            -var model keywords -var first 100 -var second 10 -var out ${out} -log "log.${out}.${phase}"
            -screen none
    WORKING_DIRECTORY "${DIR}" RESULT_VARIABLE ran)
  set(ran ${ran} PARENT_SCOPE)
endfunction()

lammps(write written)
if(NOT ran EQUAL 0)
  message(FATAL_ERROR "restart_refusal.cmake: LAMMPS failed (${DIR}/log.written.write)")
endif()
set(patch [=[
import sys
path, what = sys.argv[1], sys.argv[2]
data = bytearray(open(path, 'rb').read())
magic = (0x5350534C).to_bytes(4, 'little')
if data.count(magic) != 1:
    sys.exit('the magic occurs %d times' % data.count(magic))
at = data.index(magic)
if what in ('newer', 'older'):
    data[at + 4:at + 8] = (3 if what == 'newer' else 1).to_bytes(4, 'little')
else:
    data[at:at + 4] = (0x12345678).to_bytes(4, 'little')
open(sys.argv[3], 'wb').write(bytes(data))
]=])
foreach(what IN ITEMS newer older magic)
  execute_process(COMMAND "${PYTHON}" -c "${patch}" written.restart ${what} ${what}.restart
                  WORKING_DIRECTORY "${DIR}" RESULT_VARIABLE patched)
  if(NOT patched EQUAL 0)
    message(FATAL_ERROR "restart_refusal.cmake: could not patch the ${what} of ${DIR}/written.restart")
  endif()
endforeach()

lammps(read written)
file(READ "${DIR}/log.written.read" log)
if(NOT ran EQUAL 0 OR NOT log MATCHES "restoring pair style granular/spinslide from restart")
  message(FATAL_ERROR "restart_refusal.cmake: the unpatched file was not read (${DIR}/log.written.read)")
endif()
set(expected_newer "ERROR: Pair granular/spinslide: the restart file's pair section has layout 3, this plugin reads layout 2 only \\(the file was written by a newer plugin\\)")
set(expected_older "ERROR: Pair granular/spinslide: the restart file's pair section has layout 1, this plugin reads layout 2 only \\(the file was written by another plugin\\)")
set(expected_magic "ERROR: Pair granular/spinslide: the restart file's pair section does not start with granular/spinslide's marker")
foreach(what IN ITEMS newer older magic)
  lammps(read ${what})
  file(READ "${DIR}/log.${what}.read" log)
  if(ran EQUAL 0 OR NOT log MATCHES "${expected_${what}}")
    message(FATAL_ERROR "restart_refusal.cmake: the file with another ${what} was not refused with the plugin's message (${DIR}/log.${what}.read)")
  endif()
  message(STATUS "restart_refusal.cmake: another ${what}: refused, saying why")
endforeach()
