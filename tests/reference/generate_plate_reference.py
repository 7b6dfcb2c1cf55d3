#!/usr/bin/python3
#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#
# Generates tests/reference/plate_reference.csv: throws of flat plates (a unit
# square, an equilateral triangle, a 0.22 x 0.10 sole; uniform pressure, the
# centre of mass above the centroid, k^2 = I/m of the uniform lamina) to their
# stop, and the terminal fixed points of the direction flow, with numpy and
# scipy only, nothing of spinslide (docs/plate_dynamics.md):
#
#   du/dt = mu g F(u, w) - w z x u,   dw/dt = mu g tau(u, w)/k^2,   dtheta/dt = w,
#   dX/dt = R(theta) u,               dpath/dt = |u|,
#
# in the body frame, with mu g = 1.  The wrench of a uniform polygon about the
# instantaneous centre c = z x v/w is written with the divergence theorem as
# edge sums (y = x - c, rho = |y|, n the outward normal of an edge, h = y.n):
#   F = -sign(w) z x G/A,  G = sum_e n_e I_e,          I_e = int_e rho ds,
#   tau = -sign(w)(H + c.G)/A,  H = sum_e h_e I_e/3,   D = |w| H/A,
# and I_e = [t rho + h^2 asinh(t/|h|)]/2 between the edge's ends.
#
# Unlike the library (which integrates the twist's direction in s = -ln r),
# this integrates the raw state in a Sundman time tau, dt = r dtau with
# r = |(u, k w)|: then dr/dtau = -r D, the stop lies at tau = infinity and is
# approached exponentially; the integration (DOP853, rtol 1e-13) ends at
# r = 1e-13 r0 and adds the rest of the time, r/D, whose relative error is
# O(1e-13).  The fixed points are found by Newton's method on the gradient of
# ln D on the unit sphere of (u, k w) (grad D = -(F, tau/k), in closed form),
# its Jacobian by central differences in a tangent chart (the library uses
# its closed-form Hessian).
#   /usr/bin/python3 tests/reference/generate_plate_reference.py > tests/reference/plate_reference.csv
import sys

import numpy as np
from scipy.integrate import solve_ivp


def edge_integral(h, t):
    """An antiderivative of sqrt(h^2 + t^2) in t."""
    if h == 0.0:
        return 0.5 * t * abs(t)
    return 0.5 * (t * np.hypot(h, t) + h * h * np.arcsinh(t / abs(h)))


def area(poly):
    x, y = poly[:, 0], poly[:, 1]
    return 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)


def gyration_squared(poly):
    """k^2 = (1/A) int (x^2 + y^2) dA of the uniform lamina (shoelace form)."""
    x, y = poly[:, 0], poly[:, 1]
    xn, yn = np.roll(x, -1), np.roll(y, -1)
    cr = x * yn - xn * y
    ixx = np.sum(cr * (y * y + y * yn + yn * yn)) / 12.0
    iyy = np.sum(cr * (x * x + x * xn + xn * xn)) / 12.0
    return (ixx + iyy) / area(poly)


def wrench(poly, v, w):
    """F (2), tau and D per unit mu N of the twist (v, w), w != 0."""
    c = np.array([-v[1], v[0]]) / w
    g = np.zeros(2)
    h_sum = 0.0
    n = len(poly)
    for i in range(n):
        a, b = poly[i] - c, poly[(i + 1) % n] - c
        e = (b - a) / np.hypot(*(b - a))
        normal = np.array([e[1], -e[0]])
        h = a @ normal
        i_e = edge_integral(h, b @ e) - edge_integral(h, a @ e)
        g += normal * i_e
        h_sum += h * i_e / 3.0
    s = 1.0 if w > 0 else -1.0
    a_ = area(poly)
    force = -s * np.array([-g[1], g[0]]) / a_
    return force, -s * (h_sum + c @ g) / a_, abs(w) * h_sum / a_


def rhs(poly, k):
    def f(_, y):
        u, w, th = y[0:2], y[2], y[3]
        r = np.sqrt(u @ u + (k * w) ** 2)
        force, tau, _ = wrench(poly, u, w)
        du = force - w * np.array([-u[1], u[0]])
        c, s = np.cos(th), np.sin(th)
        vel = np.array([c * u[0] - s * u[1], s * u[0] + c * u[1]])
        return r * np.array([du[0], du[1], tau / k**2, w, vel[0], vel[1], 1.0,
                             np.hypot(*u)])
    return f


def throw(poly, k, u0, w0):
    """Stop time, rotation, displacement, path length, terminal eps and phi."""
    y0 = np.array([u0[0], u0[1], w0, 0.0, 0.0, 0.0, 0.0, 0.0])
    r0 = np.sqrt(u0[0] ** 2 + u0[1] ** 2 + (k * w0) ** 2)
    cut = 1e-13 * r0

    def small(_, y):
        return np.sqrt(y[0] ** 2 + y[1] ** 2 + (k * y[2]) ** 2) - cut
    small.terminal = True
    sol = solve_ivp(rhs(poly, k), (0.0, 1e4), y0, method="DOP853", rtol=1e-13,
                    atol=1e-30, events=small)
    if sol.status != 1:
        sys.exit("no stop within the integration range")
    y = sol.y_events[0][0]
    _, _, d = wrench(poly, y[0:2], y[2])
    # d is D at the twist (u, w) = r D(n): the rest of the time is r/D(n).
    t = y[6] + (y[0] ** 2 + y[1] ** 2 + (k * y[2]) ** 2) / d
    ell = max(np.hypot(*p) for p in poly)
    eps = np.hypot(y[0], y[1]) / (ell * abs(y[2]))
    return t, y[3], y[4], y[5], y[7], eps, np.arctan2(y[1], y[0])


