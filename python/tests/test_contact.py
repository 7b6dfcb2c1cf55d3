#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""The limit-set projection and the contact laws, checked by their defining
properties (not by the code under test): the projection is the nearest point
of the set, found here by brute force over the curve; the laws stick below
the cap and slip onto it above."""

import numpy as np
import pytest

import spinslide

PROFILES = [spinslide.UniformDisk(), spinslide.Hertz(), spinslide.Annulus(0.125)]


def brute_force_nearest(p, x, y, w, points=200_001):
    """The nearest curve point to (x, y) in (f - x)^2 + w (t - y)^2, over a
    dense sampling of the curve, refined once around the best sample."""
    s = np.linspace(0.0, 1.0, points)
    with np.errstate(divide="ignore"):
        eps = np.where(s < 1, s / (1 - s), np.inf)
    f, t = p.force_torque(eps)
    d = (f - x) ** 2 + w * (t - y) ** 2
    i = int(np.argmin(d))
    lo, hi = s[max(i - 1, 0)], s[min(i + 1, points - 1)]
    s = np.linspace(lo, hi, 20_001)
    with np.errstate(divide="ignore"):
        eps = np.where(s < 1, s / (1 - s), np.inf)
    f, t = p.force_torque(eps)
    d = (f - x) ** 2 + w * (t - y) ** 2
    return float(np.min(d))


@pytest.mark.parametrize("p", PROFILES, ids=repr)
def test_projection_is_the_nearest_point(p):
    rng = np.random.default_rng(3)
    x = rng.uniform(0, 1.6, 40)
    y = rng.uniform(0, 1.2, 40)
    w = np.exp(rng.uniform(-2, 2, 40))
    r = spinslide.project_to_limit_set(p, x, y, w)
    for i in range(40):
        if r.sticking[i]:
            # Inside: unchanged, and below the curve at its own force.
            assert (r.force[i], r.torque[i]) == (x[i], y[i]) and np.isnan(r.ratio[i])
            if x[i] < 1:
                assert y[i] <= spinslide.torque_at_force(p, x[i]) * (1 + 1e-12)
            continue
        got = (r.force[i] - x[i]) ** 2 + w[i] * (r.torque[i] - y[i]) ** 2
        best = brute_force_nearest(p, x[i], y[i], w[i])
        assert got <= best * (1 + 1e-9) + 1e-300
        # On the curve at its ratio.
        f, t = p.force_torque(r.ratio[i])
        assert r.force[i] == pytest.approx(f, rel=1e-14, abs=1e-300)
        assert r.torque[i] == pytest.approx(t, rel=1e-14, abs=1e-300)


def test_projection_broadcasts_and_gives_scalars_for_scalars():
    p = spinslide.Hertz()
    r = spinslide.project_to_limit_set(p, np.linspace(0.1, 1.5, 3)[:, None],
                                       np.linspace(0.1, 1.0, 4), 2.0)
    assert r.force.shape == r.sticking.shape == r.ratio.shape == (3, 4)
    assert r.sticking.dtype == np.bool_
    one = spinslide.project_to_limit_set(p, 1.5, 0.5, 1.0)
    assert isinstance(one.force, np.float64) and isinstance(one.sticking, np.bool_)


def test_impulse_law_sticks_below_the_cap_and_slips_on_it():
    disk = spinslide.UniformDisk()
    m = np.eye(3)
    # A slow contact: the impulse that stops it is within the cap, so it sticks
    # and (v, w) + W P = 0.
    r = spinslide.impulse_friction(disk, [0.01, -0.02], 0.03, m, 1.0, 1.0, 0.5)
    assert r.sticking
    assert np.allclose(r.force, [-0.01, 0.02], rtol=0, atol=1e-15)
    assert r.torque == pytest.approx(-0.03, abs=1e-15)
    # A fast one slips: |P| = mu Lambda F(eps), |L| = mu Lambda a T(eps) at the slip's eps.
    r = spinslide.impulse_friction(disk, [3.0, 4.0], 2.0, m, 0.5, 0.2, 0.4)
    assert not r.sticking
    f, t = disk.force_torque(r.ratio)
    assert np.hypot(*r.force) == pytest.approx(0.4 * 0.2 * f, rel=1e-13)
    assert abs(r.torque) == pytest.approx(0.4 * 0.2 * 0.5 * t, rel=1e-13)
    # Friction opposes the motion.
    assert np.dot(r.force, [3.0, 4.0]) < 0 and r.torque < 0


def test_impulse_law_over_arrays_is_the_law_per_contact():
    h = spinslide.Hertz()
    rng = np.random.default_rng(5)
    n = 50
    v = rng.normal(size=(n, 2))
    w = rng.normal(size=n)
    m = np.tile(np.diag([1.0, 1.0, 4.0]), (n, 1, 1))
    a = rng.uniform(0.01, 0.2, n)
    lam = rng.uniform(0.0, 0.5, n)
    r = spinslide.impulse_friction(h, v, w, m, a, lam, 0.3)
    assert r.force.shape == (n, 2) and r.torque.shape == (n,)
    for i in (0, 7, 49):
        one = spinslide.impulse_friction(h, v[i], w[i], m[i], a[i], lam[i], 0.3)
        assert np.array_equal(one.force, r.force[i]) and one.torque == r.torque[i]


def test_spring_law_sticks_then_slips_and_keeps_its_state():
    disk = spinslide.UniformDisk()
    kt, kw, a, n, mu = 100.0, 0.5, 0.1, 2.0, 0.5
    step = dict(tangential_stiffness=kt, twisting_stiffness=kw, radius=a, normal_force=n,
                friction_coefficient=mu)
    r = spinslide.spring_history_friction(disk, [0.0, 0.0], 0.0, [1e-4, 0.0], 1e-3, **step)
    assert r.sticking
    assert np.allclose(r.force, [-kt * 1e-4, 0.0]) and r.torque == pytest.approx(-kw * 1e-3)
    # A large increment slips onto the cap: |F| = mu N F(eps), |T| = mu N a T(eps).
    r2 = spinslide.spring_history_friction(disk, r.displacement, r.twist, [0.1, 0.05], 0.2,
                                           curve_ratio=r.curve_ratio, **step)
    assert not r2.sticking
    f, t = disk.force_torque(r2.ratio)
    assert np.hypot(*r2.force) == pytest.approx(mu * n * f, rel=1e-12)
    assert abs(r2.torque) == pytest.approx(mu * n * a * t, rel=1e-12)
    # The springs hold what the cap allows: F = -k_t xi, T = -k_w phi.
    assert np.allclose(r2.force, -kt * np.asarray(r2.displacement), rtol=1e-13)
    assert r2.torque == pytest.approx(-kw * r2.twist, rel=1e-13)
    assert r2.curve_ratio == r2.ratio


def test_vectors_and_matrices_of_another_size_are_refused():
    disk = spinslide.UniformDisk()
    m = np.eye(3)
    with pytest.raises(ValueError, match="velocity must have 1 trailing"):
        spinslide.impulse_friction(disk, [0.01, -0.02, 0.0], 0.03, m, 1.0, 1.0, 0.5)
    with pytest.raises(ValueError, match="inverse_mass must have 2 trailing"):
        spinslide.impulse_friction(disk, [0.01, -0.02], 0.03, np.eye(2), 1.0, 1.0, 0.5)
