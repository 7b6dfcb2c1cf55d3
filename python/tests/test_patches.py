#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""Flat patches from Python (docs/python.md, "Flat patches"): PolygonPatch,
friction_wrench and friction_dissipation against scipy's quadrature of the
defining integrals F = -∬ p û dA, τ = -∬ p (x × û) dA, D = ∬ p |u| dA, the
pressure against its own moment conditions, the gradient and Hessian against
differences, and throw_plate against the exact stops of pure sliding and pure
spinning."""

import math

import numpy as np
import pytest
from scipy import integrate

import spinslide
from conftest import quad_wrench

A, B = 0.11, 0.05  # a 0.22 x 0.10 box face, centred on the origin
BOX = [(-A, -B), (A, -B), (A, B), (-A, B)]


def pressure_of(centre):
    """The box's linear pressure p = 1/area + β·x with its centre of pressure
    at `centre` (inside the kern): ∬ p x = centre, ∬ x x^T = area diag(A², B²)/3."""
    area = 4 * A * B
    beta = np.array([centre[0] / (area * A * A / 3), centre[1] / (area * B * B / 3)])
    return lambda x, y: 1 / area + beta[0] * x + beta[1] * y


# Twists (v_x, v_y, ω) with the centre inside the box, on its edge, just
# outside, far away, and both spin senses.
TWISTS = [(0.02, 0.01, 1.0), (0.0, 0.11, -1.0), (0.3, -0.2, 0.7), (-0.05, 0.0, -2.0),
          (1.0, 0.5, 0.01)]


@pytest.mark.parametrize("centre", [None, (0.015, -0.005)])  # inside the kern
@pytest.mark.parametrize("twist", TWISTS)
def test_wrench_and_dissipation_against_dblquad(centre, twist):
    patch = spinslide.PolygonPatch(BOX, centre)
    p = pressure_of(centre if centre is not None else (0.0, 0.0))
    v, w = twist[:2], twist[2]
    exact = quad_wrench(p, v, w, A, B)
    force, torque = spinslide.friction_wrench(patch, v, w)
    d = spinslide.friction_dissipation(patch, v, w)
    ell = patch.radius
    # The accuracy measure: max(|ΔF_x|, |ΔF_y|, |Δτ|/ℓ).
    error = max(abs(force[0] - exact[0]), abs(force[1] - exact[1]), abs(torque - exact[2]) / ell)
    assert error < 1e-12  # measured: up to 5e-16
    assert abs(d.value - exact[3]) < 1e-9 * (math.hypot(*v) + abs(w) * ell)
    np.testing.assert_array_equal(d.gradient, -np.array([force[0], force[1], torque]))


def test_pure_sliding_is_exact():
    # ω = 0: û = v̂ everywhere, F = -v̂, τ = -e × v̂ (e the centre of pressure).
    patch = spinslide.PolygonPatch(BOX, (0.03, 0.01))
    force, torque = spinslide.friction_wrench(patch, (3.0, 4.0), 0.0)
    np.testing.assert_allclose(force, [-0.6, -0.8], rtol=0, atol=1e-16)
    assert torque == pytest.approx(-(0.03 * 0.8 - 0.01 * 0.6), abs=1e-17)


def test_pure_spin_about_the_centre_is_the_mean_radius():
    # A square of half side a spinning about its centre: τ = -(a/3)(√2 + asinh 1).
    a = 0.5
    square = spinslide.PolygonPatch([(-a, -a), (a, -a), (a, a), (-a, a)])
    force, torque = spinslide.friction_wrench(square, (0.0, 0.0), 2.0)
    np.testing.assert_allclose(force, [0, 0], atol=1e-15)
    assert torque == pytest.approx(-a / 3 * (math.sqrt(2) + math.asinh(1.0)), rel=1e-14)


def test_arrays_broadcast_and_match_single_calls():
    patch = spinslide.PolygonPatch(np.array(BOX) + 0.01)
    velocity = np.array([[0.1, 0.0], [0.0, -0.2], [0.05, 0.05], [1.0, 2.0]])
    spin = np.array([[1.0], [-0.5], [0.0]])
    force, torque = spinslide.friction_wrench(patch, velocity, spin)
    assert force.shape == (3, 4, 2) and torque.shape == (3, 4)
    d = spinslide.friction_dissipation(patch, velocity, spin)
    assert d.value.shape == (3, 4) and d.gradient.shape == (3, 4, 3)
    assert d.hessian.shape == (3, 4, 3, 3)
    for i in range(3):
        for j in range(4):
            f, t = spinslide.friction_wrench(patch, velocity[j], spin[i, 0])
            np.testing.assert_array_equal(force[i, j], f)
            assert torque[i, j] == t
    # A scalar twist gives a scalar torque; the force stays a 2-vector.
    f, t = spinslide.friction_wrench(patch, [0.1, 0.2], 1.0)
    assert f.shape == (2,) and np.ndim(t) == 0


def test_gradient_and_hessian_against_differences():
    patch = spinslide.PolygonPatch(BOX, (-0.02, 0.01))
    twist = np.array([0.03, -0.02, 1.3])
    d = spinslide.friction_dissipation(patch, twist[:2], twist[2])
    h = 1e-6
    for k in range(3):
        e = np.zeros(3)
        e[k] = h
        up = spinslide.friction_dissipation(patch, (twist + e)[:2], (twist + e)[2])
        down = spinslide.friction_dissipation(patch, (twist - e)[:2], (twist - e)[2])
        assert (up.value - down.value) / (2 * h) == pytest.approx(d.gradient[k], abs=1e-8)
        np.testing.assert_allclose((up.gradient - down.gradient) / (2 * h), d.hessian[:, k],
                                   rtol=1e-5, atol=1e-6)
    np.testing.assert_allclose(d.hessian, d.hessian.T, rtol=0, atol=1e-12)
    # Homogeneous of degree 1: ∇D·w = D, and ∇²D w = 0.
    assert d.gradient @ twist == pytest.approx(d.value, rel=1e-13)
    np.testing.assert_allclose(d.hessian @ twist, 0, atol=1e-12)


def triangle_moments(p, tri):
    """∬ p and ∬ p x over a triangle by the edge-midpoint rule (exact for degree 2)."""
    a, b, c = (np.asarray(v, float) for v in tri)
    area = abs(np.cross(b - a, c - a)) / 2
    mids = [(a + b) / 2, (b + c) / 2, (c + a) / 2]
    return (area / 3 * sum(p(m) for m in mids), area / 3 * sum(p(m) * m for m in mids))


def test_pressure_moments_and_lift_off():
    # Inside the kern the pressure is linear over the whole box; beyond it the
    # loaded part shrinks, and the load still sums to 1 with its centre where asked.
    for centre, lifts in [((0.01, 0.005), False), ((0.08, 0.02), True)]:
        patch = spinslide.PolygonPatch(BOX, centre)
        q = patch.loaded_vertices
        assert (len(q) != 4 or not np.allclose(q, np.array(BOX))) == lifts
        assert patch.shape == spinslide.PatchShape.area
        assert np.all(patch.pressure(q) >= -1e-12)
        total, first = 0.0, np.zeros(2)
        for k in range(1, len(q) - 1):
            t, f = triangle_moments(patch.pressure, (q[0], q[k], q[k + 1]))
            total, first = total + t, first + f
        assert total == pytest.approx(1.0, abs=1e-13)
        np.testing.assert_allclose(first, centre, atol=1e-14)
        np.testing.assert_allclose(patch.centre, centre, atol=0)
    uniform = spinslide.PolygonPatch(BOX)
    assert uniform.pressure((0.03, -0.04)) == pytest.approx(1 / (4 * A * B), rel=1e-14)
    assert uniform.radius == pytest.approx(math.hypot(A, B), rel=1e-15)


def test_line_and_point_patches():
    # A uniform segment from (-L, 0) to (L, 0) spinning about its middle: τ = -L/2.
    L = 0.3
    seg = spinslide.PolygonPatch.segment((-L, 0.0), (L, 0.0))
    assert seg.shape == spinslide.PatchShape.line
    force, torque = spinslide.friction_wrench(seg, (0.0, 0.0), 1.0)
    assert torque == pytest.approx(-L / 2, rel=1e-14)
    np.testing.assert_allclose(force, 0, atol=1e-15)
    # Translating across it at an angle, with a spin: against 1-D quadrature.
    v, w = (0.1, 0.2), 0.5
    def density(s, k):
        ux, uy = v[0], v[1] + w * s
        n = math.hypot(ux, uy)
        return -(ux, uy, s * uy)[k] / n / (2 * L)
    exact = [integrate.quad(density, -L, L, args=(k,), epsabs=1e-14, epsrel=1e-14)[0]
             for k in range(3)]
    force, torque = spinslide.friction_wrench(seg, v, w)
    np.testing.assert_allclose([*force, torque], exact, rtol=0, atol=1e-13)
    # A polygon's centre of pressure on an edge makes a line patch there.
    edge = spinslide.PolygonPatch(BOX, (0.0, -B))
    assert edge.shape == spinslide.PatchShape.line
    # Point friction: -û at the point.
    point = spinslide.PolygonPatch.point((0.1, 0.0))
    assert point.shape == spinslide.PatchShape.point
    force, torque = spinslide.friction_wrench(point, (0.0, 0.0), 2.0)
    np.testing.assert_allclose(force, [0.0, -1.0], atol=1e-16)
    assert torque == pytest.approx(-0.1, rel=1e-15)
    # Pivoting about the point itself: no slip, and a Hessian that diverges.
    pivot = spinslide.friction_dissipation(point, (0.0, -0.2), 2.0)
    assert pivot.value == 0 and np.all(np.isinf(pivot.hessian))


@pytest.mark.parametrize("vertices, centre, message", [
    ([(0, 0), (1, 0)], None, "vertices"),
    ([(0, 0), (1, 0), (1, 1), (0.9, 0.1)], None, "convex"),
    ([(0, 0), (1, 0), (0, 1)], (1.0, 1.0), "centre of pressure"),
    ([(0, 0), (1, 0), (float("nan"), 1)], None, "vertex"),
    ([(0, 0), (1, 0), (2, 0)], None, "area"),
])
def test_bad_patches_raise_the_library_message(vertices, centre, message):
    with pytest.raises(ValueError, match="spinslide::polygon_patch") as e:
        spinslide.PolygonPatch(vertices, centre)
    assert message in str(e.value)


def test_bad_shapes_and_twists():
    with pytest.raises(ValueError, match=r"\(n, 2\)"):
        spinslide.PolygonPatch([0.0, 1.0, 2.0])
    with pytest.raises(ValueError, match="centre_of_pressure"):
        spinslide.PolygonPatch(BOX, (0.0, 0.0, 0.0))
    with pytest.raises(ValueError, match="segment"):
        spinslide.PolygonPatch.segment((0.0, 0.0), (0.0, 0.0))
    patch = spinslide.PolygonPatch(BOX)
    with pytest.raises(ValueError, match="zero twist"):
        spinslide.friction_wrench(patch, (0.0, 0.0), 0.0)
    with pytest.raises(ValueError, match="zero twist"):
        spinslide.friction_dissipation(patch, [[1.0, 0.0], [0.0, 0.0]], 0.0)
    with pytest.raises(ValueError, match="velocity"):
        spinslide.friction_wrench(patch, (1.0, 0.0, 0.0), 1.0)
    with pytest.raises(TypeError):
        spinslide.friction_wrench(patch, "fast", 1.0)
    assert "PolygonPatch(shape=area" in repr(patch)


def test_throw_plate_exact_limits():
    mu, g, k = 0.3, 9.81, 0.07
    square = spinslide.PolygonPatch([(-0.1, -0.1), (0.1, -0.1), (0.1, 0.1), (-0.1, 0.1)])
    # Pure sliding: decelerates at μg, stops at v/(μg) after v²/(2μg), without turning.
    r = spinslide.throw_plate(square, gyration_radius=k, friction_coefficient=mu, gravity=g,
                              velocity=(0.6, 0.8), spin=0.0, angle=0.3)
    assert r.reached_stop
    assert r.time == pytest.approx(1.0 / (mu * g), rel=1e-10)
    assert r.distance == pytest.approx(1.0 / (2 * mu * g), rel=1e-10)
    c, s = math.cos(0.3), math.sin(0.3)
    np.testing.assert_allclose(r.displacement, np.array([c * 0.6 - s * 0.8, s * 0.6 + c * 0.8])
                               / (2 * mu * g), rtol=1e-10)
    assert abs(r.rotation) < 1e-12
    # Pure spin about the centre: dω/dt = -μg m/k² with m = (a/3)(√2 + asinh 1).
    m = 0.1 / 3 * (math.sqrt(2) + math.asinh(1.0))
    r = spinslide.throw_plate(square, gyration_radius=k, friction_coefficient=mu, gravity=g,
                              velocity=(0.0, 0.0), spin=5.0)
    assert r.time == pytest.approx(5.0 * k * k / (mu * g * m), rel=1e-10)
    assert r.rotation == pytest.approx(25.0 * k * k / (2 * mu * g * m), rel=1e-10)
    assert r.terminal.ratio == 0 and r.terminal.spin_sense == 1
    path = r.path
    assert path["position"].shape == (len(path["time"]), 2)
    assert path["time"][-1] == r.time
    with pytest.raises(ValueError, match="gyration_radius"):
        spinslide.throw_plate(square, gyration_radius=-1.0, friction_coefficient=mu, gravity=g,
                              velocity=(1.0, 0.0), spin=0.0)


def test_plate_terminal_points_are_where_the_wrench_opposes_the_twist():
    # A uniform square lamina (k² = L²/6): at each fixed point (F, τ/k) is
    # antiparallel to n = (u, kω) (docs/plate_dynamics.md), checked by dblquad.
    a = 0.1
    k = math.sqrt((2 * a) ** 2 / 6)
    square = spinslide.PolygonPatch([(-a, -a), (a, -a), (a, a), (-a, a)])
    points = spinslide.plate_terminal_points(square, gyration_radius=k)
    stable = [p for p in points if p.stable]
    assert stable and all(p.ratio > 0 for p in stable)
    for p in points:
        n = p.twist
        assert np.linalg.norm(n) == pytest.approx(1.0, rel=1e-14)
        v, w = n[:2], n[2] / k
        fx, fy, tau, _ = quad_wrench(lambda x, y: 1 / (4 * a * a), v, w, a, a)
        g = np.array([fx, fy, tau / k])
        np.testing.assert_allclose(g / np.linalg.norm(g), -n, atol=1e-12)  # measured: 3.3e-16
        if p.ratio > 0:
            assert p.ratio == pytest.approx(np.hypot(*v) / (square.radius * w), rel=1e-12)
            assert p.direction == pytest.approx(math.atan2(v[1], v[0]), abs=1e-12)
    # The stable ones slip along a diagonal (the square's symmetry).
    for p in stable:
        assert math.degrees(p.direction) % 90 == pytest.approx(45, abs=1e-9)
    with pytest.raises(ValueError, match="gyration_radius"):
        spinslide.plate_terminal_points(square, gyration_radius=0.0)
