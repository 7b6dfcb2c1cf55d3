#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""Speed of the Python package against the C++ batch, in the same process.

    PYTHONPATH=build/release/python /usr/bin/python3 python/benchmarks/bench_python.py

1. force_torque over 1e6 ratios from Python (numpy in, two new arrays out),
   per ratio, against the C++ force_torque_batch on the same ratios into
   preallocated buffers (spinslide._core._force_torque_batch_into: the
   library call alone, in the same module, same compiler and flags).  Goal
   (issue 29): at most 1.5x.
2. stop_results over 1e5 throws on 1, 2, ... threads up to the cores:
   throws per second and the speed-up.
Each time is the best of several runs (the least disturbed).
"""

import argparse
import os
import time

import numpy as np

import spinslide
from spinslide import _core


def best_of(f, repeat):
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        f()
        best = min(best, time.perf_counter() - start)
    return best


def values(n, repeat):
    rng = np.random.default_rng(20261127)
    eps = np.exp(rng.uniform(np.log(1e-4), np.log(1e4), n))  # log-uniform over 8 decades
    f = np.empty_like(eps)
    t = np.empty_like(eps)
    cxx = best_of(lambda: _core._force_torque_batch_into(eps, f, t), repeat)
    py = best_of(lambda: spinslide.force_torque(eps), repeat)
    py32 = best_of(lambda: spinslide.force_torque(eps.astype(np.float32)), repeat)
    print(f"force_torque, {n} ratios log-uniform in [1e-4, 1e4], best of {repeat}:")
    print(f"  C++ force_torque_batch (baseline) {1e9 * cxx / n:6.2f} ns per ratio")
    print(f"  Python spinslide.force_torque     {1e9 * py / n:6.2f} ns per ratio  "
          f"ratio {py / cxx:.2f}  (goal <= 1.5)")
    print(f"  Python, float32 in and out        {1e9 * py32 / n:6.2f} ns per ratio")
    return py / cxx


def throws(n, repeat):
    rng = np.random.default_rng(7)
    v0 = rng.uniform(0.1, 3.0, n)
    w0 = rng.uniform(0.1, 3.0, n)
    disk = spinslide.UniformDisk()
    cores = os.cpu_count() or 1
    print(f"stop_results, {n} throws of the uniform disk at gamma = 0.5, best of {repeat}:")
    base = None
    for k in sorted({1, *range(2, cores + 1)}):
        s = best_of(lambda: spinslide.stop_results(disk, 0.5, v0, w0, threads=k), repeat)
        base = base or s
        print(f"  {k} thread(s): {s:6.2f} s, {n / s:9.0f} throws/s, speed-up {base / s:.2f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ratios", type=int, default=1_000_000)
    parser.add_argument("--throws", type=int, default=100_000)
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    values(args.ratios, args.repeat)
    throws(args.throws, max(1, args.repeat // 2))


if __name__ == "__main__":
    main()
