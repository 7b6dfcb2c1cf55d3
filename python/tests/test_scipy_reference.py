#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""An independent check with scipy: the defining area integrals (the paper's,
docs/theory.md §1) by scipy.integrate.dblquad, for the uniform disk and the
Hertz load, at a few ratios on both sides of eps = 1:

    F(eps) = ∫ p (eps - y)/rho dA / ∫ p dA,
    T(eps) = ∫ p (x² + y² - eps y)/rho dA / ∫ p dA,   rho = √(x² + (y - eps)²)

on the unit disk (velocity field of a disk spinning about the origin and
sliding along x, in units of R omega).  The integrands are bounded but not
smooth at (0, eps) (see area_integrals): dblquad reaches about 1e-10 here."""

import math

import numpy as np
import pytest
from scipy.integrate import dblquad

import spinslide

LOADS = {
    "uniform": (lambda r2: 1.0, spinslide.UniformDisk()),
    "hertz": (lambda r2: math.sqrt(max(1.0 - r2, 0.0)), spinslide.Hertz()),
}


def area_integrals(pressure, eps):
    """(F, T) by dblquad.  For eps < 1 the point at rest (0, eps) lies in the
    disk, where the integrands are not smooth: there in polar coordinates
    about it, x = s cos(phi), y = eps + s sin(phi), in which they are smooth
    ((eps - y)/rho = -sin(phi), (x² + y² - eps y)/rho = s + eps sin(phi)) and
    the rim is s = -eps sin(phi) + √(1 - eps² cos²(phi))."""
    if eps < 1:
        def integrate(g):
            value, _ = dblquad(
                lambda s, phi: pressure(s * s + 2 * eps * s * math.sin(phi) + eps * eps)
                * g(s, phi) * s,
                0, 2 * math.pi, 0.0,
                lambda phi: -eps * math.sin(phi) + math.sqrt(1 - (eps * math.cos(phi)) ** 2),
                epsabs=1e-13, epsrel=1e-12)
            return value

        load = integrate(lambda s, phi: 1.0)
        force = integrate(lambda s, phi: -math.sin(phi))
        torque = integrate(lambda s, phi: s + eps * math.sin(phi))
        return force / load, torque / load

    def integrate(g):
        value, _ = dblquad(lambda x, y: pressure(x * x + y * y) * g(x, y),
                           -1, 1, lambda y: -math.sqrt(1 - y * y), lambda y: math.sqrt(1 - y * y),
                           epsabs=1e-13, epsrel=1e-12)
        return value

    def rho(x, y):
        return math.hypot(x, y - eps)

    load = integrate(lambda x, y: 1.0)
    force = integrate(lambda x, y: (eps - y) / rho(x, y))
    torque = integrate(lambda x, y: (x * x + y * y - eps * y) / rho(x, y))
    return force / load, torque / load


@pytest.mark.parametrize("name", sorted(LOADS))
@pytest.mark.parametrize("eps", [0.25, 0.8, 1.7, 5.0])
def test_values_agree_with_dblquad(name, eps):
    pressure, profile = LOADS[name]
    f, t = area_integrals(pressure, eps)
    pf, pt = profile.force_torque(eps)
    assert pf == pytest.approx(f, rel=1e-10)
    assert pt == pytest.approx(t, rel=1e-10)
    if name == "uniform":
        assert spinslide.force(eps) == pf and spinslide.torque(eps) == pt
