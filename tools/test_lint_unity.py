#!/usr/bin/env python3
"""The CTest test lint.unity: tools/lint_unity.py on sources made here.

    tools/test_lint_unity.py CXX

Writes five small sources and their compile_commands.json into a temporary
directory, runs lint_unity.py on them and checks its jobs:
- the two sources with one command form one unity source, although their
  anonymous-namespace helpers collide (pi a variable in one, a function in
  the other; helper a function and a struct): CXX -fsyntax-only compiles the
  unity source, and the same two sources pasted together do not (so the
  namespaces are what makes it compile);
- an #include inside #if 0 is not pulled to the top (it names a missing
  header);
- a source that defines into a named namespace, one that specializes a
  template, and one with a command of its own stay alone;
- the members file lists the unity source's sources.
"""

import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))

SOURCES = {
    "local.hpp": "#pragma once\nstruct local_type { int n = 2; };\n",
    "a.cpp": (
        "#include <cmath>\n#include \"local.hpp\"\n#if 0\n#include \"missing.hpp\"\n#endif\n"
        "namespace {\nconstexpr double pi = 3.14159;\nint helper() { return local_type{}.n; }\n}  // namespace\n"
        "int use_a() { return helper() + static_cast<int>(std::floor(pi)); }\n"
    ),
    "b.cpp": (
        "#include <vector>\n#include \"local.hpp\"\n"
        "namespace {\ndouble pi() { return 3.0; }\nstruct helper { std::vector<int> v; };\n}  // namespace\n"
        "int use_b() { return static_cast<int>(helper{}.v.size() + pi()) + local_type{}.n; }\n"
    ),
    "named.cpp": "#include \"local.hpp\"\nnamespace reference {\nint f() { return local_type{}.n; }\n}\n",
    "spec.cpp": "#include <functional>\nstruct key {};\ntemplate <>\nstruct std::hash<key> {\n  unsigned long operator()(key) const { return 0; }\n};\n",
    "other.cpp": "int other() { return 1; }\n",
}


def fail(message):
    print(f"lint.unity: FAILED: {message}")
    sys.exit(1)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    cxx = sys.argv[1]
    with tempfile.TemporaryDirectory() as root:
        for name, text in SOURCES.items():
            with open(os.path.join(root, name), "w", encoding="utf-8") as f:
                f.write(text)
        cpp = [n for n in SOURCES if n.endswith(".cpp")]
        database = [
            {
                "directory": root,
                "command": f"{cxx} -std=c++17 {'-DOTHER ' if n == 'other.cpp' else ''}-o {n}.o -c {root}/{n}",
                "file": f"{root}/{n}",
            }
            for n in cpp
        ]
        with open(os.path.join(root, "compile_commands.json"), "w", encoding="utf-8") as f:
            json.dump(database, f)
        out = os.path.join(root, "out")
        run = subprocess.run(
            [sys.executable, os.path.join(HERE, "lint_unity.py"), os.path.join(root, "compile_commands.json"), out],
            input="".join(n + "\n" for n in cpp), capture_output=True, text=True, cwd=root, check=False)
        if run.returncode != 0:
            fail(f"lint_unity.py exited {run.returncode}: {run.stderr}")
        jobs = run.stdout.split()
        unity = os.path.join(out, "unity_1.cpp")
        expected = [f"unity:{unity}", "named.cpp", "other.cpp", "spec.cpp"]
        if jobs != expected:
            fail(f"jobs {jobs}, expected {expected}")
        with open(os.path.join(out, "unity_1.members"), encoding="utf-8") as f:
            members = f.read().split()
        if members != ["a.cpp", "b.cpp"]:
            fail(f"members {members}, expected a.cpp b.cpp")
        with open(os.path.join(out, "compile_commands.json"), encoding="utf-8") as f:
            commands = json.load(f)
        if [c["file"] for c in commands] != [unity]:
            fail(f"compile_commands.json of the unity sources: {commands}")
        compiled = subprocess.run([cxx, "-std=c++17", "-fsyntax-only", unity], capture_output=True, text=True, check=False)
        if compiled.returncode != 0:
            fail(f"the unity source does not compile:\n{compiled.stderr}")
        pasted = os.path.join(root, "pasted.cpp")
        with open(pasted, "w", encoding="utf-8") as f:
            f.write(SOURCES["a.cpp"] + SOURCES["b.cpp"])
        if subprocess.run([cxx, "-std=c++17", "-fsyntax-only", pasted], capture_output=True, check=False).returncode == 0:
            fail("a.cpp and b.cpp pasted together compile: the test's helpers do not collide")
    print("lint.unity: OK (a.cpp and b.cpp in one unity source that compiles; named.cpp, spec.cpp, other.cpp alone)")


if __name__ == "__main__":
    main()
