# Regenerates a fast path's tables (GENERATOR: tools/generate_disk_tables.cpp
# or tools/generate_hertz_tables.cpp) and fails if their numbers differ from
# the committed header COMMITTED.  Comment lines are
# not compared: they carry the generator's measured errors, which depend on
# how the generator itself was compiled (FMA contraction).
execute_process(COMMAND "${GENERATOR}" OUTPUT_FILE "${OUTPUT}" RESULT_VARIABLE status
                ERROR_VARIABLE report)
message(STATUS "${report}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${GENERATOR} failed (${status})")
endif()
file(STRINGS "${OUTPUT}" regenerated REGEX "^[^/]")
file(STRINGS "${COMMITTED}" committed REGEX "^[^/]")
if(NOT regenerated STREQUAL committed)
  message(FATAL_ERROR "The numbers in ${COMMITTED} differ from the generator's output "
                      "${OUTPUT}; regenerate it (see the generator's first comment).")
endif()
message(STATUS "The committed tables match the generator's output.")
