#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#
# The borders between the library's parts (docs/architecture.md, "Borders";
# issue 40), checked on the #include <spinslide/...> lines of every header
# under include/spinslide/:
#
#   cmake -DROOT=<repository> -P tools/include_borders.cmake
#   cmake -DROOT=<repository> -DSELF_TEST=ON -DWORK=<scratch dir> -P tools/include_borders.cmake
#
# The parts are the folders base/, values/, motion/ and contact/ (each with
# its own detail/), and the umbrellas spinslide.hpp, values.hpp, motion.hpp,
# contact.hpp beside them.  The rules:
#   1. every header lives in one of the four folders, or is an umbrella;
#   2. base includes only base; values include base and values; motion
#      includes base, values and motion; contact includes base, values and
#      contact (so values include neither motion nor contact, and motion and
#      contact do not include each other);
#   3. nothing under include/spinslide/ includes an engine adapter
#      (<spinslide/engines/...>, or an engine's own header such as
#      <mujoco/mujoco.h>, <btBulletDynamicsCommon.h>, <box2d/...>, <lammps...>);
#   4. every <spinslide/...> include names a header that exists, and an
#      umbrella includes only the core;
#   5. each part's umbrella (values.hpp, motion.hpp, contact.hpp) includes
#      every public header of its part (not detail/), and spinslide.hpp the
#      three umbrellas, so that <spinslide/spinslide.hpp> gives all of the core.
# It fails (FATAL_ERROR) naming every violation.  CMake is the one tool that
# is there wherever the tests run, so the check never skips.
#
# SELF_TEST plants one forbidden include of each kind in a copy of the tree
# under WORK and fails unless each is caught, with its rule named.

cmake_minimum_required(VERSION 3.16)

if(NOT DEFINED ROOT)
  message(FATAL_ERROR "include_borders: pass -DROOT=<repository root>")
endif()

set(_parts base values motion contact)
set(_umbrellas spinslide.hpp values.hpp motion.hpp contact.hpp)
# What each part may include (besides itself).
set(_may_base "base")
set(_may_values "base;values")
set(_may_motion "base;values;motion")
set(_may_contact "base;values;contact")
set(_may_umbrella "base;values;motion;contact;umbrella")

# The part of a header path relative to include/spinslide/: one of _parts,
# "umbrella", "engine", or "outside" (a header in no part).
function(_part_of rel out)
  string(REGEX MATCH "^[^/]+" first "${rel}")
  if(rel IN_LIST _umbrellas)
    set(${out} umbrella PARENT_SCOPE)
  elseif(first STREQUAL "engines")
    set(${out} engine PARENT_SCOPE)
  elseif(first IN_LIST _parts AND rel MATCHES "/")
    set(${out} "${first}" PARENT_SCOPE)
  else()
    set(${out} outside PARENT_SCOPE)
  endif()
endfunction()

# Checks the tree under <tree>/include/spinslide; sets <out> to the list of
# violations, each "rule N: <header> ...".
function(check_borders tree out)
  set(base "${tree}/include/spinslide")
  file(GLOB_RECURSE headers RELATIVE "${base}" "${base}/*.hpp")
  list(SORT headers)
  set(violations "")
  foreach(h IN LISTS headers)
    _part_of("${h}" part)
    if(part STREQUAL "outside" OR part STREQUAL "engine")
      list(APPEND violations "rule 1: ${h} is in none of base/, values/, motion/, contact/ and is no umbrella")
      continue()
    endif()
    file(STRINGS "${base}/${h}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*<")
    foreach(line IN LISTS lines)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*<([^>]+)>.*$" "\\1" inc "${line}")
      if(inc MATCHES "^(mujoco/|box2d/|Bullet|btBullet|bullet/|lammps|pointers\\.h|pair\\.h|fix\\.h)")
        list(APPEND violations "rule 3: ${h} includes the engine header <${inc}>")
        continue()
      endif()
      if(NOT inc MATCHES "^spinslide/")
        continue()
      endif()
      string(REGEX REPLACE "^spinslide/" "" target "${inc}")
      _part_of("${target}" to)
      if(to STREQUAL "engine")
        list(APPEND violations "rule 3: ${h} includes the engine adapter <${inc}>")
      elseif(NOT EXISTS "${base}/${target}")
        list(APPEND violations "rule 4: ${h} includes <${inc}>, which does not exist")
      elseif(NOT to STREQUAL part AND NOT to IN_LIST _may_${part})
        list(APPEND violations "rule 2: ${h} (${part}) includes <${inc}> (${to})")
      endif()
    endforeach()
  endforeach()
  # Rule 5: the umbrellas are complete.
  set(umbrella_of_values values.hpp)
  set(umbrella_of_motion motion.hpp)
  set(umbrella_of_contact contact.hpp)
  foreach(h IN LISTS headers)
    if(NOT h MATCHES "^(values|motion|contact)/[^/]+\\.hpp$")
      continue()
    endif()
    set(umbrella "${CMAKE_MATCH_1}.hpp")
    file(STRINGS "${base}/${umbrella}" lines REGEX "^#include <spinslide/${h}>")
    if(lines STREQUAL "")
      list(APPEND violations "rule 5: ${umbrella} does not include <spinslide/${h}>")
    endif()
  endforeach()
  foreach(umbrella IN ITEMS values.hpp motion.hpp contact.hpp)
    file(STRINGS "${base}/spinslide.hpp" lines REGEX "^#include <spinslide/${umbrella}>")
    if(lines STREQUAL "")
      list(APPEND violations "rule 5: spinslide.hpp does not include <spinslide/${umbrella}>")
    endif()
  endforeach()
  set(${out} "${violations}" PARENT_SCOPE)
