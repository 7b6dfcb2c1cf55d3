#!/usr/bin/env python3
"""The warnings-only pass of the matrix's cells that CI leaves out
(docs/reliability.md, "The compiler and sanitizer matrix"): by hand before a
release.

    tools/warnings_only.py PRESET [JOBS]

Configures the CMake preset PRESET (gcc-cxx20 or clang-cxx20: C++20 with
-Wall -Wextra -Wpedantic -Wconversion -Wshadow -Werror) with its compile
commands exported, then runs every translation unit of the project through
its compiler's front end with -fsyntax-only: the same parse, template
instantiation and front-end warnings as a build, without code generation,
linking or running anything.  Any warning is an error (-Werror): the pass
fails, naming every source that failed with the compiler's output.

The optimizer's own warnings are the release build's (-O3) concern, where
.ci/run looks for them; this pass is for the front ends in the standard CI
does not build them in.  Needs cmake and the preset's compiler; JOBS defaults to 2.
"""

import json
import shlex
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path


def syntax_only(command):
    """The compile command with -fsyntax-only in place of -c and -o FILE."""
    args = shlex.split(command)
    out = []
    skip = False
    for arg in args:
        if skip:
            skip = False
            continue
        if arg == "-o":
            skip = True
            continue
        if arg == "-c":
            continue
        out.append(arg)
    return out + ["-fsyntax-only"]


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__.split("\n\n")[1])
    preset = sys.argv[1]
    jobs = int(sys.argv[2]) if len(sys.argv) == 3 else 2
    root = Path(__file__).resolve().parent.parent
    start = time.monotonic()
    # Debug at -O0, as the matrix built these presets before: assertions kept.
    subprocess.run(["cmake", "--preset", preset, "-DCMAKE_EXPORT_COMPILE_COMMANDS=ON",
                    "-DCMAKE_BUILD_TYPE=Debug", "-DCMAKE_CXX_FLAGS_DEBUG=-O0"],
                   cwd=root, check=True, stdout=subprocess.DEVNULL)
    database = root / "build" / preset / "compile_commands.json"
    entries = json.loads(database.read_text())
    if not entries:
        sys.exit(f"warnings_only: {database} lists no translation unit")

    def check(entry):
        run = subprocess.run(syntax_only(entry["command"]), cwd=entry["directory"],
                             capture_output=True, text=True)
        return entry["file"], run.returncode, run.stdout + run.stderr

    failed = []
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        for name, code, output in pool.map(check, entries):
            if code != 0 or output.strip():
                failed.append(name)
                print(f"warnings_only: {preset}: {name}\n{output}", flush=True)
    elapsed = time.monotonic() - start
    print(f"warnings_only: {preset}: {len(entries)} translation units, "
          f"{len(failed)} with warnings or errors ({elapsed:.0f} s)")
    if failed:
        sys.exit(1)


if __name__ == "__main__":
    main()
