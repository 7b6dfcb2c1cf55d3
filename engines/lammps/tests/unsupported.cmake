# The plugin refuses what it cannot do with a message that says why
# (engines/lammps/tests/in.unsupported): each case must fail with its message.
#   cmake -DLMP=... -DPLUGIN=... -DINPUT=... -DDIR=... -P unsupported.cmake
foreach(var LMP PLUGIN INPUT DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "unsupported.cmake: pass -D${var}=...")
  endif()
endforeach()
file(MAKE_DIRECTORY "${DIR}")
set(expected
  "pair_coeff granular/spinslide: tangential mindlin_rescale: the plugin has linear_nohistory, linear_history and mindlin"
  "pair_coeff granular/spinslide: cutoff must be > 0 \\(leave it out for the automatic cutoff"
  "Fix wall/gran/spinslide: region: a region wall is fix wall/gran/region/spinslide"
  "Pair granular/spinslide: coupling yes needs twisting marshall"
  "Fix wall/gran/spinslide: with damping tsuji, the damping number is the coefficient of restitution"
  "pair_coeff granular/spinslide: with damping tsuji, the damping number is the coefficient of restitution"
  "Fix wall/gran/region/spinslide: region nosuch does not exist"
  "Fix wall/gran/spinslide: a zcylinder wall needs x and y not periodic"
  "Fix wall/gran/spinslide: wiggle: the plane and cylinder walls are fixed in space: move a region wall"
  "Fix wall/gran/spinslide: jkr walls are not supported")
set(case 0)
foreach(message IN LISTS expected)
  math(EXPR case "${case} + 1")
  execute_process(
    COMMAND "${LMP}" -in "${INPUT}" -var plugin "${PLUGIN}" -var case ${case} -log none
    WORKING_DIRECTORY "${DIR}" RESULT_VARIABLE ran OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(ran EQUAL 0 OR NOT "${out}${err}" MATCHES "ERROR: ${message}")
    message(FATAL_ERROR "unsupported.cmake: case ${case}: expected the error '${message}', got:\n${out}${err}")
  endif()
  message(STATUS "case ${case}: refused, saying why")
endforeach()
