# The user code of an engine snippet (the lines between "// snippet begin"
# and "// snippet end" in SNIPPET; a file without them, such as a model, as a
# whole) must appear in DOC (docs/engines.md), token for token (each run of
# blanks and line breaks counts as one blank, so that either may be
# formatted on its own), so that the docs show code that compiles and runs.
file(READ "${SNIPPET}" source)
if(SNIPPET MATCHES "\\.(cpp|hpp)$")
  string(REGEX MATCH "// snippet begin\n(.*)\n[ ]*// snippet end" found "${source}")
  if(NOT found)
    message(FATAL_ERROR "${SNIPPET}: no '// snippet begin' ... '// snippet end' block")
  endif()
  set(user_code "${CMAKE_MATCH_1}")
else()
  set(user_code "${source}")
endif()
string(REGEX REPLACE "[ \t\n]+" " " block "${user_code}")
string(STRIP "${block}" block)
file(READ "${DOC}" doc)
string(REGEX REPLACE "[ \t\n]+" " " doc "${doc}")
string(FIND "${doc}" "${block}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${DOC} does not show the snippet of ${SNIPPET} verbatim:\n${block}")
endif()
message(STATUS "${DOC} shows the snippet of ${SNIPPET}")
