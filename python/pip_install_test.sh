#!/usr/bin/env bash
# CTest python_pip_install (python/CMakeLists.txt): the README's install, as a
# user runs it, into a fresh virtual environment, offline, then the pytest
# suite against the installed package (not the build tree's copy).
#   pip_install_test.sh PYTHON SOURCE_DIR WORK_DIR
# The sources are copied first (only what the package needs: pip builds in
# place, and its build/ and *.egg-info stay out of the source tree).
set -euo pipefail
python=$1 source=$2 work=$3
rm -rf "$work"
mkdir -p "$work/src"
cd "$source"
cp -r pyproject.toml setup.py VERSION LICENSE include python "$work/src/"
mkdir -p "$work/src/docs" && cp docs/python.md "$work/src/docs/"
"$python" -m venv --system-site-packages "$work/venv"
"$work/venv/bin/pip" install --no-build-isolation --no-index --quiet "$work/src"
cd "$work"  # not the source tree: the installed package is imported
"$work/venv/bin/python" -c 'import spinslide, sys; print("installed:", spinslide.__file__, spinslide.__version__)'
# The installed package's version, module and metadata, is VERSION's.
"$work/venv/bin/python" - "$(cat "$source/VERSION")" <<'EOF'
import importlib.metadata, sys
import spinslide
said = {"spinslide.__version__": spinslide.__version__,
        "its metadata": importlib.metadata.version("spinslide")}
wrong = {k: v for k, v in said.items() if v != sys.argv[1]}
sys.exit(f"VERSION is {sys.argv[1]}, but {wrong}" if wrong else 0)
EOF
SPINSLIDE_SOURCE_DIR="$source" "$work/venv/bin/python" -m pytest -q -p no:cacheprovider "$source/python/tests"
