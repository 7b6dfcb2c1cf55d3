#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""A flat patch's contact from Python (docs/python.md, "Flat patches"): the
projection onto its limit set, the inverse map of its limit surface and its
impulse law, against scipy's dblquad of the wrench (test_patches' box) and the
maximum-dissipation principle: the limit set's boundary point W(t), the
friction wrench of the twist t, has the outward normal -t (in the limit
set's units, (-v, -l omega)), so a slipping answer p = W(t) is the nearest
point in the metric M exactly when M (z - p) is a positive multiple of it."""

import math

import numpy as np
import pytest

import spinslide
from conftest import quad_wrench

A, B = 0.11, 0.05
BOX = [(-A, -B), (A, -B), (A, B), (-A, B)]
PATCH = spinslide.PolygonPatch(BOX)
ELL = PATCH.radius


def uniform(x, y):
    return 1 / (4 * A * B)


def quad(v, w):
    """(F_x, F_y, tau) of the box by dblquad, physical units."""
    return quad_wrench(uniform, v, w, A, B)[:3]


METRICS = [np.eye(3), np.array([[2.0, 0.3, -0.2], [0.3, 1.0, 0.1], [-0.2, 0.1, 0.5]])]
TRIALS = [((1.2, 0.4), 0.3), ((0.0, -2.0), -0.5), ((0.1, 0.05), 1.5), ((-3.0, 1.0), 0.0)]


@pytest.mark.parametrize("metric", METRICS)
@pytest.mark.parametrize("trial", TRIALS)
def test_slipping_projection_is_on_the_surface_and_nearest(metric, trial):
    force, torque = trial
    r = spinslide.project_to_limit_set(PATCH, force, torque, metric)
    assert not r.sticking
    # The answer is the friction wrench of its slip (dblquad), in the set's units.
    exact = quad(r.slip_velocity, r.slip_spin)
    p = np.array([r.force[0], r.force[1], r.torque])
    np.testing.assert_allclose(p, [exact[0], exact[1], exact[2] / ELL], rtol=0, atol=1e-12)
    # M (z - p) along the outward normal -(v, l omega): the nearest point.
    z = np.array([force[0], force[1], torque])
    g = metric @ (z - p)
    n = -np.array([r.slip_velocity[0], r.slip_velocity[1], ELL * r.slip_spin])
    assert g @ n > 0
    np.testing.assert_allclose(g / np.linalg.norm(g), n / np.linalg.norm(n), atol=1e-12)
    v, w = np.hypot(*r.slip_velocity), abs(r.slip_spin) * ELL
    assert r.ratio == (pytest.approx(v / w, rel=1e-14) if w > 0 else math.inf)


def test_inside_sticks_and_arrays_broadcast():
    # Half of a boundary point (dblquad's wrench of a twist) is inside: it sticks, unchanged.
    f = quad((0.02, 0.01), 1.0)
    inside = 0.5 * np.array([f[0], f[1], f[2] / ELL])
    r = spinslide.project_to_limit_set(PATCH, inside[:2], inside[2], np.eye(3))
    assert r.sticking and math.isnan(r.ratio)
    np.testing.assert_array_equal(r.force, inside[:2])
    assert r.torque == inside[2]
    np.testing.assert_array_equal(r.slip_velocity, [0, 0])
    assert r.slip_spin == 0
    # Arrays: the trials (4, 2) and (4,) against one metric, each as alone.
    forces = np.array([t[0] for t in TRIALS])
    torques = np.array([t[1] for t in TRIALS])
    many = spinslide.project_to_limit_set(PATCH, forces, torques, metric=METRICS[1])
    assert many.force.shape == (4, 2) and many.slip_velocity.shape == (4, 2)
    for i, (force, torque) in enumerate(TRIALS):
        one = spinslide.project_to_limit_set(PATCH, force, torque, METRICS[1])
        np.testing.assert_array_equal(many.force[i], one.force)
        assert many.slip_spin[i] == one.slip_spin
        # A warm start from the answer's own slip gives the same point.
        warm = spinslide.project_to_limit_set(PATCH, force, torque, METRICS[1],
                                              start_velocity=one.slip_velocity,
                                              start_spin=one.slip_spin)
        np.testing.assert_allclose(warm.force, one.force, rtol=0, atol=1e-13)


@pytest.mark.parametrize("twist", [((0.02, 0.01), 1.0), ((0.3, -0.2), 0.7), ((1.0, 0.5), 0.01),
                                   ((0.0, 0.11), -1.0), ((0.5, 0.0), 0.0)])
@pytest.mark.parametrize("scale", [0.7, 1.0, 2.5])
def test_limit_surface_twist_inverts_the_wrench(twist, scale):
    v, w = twist
    f = quad(v, w)
    r = spinslide.limit_surface_twist(PATCH, scale * f[:2], scale * f[2])
    assert r.gauge == pytest.approx(scale, rel=1e-12)
    size = math.hypot(math.hypot(*v), ELL * w)
    np.testing.assert_allclose([*r.velocity, ELL * r.spin], [v[0] / size, v[1] / size,
                                                             ELL * w / size], atol=1e-12)


def test_limit_surface_twist_arrays_and_errors():
    forces = np.array([[0.5, 0.0], [0.0, 0.2], [-0.1, 0.1]])
    torques = np.array([0.0, 0.01, -0.02])
    r = spinslide.limit_surface_twist(PATCH, forces, torques)
    assert r.velocity.shape == (3, 2) and r.spin.shape == (3,) and r.gauge.shape == (3,)
    one = spinslide.limit_surface_twist(PATCH, forces[1], torques[1])
    assert r.gauge[1] == one.gauge and np.ndim(one.gauge) == 0
    with pytest.raises(ValueError, match="zero wrench"):
        spinslide.limit_surface_twist(PATCH, (0.0, 0.0), 0.0)
    with pytest.raises(ValueError, match="positive-definite"):
        spinslide.project_to_limit_set(PATCH, (1.0, 0.0), 0.0, -np.eye(3))
    with pytest.raises(TypeError, match="metric"):
        spinslide.project_to_limit_set(PATCH, (1.0, 0.0), 0.0)
    with pytest.raises(TypeError, match="torque_weight"):
        spinslide.project_to_limit_set(spinslide.UniformDisk(), 1.0, 0.0, metric=np.eye(3))


def test_impulse_law_sticks_then_slips_onto_the_surface():
    m = np.array([[2.0, 0.1, 0.3], [0.1, 1.5, -0.2], [0.3, -0.2, 40.0]])
    # Slow: the impulse that stops the contact, -W^-1 (v, omega), is within mu Lambda L.
    v, w = np.array([0.001, -0.002]), 0.01
    r = spinslide.impulse_friction(PATCH, v, w, m, normal_impulse=1.0, friction_coefficient=0.5)
    assert r.sticking
    stop = -np.linalg.solve(m, [v[0], v[1], w])
    np.testing.assert_allclose([*r.force, r.torque], stop, rtol=1e-13, atol=1e-16)
    # Fast: it slips; the velocity after is (v, omega) + W P, and the impulse over
    # mu Lambda is the friction wrench of that velocity (dblquad).
    v, w, load = np.array([0.8, -0.3]), 4.0, 0.5 * 0.2
    r = spinslide.impulse_friction(PATCH, v, w, m, normal_impulse=0.2, friction_coefficient=0.5)
    assert not r.sticking
    impulse = np.array([r.force[0], r.force[1], r.torque])
    after = np.array([v[0], v[1], w]) + m @ impulse
    np.testing.assert_allclose([*r.slip_velocity, r.slip_spin], after, rtol=1e-9, atol=1e-12)
    exact = quad(r.slip_velocity, r.slip_spin)
    np.testing.assert_allclose(impulse / load, exact, rtol=0, atol=1e-9)
    with pytest.raises(TypeError, match="no radius"):
        spinslide.impulse_friction(PATCH, v, w, m, 0.1, 0.2, 0.5)
