#!/usr/bin/env python3
#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""Instructions per call of every path an engine's step calls (issue 41;
docs/performance.md, "Instruction counts"), counted by callgrind: exact and
deterministic, where timings move with the machine's load.

    tools/path_instructions.py DRIVER [--budgets FILE [--lower-budgets] | --markdown]

DRIVER is tools/path_instructions.cpp built with g++ -O3 -DNDEBUG
-march=x86-64 -mtune=generic (the CMake target path_instructions does
that), or a driver of the same kind: the LAMMPS plugin's law
(engines/lammps/tests/law_instructions.cpp) or MuJoCo's steps
(engines/mujoco/tests/step_instructions.cpp).  One run of it under
callgrind dumps each case's count; this script subtracts the bare loop
("loop") and divides by the calls, and gives each path as a multiple of its
unit (unit_of): the same profile's force_torque in the same type, or for an
engine's step the same scene's step with the engine's own friction.

With --budgets, every path must have a line in FILE (path, goal, budget:
multiples of force_torque) and is checked against its budget with 10 %
room; the exit status is 1 if one exceeds it or has no line.  A budget above
its goal is a goal not yet met, and the table says so.  --lower-budgets
rewrites FILE with each budget lowered to the measured multiple (rounded up
to two decimals; never below the goal, never raised): after a cut.
"""
import argparse
import glob
import math
import os
import re
import subprocess
import sys
import tempfile

ROOM = 1.10  # a path may exceed its budget by 10 % (issue 41)


def run(driver):
    """{case: instructions per call, loop subtracted}, {case: warm offset}."""
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "callgrind.out")
        proc = subprocess.run(
            ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}",
             "--dump-line=no", "--compress-strings=no", "--compress-pos=no", driver],
            capture_output=True, text=True, check=False)
        if proc.returncode != 0:
            sys.exit(f"path_instructions: {driver} failed under valgrind:\n{proc.stderr}")
        totals = {}
        for dump in glob.glob(out + ".*"):
            with open(dump, encoding="utf-8") as f:
                text = f.read()
            name = re.search(r"^desc: Trigger: Client Request: (\S+)$", text, re.M)
            total = re.search(r"^totals: (\d+)$", text, re.M)
            if name and total:
                totals[name.group(1)] = int(total.group(1))
    calls, offsets = {}, {}
    for line in proc.stdout.splitlines():
        word = line.split()
        if word and word[0] == "case":
            calls[word[1]] = int(word[2])
        elif word and word[0] == "offset":
            offsets[word[1]] = float(word[2])
    missing = sorted(set(calls) - set(totals))
    if missing:
        sys.exit(f"path_instructions: no callgrind dump for {', '.join(missing)}")
    per_call = {c: totals[c] / calls[c] for c in calls}
    counts = {}
    for case, value in per_call.items():
        if case.startswith("loop."):
            continue
        counts[case] = value - per_call["loop." + case.split(".")[2]]
    return counts, offsets


def unit_of(case):
    """The case that is the unit of `case`: the same profile's force_torque,
    for a flat patch's impulse law (issue 42: ≤ 8× its wrench) the
    rectangle's uniform wrench, and for an engine's step with spinslide
    ("mujoco_step.SCENE.double.ours") the same scene's step with the
    engine's own friction (".native"); None for a unit itself."""
    path, profile, real, *mode = case.split(".")
    if path == "patch_impulse":
        return "patch_wrench.disk.double.uniform"
    if path == "mujoco_step":
        return None if mode == ["native"] else f"{path}.{profile}.{real}.native"
    return f"force_torque.{profile}.{real}" if path != "force_torque" else None


def read_budgets(path):
    budgets = {}
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.split("#", 1)[0].split()
            if not line:
                continue
            if len(line) != 3:
                sys.exit(f"{path}:{number}: expected 'case goal budget'")
            budgets[line[0]] = (float(line[1]), float(line[2]))
    return budgets


MODES = ("warm", "spread", "cold", "sticking", "uniform", "linear", "construction", "ours")


def markdown(counts):
    """One row per path, profile and type; per mode, instructions (× its unit)."""
    measured = [c for c in counts if unit_of(c)]
    modes = [m for m in MODES if any(c.endswith("." + m) for c in measured)]
    print("| path | profile | type | unit | " + " | ".join(modes) + " |")
    print("| --- | --- | --- | ---: | " + " | ".join("---:" for _ in modes) + " |")
    rows = sorted({tuple(c.split(".")[:3]) for c in measured})
    for path, profile, real in rows:
        unit = counts[unit_of(next(c for c in measured if c.startswith(f"{path}.{profile}.{real}.")))]
        cells = []
        for m in modes:
            n = counts.get(f"{path}.{profile}.{real}.{m}")
            cells.append("" if n is None else f"{n:.0f} ({n / unit:.1f}×)")
        print(f"| {path} | {profile} | {real} | {unit:.0f} | " + " | ".join(cells) + " |")


def lower_budgets(path, counts):
    """Rewrites the budget column of `path` after a cut (never raising one)."""
    lines = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            word = line.split("#", 1)[0].split()
            if len(word) == 3 and word[0] in counts and unit_of(word[0]):
                goal, budget = float(word[1]), float(word[2])
                measured = math.ceil(counts[word[0]] / counts[unit_of(word[0])] * 100) / 100
                new = min(budget, max(goal, measured))
                line = f"{word[0]:40} {word[1]:5} {new:g}\n"
            lines.append(line)
    with open(path, "w", encoding="utf-8") as f:
        f.writelines(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("driver")
    parser.add_argument("--budgets")
    parser.add_argument("--lower-budgets", action="store_true",
                        help="lower the budgets in the --budgets file to the counts measured")
    parser.add_argument("--markdown", action="store_true",
                        help="print a Markdown table of the counts instead")
    args = parser.parse_args()
    counts, offsets = run(args.driver)
    if args.markdown:
        markdown(counts)
        return 0
    if args.lower_budgets and args.budgets:
        lower_budgets(args.budgets, counts)
    budgets = read_budgets(args.budgets) if args.budgets else {}
    failed = []
    for case in sorted(counts):
        unit = unit_of(case)
        if unit is None:
            print(f"{case:42} {counts[case]:8.0f}")
            continue
        ratio = counts[case] / counts[unit]
        verdict, goal_text, budget_text = "", "", ""
        if case in budgets:
            goal, budget = budgets[case]
            goal_text, budget_text = f"{goal:g}", f"{budget:g}"
            if ratio > budget * ROOM:
                verdict = f"OVER BUDGET (> {budget * ROOM:.2f})"
                failed.append(case)
            elif ratio > goal:
                verdict = "goal missed"
            else:
                verdict = "goal met"
        elif args.budgets:
            verdict = "NO BUDGET"
            failed.append(case)
        if case in offsets:
            verdict += f" (start {offsets[case]:.2g} off)"
        print(f"{case:42} {counts[case]:8.0f} {ratio:8.2f}x  goal {goal_text:>4}"
              f"  budget {budget_text:>5}  {verdict}")
    if failed:
        print(f"path_instructions: {len(failed)} path(s) over budget or without one: "
              f"{', '.join(failed)}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
