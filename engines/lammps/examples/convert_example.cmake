# Converts one of LAMMPS' own granular example inputs to the spinslide
# plugin (issue 30), from the LAMMPS source tree's copy, so that no LAMMPS
# text is kept here: the conversion is the recipe below.
#
#   cmake -DIN=<lammps>/examples/granular/in.pour.drum -DOUT=in.pour.drum.spinslide
#         -P convert_example.cmake
#
# The converted input takes -var model stock|uncoupled|coupled (default
# coupled), -var plugin <spinslideplugin.so>, -var out <dump prefix>, and
# -var run1 N, -var run2 N, ... for the length of each `run` (default: the
# original's).  What changes, line by line:
#   - first: `plugin load ${plugin}` and the variables above;
#   - `pair_style granular` -> stock: itself; uncoupled: `pair_style
#     granular/spinslide coupling no twist_transfer negate` (LAMMPS' sign
#     convention for the twisting spring when a contact changes owner, so
#     that it equals LAMMPS bit for bit); coupled: `pair_style
#     granular/spinslide` (coupling yes, the spring's own convention).  The
#     pair_coeff lines stay: the plugin reads LAMMPS' model keywords;
#   - `fix ID group wall/gran granular ...` and `fix ID group wall/gran/region
#     granular ...` -> the plugin's wall/gran/spinslide and
#     wall/gran/region/spinslide with the same keywords; uncoupled adds
#     `coupling no moduli legacy` (LAMMPS 2021's wall constants of the
#     material models) and, for region walls, `slots legacy` (LAMMPS 2021's
#     mismatch of a corner contact's history, docs/lammps.md);
#   - `run N` -> `run ${runK}`;
#   - before the first run: a dump of every atom (id type x v f torque omega)
#     at full precision every ${dumpevery} steps (default 500), sorted by
#     id, into ${out}.dump, for compare_dumps.
#   - LAMMPS' older styles: `pair_style [hybrid] gran/hooke|gran/hooke/history|
#     gran/hertz/history ARGS` -> `pair_style granular/spinslide [coupling no]`,
#     and the `pair_coeff` after it -> `pair_coeff * * gran/... ARGS` (the
#     plugin reads the older style's numbers there); `fix ... wall/gran
#     hooke|hooke/history|hertz/history ...` (and wall/gran/region) -> the
#     plugin's walls with the same words, `coupling no` added for uncoupled.
#     Uncoupled, the plugin computes them in their own arithmetic; coupled,
#     as their equivalent with Marshall's twisting spring added.
# Anything else is kept as it is.
foreach(var IN ITEMS IN OUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "convert_example.cmake: pass -D${var}=...")
  endif()
endforeach()
file(READ "${IN}" text)
# one LAMMPS command per line: join the lines continued with '&'
string(REGEX REPLACE "&[ \t]*\n" " " text "${text}")
string(REPLACE ";" "\\;" text "${text}")
string(REPLACE "\n" ";" lines "${text}")

get_filename_component(name "${IN}" NAME)
set(head "# ${name} of LAMMPS' examples, converted by engines/lammps/examples/convert_example.cmake
variable        model index coupled
variable        plugin index spinslideplugin.so
variable        out index ${name}_\${model}
variable        dumpevery index 500
plugin          load \${plugin}
")
set(body "")
set(nrun 0)
set(legacy "")
foreach(line IN LISTS lines)
  string(REGEX REPLACE "[ \t]+$" "" command "${line}")
  if(command MATCHES "^pair_style[ \t]+granular$")
    string(APPEND body "if \"\${model} == stock\" then \"${command}\" &
elif \"\${model} == uncoupled\" \"pair_style granular/spinslide coupling no twist_transfer negate\" &
else \"pair_style granular/spinslide\"\n")
  elseif(command MATCHES "^pair_style[ \t]+(hybrid[ \t]+)?(gran/[a-z/]+[ \t].*)$")
    # LAMMPS' older styles: their numbers go into the plugin's pair_coeff
    string(REGEX REPLACE "[ \t]+" " " legacy "${CMAKE_MATCH_2}")
    string(APPEND body "if \"\${model} == stock\" then \"${command}\" &
elif \"\${model} == uncoupled\" \"pair_style granular/spinslide coupling no\" &
else \"pair_style granular/spinslide\"\n")
  elseif(command MATCHES "^pair_coeff" AND legacy)
    string(APPEND body "if \"\${model} == stock\" then \"${command}\" &
else \"pair_coeff * * ${legacy}\"\n")
  elseif(command MATCHES "^fix[ \t]+([^ \t]+)[ \t]+([^ \t]+)[ \t]+(wall/gran|wall/gran/region)[ \t]+(granular|hooke|hooke/history|hertz/history)[ \t]+(.*)$")
    # the walls: the plugin's, with the same words; uncoupled as LAMMPS 2021
    set(wall "fix ${CMAKE_MATCH_1} ${CMAKE_MATCH_2} ${CMAKE_MATCH_3}/spinslide ${CMAKE_MATCH_4} ${CMAKE_MATCH_5}")
    set(ab "coupling no")
    if(CMAKE_MATCH_4 STREQUAL "granular")
      string(APPEND ab " moduli legacy")
    endif()
    if(CMAKE_MATCH_3 STREQUAL "wall/gran/region")
      string(APPEND ab " slots legacy")
    endif()
    string(APPEND body "if \"\${model} == stock\" then \"${command}\" &
elif \"\${model} == uncoupled\" \"${wall} ${ab}\" &
else \"${wall}\"\n")
  elseif(command MATCHES "^fix[ \t]+[^ \t]+[ \t]+[^ \t]+[ \t]+wall/gran")
    message(FATAL_ERROR "convert_example.cmake: ${name}: `${command}`: only walls of style granular, hooke, hooke/history and hertz/history are converted")
  elseif(command MATCHES "^run[ \t]+([0-9]+)(.*)$")
    math(EXPR nrun "${nrun} + 1")
    string(APPEND head "variable        run${nrun} index ${CMAKE_MATCH_1}\n")
    if(nrun EQUAL 1)
      string(APPEND body "dump            spinslide_ab all custom \${dumpevery} \${out}.dump id type x y z vx vy vz fx fy fz tqx tqy tqz omegax omegay omegaz
dump_modify     spinslide_ab sort id format float %.17g\n")
    endif()
    string(APPEND body "run             \${run${nrun}}${CMAKE_MATCH_2}\n")
  else()
    string(APPEND body "${line}\n")
  endif()
endforeach()
if(nrun EQUAL 0)
  message(FATAL_ERROR "convert_example.cmake: ${name}: no run command")
endif()
file(WRITE "${OUT}" "${head}${body}")
message(STATUS "convert_example.cmake: ${name} -> ${OUT} (${nrun} runs)")
