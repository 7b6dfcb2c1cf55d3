#  Copyright (c) 2026 the spinslide developers.
#  Distributed under the Boost Software License, Version 1.0.
#  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
"""Values against the committed high-precision references, with the C++
tests' budgets: 𝓕 and 𝓣 within 4 ulp, the derivatives within 16."""

import numpy as np
import pytest

import spinslide
from conftest import ratio_of, relative, rows, ulps


def test_disk_functions_within_4_ulp_derivatives_within_16(disk_rows):
    eps = np.array([ratio_of(r) for r in disk_rows])
    f, t = spinslide.force_torque(eps)
    worst = {"F": 0.0, "T": 0.0, "F'": 0.0, "T'": 0.0}
    for i, r in enumerate(disk_rows):
        worst["F"] = max(worst["F"], ulps(f[i], r["force"]),
                         ulps(spinslide.force(eps[i]), r["force"]))
        worst["T"] = max(worst["T"], ulps(t[i], r["torque"]),
                         ulps(spinslide.torque(eps[i]), r["torque"]))
        worst["F'"] = max(worst["F'"], ulps(spinslide.force_derivative(eps[i]),
                                            r["force_derivative"]))
        worst["T'"] = max(worst["T'"], ulps(spinslide.torque_derivative(eps[i]),
                                            r["torque_derivative"]))
    print("disk, largest errors in ulps:", worst)
    assert len(disk_rows) > 300
    assert worst["F"] <= 4 and worst["T"] <= 4
    assert worst["F'"] <= 16 and worst["T'"] <= 16


def test_disk_in_float32_within_4_float_ulp(disk_rows):
    exact_in_float = [r for r in disk_rows if r["float_exact"] == "1"]
    eps = np.array([ratio_of(r) for r in exact_in_float], dtype=np.float32)
    f, t = spinslide.force_torque(eps)
    assert f.dtype == np.float32 and t.dtype == np.float32
    worst = 0.0
    for i, r in enumerate(exact_in_float):
        worst = max(worst, ulps(f[i], r["force"], np.float32), ulps(t[i], r["torque"], np.float32))
    assert len(exact_in_float) > 100
    assert worst <= 4


def test_the_profile_class_of_the_disk_gives_the_same_numbers(disk_rows):
    eps = np.array([ratio_of(r) for r in disk_rows])
    disk = spinslide.UniformDisk()
    f, t = spinslide.force_torque(eps)
    assert np.array_equal(disk.force(eps), f)
    assert np.array_equal(disk.torque(eps), t)
    assert np.array_equal(disk.force_derivative(eps), spinslide.force_derivative(eps))


@pytest.mark.parametrize("name, make", [("hertz", spinslide.Hertz),
                                        ("boussinesq", spinslide.Boussinesq)])
def test_elastic_profiles_within_4_ulp_derivatives_within_16(name, make):
    p = make()
    # No header row: profile, eps (hex), F, T, F'.
    table = [dict(zip(("profile", "eps", "F", "T", "F'"), line.strip().split(",")))
             for line in open(rows.__globals__["REFERENCE"] / "elastic_reference.csv")
             if not line.startswith("#") and line.startswith(name + ",")]
    assert len(table) == 229
    worst_values = worst_slope = 0.0
    for r in table:
        e = float.fromhex(r["eps"])
        f, t = p.force_torque(e)
        worst_values = max(worst_values, ulps(f, r["F"]), ulps(t, r["T"]))
        worst_slope = max(worst_slope, ulps(p.force_derivative(e), r["F'"]))
    print(name, "largest errors in ulps: values", worst_values, "F'", worst_slope)
    assert worst_values <= 4
    assert worst_slope <= 16


def two_tier():
    return spinslide.WeightedSum([(0.6, spinslide.Scaled(spinslide.UniformDisk(), 0.5)),
                                  (0.4, spinslide.Annulus(0.5))])


PROFILES = {
    "annulus_0.125": lambda: spinslide.Annulus(0.125),
    "ring": spinslide.Ring,
    "hertz": spinslide.Hertz,
    "boussinesq": spinslide.Boussinesq,
    "two_tier": two_tier,
    "parabolic": lambda: spinslide.RadialProfile(lambda r: (1 - r) * (1 + r)),
}


