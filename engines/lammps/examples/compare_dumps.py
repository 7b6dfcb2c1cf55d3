#!/usr/bin/env python3
"""Compare two LAMMPS custom dumps (sorted by id, same columns) snapshot by
snapshot: the largest absolute difference of each column, and of all columns
relative to that column's largest magnitude.

    compare_dumps.py a.dump b.dump [--tol REL]

Exit status 0 if every relative difference is <= REL (default 0: identical).
"""
import sys


def snapshots(path):
    with open(path) as f:
        lines = iter(f)
        for line in lines:
            if not line.startswith("ITEM: TIMESTEP"):
                continue
            step = int(next(lines))
            next(lines)
            n = int(next(lines))
            next(lines)
            for _ in range(3):
                next(lines)
            cols = next(lines).split()[2:]
            rows = [next(lines).split() for _ in range(n)]
            yield step, cols, rows


def main():
    args = sys.argv[1:]
    tol = 0.0
    if "--tol" in args:
        k = args.index("--tol")
        tol = float(args[k + 1])
        del args[k:k + 2]
    a_path, b_path = args
    worst = 0.0
    identical = True
    for (sa, ca, ra), (sb, cb, rb) in zip(snapshots(a_path), snapshots(b_path)):
        if sa != sb or ca != cb or len(ra) != len(rb):
            print(f"step {sa}/{sb}: the dumps do not match in shape")
            return 2
        if not ra:
            print(f"step {sa:7d}: no atoms")
            continue
        diffs = []
        for c, name in enumerate(ca):
            if name == "id":
                continue
            va = [float(r[c]) for r in ra]
            vb = [float(r[c]) for r in rb]
            scale = max(max(abs(x) for x in va), 1e-300)
            d = max(abs(x - y) for x, y in zip(va, vb))
            if d != 0.0:
                identical = False
            diffs.append((name, d, d / scale))
        rel = max(r for _, _, r in diffs)
        worst = max(worst, rel)
        big = max(diffs, key=lambda t: t[2])
        print(f"step {sa:7d}: max relative difference {rel:.3e} (column {big[0]}, "
              f"absolute {big[1]:.3e})")
    print("identical" if identical else f"largest relative difference {worst:.3e}")
    return 0 if worst <= tol else 1


if __name__ == "__main__":
    sys.exit(main())
