#!/usr/bin/python3
"""The dynamic angle of repose and the surface flow of in.drum's runs.

    drum.py drum1.dump [drum2.dump ...]

For each snapshot of a dump: the spheres are binned along x (bins 1 wide,
the drum's cross-section is x-z); in each bin the free surface is the
highest sphere top (z + radius).  The angle is atan of the least-squares
slope of the surface over the bins within 60 % of the surface's half-width
of its centre (away from the drum wall), in degrees, as a magnitude.  The
surface speed is the mean speed, in the x-z plane, of the spheres whose
top lies within one diameter of the surface of their bin.  Each run's
values are the means over its snapshots; the last line gives the mean over
the runs and its standard error.
"""
import math
import sys

import numpy as np


def snapshots(path):
    with open(path) as f:
        lines = f.read().split("\n")
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            n = int(lines[i + 3])
            cols = lines[i + 8].split()[2:]
            rows = np.array([[float(v) for v in line.split()] for line in lines[i + 9:i + 9 + n]])
            yield {c: rows[:, k] for k, c in enumerate(cols)}
            i += 9 + n
        else:
            i += 1


def surface(snap):
    x, top = snap["x"], snap["z"] + snap["radius"]
    edges = np.arange(math.floor(x.min()), math.ceil(x.max()) + 1.0, 1.0)
    centres, heights, members = [], [], []
    for lo, hi in zip(edges[:-1], edges[1:]):
        sel = (x >= lo) & (x < hi)
        if sel.sum() >= 2:
            centres.append(0.5 * (lo + hi))
            h = top[sel].max()
            heights.append(h)
            members.append(np.where(sel & (top > h - 1.0))[0])
    return np.array(centres), np.array(heights), members


def measure(snap):
    centres, heights, members = surface(snap)
    mid = 0.5 * (centres.min() + centres.max())
    half = 0.5 * (centres.max() - centres.min())
    inner = np.abs(centres - mid) <= 0.6 * half
    slope = np.polyfit(centres[inner], heights[inner], 1)[0]
    layer = np.concatenate([members[k] for k in np.where(inner)[0]])
    speed = np.hypot(snap["vx"][layer], snap["vz"][layer]).mean()
    return abs(math.degrees(math.atan(slope))), speed


def main(paths):
    angles, speeds = [], []
    for path in paths:
        values = [measure(s) for s in snapshots(path)]
        angle = float(np.mean([v[0] for v in values]))
        speed = float(np.mean([v[1] for v in values]))
        angles.append(angle)
        speeds.append(speed)
        print(f"{path}: {angle:.2f} deg, surface speed {speed:.3f} ({len(values)} snapshots)")
    if len(paths) > 1:
        n = len(paths)
        print(f"mean angle {np.mean(angles):.2f} deg (standard error "
              f"{np.std(angles, ddof=1) / math.sqrt(n):.2f}), mean surface speed "
              f"{np.mean(speeds):.3f} ({np.std(speeds, ddof=1) / math.sqrt(n):.3f}), {n} runs")
    return 0


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1:]))
