#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""A Monte Carlo of throws with a progress bar: how far and how long an
elastic sphere's flat contact (Hertz) slides and spins when thrown at random.

    python monte_carlo.py [--throws 1000000] [--gamma 0.4] [--out DIR] [--threads 0]

Starts (v0*, omega0*) uniform on [0, 2] x [0, 2]; every throw exact
(spinslide.stop_results on all cores, the GIL released, a progress bar on
stderr).  Prints the mean and spread of the stop time, distance and angle,
and the fraction that end in each terminal regime; writes monte_carlo.png
(histograms of the stop time and of the final ratio eps).
"""

import argparse
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import spinslide  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--throws", type=int, default=1_000_000)
    parser.add_argument("--gamma", type=float, default=0.4, help="I/(m a^2)")
    parser.add_argument("--threads", type=int, default=0, help="0: all cores")
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--out", type=Path, default=Path("."))
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    v0 = rng.uniform(0, 2, args.throws)
    w0 = rng.uniform(0, 2, args.throws)
    hertz = spinslide.Hertz()
    start = time.perf_counter()
    r = spinslide.stop_results(hertz, args.gamma, v0, w0, threads=args.threads, progress=True)
    seconds = time.perf_counter() - start
    print(f"{args.throws} throws in {seconds:.1f} s ({args.throws / seconds:,.0f} per second)")
    for name in ("time", "distance", "angle"):
        x = getattr(r, name)
        print(f"  stop {name:8s}: mean {x.mean():.4f}, sd {x.std():.4f}, max {x.max():.4f}")
    state = spinslide.terminal_motion(hertz, args.gamma)
    print(f"  terminal regime at gamma = {args.gamma}: {state.regime.name}, eps -> {state.ratio:.6f}")
    finite = np.isfinite(r.terminal_ratio) & (r.terminal_ratio > 0)
    print(f"  throws ending sliding and spinning: {finite.mean():.4f}")
    args.out.mkdir(parents=True, exist_ok=True)
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
    left.hist(r.time, bins=200, color="#1f77b4")
    left.set(title="stop time of random throws (Hertz)", xlabel=r"$t^*$", ylabel="throws")
    edges = np.linspace(0, 2, 61)
    total, _, _ = np.histogram2d(v0, w0, bins=(edges, edges), weights=r.time)
    count, _, _ = np.histogram2d(v0, w0, bins=(edges, edges))
    with np.errstate(invalid="ignore"):
        mean = total / count
    image = right.imshow(mean.T, origin="lower", extent=(0, 2, 0, 2), cmap="viridis",
                         aspect="equal")
    fig.colorbar(image, ax=right, label=r"mean $t^*$")
    right.set(title="mean stop time over the starts", xlabel=r"$v_0^*$",
              ylabel=r"$\omega_0^*$")
    fig.savefig(args.out / "monte_carlo.png", dpi=110)
    print(f"wrote {args.out / 'monte_carlo.png'}")


if __name__ == "__main__":
    main()
