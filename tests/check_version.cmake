# CTest version_consistent (the top-level CMakeLists.txt): the version is
# written once, in VERSION at the repository's root, and everything that
# names it must agree with that file.  Fails, naming each disagreement, where
#   - CMake's PROJECT_VERSION (as configured) or the package version file
#     (spinslideConfigVersion.cmake) says another version;
#   - a CMakeLists.txt writes a version number in project() instead of
#     reading VERSION;
#   - pyproject.toml writes a version instead of reading VERSION, or setup.py
#     passes one; and, with PYTHON, `setup.py --version` prints another;
#   - a find_package(spinslide X.Y ...) line of README.md, docs/, the consume
#     tests (tests/consume), engines/ or examples/ asks for another X.Y, or
#     a GIT_TAG vX.Y.Z there names another version;
#   - a version literal ending a string ("... v0.1") sits in engines/;
#   - CHANGELOG.md's newest version (its first "## [X.Y.Z]") is another;
#   - with PYTHON and PYTHONPATH (the Python package is built):
#     spinslide.__version__ is another.
#
#   cmake -DSOURCE_DIR=<repo> -DPROJECT_VERSION=<x.y.z>
#         [-DCONFIG_VERSION_FILE=<build>/spinslideConfigVersion.cmake]
#         [-DPYTHON=<interpreter> -DPYTHONPATH=<build>/python] -P check_version.cmake
cmake_minimum_required(VERSION 3.16)

if(NOT SOURCE_DIR OR NOT DEFINED PROJECT_VERSION)
  message(FATAL_ERROR "check_version.cmake: SOURCE_DIR and PROJECT_VERSION must be set")
endif()

file(STRINGS "${SOURCE_DIR}/VERSION" version LIMIT_COUNT 1)
if(NOT version MATCHES "^([0-9]+)\\.([0-9]+)\\.([0-9]+)$")
  message(FATAL_ERROR "VERSION must hold one line MAJOR.MINOR.PATCH, not '${version}'")
endif()
set(major_minor "${CMAKE_MATCH_1}.${CMAKE_MATCH_2}")

set(problems "")
macro(disagree what)
  string(APPEND problems "\n  ${what}")
endmacro()

# CMake: the configured version and the package version file.
if(NOT PROJECT_VERSION STREQUAL version)
  disagree("CMake's PROJECT_VERSION is ${PROJECT_VERSION} (reconfigure, or see CMakeLists.txt)")
endif()
if(CONFIG_VERSION_FILE)
  file(STRINGS "${CONFIG_VERSION_FILE}" package_version REGEX "^set\\(PACKAGE_VERSION \"")
  string(REGEX REPLACE "^set\\(PACKAGE_VERSION \"([^\"]*)\"\\).*" "\\1" package_version
                       "${package_version}")
  if(NOT package_version STREQUAL version)
    disagree("${CONFIG_VERSION_FILE}: PACKAGE_VERSION ${package_version}")
  endif()
endif()

# Every tracked-looking file that may name the version.
file(GLOB_RECURSE cmake_lists RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/CMakeLists.txt"
     "${SOURCE_DIR}/cmake/*" "${SOURCE_DIR}/tests/*CMakeLists.txt"
     "${SOURCE_DIR}/engines/*CMakeLists.txt" "${SOURCE_DIR}/examples/*CMakeLists.txt"
     "${SOURCE_DIR}/python/*CMakeLists.txt" "${SOURCE_DIR}/benchmarks/*CMakeLists.txt"
     "${SOURCE_DIR}/fuzz/*CMakeLists.txt")
