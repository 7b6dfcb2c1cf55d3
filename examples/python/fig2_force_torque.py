#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""The paper's Fig. 2 from Python: F(eps) and T(eps) of the uniformly pressed
disk, and the coupling curve T(F) (the limit curve of the contact).

    python fig2_force_torque.py [OUTPUT_DIR]

Writes fig2_force_torque.csv (the same grid and columns as the C++ demo
examples/paper writes) and fig2_force_torque.png (matplotlib).
"""

import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import spinslide  # noqa: E402


def data():
    """(a) eps in [0, 5] by 0.01; (b) eps log-spaced over [1e-4, 1e4]: the whole curve."""
    linear = np.arange(501) / 100.0
    # math.pow is C's pow, as in the C++ demo (numpy's power may differ by an ulp).
    logarithmic = np.array([math.pow(10.0, -4 + i / 100.0) for i in range(801)])
    return [(e, *spinslide.force_torque(e)) for e in (linear, logarithmic)]


def main(out=Path(".")):
    out.mkdir(parents=True, exist_ok=True)
    (a, b) = data()
    with open(out / "fig2_force_torque.csv", "w") as f:
        f.write("eps,F,T\n")
        for block in (a, b):
            for e, force, torque in zip(*block):
                f.write(f"{e:.6g},{force:.17g},{torque:.17g}\n")
            f.write("\n\n")
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
    left.plot(a[0], a[1], lw=2, label=r"$\mathcal{F}(\varepsilon)$")
    left.plot(a[0], a[2], lw=2, ls="--", label=r"$\mathcal{T}(\varepsilon)$")
    left.set(title="(a) friction force and torque", xlabel=r"$\varepsilon = v/(R\omega)$")
    left.legend(loc="center right")
    left.grid(True)
    right.plot(b[1], b[2], lw=2)
    right.set(title="(b) the coupling: possible $(\\mathcal{F}, \\mathcal{T})$ pairs",
              xlabel=r"$\mathcal{F}$", ylabel=r"$\mathcal{T}$", xlim=(0, 1), ylim=(0, 0.7))
    right.grid(True)
    fig.savefig(out / "fig2_force_torque.png", dpi=110)
    print(f"wrote {out / 'fig2_force_torque.csv'} and {out / 'fig2_force_torque.png'}")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("."))