endfunction()

if(NOT SELF_TEST)
  check_borders("${ROOT}" violations)
  list(LENGTH violations n)
  if(n GREATER 0)
    list(JOIN violations "\n  " text)
    message(FATAL_ERROR "include_borders: ${n} violation(s):\n  ${text}")
  endif()
  file(GLOB_RECURSE all RELATIVE "${ROOT}/include/spinslide" "${ROOT}/include/spinslide/*.hpp")
  list(LENGTH all nheaders)
  message(STATUS "include_borders: ${nheaders} headers, every include within its borders")
  return()
endif()

# ------------------------------------------------------------------ self test
if(NOT DEFINED WORK)
  message(FATAL_ERROR "include_borders: SELF_TEST needs -DWORK=<scratch directory>")
endif()
# Each plant: the header that gets the include, the include, the rule that
# must catch it.
set(_plants
    "values/disk.hpp|spinslide/motion/dynamics.hpp|rule 2"
    "values/detail/horner.hpp|spinslide/contact/limit_set.hpp|rule 2"
    "motion/terminal.hpp|spinslide/contact/pair_friction.hpp|rule 2"
    "contact/limit_set.hpp|spinslide/motion/terminal_state.hpp|rule 2"
    "base/detail/checks.hpp|spinslide/values/disk.hpp|rule 2"
    "contact/pair_friction.hpp|spinslide/engines/mujoco.hpp|rule 3"
    "values/profile.hpp|mujoco/mujoco.h|rule 3"
    "motion/dynamics.hpp|spinslide/motion/no_such_header.hpp|rule 4")
set(failures "")
set(i 0)
foreach(plant IN LISTS _plants)
  string(REPLACE "|" ";" fields "${plant}")
  list(GET fields 0 header)
  list(GET fields 1 include)
  list(GET fields 2 rule)
  set(tree "${WORK}/plant${i}")
  math(EXPR i "${i} + 1")
  file(REMOVE_RECURSE "${tree}")
  file(COPY "${ROOT}/include" DESTINATION "${tree}")
  file(APPEND "${tree}/include/spinslide/${header}" "#include <${include}>\n")
  check_borders("${tree}" violations)
  list(FILTER violations INCLUDE REGEX "^${rule}: ${header} ")
  if(violations STREQUAL "")
    list(APPEND failures "${header} including <${include}> was not caught by ${rule}")
  else()
    message(STATUS "include_borders self test: caught ${violations}")
  endif()
  file(REMOVE_RECURSE "${tree}")
endforeach()
# A public header that its part's umbrella misses.
set(tree "${WORK}/plant_umbrella")
file(REMOVE_RECURSE "${tree}")
file(COPY "${ROOT}/include" DESTINATION "${tree}")
file(WRITE "${tree}/include/spinslide/motion/new_part.hpp" "#pragma once\n")
check_borders("${tree}" violations)
list(FILTER violations INCLUDE REGEX "^rule 5: motion.hpp does not include <spinslide/motion/new_part.hpp>")
if(violations STREQUAL "")
  list(APPEND failures "motion/new_part.hpp, missing from motion.hpp, was not caught by rule 5")
else()
  message(STATUS "include_borders self test: caught ${violations}")
endif()
file(REMOVE_RECURSE "${tree}")
# A header outside the parts.
set(tree "${WORK}/plant_outside")
file(REMOVE_RECURSE "${tree}")
file(COPY "${ROOT}/include" DESTINATION "${tree}")
file(WRITE "${tree}/include/spinslide/stray.hpp" "#pragma once\n")
check_borders("${tree}" violations)
list(FILTER violations INCLUDE REGEX "^rule 1: stray.hpp ")
if(violations STREQUAL "")
  list(APPEND failures "stray.hpp outside the parts was not caught by rule 1")
else()
  message(STATUS "include_borders self test: caught ${violations}")
endif()
file(REMOVE_RECURSE "${tree}")
# The tree itself passes.
check_borders("${ROOT}" violations)
if(NOT violations STREQUAL "")
  list(APPEND failures "the tree itself violates: ${violations}")
endif()
if(NOT failures STREQUAL "")
  list(JOIN failures "\n  " text)
  message(FATAL_ERROR "include_borders self test FAILED:\n  ${text}")
endif()
message(STATUS "include_borders self test: every planted violation caught, the tree passes")