file(GLOB_RECURSE texts RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/README.md" "${SOURCE_DIR}/docs/*.md"
     "${SOURCE_DIR}/engines/*.md" "${SOURCE_DIR}/examples/*.md")
set(scanned "")
foreach(file IN LISTS cmake_lists texts)
  if(NOT file MATCHES "^build/")
    list(APPEND scanned "${file}")
  endif()
endforeach()
list(REMOVE_DUPLICATES scanned)

foreach(file IN LISTS scanned)
  # A number in project(): the version must be read from VERSION.
  if(file MATCHES "CMakeLists\\.txt$")
    file(STRINGS "${SOURCE_DIR}/${file}" hits REGEX "^[ \t]*project\\([^)]*VERSION[ \t]+[0-9]")
    foreach(hit IN LISTS hits)
      disagree("${file}: a version number in project(); read VERSION instead: ${hit}")
    endforeach()
  endif()
  # find_package(spinslide X.Y ...): the version VERSION's major.minor.
  file(STRINGS "${SOURCE_DIR}/${file}" hits REGEX "find_package\\([ \t]*spinslide[ \t]+[0-9]")
  foreach(hit IN LISTS hits)
    string(REGEX MATCH "find_package\\([ \t]*spinslide[ \t]+([0-9][0-9.]*)" call "${hit}")
    set(asked "${CMAKE_MATCH_1}")
    if(NOT asked STREQUAL major_minor AND NOT asked STREQUAL version)
      disagree("${file}: ${call} ...), not ${major_minor}")
    endif()
  endforeach()
  # GIT_TAG vX.Y.Z: VERSION's.
  file(STRINGS "${SOURCE_DIR}/${file}" hits REGEX "GIT_TAG[ \t]+v[0-9]")
  foreach(hit IN LISTS hits)
    string(REGEX MATCH "GIT_TAG[ \t]+v([0-9][0-9.]*)" tag "${hit}")
    if(NOT CMAKE_MATCH_1 STREQUAL version)
      disagree("${file}: ${tag}, not v${version}")
    endif()
  endforeach()
endforeach()

# Version literals ending a string in the engines' sources (the LAMMPS
# plugin's info strings take SPINSLIDE_VERSION from their CMake).
file(GLOB_RECURSE engine_sources RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/engines/*.cpp"
     "${SOURCE_DIR}/engines/*.h")
foreach(file IN LISTS engine_sources)
  file(STRINGS "${SOURCE_DIR}/${file}" hits REGEX " v[0-9]+\\.[0-9]+(\\.[0-9]+)?\"")
  foreach(hit IN LISTS hits)
    string(STRIP "${hit}" hit)
    disagree("${file}: a version number in a string; use SPINSLIDE_VERSION: ${hit}")
  endforeach()
endforeach()

# The Python package: pyproject.toml reads VERSION, setup.py names none.
file(READ "${SOURCE_DIR}/pyproject.toml" pyproject)
if(NOT pyproject MATCHES "\ndynamic = \\[[^]\n]*\"version\"")
  disagree("pyproject.toml: [project] has no dynamic = [\"version\"]")
endif()
if(NOT pyproject MATCHES "\n\\[tool\\.setuptools\\.dynamic\\]\n([^[]*\n)?version = { *file = \"VERSION\" *}")
  disagree("pyproject.toml: no [tool.setuptools.dynamic] version = { file = \"VERSION\" }")
endif()
if(pyproject MATCHES "\nversion = \"([^\"]*)\"")
  disagree("pyproject.toml: version = \"${CMAKE_MATCH_1}\" written in place of VERSION's")
endif()
file(READ "${SOURCE_DIR}/setup.py" setup_py)
if(setup_py MATCHES "version *= *[\"'][0-9]")
  disagree("setup.py: a version written in place of VERSION's")
endif()

# CHANGELOG.md: its newest version (Keep a Changelog: the first "## [X.Y.Z]";
# "## [Unreleased]" above it is not a version).
file(STRINGS "${SOURCE_DIR}/CHANGELOG.md" released REGEX "^## \\[[0-9]+\\.[0-9]+\\.[0-9]+\\]")
list(LENGTH released count)
if(count EQUAL 0)
  disagree("CHANGELOG.md: no \"## [X.Y.Z]\" section")
else()
  list(GET released 0 newest)
  string(REGEX REPLACE "^## \\[([^]]*)\\].*" "\\1" newest "${newest}")
  if(NOT newest STREQUAL version)
    disagree("CHANGELOG.md: the newest version is ${newest}")
  endif()
endif()

# What the Python build tools and the built package say.
set(python_note "")
if(PYTHON)
  string(APPEND python_note "; setup.py --version")
  execute_process(COMMAND "${PYTHON}" setup.py --version
                  WORKING_DIRECTORY "${SOURCE_DIR}"
                  RESULT_VARIABLE failed OUTPUT_VARIABLE said ERROR_VARIABLE errors
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(failed)
    disagree("setup.py --version failed: ${errors}")
  elseif(NOT said STREQUAL version)
    disagree("setup.py --version (the package's metadata) says ${said}")
  endif()
  if(PYTHONPATH)
    string(APPEND python_note ", spinslide.__version__")
    execute_process(COMMAND "${CMAKE_COMMAND}" -E env "PYTHONPATH=${PYTHONPATH}" "${PYTHON}" -c
                            "import spinslide; print(spinslide.__version__)"
                    RESULT_VARIABLE failed OUTPUT_VARIABLE said ERROR_VARIABLE errors
                    OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(failed)
      disagree("import spinslide (${PYTHONPATH}; build spinslide_python_core first) failed: ${errors}")
    elseif(NOT said STREQUAL version)
      disagree("spinslide.__version__ (${PYTHONPATH}) is ${said}")
    endif()
  endif()
endif()

if(problems)
  message(FATAL_ERROR "The version is ${version} (VERSION), but:${problems}")
endif()
list(LENGTH scanned files)
message(STATUS "version ${version} everywhere (${files} CMake and Markdown files scanned"
               "${python_note})")
