#!/usr/bin/python3
"""The angle of repose of the heaps of in.repose, from their dumps.

    repose.py heap1.xyz [heap2.xyz ...]

For each heap: the plate is the layer of spheres whose centres lie below
z = -0.4 (in.repose puts them at -0.5), its radius the farthest of their
centres from the axis plus 0.5.  The other spheres over the plate are
binned by their distance r from the axis (bins 1 wide); in each bin the heap's surface is
the highest sphere top (z + radius).  The slope is the least-squares line
through the surface heights of the bins between r = 1.5 and r = plate - 1.5
(the tip and the rim excluded); the angle is atan(-slope), in degrees.
Prints one angle per heap, then the mean and the standard error.
"""
import argparse
import math
import sys

import numpy as np


def heap_angle(path):
    data = []
    with open(path) as f:
        lines = f.readlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    cols = lines[start].split()[2:]
    ix, iy, iz, ir = (cols.index(c) for c in ("x", "y", "z", "radius"))
    for line in lines[start + 1:]:
        v = line.split()
        if v:
            data.append((float(v[ix]), float(v[iy]), float(v[iz]), float(v[ir])))
    a = np.array(data)
    r = np.hypot(a[:, 0], a[:, 1])
    top = a[:, 2] + a[:, 3]
    in_plate = a[:, 2] < -0.4
    if not in_plate.any():
        raise SystemExit(f"repose.py: {path}: no plate spheres (z < -0.4) in the dump")
    plate = r[in_plate].max() + 0.5
    above = ~in_plate & (r < plate)
    edges = np.arange(0.0, plate + 1e-9, 1.0)
    centres, heights = [], []
    for lo, hi in zip(edges[:-1], edges[1:]):
        sel = above & (r >= lo) & (r < hi)
        if sel.any():
            centres.append(0.5 * (lo + hi))
            heights.append(top[sel].max())
    centres, heights = np.array(centres), np.array(heights)
    fit = (centres >= 1.5) & (centres <= plate - 1.5)
    if fit.sum() < 3:
        raise SystemExit(f"repose.py: {path}: too few surface bins to fit ({fit.sum()})")
    slope = np.polyfit(centres[fit], heights[fit], 1)[0]
    return math.degrees(math.atan(-slope)), int(above.sum())


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dumps", nargs="+")
    args = parser.parse_args()
    angles = []
    for path in args.dumps:
        angle, n = heap_angle(path)
        angles.append(angle)
        print(f"{path}: {angle:.2f} deg ({n} spheres on the plate)")
    if len(angles) > 1:
        mean = float(np.mean(angles))
        sem = float(np.std(angles, ddof=1) / math.sqrt(len(angles)))
        print(f"mean {mean:.2f} deg, standard error {sem:.2f} deg, {len(angles)} heaps")
    return 0


if __name__ == "__main__":
    sys.exit(main())
