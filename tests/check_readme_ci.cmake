# The README's test command and the command in .ci/run must be identical:
# CI has to run exactly what a new user is told to run.
file(READ "${SOURCE_DIR}/.ci/run" ci)
file(READ "${SOURCE_DIR}/README.md" readme)
string(REGEX MATCH "\napt-get[^\n]*ctest --preset release\n" ci_command "${ci}")
if(NOT ci_command)
  message(FATAL_ERROR ".ci/run has no 'apt-get ... ctest --preset release' command line")
endif()
string(FIND "${readme}" "${ci_command}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "README.md does not contain the command of .ci/run:${ci_command}")
endif()
message(STATUS "README and .ci/run agree:${ci_command}")
