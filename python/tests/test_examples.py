#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""The Python examples (examples/python) against the C++ programs' output:
Figs. 2 and 3 against the CSV data of the C++ demo (examples/paper), the CD
fit against cd_experiment's own fit of the same frames, and the Monte Carlo
run small.  CTest's python_tests names the C++ programs
(SPINSLIDE_PAPER_EXE, SPINSLIDE_CD_EXPERIMENT_EXE); where they are not
built (the install test, or a build without examples) the comparisons are
skipped and say so."""

import csv
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import spinslide
from conftest import SOURCE

EXAMPLES = SOURCE / "examples" / "python"
PAPER = os.environ.get("SPINSLIDE_PAPER_EXE")
CD = os.environ.get("SPINSLIDE_CD_EXPERIMENT_EXE")
needs_paper = pytest.mark.skipif(not PAPER, reason="the C++ demo (paper) is not built here")
needs_cd = pytest.mark.skipif(not CD, reason="the C++ cd_experiment is not built here")


def run_example(name, *args):
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [p for p in (os.environ.get("PYTHONPATH"),) if p]))
    done = subprocess.run([sys.executable, str(EXAMPLES / name), *map(str, args)], env=env,
                          capture_output=True, text=True, check=True)
    return done.stdout


def blocks(path):
    """A gnuplot-style CSV (a header, blocks separated by blank lines) as lists of float rows."""
    out, current = [], []
    with open(path) as f:
        next(f)
        for line in f:
            if line.strip():
                current.append([float(x) for x in line.split(",")])
            elif current:
                out.append(np.array(current))
                current = []
    if current:
        out.append(np.array(current))
    return out


@pytest.fixture(scope="module")
def paper_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp("paper")
    subprocess.run([PAPER, str(out)], check=True, capture_output=True)
    return out


@needs_paper
def test_fig2_has_the_cpp_figures_data(paper_dir, tmp_path):
    run_example("fig2_force_torque.py", tmp_path)
    ours, theirs = blocks(tmp_path / "fig2_force_torque.csv"), blocks(
        paper_dir / "fig2_force_torque.csv")
    assert [b.shape for b in ours] == [b.shape for b in theirs] == [(501, 3), (801, 3)]
    for a, b in zip(ours, theirs):
        assert np.array_equal(a, b)  # the same values, printed to 17 digits
    assert (tmp_path / "fig2_force_torque.png").stat().st_size > 20_000


@needs_paper
def test_fig3_passes_through_the_cpp_figures_points(paper_dir, tmp_path):
    run_example("fig3_trajectories.py", tmp_path)
    ours, theirs = blocks(tmp_path / "fig3_trajectories.csv"), blocks(
        paper_dir / "fig3_trajectories.csv")
    assert len(ours) == len(theirs) == 16
    disk = spinslide.UniformDisk()
    a = (np.arange(16) + 0.5) / 16 * np.pi / 2
    for i, points in enumerate(theirs):
        # The C++ figure's samples (its integrator's steps, printed to 9
        # digits) lie on the Python trajectory at the same times: within the
        # printing of v, ω and t (9 digits: 5e-9 relative; |dv/dt| = 𝓕 ≤ 1,
        # |dω/dt| = 𝓣/γ ≤ 4/3).  (At the exact times they are equal, bit for bit:
        # test_dynamics.)
        t = points[:, 1]
        at = spinslide.trajectory(disk, 0.5, np.cos(a[i]), np.sin(a[i]), t)
        for ours_v, theirs_v in ((at["speed"], points[:, 2]), (at["spin"], points[:, 3])):
            bound = 5.01e-9 * (np.abs(theirs_v) + (4 / 3) * t) + 1e-15
            assert np.all(np.abs(ours_v - theirs_v) <= bound)
        # The Python figure is dense: at least 300 points per throw.
        assert len(ours[i]) >= 300
    assert (tmp_path / "fig3_trajectories.png").stat().st_size > 20_000


@needs_cd
def test_cd_fit_matches_the_cpp_analysis(tmp_path):
    printed = subprocess.run([CD, "--out", str(tmp_path)], check=True, capture_output=True,
                             text=True).stdout
    line = next(x for x in printed.splitlines() if x.startswith("the authors' fit"))
    a_cxx, b_cxx = (float(v) for v in re.findall(r"[ab] = ([-0-9.e]+)", line))
    out = run_example("fit_cd_experiment.py", tmp_path / "cd_frames.csv", tmp_path)
    a, b = (float(v) for v in re.findall(r"[ab] = ([-0-9.e]+)", out.splitlines()[1]))
    assert a == pytest.approx(a_cxx, abs=5e-6)   # printed to 5 decimals
    assert b == pytest.approx(b_cxx, abs=5e-7)   # and to 6
    assert (tmp_path / "cd_fit.png").exists()


def test_monte_carlo_runs_small(tmp_path):
    out = run_example("monte_carlo.py", "--throws", 20000, "--out", tmp_path)
    assert "20000 throws in" in out
    assert "sliding_and_spinning" in out
    assert (tmp_path / "monte_carlo.png").stat().st_size > 20_000
