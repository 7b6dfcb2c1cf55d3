#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""The paper's CD experiment analysed from Python: mu(n) = a + b n fitted to
tracked frames, as the authors did it (docs/experiment.md).

    python fit_cd_experiment.py FRAMES.csv [OUTPUT_DIR]

FRAMES.csv: the tracked data format of examples/cd_experiment (a header,
then throw,t,x,y,theta per frame: the throw number n, time in s, the disk's
centre in m and its unwrapped angle in rad, frames in time order from
release).  `cd_experiment --out DIR` writes a simulated one, DIR/cd_frames.csv.

For each throw: parabolas fitted by least squares to x(t), y(t) and theta(t)
over the first 7 frames give, at the middle frame, v, omega and the
decelerations, hence mu F = -(a.v/|v|)/g, mu T = -gamma R d(omega)/dt / g and
eps = v/(R omega).  Dividing by the CD's F(eps) and T(eps) (an annulus with a
hole of 1/8 of the radius: spinslide.Annulus(0.125)) gives two estimates of mu
per throw; mu(n) = a + b n is their ordinary least-squares line (the authors'
fit; the C++ program also prints a weighted, window-corrected one).
Writes cd_fit.png: the measured force and torque divided by the fitted mu(n),
over the theory curves.
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import spinslide  # noqa: E402

R = 0.06                     # m, the CD's radius
HOLE = 0.125                 # the hole's radius over R
GAMMA = (1 + HOLE ** 2) / 2  # I/(m R²) of the annulus
G = 9.81                     # m/s²
FIT_FRAMES = 7


def read_frames(path):
    data = np.genfromtxt(path, delimiter=",", names=True)
    throws = {}
    for n in np.unique(data["throw"]).astype(int):
        rows = data[data["throw"] == n]
        throws[n] = (rows["t"], rows["x"], rows["y"], rows["theta"])
    return throws


def parabola(t, y, tc):
    """Slope and curvature (second derivative) at tc of the least-squares parabola."""
    c = np.polynomial.polynomial.polyfit(t - tc, y, 2)
    return c[1], 2 * c[2]


def measure(throws):
    """Per throw: n, eps, mu F, mu T (the frames' estimates)."""
    out = []
    for n, (t, x, y, th) in sorted(throws.items()):
        if len(t) < FIT_FRAMES:
            print(f"throw {n}: {len(t)} frames, skipped (need {FIT_FRAMES})")
            continue
        t, x, y, th = (a[:FIT_FRAMES] for a in (t, x, y, th))
        tc = t[FIT_FRAMES // 2]
        (vx, ax), (vy, ay), (w, dw) = parabola(t, x, tc), parabola(t, y, tc), parabola(t, th, tc)
        v = np.hypot(vx, vy)
        if not (v > 0 and abs(w) > 0):
            continue
        mu_f = -(ax * vx + ay * vy) / v / G
        mu_t = GAMMA * R * -dw * np.sign(w) / G
        out.append((n, v / (R * abs(w)), mu_f, mu_t))
    return np.array(out)


def fit_mu(measured):
    """mu(n) = a + b n by ordinary least squares over both estimates of every
    throw; the standard errors from the residuals."""
    cd = spinslide.Annulus(HOLE)
    n, eps, mu_f, mu_t = measured.T
    force, torque = cd.force_torque(eps)
    x = np.concatenate([n, n])
    y = np.concatenate([mu_f / force, mu_t / torque])
    design = np.column_stack([np.ones_like(x), x])
    coef, rss, *_ = np.linalg.lstsq(design, y, rcond=None)
    sigma2 = rss[0] / (len(y) - 2)
    cov = sigma2 * np.linalg.inv(design.T @ design)
    return coef[0], coef[1], np.sqrt(cov[0, 0]), np.sqrt(cov[1, 1])


def main(frames, out=Path(".")):
    out.mkdir(parents=True, exist_ok=True)
    measured = measure(read_frames(frames))
    a, b, se_a, se_b = fit_mu(measured)
    print(f"{len(measured)} throws analysed (parabolas over the first {FIT_FRAMES} frames)")
    print(f"the authors' fit: a = {a:.5f} +- {se_a:.5f},  b = {b:.6f} +- {se_b:.6f}")
    n, eps, mu_f, mu_t = measured.T
    mu = a + b * n
    curve = np.geomspace(0.05, 5, 300)
    force, torque = spinslide.Annulus(HOLE).force_torque(curve)
    fig, ax = plt.subplots(figsize=(6, 4.2), constrained_layout=True)
    ax.plot(curve, force, lw=2, color="#1f77b4", label=r"$\mathcal{F}(\varepsilon)$, annulus")
    ax.plot(curve, torque, lw=2, color="#d62728", label=r"$\mathcal{T}(\varepsilon)$, annulus")
    ax.plot(eps, mu_f / mu, "o", color="#1f77b4", mfc="none", label="measured F / mu(n)")
    ax.plot(eps, mu_t / mu, "s", color="#d62728", mfc="none", label="measured T / mu(n)")
    ax.set(xscale="log", xlabel=r"$\varepsilon = v/(R\omega)$",
           title=f"CD throws: mu(n) = {a:.4f} + {b:.6f} n")
    ax.grid(True)
    ax.legend()
    fig.savefig(out / "cd_fit.png", dpi=110)
    print(f"wrote {out / 'cd_fit.png'}")
    return a, b


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(Path(sys.argv[1]), Path(sys.argv[2]) if len(sys.argv) > 2 else Path("."))
