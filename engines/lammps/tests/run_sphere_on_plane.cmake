# Runs engines/lammps/examples/in.sphere_on_plane (coupling yes and no) and
# sphere_on_plane_reference (spinslide's own integration of the same contact
# law), parses the stop times both print ("  sphere N, ...: sliding stops at
# t = A, spinning at t = B" under "coupling yes|no: ..."), and fails unless
# each LAMMPS stop time is within REL (default 0.01) of the reference's, or
# within one LAMMPS step STEP (default 0.0002), whichever is larger: LAMMPS
# reads a stop at the first step past the threshold, so its times are late by
# up to one step, which exceeds 1 % for times below 0.02 (here only the
# quantities not thrown, which stop at t = 0).
# PROFILE (default hertz; "annulus 0.5" for the annulus) is the patch's
# profile, given to both (-var profile, --profile); COUPLINGS (default
# "yes;no") the runs compared.
#   cmake -DLMP=... -DPLUGIN=... -DINPUT=... -DREFERENCE=... -DDIR=...
#         [-DREL=0.01] [-DSTEP=0.0002] [-DPROFILE=ring] [-DCOUPLINGS=yes]
#         -P run_sphere_on_plane.cmake
foreach(var LMP PLUGIN INPUT REFERENCE DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_sphere_on_plane.cmake: pass -D${var}=...")
  endif()
endforeach()
if(NOT DEFINED REL)
  set(REL 0.01)
endif()
if(NOT DEFINED STEP)
  set(STEP 0.0002)
endif()
if(NOT DEFINED PROFILE)
  set(PROFILE hertz)
endif()
if(NOT DEFINED COUPLINGS)
  set(COUPLINGS yes no)
endif()
separate_arguments(profile_args UNIX_COMMAND "${PROFILE}")
file(MAKE_DIRECTORY "${DIR}")

# CMake has integer arithmetic only: times as integers in units of 1e-6 (the
# LAMMPS input prints 4 decimals, the reference 6).
function(to_micro text out)
  if(NOT text MATCHES "^(-?)([0-9]*)(\\.([0-9]*))?$")
    message(FATAL_ERROR "run_sphere_on_plane.cmake: cannot read the time '${text}'")
  endif()
  set(sign "${CMAKE_MATCH_1}")
  set(whole "${CMAKE_MATCH_2}")
  set(frac "${CMAKE_MATCH_4}000000")
  string(SUBSTRING "${frac}" 0 6 frac)
  # no leading zeros for math() (REGEX REPLACE re-anchors ^ after each match)
  while(frac MATCHES "^0[0-9]")
    string(SUBSTRING "${frac}" 1 -1 frac)
  endwhile()
  if(whole STREQUAL "")
    set(whole 0)
  endif()
  math(EXPR value "${sign}(${whole} * 1000000 + ${frac})")
  set(${out} ${value} PARENT_SCOPE)
endfunction()

# The six stop times of one coupling's block in `text`, as
# <prefix>_<sphere>_{slide,spin} in micro-units.
function(parse_block text coupling prefix)
  string(REGEX MATCH "coupling ${coupling}:[^\n]*\n[^\n]*\n[^\n]*\n[^\n]*" block "${text}")
  if(NOT block)
    message(FATAL_ERROR "run_sphere_on_plane.cmake: no 'coupling ${coupling}:' block in\n${text}")
  endif()
  foreach(n 1 2 3)
    if(NOT block MATCHES
       "sphere ${n},[^\n]*sliding stops at t = ([-0-9.]+), spinning at t = ([-0-9.]+)")
      message(FATAL_ERROR "run_sphere_on_plane.cmake: no line for sphere ${n} in\n${block}")
    endif()
    set(spin "${CMAKE_MATCH_2}")
    to_micro("${CMAKE_MATCH_1}" slide_us)
    to_micro("${spin}" spin_us)
    set(${prefix}_${n}_slide ${slide_us} PARENT_SCOPE)
    set(${prefix}_${n}_spin ${spin_us} PARENT_SCOPE)
  endforeach()
endfunction()

# the reference
execute_process(COMMAND "${REFERENCE}" --profile ${profile_args} OUTPUT_VARIABLE ref_text
                RESULT_VARIABLE ran)
file(WRITE "${DIR}/reference.txt" "${ref_text}")
if(NOT ran EQUAL 0)
  message(FATAL_ERROR "run_sphere_on_plane.cmake: the reference failed (${ran})")
endif()
message("${ref_text}")

to_micro("${STEP}" step_us)
to_micro("${REL}" rel_ppm)  # REL in parts per 10^6

set(failures 0)
set(names "sliding (v_x = 1)" "spinning (w_z = 20)" "both")
foreach(coupling IN LISTS COUPLINGS)
  execute_process(
    COMMAND "${LMP}" -in "${INPUT}" -var plugin "${PLUGIN}" -var coupling ${coupling}
            -var profile "${PROFILE}" -log "log.${coupling}"
    WORKING_DIRECTORY "${DIR}" OUTPUT_VARIABLE lmp_text RESULT_VARIABLE ran)
  if(NOT ran EQUAL 0)
    message(FATAL_ERROR
      "run_sphere_on_plane.cmake: LAMMPS failed with coupling ${coupling} (${DIR}/log.${coupling})")
  endif()
  parse_block("${lmp_text}" ${coupling} lmp)
  parse_block("${ref_text}" ${coupling} ref)
  foreach(n 1 2 3)
    math(EXPR i "${n} - 1")
    list(GET names ${i} name)
    foreach(what slide spin)
      set(l ${lmp_${n}_${what}})
      set(r ${ref_${n}_${what}})
      math(EXPR diff "${l} - ${r}")
      set(absdiff ${diff})
      if(diff LESS 0)
        math(EXPR absdiff "0 - (${diff})")
      endif()
      math(EXPR allowed "${r} * ${rel_ppm} / 1000000")
      if(allowed LESS step_us)
        set(allowed ${step_us})
      endif()
      set(verdict ok)
      if(l LESS 0 OR r LESS 0 OR absdiff GREATER allowed)
        set(verdict FAIL)
        math(EXPR failures "${failures} + 1")
      endif()
      message("coupling ${coupling}, sphere ${n} ${name}, ${what} stop (1e-6): "
              "LAMMPS ${l}, reference ${r}, difference ${diff}, allowed ${allowed}: ${verdict}")
    endforeach()
  endforeach()
endforeach()
if(failures GREATER 0)
  message(FATAL_ERROR "run_sphere_on_plane.cmake: ${failures} stop times disagree")
endif()