@pytest.mark.parametrize("name", sorted(PROFILES))
def test_profiles_against_the_area_integrals(name):
    """The 2-D area integrals (generate_profile_reference.cpp), independent of
    the ring kernel: 1e-13 relative on [1e-6, 1e6], as in C++."""
    p = PROFILES[name]()
    table = [r for r in rows("profile_reference.csv")
             if r["profile"] == name and 1e-6 <= float(r["eps"]) <= 1e6]
    eps = np.array([ratio_of(r) for r in table])
    f, t = p.force_torque(eps)
    worst = max(max(relative(f[i], r["force"]), relative(t[i], r["torque"]))
                for i, r in enumerate(table))
    assert len(table) > 40
    assert worst <= 1e-13, worst


def test_terminal_ratio_within_1_ulp():
    text = (rows.__globals__["REFERENCE"] / "terminal_ratio.txt").read_text()
    exact = [line for line in text.splitlines() if not line.startswith("#")][0].strip()
    assert ulps(spinslide.terminal_ratio(), exact) <= 1


def test_limits_and_moments():
    for p in (spinslide.UniformDisk(), spinslide.Hertz(), spinslide.Annulus(0.3),
              spinslide.Ring(), two_tier()):
        assert p.force(0.0) == 0.0 and p.force(np.inf) == 1.0
        assert p.torque(np.inf) == 0.0
        assert p.torque(0.0) == pytest.approx(p.mean_radius(), rel=1e-15)
    disk = spinslide.UniformDisk()
    assert (disk.mean_radius(), disk.mean_inverse_radius(), disk.mean_square_radius()) == (
        2 / 3, 2.0, 0.5)
    # The moments of the Hertz load: 3π/16, 3π/4, 2/5 (docs/theory.md §6).
    h = spinslide.Hertz()
    assert h.mean_radius() == pytest.approx(3 * np.pi / 16, rel=1e-15)
    assert h.mean_inverse_radius() == pytest.approx(3 * np.pi / 4, rel=1e-15)
    assert h.mean_square_radius() == pytest.approx(0.4, rel=1e-15)


def test_coupling_round_trips():
    for p in (spinslide.UniformDisk(), spinslide.Hertz(), spinslide.Annulus(0.125)):
        # (ε's condition from 𝓕 grows as 1/(ε𝓕′) ~ 4ε²: ε up to 4 here.)
        eps = np.array([1e-3, 0.3, 1.0, 2.0, 4.0])
        f, t = p.force_torque(eps)
        assert np.allclose(spinslide.ratio_from_force(p, f), eps, rtol=1e-12)
        assert np.allclose(spinslide.torque_at_force(p, f), t, rtol=1e-13)
        assert np.allclose(spinslide.ratio_from_torque(p, t), eps, rtol=1e-12)
        assert np.allclose(spinslide.force_at_torque(p, t), f, rtol=1e-13)
    f, t = spinslide.coupling_curve(spinslide.UniformDisk(), points=5)
    assert f[0] == 0 and f[-1] == 1 and t[0] == pytest.approx(2 / 3) and t[-1] == 0
    assert np.all(np.diff(f) > 0) and np.all(np.diff(t) < 0)


def test_tabulated_matches_its_profile_and_has_a_derivative():
    h = spinslide.Hertz()
    table = spinslide.Tabulated(h)
    eps = np.geomspace(1e-4, 1e4, 101)
    assert np.allclose(table.force(eps), h.force(eps), rtol=1e-10, atol=0)
    assert np.allclose(table.torque(eps), h.torque(eps), rtol=1e-10, atol=0)
    assert np.allclose(table.force_derivative(eps), h.force_derivative(eps), rtol=1e-7, atol=0)


def test_weighted_sum_is_the_weighted_mean():
    a, b = spinslide.UniformDisk(), spinslide.Ring()
    s = spinslide.WeightedSum([(3.0, a), (1.0, b)])
    eps = np.geomspace(1e-3, 1e3, 13)
    assert np.allclose(s.force(eps), 0.75 * a.force(eps) + 0.25 * b.force(eps), rtol=1e-15)
    assert s.mean_radius() == pytest.approx(0.75 * 2 / 3 + 0.25, rel=1e-15)


