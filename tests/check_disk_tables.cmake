# Regenerates the fast path's tables and fails if their numbers differ from
# the committed include/spinslide/detail/disk_tables.hpp.  Comment lines are
# not compared: they carry the generator's measured errors, which depend on
# how the generator itself was compiled (FMA contraction).
execute_process(COMMAND "${GENERATOR}" OUTPUT_FILE "${OUTPUT}" RESULT_VARIABLE status
                ERROR_VARIABLE report)
message(STATUS "${report}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "generate_disk_tables failed (${status})")
endif()
file(STRINGS "${OUTPUT}" regenerated REGEX "^[^/]")
file(STRINGS "${COMMITTED}" committed REGEX "^[^/]")
if(NOT regenerated STREQUAL committed)
  message(FATAL_ERROR "The numbers in ${COMMITTED} differ from the generator's output "
                      "${OUTPUT}; regenerate it (see tools/generate_disk_tables.cpp).")
endif()
message(STATUS "The committed tables match the generator's output.")