def chart(n):
    a = np.array([1.0, 0.0, 0.0]) if abs(n[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = a - (a @ n) * n
    e1 /= np.linalg.norm(e1)
    return e1, np.cross(n, e1)


def sphere_gradient(poly, k, n, e1, e2):
    """Minus the direction flow, grad ln D(m) - m at m = n/|n|, in the chart
    (e1, e2): grad D = -(F, tau/k) in the coordinates (u, k w), the wrench in
    closed form."""
    m = n / np.linalg.norm(n)
    force, tau, d = wrench(poly, m[:2], m[2] / k)
    g = -np.array([force[0], force[1], tau / k]) / d - m
    return np.array([g @ e1, g @ e2])


def fixed_point(poly, k, n, h=1e-6):
    """Newton on the direction flow dn/ds = -(grad ln D - n); the eigenvalues
    of minus its Jacobian (central differences, O(h^2)) are the exponents."""
    n = n / np.linalg.norm(n)
    for _ in range(80):
        e1, e2 = chart(n)
        g = sphere_gradient(poly, k, n, e1, e2)
        jac = np.column_stack([(sphere_gradient(poly, k, n + h * e, e1, e2) -
                                sphere_gradient(poly, k, n - h * e, e1, e2)) / (2 * h)
                               for e in (e1, e2)])
        d = -np.linalg.solve(jac, g)
        if np.linalg.norm(d) > 0.1:
            d *= 0.1 / np.linalg.norm(d)
        n = n + d[0] * e1 + d[1] * e2
        n /= np.linalg.norm(n)
        if np.linalg.norm(d) < 1e-13:
            break
    return n, np.linalg.eigvalsh(0.5 * (jac + jac.T))


def regular(m, radius, start):
    return np.array([[radius * np.cos(start + 2 * np.pi * i / m),
                      radius * np.sin(start + 2 * np.pi * i / m)] for i in range(m)])


SHAPES = {
    "square": regular(4, np.sqrt(0.5), np.pi / 4),
    "triangle": regular(3, 1.0, np.pi / 2),
    "sole": np.array([[-0.11, -0.05], [0.11, -0.05], [0.11, 0.05], [-0.11, 0.05]]),
}
# Starts: (eps0, phi0 in degrees, spin sense), eps0 = |u0|/(l |w0|), w0 = +-1/l.
STARTS = [(0.2, 10.0, 1), (0.5, 33.0, 1), (1.0, 71.0, -1), (3.0, 152.0, 1), (0.8, -40.0, -1),
          (2.0, 100.0, -1)]
# The fixed points' guesses (eps*, phi* in degrees) for w > 0.
# eps = 0 is pure spinning (a fixed point where the spin about the centroid has no force).
GUESSES = {"square": [(0.53, 45.0), (0.49, 0.0), (0.0, 0.0)],
           "triangle": [(0.45, 0.0), (0.32, 60.0), (0.0, 0.0)],
           "sole": [(0.59, 90.0), (0.0, 0.0)]}


def main():
    print("# spinslide reference: flat plates thrown on a plane (uniform pressure, mu g = 1,")
    print("# k^2 of the uniform lamina), by tests/reference/generate_plate_reference.py (numpy")
    print("# %s, scipy %s): closed-form edge sums, DOP853 in a Sundman time to r = 1e-13 r0." %
          (np.__version__, __import__("scipy").__version__))
    print("# throw rows: shape,k2,u0x,u0y,omega0,time,rotation,x,y,path,eps_end,phi_end")
    print("# fixed rows: shape,k2,eps,phi,exponent_1,exponent_2 (phi of the slip in the body")
    print("# frame, omega > 0; exponents: the direction's deviation decays as r^exponent)")
    for name, poly in SHAPES.items():
        k2 = gyration_squared(poly)
        k = np.sqrt(k2)
        ell = max(np.hypot(*p) for p in poly)
        for eps0, phi0, sense in STARTS:
            w0 = sense / ell
            u0 = eps0 * ell * abs(w0) * np.array([np.cos(np.radians(phi0)),
                                                  np.sin(np.radians(phi0))])
            t, rot, x, y, path, eps, phi = throw(poly, k, u0, w0)
            print("throw,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.10g,%.10g" %
                  (name, k2, u0[0], u0[1], w0, t, rot, x, y, path, eps, phi))
        for eps_g, phi_g in GUESSES[name]:
            nu = eps_g * ell / k
            guess = np.array([nu * np.cos(np.radians(phi_g)), nu * np.sin(np.radians(phi_g)), 1.0])
            n, ex = fixed_point(poly, k, guess)
            eps = np.hypot(n[0], n[1]) * k / (ell * abs(n[2]))
            print("fixed,%s,%.17g,%.12g,%.12g,%.8g,%.8g" %
                  (name, k2, eps, np.arctan2(n[1], n[0]), ex[0], ex[1]))


if __name__ == "__main__":
    main()
