#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""A box pushed quasi-statically at a point of its side: the exact limit
surface of its face against the Howe-Cutkosky ellipsoid.

    python push_box.py [--out DIR] [--half-length 0.15] [--half-width 0.10]

The box's face is the rectangle [-a, a] x [-b, b] under uniform pressure
(spinslide.PolygonPatch).  A frictionless point pusher touches the side
y = -b at x = s and pushes along its inward normal +y: the push is the load
(f, x_p x f) = lambda (0, 1, s) (per unit mu N; lambda adjusts).  Slow enough
for inertia not to matter, the box moves with the twist w = (v_x, v_y, omega)
whose friction wrench balances it, -grad D(w) = -lambda (0, 1, s): the
normal of the limit surface at that load.

- The exact model takes w from the limit surface's inverse map,
  spinslide.limit_surface_twist: the twist whose friction wrench is the
  surface's point on the ray of -(0, 1, s).  (The test checks it against
  scipy's minimum of D(w) on the plane (0, 1, s) . w = 1, where
  grad D = lambda (0, 1, s) and lambda = D.)
- The ellipsoid model (Howe and Cutkosky; Lynch, Maruyama and Mason) takes the
  limit surface F^T H F = 1 with H = diag(1/f_max^2, 1/f_max^2, 1/m_max^2),
  f_max = 1 (pure translation) and m_max the torque of a pure spin about the
  centre of pressure, both exact; then w is proportional to H (0, 1, s), and
  the box turns about x_c = -m_max^2 / s on the axis through its centre.

Prints, for push points along the side, the rotation centre of both models
and their ratio, and the path of the box under a sustained push (the pusher
moving straight on at constant speed, its contact sliding along the side)
until the pusher slides off a corner; writes push_box.png.
"""

import argparse
from pathlib import Path

import numpy as np
from scipy import integrate, optimize

import spinslide


def box_patch(a, b):
    """The face [-a, a] x [-b, b], uniform pressure."""
    return spinslide.PolygonPatch([(-a, -b), (a, -b), (a, b), (-a, b)])


def spin_moment(patch):
    """m_max: the friction torque of a pure spin about the centre of pressure."""
    c = patch.centre
    # A spin about c: the origin's velocity is -omega z x c.
    _, torque = spinslide.friction_wrench(patch, (c[1], -c[0]), 1.0)
    return abs(float(torque))


def exact_twist(patch, load):
    """The twist (v_x, v_y, omega) whose friction wrench balances `load`
    (F_x, F_y, tau), scaled so that load . w = 1: the limit surface's inverse
    map at the friction wrench -load."""
    load = np.asarray(load, float)
    point = spinslide.limit_surface_twist(patch, -load[:2], -load[2])
    w = np.array([point.velocity[0], point.velocity[1], point.spin])
    return w / (load @ w)


def ellipsoid_twist(load, m_max, f_max=1.0):
    """The ellipsoid model's twist for `load`, scaled so that load . w = 1."""
    w = np.asarray(load, float) / np.array([f_max**2, f_max**2, m_max**2])
    return w / (np.asarray(load, float) @ w)


def rotation_centre(w):
    """The point (in the box frame) about which the twist w turns: z x v / omega."""
    return np.array([-w[1], w[0]]) / w[2]


def push_path(twist_at, a, b, offset, travel, speed=1.0):
    """The box under a pusher that moves along world +y at `speed` from the
    point (offset, -b) of the box's side, frictionless, quasi-static.
    twist_at(s) is a model's body-frame twist for a push at x = s of the side.
    Returns times and the states (X, Y, theta, s) until the pusher has
    travelled `travel` or slid off a corner (|s| = a)."""

    def rates(_, state):
        theta, s = state[2], state[3]
        w = twist_at(s)
        # The contact point (s, -b) keeps the pusher's normal velocity, V cos(theta).
        k = speed * np.cos(theta) / (w[1] + w[2] * s)
        v, omega = k * w[:2], k * w[2]
        c, sn = np.cos(theta), np.sin(theta)
        return [c * v[0] - sn * v[1], sn * v[0] + c * v[1], omega,
                speed * sn - (v[0] + omega * b)]

    def off_corner(_, state):
        return a - abs(state[3])

    off_corner.terminal = True
    solution = integrate.solve_ivp(rates, (0.0, travel / speed), [0.0, 0.0, 0.0, offset],
                                   events=off_corner, rtol=1e-10, atol=1e-12, max_step=0.01)
    return solution.t, solution.y.T


