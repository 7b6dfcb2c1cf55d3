# Compiles SOURCE with -DMISUSE=${MISUSE} and checks the outcome: MISUSE 0
# must compile; any other must fail with EXPECT in the compiler's output.
#   cmake -DCXX=... -DINCLUDES="dir|dir" -DSOURCE=... -DMISUSE=n [-DEXPECT=regex] -P check.cmake
string(REPLACE "|" ";" include_dirs "${INCLUDES}")
set(flags -std=c++17 -fsyntax-only -DMISUSE=${MISUSE})
foreach(dir IN LISTS include_dirs)
  list(APPEND flags "-I${dir}")
endforeach()
execute_process(COMMAND "${CXX}" ${flags} "${SOURCE}"
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(MISUSE EQUAL 0)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "the correct call did not compile:\n${out}")
  endif()
elseif(result EQUAL 0)
  message(FATAL_ERROR "misuse ${MISUSE} compiled")
elseif(NOT out MATCHES "${EXPECT}")
  message(FATAL_ERROR "misuse ${MISUSE} failed without '${EXPECT}':\n${out}")
endif()
message(STATUS "misuse ${MISUSE}: as expected")
