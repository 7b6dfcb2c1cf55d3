#!/usr/bin/python3
"""The figure of what coupling does to a heap and a drum (run.sh's output).

    plot.py OUTDIR figure.png

Three panels, each with the four cases (coupling off and on, rolling
resistance off and on): the heap's angle of repose, the drum's dynamic
angle, and the drum's surface speed; each seed a small dot, the mean of the
seeds with its standard error as a bar.
"""
import glob
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import drum  # noqa: E402
import repose  # noqa: E402

CASES = [("no", "no"), ("yes", "no"), ("no", "yes"), ("yes", "yes")]
LABELS = ["uncoupled", "coupled", "uncoupled\n+ rolling", "coupled\n+ rolling"]


def values(outdir, experiment, coupling, rolling):
    suffix = "xyz" if experiment == "repose" else "dump"
    paths = sorted(glob.glob(os.path.join(outdir, f"{experiment}_{coupling}_{rolling}_*.{suffix}")))
    if not paths:
        raise SystemExit(f"plot.py: no {experiment} runs for coupling {coupling}, rolling {rolling}")
    if experiment == "repose":
        return [[repose.heap_angle(p)[0]] for p in paths]
    out = []
    for p in paths:
        per = [drum.measure(s) for s in drum.snapshots(p)]
        out.append([np.mean([v[0] for v in per]), np.mean([v[1] for v in per])])
    return out


def panel(ax, data, title, unit):
    for k, vals in enumerate(data):
        vals = np.asarray(vals)
        mean = vals.mean()
        sem = vals.std(ddof=1) / math.sqrt(len(vals)) if len(vals) > 1 else 0.0
        colour = "C1" if k % 2 else "C0"
        ax.plot(np.full(len(vals), k) + np.linspace(-0.12, 0.12, len(vals)), vals, ".",
                color=colour, alpha=0.5)
        ax.errorbar(k, mean, yerr=sem, fmt="o", color=colour, capsize=5, markersize=7)
    ax.set_xticks(range(len(LABELS)))
    ax.set_xticklabels(LABELS, fontsize=8)
    ax.set_title(title, fontsize=10)
    ax.set_ylabel(unit)
    ax.grid(axis="y", alpha=0.3)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    outdir, figure = sys.argv[1], sys.argv[2]
    heap = [[v[0] for v in values(outdir, "repose", c, r)] for c, r in CASES]
    runs = [values(outdir, "drum", c, r) for c, r in CASES]
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.8))
    panel(axes[0], heap, "heap on a plate: angle of repose", "degrees")
    panel(axes[1], [[v[0] for v in r] for r in runs], "rotating drum: dynamic angle", "degrees")
    panel(axes[2], [[v[1] for v in r] for r in runs], "rotating drum: surface speed",
          "speed (lj units)")
    seeds = min(len(v) for v in heap + runs)
    fig.suptitle("LAMMPS, granular/spinslide: coupled sliding-twisting friction against "
                 f"independent caps ({seeds} seeds each; bars: standard error)", fontsize=10)
    fig.tight_layout()
    fig.savefig(figure, dpi=120)
    print(f"plot.py: wrote {figure}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