def draw_box(ax, state, a, b, **style):
    x, y, theta = state[:3]
    c, s = np.cos(theta), np.sin(theta)
    corners = np.array([(-a, -b), (a, -b), (a, b), (-a, b), (-a, -b)])
    ax.plot(x + c * corners[:, 0] - s * corners[:, 1], y + s * corners[:, 0] + c * corners[:, 1],
            **style)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("."))
    parser.add_argument("--half-length", type=float, default=0.15, help="a [m]")
    parser.add_argument("--half-width", type=float, default=0.10, help="b [m]")
    parser.add_argument("--offset", type=float, default=0.3, help="the sustained push's s/a")
    parser.add_argument("--travel", type=float, default=1.0, help="the pusher's travel [m]")
    args = parser.parse_args()
    a, b = args.half_length, args.half_width
    patch = box_patch(a, b)
    m_max = spin_moment(patch)
    print(f"box face {2 * a:g} x {2 * b:g} m, uniform pressure: f_max = 1, m_max = {m_max:.9f} m")
    print("push at x = s on the side y = -b, along +y; rotation centre x_c (y_c = 0) and omega/v_y")
    print(f"{'s/a':>6} {'x_c exact':>14} {'x_c ellipsoid':>14} {'ratio':>8} "
          f"{'omega/v exact':>14} {'omega/v ellip.':>14}")
    offsets = np.linspace(0.02, 1.0, 50) * a
    centres = []
    for s in offsets:
        load = (0.0, 1.0, s)
        we, wh = exact_twist(patch, load), ellipsoid_twist(load, m_max)
        ce, ch = rotation_centre(we), rotation_centre(wh)
        centres.append((ce[0], ch[0]))
        if np.isclose(s / a, [0.1, 0.2, 0.3, 0.5, 0.7, 1.0], atol=0.011).any():
            print(f"{s / a:6.2f} {ce[0]:14.9f} {ch[0]:14.9f} {ce[0] / ch[0]:8.5f} "
                  f"{we[2] / we[1]:14.9f} {wh[2] / wh[1]:14.9f}")
    centres = np.array(centres)

    def disagreement(s):
        load = (0.0, 1.0, s)
        return (rotation_centre(exact_twist(patch, load))[0]
                / rotation_centre(ellipsoid_twist(load, m_max))[0] - 1)

    same = optimize.brentq(disagreement, 0.1 * a, a, xtol=1e-12)
    print(f"the two models turn the box alike only at s = {same / a:.6f} a "
          f"(x_c = {rotation_centre(exact_twist(patch, (0.0, 1.0, same)))[0]:.9f} m)")
    small = 1e-3 * a
    limit = rotation_centre(exact_twist(patch, (0.0, 1.0, small)))[0] * small
    print(f"small offsets: x_c s -> {limit:.9f} m^2 exact (b^2/3 = {b * b / 3:.9f}), "
          f"{-m_max**2:.9f} ellipsoid (-m_max^2)")

    paths, travelled = {}, 0.0
    for name, twist_at in (("exact", lambda s: exact_twist(patch, (0.0, 1.0, s))),
                           ("ellipsoid", lambda s: ellipsoid_twist((0.0, 1.0, s), m_max))):
        t, states = push_path(twist_at, a, b, args.offset * a, args.travel)
        paths[name], travelled = states, max(travelled, t[-1])
        end = states[-1]
        how = "slid off the corner" if abs(end[3]) >= a * (1 - 1e-9) else "still in contact"
        print(f"sustained push at s = {args.offset:g} a, {name:9s}: after a pusher travel of "
              f"{t[-1]:.6f} m ({how}) the box is at ({end[0]:.6f}, {end[1]:.6f}) m, turned "
              f"{np.degrees(end[2]):.4f} deg, contact at s = {end[3] / a:.6f} a")

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.6))
    left.plot(offsets / a, -centres[:, 0] / a, label="exact limit surface")
    left.plot(offsets / a, -centres[:, 1] / a, "--", label="Howe-Cutkosky ellipsoid")
    left.set_yscale("log")
    left.set_xlabel("push offset s / a")
    left.set_ylabel("rotation centre's distance -x_c / a (opposite side)")
    left.set_title(f"{2 * a:g} x {2 * b:g} box face, uniform pressure")
    left.legend()
    left.grid(True, which="both", alpha=0.3)
    s0 = args.offset * a
    right.plot([s0, s0], [-b, -b + travelled], ":", color="grey", lw=1, label="pusher's line")
    for (name, states), colour in zip(paths.items(), ("C0", "C1")):
        right.plot(states[:, 0], states[:, 1], color=colour, label=f"box centre, {name}")
        for i in np.linspace(0, len(states) - 1, 4).astype(int):
            draw_box(right, states[i], a, b, color=colour, lw=0.9, alpha=0.8)
    draw_box(right, (0.0, 0.0, 0.0), a, b, color="black", lw=1.2)
    right.set_aspect("equal")
    right.set_xlabel("x [m]")
    right.set_ylabel("y [m]")
    right.set_title(f"pushed along +y at s = {args.offset:g} a until it slides off")
    right.legend(loc="lower right", fontsize=8)
    fig.tight_layout()
    args.out.mkdir(parents=True, exist_ok=True)
    fig.savefig(args.out / "push_box.png", dpi=110)
    print(f"wrote {args.out / 'push_box.png'}")


if __name__ == "__main__":
    main()
