#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""The extension module of the Python package (metadata: pyproject.toml).

The same sources as CMake's target spinslide_python_core (python/CMakeLists.txt):
python/src/*.cpp on the library's headers in include/.  The translation units
compile in parallel (SPINSLIDE_BUILD_JOBS, default: all cores).  The version
is VERSION's (pyproject.toml reads it for the metadata; the module gets it as
SPINSLIDE_VERSION, spinslide.__version__).
"""
from glob import glob
from pathlib import Path

from pybind11.setup_helpers import ParallelCompile, Pybind11Extension
from setuptools import setup

ParallelCompile("SPINSLIDE_BUILD_JOBS", default=0).install()

VERSION = (Path(__file__).resolve().parent / "VERSION").read_text(encoding="utf-8").strip()

setup(
    ext_modules=[
        Pybind11Extension(
            "spinslide._core",
            sorted(glob("python/src/*.cpp")),
            include_dirs=["include"],
            cxx_std=17,
            extra_compile_args=["-O3", "-g0"],  # no debug info in the wheel
            define_macros=[("SPINSLIDE_VERSION", f'"{VERSION}"')],
        )
    ],
)