# The derivatives of the profiles without a closed form (a central difference
# in ln ε, docs/python.md), against analytic identities and closed forms
# computed independently here.
DERIVATIVE_RATIOS = np.array([1e-8, 0.01, 0.05, 0.1, 0.12, 0.13, 0.3, 0.9, 0.99, 0.999, 1.001,
                              1.01, 2.0, 10.0, 100.0, 1e5, 1e10])


def test_annulus_derivative_against_the_disk_identity():
    """A uniform annulus is the disk minus its inner disk of radius b, whose
    ratio is ε/b: 𝓕′_b(ε) = (𝓕′(ε) − b𝓕′(ε/b))/(1 − b²), with the disk's
    closed-form 𝓕′ (held to 16 ulp above)."""
    for b in (0.125, 0.4):
        e = DERIVATIVE_RATIOS
        exact = (spinslide.force_derivative(e) - b * spinslide.force_derivative(e / b)) / (1 - b * b)
        got = spinslide.Annulus(b).force_derivative(e)
        near = np.minimum(np.abs(np.log(e / b)), np.abs(np.log(e)))
        worst_far = np.max(np.abs(got / exact - 1)[near > 1e-3])
        worst_near = np.max(np.abs(got / exact - 1))
        print(f"annulus {b}: F' within {worst_far:.1e} (1e-3 in ln eps from 1 and b), "
              f"{worst_near:.1e} everywhere")
        assert worst_far <= 1e-10
        assert worst_near <= 1e-6
        assert spinslide.Annulus(b).force_derivative(b) == pytest.approx(
            (spinslide.force_derivative(b) - b * spinslide.force_derivative(1.0)) / (1 - b * b),
            rel=1e-6)


def test_ring_derivative_against_its_closed_form():
    """The ring (docs/theory.md (R3)) with modulus k = min(ε, 1/ε):
    ε < 1: 𝓕 = (2/π)(E − (1 − k²)K)/k, so 𝓕′ = (2/π)(K − (E − (1 − k²)K)/k²);
    ε > 1: 𝓕 = (2/π)E(k), so 𝓕′ = (2/π)k(K − E); K, E by scipy."""
    from scipy.special import ellipe, ellipk

    e = np.array([0.05, 0.3, 0.8, 0.95, 0.99, 0.999, 1.001, 1.01, 1.05, 1.5, 5.0, 20.0])
    k = np.where(e < 1, e, 1 / e)
    K, E = ellipk(k * k), ellipe(k * k)
    exact = np.where(e < 1, (2 / np.pi) * (K - (E - (1 - k * k) * K) / (k * k)),
                     (2 / np.pi) * k * (K - E))
    worst = np.max(np.abs(spinslide.Ring().force_derivative(e) / exact - 1))
    print(f"ring: F' within {worst:.1e}")
    assert worst <= 1e-10


def test_sum_scaled_and_radial_derivatives():
    e = np.geomspace(1e-3, 1e3, 25)
    e = e[np.abs(np.log(e)) > 1e-2]
    disk, hertz = spinslide.UniformDisk(), spinslide.Hertz()
    s = spinslide.WeightedSum([(0.3, disk), (0.7, hertz)])
    exact = 0.3 * disk.force_derivative(e) + 0.7 * hertz.force_derivative(e)
    assert np.allclose(s.force_derivative(e), exact, rtol=1e-10, atol=0)
    half = spinslide.Scaled(disk, 0.5)  # 𝓕(ε/a), so 𝓕′(ε/a)/a
    e_half = e[np.abs(np.log(e / 0.5)) > 1e-2]
    assert np.allclose(half.force_derivative(e_half), 2 * disk.force_derivative(2 * e_half),
                       rtol=1e-10, atol=0)
    flat = spinslide.RadialProfile(lambda r: 1.0)  # the disk, by quadrature
    assert np.allclose(flat.force_derivative(e), disk.force_derivative(e), rtol=1e-9, atol=0)
    assert np.allclose(s.torque_derivative(e), -e * s.force_derivative(e), rtol=1e-15, atol=0)
    # The ends: ⟨1/r⟩/2 at 0 and 0 at ∞.
    assert s.force_derivative(0.0) == pytest.approx(s.mean_inverse_radius() / 2, rel=1e-15)
    assert s.force_derivative(np.inf) == 0.0
