#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""The paper's Fig. 3 from Python: 16 throws of the uniformly pressed disk
(gamma = 1/2) from starts on a quarter circle, (a) in the (v*, omega*) plane
and (b) eps against v*, which tends to eps_0 = 0.653 as the disk stops.

    python fig3_trajectories.py [OUTPUT_DIR]

Each throw is sampled densely (spinslide.trajectory at 400 times, spaced
evenly in log(t_stop - t) towards the stop, where eps still moves), so the
curves are smooth at any size.  Writes fig3_trajectories.csv
(throw, t, v, omega, eps) and fig3_trajectories.png.
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import spinslide  # noqa: E402

THROWS = 16
GAMMA = 0.5


def starts():
    a = (np.arange(THROWS) + 0.5) / THROWS * np.pi / 2  # the direction of (v0*, omega0*)
    return np.cos(a), np.sin(a)


def sample_times(stop, points=400):
    """From 0 to just before the stop: half the points evenly in t, half evenly
    in log(stop - t) down to 1e-9 of the stop time, and the stop itself."""
    even = np.linspace(0.0, stop, points // 2, endpoint=False)
    near = stop - np.geomspace(0.5 * stop, 1e-9 * stop, points // 2)
    return np.unique(np.concatenate([even, near, [stop]]))


def throws(disk=None):
    disk = disk or spinslide.UniformDisk()
    out = []
    for v0, w0 in zip(*starts()):
        stop = spinslide.simulate_throw(disk, GAMMA, v0, w0).time
        out.append(spinslide.trajectory(disk, GAMMA, v0, w0, sample_times(stop)))
    return out


def main(out=Path(".")):
    out.mkdir(parents=True, exist_ok=True)
    samples = throws()
    with open(out / "fig3_trajectories.csv", "w") as f:
        f.write("throw,t,v,omega,eps\n")
        for i, s in enumerate(samples):
            for row in zip(s["time"], s["speed"], s["spin"], s["ratio"]):
                f.write(f"{i}," + ",".join(f"{x:.9g}" for x in row) + "\n")
            f.write("\n\n")
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2), constrained_layout=True)
    for s in samples:
        moving = s["speed"] > 0
        left.plot(s["speed"], s["spin"], lw=1.3)
        right.plot(s["speed"][moving], s["ratio"][moving], lw=1.3)
    left.set(title=r"(a) trajectories in the $(v^*, \omega^*)$ plane", xlabel=r"$v^*$",
             ylabel=r"$\omega^*$", aspect="equal")
    right.axhline(spinslide.terminal_ratio(), color="black", ls="--", lw=1)
    right.set(title=r"(b) $\varepsilon$ tends to $\varepsilon_0 = 0.653$ as the disk stops",
              xlabel=r"$v^*$", ylabel=r"$\varepsilon = v^*/\omega^*$", yscale="log",
              ylim=(0.01, 100))
    for ax in (left, right):
        ax.grid(True)
    fig.savefig(out / "fig3_trajectories.png", dpi=110)
    print(f"wrote {out / 'fig3_trajectories.csv'} and {out / 'fig3_trajectories.png'}")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("."))
