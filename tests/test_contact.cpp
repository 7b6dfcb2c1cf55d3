//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The contact law for simulators (contact_law.hpp).
#include <gtest/gtest.h>

#include <spinslide/contact/contact_inputs.hpp>
#include <spinslide/contact/contact_law.hpp>
#include <spinslide/values/approximations.hpp>
#include <spinslide/values/disk.hpp>
#include <spinslide/values/profile.hpp>

#include <boost/math/special_functions/relative_difference.hpp>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>

#include "quadrature_moments.hpp"

namespace {

using namespace spinslide;
using boost::math::relative_difference;
using vec2 = std::array<double, 2>;
using vec3 = std::array<double, 3>;

// The named inputs (a, N, μ) of a contact, from plain numbers in this order.
force_contact<double> contact_of(double radius, double normal, double mu) {
  return {patch_radius<double>{radius}, normal_force<double>{normal},
          friction_coefficient<double>{mu}};
}
force_contact<float> contact_of(float radius, float normal, float mu) {
  return {patch_radius<float>{radius}, normal_force<float>{normal},
          friction_coefficient<float>{mu}};
}

// A user's vector with public members (as Box2D's b2Vec2).
struct member_vec2 {
  float x, y;
};
// An Eigen-like 3-vector: operator[] and x()/y()/z() accessors, no public data.
class eigen_like3 {
 public:
  eigen_like3() = default;
  eigen_like3(double a, double b, double c) : d_{a, b, c} {}
  double& operator[](int i) { return d_[i]; }
  const double& operator[](int i) const { return d_[i]; }
  double x() const { return d_[0]; }
  double y() const { return d_[1]; }
  double z() const { return d_[2]; }

 private:
  double d_[3] = {0, 0, 0};
};

TEST(ContactLaw, ForceOpposesSlidingTorqueOpposesSpin) {
  const contact_law<> law(uniform_disk<>(), velocity_scale<double>{1e-6});
  const double a = 0.05, N = 2.0, mu = 0.5;
  for (double angle : {0.0, 1.0, 2.5, -2.0}) {
    for (double w : {-30.0, -1.0, 0.5, 8.0}) {
      const double speed = 0.7;
      const vec2 v = {speed * std::cos(angle), speed * std::sin(angle)};
      const auto r = law(v, w, contact_of(a, N, mu));
      const double eps = speed / (a * std::fabs(w));
      const double F = mu * N * force(eps), T = mu * N * a * torque(eps);
      EXPECT_LE(relative_difference(std::hypot(r.force[0], r.force[1]), F), 4e-16);
      EXPECT_NEAR(r.force[0] * v[1] - r.force[1] * v[0], 0.0, 1e-15);  // parallel
      EXPECT_LT(r.force[0] * v[0] + r.force[1] * v[1], 0);             // and opposed
      EXPECT_LE(relative_difference(r.torque, -std::copysign(T, w)), 4e-16);
    }
  }
}

TEST(ContactLaw, ThreeDimensionalMatchesPlanarInTheTangentPlane) {
  const contact_law<> law(uniform_disk<>(), velocity_scale<double>{1e-6});
  // A tilted normal and an orthonormal tangent basis (t1, t2, n).
  const vec3 n = {1.0 / 3, 2.0 / 3, 2.0 / 3};
  const vec3 t1 = {2.0 / 3, 1.0 / 3, -2.0 / 3};
  const vec3 t2 = {-2.0 / 3, 2.0 / 3, -1.0 / 3};  // n × t1
  const double vt1 = 0.3, vt2 = -0.2, vn = 5.0, wn = 7.0, wt = 3.0;
  vec3 v, w;
  for (std::size_t i = 0; i < 3; ++i) {
    v[i] = vt1 * t1[i] + vt2 * t2[i] + vn * n[i];  // the normal part must be ignored
    w[i] = wn * n[i] + wt * t1[i];                 // rolling must be ignored
  }
  const auto r3 = law(v, w, contact_normal{n}, contact_of(0.02, 3.0, 0.4));
  const auto r2 = law(vec2{vt1, vt2}, wn, contact_of(0.02, 3.0, 0.4));
  // Removing the normal part (|v_n| = 5 against |v_t| = 0.36) costs ~4 bits.
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(r3.force[i], r2.force[0] * t1[i] + r2.force[1] * t2[i], 1e-14);
    EXPECT_NEAR(r3.torque[i], r2.torque * n[i], 1e-14);
  }
}

// The 3-D friction acts at the patch centre c: about a body's centre of mass
// x it carries the moment (c − x) × F as well.  A patch h below x with the
// force along x̂ gives the moment (0, −hF, 0) (by hand), added to the spin
// torque along the normal; and about c itself nothing changes.
TEST(ContactLaw, WrenchAboutAnyPoint) {
  const contact_law<> law(uniform_disk<>(), velocity_scale<double>{1e-6});
  const vec3 n{0, 0, 1};
  const auto r =
      law(vec3{-0.5, 0, 0}, vec3{0, 0, 3}, contact_normal{n}, contact_of(0.05, 2.0, 0.5));
  const double h = 0.25;  // exact in binary, as is 3 - h
  const vec3 centre{1, 2, 3 - h}, mass_centre{1, 2, 3};
  const auto about_x = wrench_about(r, centre, mass_centre);
  EXPECT_EQ(about_x.force, r.force);
  EXPECT_DOUBLE_EQ(about_x.torque[0], r.torque[0]);
  EXPECT_DOUBLE_EQ(about_x.torque[1], r.torque[1] - h * r.force[0]);
  EXPECT_DOUBLE_EQ(about_x.torque[2], r.torque[2]);
  EXPECT_GT(r.force[0], 0);  // against v
  const auto about_c = wrench_about(r, centre, centre);
  EXPECT_EQ(about_c.torque, r.torque);
}

TEST(ContactLaw, UsersVectorTypes) {
  const contact_law<uniform_disk<float>> lawf(uniform_disk<float>(), velocity_scale<float>{1e-6f});
  const auto b = lawf(member_vec2{0.3f, 0.4f}, 10.0f, contact_of(0.05f, 2.0f, 0.5f));
  const auto s = lawf(std::array<float, 2>{0.3f, 0.4f}, 10.0f, contact_of(0.05f, 2.0f, 0.5f));
  EXPECT_EQ(b.force.x, s.force[0]);
  EXPECT_EQ(b.force.y, s.force[1]);
  EXPECT_EQ(b.torque, s.torque);
  const contact_law<> law(uniform_disk<>(), velocity_scale<double>{1e-6});
  const auto e = law(eigen_like3(0.3, 0.4, 0), eigen_like3(0, 0, 10),
                     contact_normal{eigen_like3(0, 0, 1)}, contact_of(0.05, 2.0, 0.5));
  const auto a = law(vec3{0.3, 0.4, 0}, vec3{0, 0, 10}, contact_normal{vec3{0, 0, 1}},
                     contact_of(0.05, 2.0, 0.5));
  for (int i = 0; i < 3; ++i) {  // eigen_like3 is indexed by int, std::array by std::size_t
    EXPECT_EQ(e.force[i], a.force[static_cast<std::size_t>(i)]);
    EXPECT_EQ(e.torque[i], a.torque[static_cast<std::size_t>(i)]);
  }
  EXPECT_EQ(e.force.x(), a.force[0]);
}

TEST(ContactLaw, HertzProfileForSphereContacts) {
  // A sphere of effective radius R* pressed by δ: contact radius a = √(R*δ).
  const double Rstar = 0.01, delta = 1e-5, a = std::sqrt(Rstar * delta);
  const contact_law<hertz<>> law(hertz<>(), velocity_scale<double>{1e-6});
  const auto r = law(vec2{0.001, 0.0}, 5.0, contact_of(a, 1.0, 0.3));
  const double eps = 0.001 / (a * 5.0);
  EXPECT_LE(relative_difference(-r.force[0], 0.3 * hertz<>().force(eps)), 1e-15);
  EXPECT_LE(relative_difference(-r.torque, 0.3 * a * hertz<>().torque(eps)), 1e-15);
}

// The law's result is a friction_result (issue 40): its ratio is the
// motion's ε = |v|/(a|ω|) (+∞ sliding, 0 spinning, NaN at rest), and
// curve() the limit curve's point there, (ε, 𝓕(ε), 𝓣(ε)), in 2-D as in 3-D.
TEST(ContactLaw, ReportsTheMotionsRatioAndCurvePoint) {
  const contact_law<hertz<>> law(hertz<>(), velocity_scale<double>{1e-6});
  const double a = 0.02;
  const auto planar = law(vec2{0.003, -0.004}, -2.0, contact_of(a, 1.0, 0.3));
  const double eps = 0.005 / (a * 2.0);
  EXPECT_FALSE(planar.sticking);
  EXPECT_EQ(planar.ratio, eps);
  EXPECT_EQ(planar.curve().ratio, eps);
  EXPECT_EQ(planar.curve().force, hertz<>().force(eps));
  EXPECT_EQ(planar.curve().torque, hertz<>().torque(eps));
  const auto spatial = law(vec3{0.003, -0.004, 0.0}, vec3{0.0, 0.0, -2.0},
                           contact_normal<vec3>{vec3{0.0, 0.0, 1.0}}, contact_of(a, 1.0, 0.3));
  EXPECT_EQ(spatial.ratio, eps);
  EXPECT_EQ(spatial.curve().force, planar.curve().force);
  EXPECT_EQ(law(vec2{1.0, 0.0}, 0.0, contact_of(a, 1.0, 0.3)).ratio,
            std::numeric_limits<double>::infinity());
  const auto spinning = law(vec2{0.0, 0.0}, 3.0, contact_of(a, 1.0, 0.3));
  EXPECT_EQ(spinning.ratio, 0.0);
  EXPECT_EQ(spinning.curve().torque, hertz<>().mean_radius());
  EXPECT_TRUE(std::isnan(law(vec2{0.0, 0.0}, 0.0, contact_of(a, 1.0, 0.3)).ratio));
}

TEST(Regularization, ExactAboveTheScaleContinuousAndZeroAtRest) {
  const double vs = 1e-3;
  const contact_law<> law(uniform_disk<>(), velocity_scale<double>{vs});
  const double a = 0.1;
  // Above the scale: the exact law.
  const auto hi = law(vec2{2e-3, 0}, 3e-2, contact_of(a, 1, 1));
  EXPECT_LE(relative_difference(-hi.force[0], force(2e-3 / (a * 3e-2))), 4e-16);
  // Continuous across ρ = v_s along a ray, and → 0 at rest along any direction.
  for (double dir : {0.0, 0.7, 1.5707963267948966}) {
    const double c = std::cos(dir), s = std::sin(dir);
    auto at = [&](double rho) { return law(vec2{rho * c, 0}, rho * s / a, contact_of(a, 1, 1)); };
    const auto below = at(vs * (1 - 1e-12)), above = at(vs * (1 + 1e-12));
    EXPECT_NEAR(below.force[0], above.force[0], 1e-11);
    EXPECT_NEAR(below.torque, above.torque, 1e-11);
    const auto tiny = at(1e-12);
    EXPECT_LE(std::fabs(tiny.force[0]) + std::fabs(tiny.torque), 2e-9);
  }
  const auto rest = law(vec2{0, 0}, 0.0, contact_of(a, 1, 1));
  EXPECT_EQ(rest.force[0], 0);
  EXPECT_EQ(rest.torque, 0);
}

// The regularized law has no static friction (docs/contact.md, "Creep"): a
// block on a slope below the friction angle, stepped explicitly, settles to
// sliding at v_s·F/(μN) = v_s tan α/μ: 2.9 mm/s for tan α = 0.15, μ = 0.3
// and v_s = 2μgΔt at Δt = 1 ms.  (The impulse law holds it at rest:
// ImpulseFriction.BlockOnASlopeSticksExactlyAndSlidesExactly.)
TEST(Regularization, CreepsBelowTheFrictionAngle) {
  const double mu = 0.3, g = 9.81, dt = 1e-3, slope = 0.15, mass = 2, a = 0.05;
  const double alpha = std::atan(slope), vs = 2 * mu * g * dt;
  const contact_law<> law(uniform_disk<>(), velocity_scale<double>{vs});
  const auto c = contact_of(a, mass * g * std::cos(alpha), mu);
  double v = 0;
  for (int k = 0; k < 10000; ++k) {
    const auto fr = law(vec2{v, 0}, 0.0, c);
    v += (g * std::sin(alpha) + fr.force[0] / mass) * dt;
  }
  EXPECT_NEAR(v, vs * slope / mu, 1e-12);
  EXPECT_NEAR(v, 2.943e-3, 1e-6);
}

// The friction never does positive work: −(F·v + T·ω) ≥ 0, for 10⁵ random
// states spanning the regularized and the exact regime.
TEST(Regularization, AlwaysDissipative) {
  const contact_law<> law(uniform_disk<>(), velocity_scale<double>{1e-2});
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1), e(-6, 2);
  for (int i = 0; i < 100000; ++i) {
    const vec2 v = {u(rng) * std::pow(10.0, e(rng)), u(rng) * std::pow(10.0, e(rng))};
    const double w = u(rng) * std::pow(10.0, e(rng)), a = std::pow(10.0, e(rng));  // a > 0
    const auto r = law(v, w, contact_of(a, 1.0, 0.5));
    const double power = r.force[0] * v[0] + r.force[1] * v[1] + r.torque * w;
    ASSERT_LE(power, 0) << i;
    ASSERT_TRUE(std::isfinite(r.force[0]) && std::isfinite(r.force[1]) && std::isfinite(r.torque));
  }
}

// Finite and, to 1e-14 (or 4 denorm_min), the documented law: F = −μN𝓕(ε)v̂
// and T = −sign(ω)μN a𝓣(ε), scaled by min(1, ρ/v_s), with ε = |v|/(a|ω|) and
// ρ = √(|v|² + (aω)²) formed in long double, whose range holds every
// product here (a|ω| from 1e-600 to 1e600), and 𝓕, 𝓣 in long double.
TEST(Regularization, FiniteForEveryFiniteInput) {
  const contact_law<> law(uniform_disk<>(), velocity_scale<double>{1e-6});
  const double big = 1e300, tiny = 1e-300, mu = 0.5, N = 1.0;
  auto expect_close = [](double got, long double want) {
    return std::fabs(got - want) <=
           std::max(1e-14L * std::fabs(want), 4.0L * std::numeric_limits<double>::denorm_min());
  };
  for (double vx : {0.0, tiny, 1.0, big, -big})
    for (double w : {0.0, tiny, -1.0, big})
      for (double a : {tiny, 0.05, big}) {
        const auto r = law(vec2{vx, vx / 2}, w, contact_of(a, N, mu));
        EXPECT_TRUE(std::isfinite(r.force[0]) && std::isfinite(r.force[1]) &&
                    std::isfinite(r.torque))
            << vx << " " << w << " " << a;
        const long double speed = std::hypot(static_cast<long double>(vx), vx / 2.0L),
                          rim = static_cast<long double>(a) * std::fabs(w);
        const long double scale = std::min(1.0L, std::hypot(speed, rim) / law.velocity_scale());
        long double fx = 0, fy = 0, t = 0;
        if (speed > 0) {
          const long double F = force(rim > 0 ? speed / rim : INFINITY);
          fx = -mu * N * F * scale * (vx / speed);
          fy = fx / 2;
        }
        if (rim > 0) {
          const long double T = torque(speed / rim);
          t = -std::copysign(mu * N * a * T * scale, static_cast<long double>(w));
        }
        if (rim > std::numeric_limits<double>::max() && std::fabs(fx) > 0) {
          // Known and open (docs/reliability.md): where a|ω| overflows
          // double (a = ω = 1e300) the law takes ε = 0, so 𝓕 = 0 where it is
          // ε = 1e-300 and the force is 5e-301: no larger than the true one.
          EXPECT_LE(std::fabs(r.force[0]), std::fabs(fx)) << vx << " " << w << " " << a;
          EXPECT_LE(std::fabs(r.force[1]), std::fabs(fy)) << vx << " " << w << " " << a;
        } else {
          EXPECT_TRUE(expect_close(r.force[0], fx))
              << vx << " " << w << " " << a << ": " << r.force[0] << " vs " << fx;
          EXPECT_TRUE(expect_close(r.force[1], fy)) << vx << " " << w << " " << a;
        }
        EXPECT_TRUE(expect_close(r.torque, t))
            << vx << " " << w << " " << a << ": " << r.torque << " vs " << t;
      }
}

TEST(ContactLaw, BadInputIsADomainError) {
  const contact_law<> law(uniform_disk<>(), velocity_scale<double>{1e-6});
  EXPECT_THROW(law(vec2{1, 0}, 1.0, contact_of(-0.1, 1.0, 0.5)), std::domain_error);
  EXPECT_THROW(law(vec2{1, 0}, 1.0, contact_of(0.0, 1.0, 0.5)), std::domain_error);  // a <= 0
  EXPECT_THROW(law(vec2{1, 0}, 1.0, contact_of(0.1, -1.0, 0.5)), std::domain_error);
  EXPECT_THROW(law(vec2{1, 0}, 1.0, contact_of(0.1, 1.0, -0.5)), std::domain_error);
  EXPECT_THROW(law(vec2{std::nan(""), 0}, 1.0, contact_of(0.1, 1.0, 0.5)), std::domain_error);
  EXPECT_THROW(law(vec2{1, 0}, std::nan(""), contact_of(0.1, 1.0, 0.5)), std::domain_error);
  EXPECT_THROW(law(vec2{1, 0}, 1.0, contact_of(0.1, std::nan(""), 0.5)), std::domain_error);
  EXPECT_THROW(contact_law<>(uniform_disk<>(), velocity_scale<double>{-1.0}), std::domain_error);
}

// ---------------------------------------------------------------- regressions
//
// Each failure a fuzz harness (fuzz/) found in the contact law, with the
// input it reported; docs/reliability.md lists them.  The expectations are
// the law as documented (contact_law.hpp): F = −μN𝓕(ε) v̂ and T = −μN a 𝓣(ε)
// sign(ω) n̂ with ε = |v_t|/(a|ω_n|), scaled by min(1, ρ/v_s) where ρ =
// √(|v_t|² + (aω_n)²), evaluated in long double or cpp_bin_float_50.

constexpr double max_d = std::numeric_limits<double>::max();
constexpr double double_eps = std::numeric_limits<double>::epsilon();

// fuzz_contact: f/|v| overflowed for a tiny 3-D sliding speed (NaN force);
// guards −f (v/|v|).  ω = 0: ε = ∞, 𝓕 = 1 and 𝓣 = 0, and ρ = |v| = 1e-322
// is below v_s: F = −μN (|v|/v_s) x̂.
TEST(ContactLaw, RegressionTinySlidingSpeedIn3D) {
  const contact_law<> law(uniform_disk<>(), velocity_scale<double>{1e-6});
  const double v = 9.88131291682493088353e-323, N = 8.98846567431157854073e+307,
               mu = 4.58359719837098179601e-05;
  const auto r =
      law(vec3{v, 0, 0}, vec3{0, 0, 0}, contact_normal{vec3{0, 0, 1}}, contact_of(1.0, N, mu));
  const double expected =
      -double(static_cast<long double>(mu) * N * v / law.velocity_scale());  // −4.1e-13
  EXPECT_NEAR(r.force[0], expected, 4 * double_eps * -expected);
  EXPECT_EQ(r.force[1], 0);
  EXPECT_EQ(r.force[2], 0);
  for (const double t : r.torque) EXPECT_EQ(t, 0);
}

// fuzz_contact: μN a overflowed times 𝓣 = 0 (planar, no spin: NaN torque);
// guards (μN s)(a𝓣).  ω = 0: 𝓣(∞) = 0 and 𝓕 = 1, and ρ = |v| = 3.4e-13 < v_s:
// F = −μN (|v|/v_s) x̂, T = 0.
TEST(ContactLaw, RegressionOverflowingLoadAndRadiusWithoutSpin) {
  const contact_law<> law(uniform_disk<>(), velocity_scale<double>{1e-6});
  const double v = 3.4e-13, mu = 0.156875143087110618945;
  const auto r = law(vec2{v, 0}, 0.0, contact_of(max_d, max_d, mu));
  EXPECT_EQ(r.torque, 0);
  const double expected = -double(static_cast<long double>(mu) * max_d * v / law.velocity_scale());
  EXPECT_NEAR(r.force[0], expected, 4 * double_eps * -expected);
  EXPECT_EQ(r.force[1], 0);
}

// fuzz_contact (the 1e7-input campaign): μN s underflowed to 0 where a𝓣
// overflows (NaN torque); guards detail::product.  Expected: the same law at
// a/c and ω c, times c (the torque is ∝ a at fixed aω; c = 2^600 keeps every
// product normal), and the law itself: the cone's 𝓣 = τ²/√(ε² + τ²) (on the
// ellipse 𝓕² + 𝓣²/τ² = 1 with normal along (ε, 1)), scaled by ρ/v_s.
TEST(ContactLaw, RegressionTorqueOfAnUnderflowingLoadAtAnOverflowingRadius) {
  const double vs = 8.98846567431157854073e+307, a = 8.98846567431157854073e+307,
               tau = 174827.100707625766518;
  const contact_law<elliptic_limit_surface<double>> law(elliptic_limit_surface<double>(tau),
                                                        velocity_scale<double>{vs});
  const vec2 v{7.82232238000716571555e-24, 1.1956970914634861867e-258};
  const double spin = 2.71736105212685599297e-322, N = 2.22044604925031308085e-16,
               mu = 0.0444809783472058864473;
  const double c = std::ldexp(1.0, 600);
  const auto r = law(v, spin, contact_of(a, N, mu));
  const auto scaled = law(v, spin * c, contact_of(a / c, N, mu));
  ASSERT_TRUE(std::isfinite(r.torque));
  EXPECT_LT(r.torque, 0);
  EXPECT_NEAR(r.torque / (scaled.torque * c), 1, 1e-14);
  using big = boost::multiprecision::cpp_bin_float_50;
  const big speed = sqrt(big(v[0]) * v[0] + big(v[1]) * v[1]), rim = big(a) * spin;
  const big eps = speed / rim, rho = sqrt(speed * speed + rim * rim);
  const big T = big(tau) * tau / sqrt(eps * eps + big(tau) * tau);
  const double expected = -static_cast<double>(big(mu) * N * a * T * (rho / vs));
  EXPECT_NEAR(r.torque, expected, 1e-14 * -expected);
}

// fuzz_contact (the 1e7-input campaign): v·n overflowed for velocity
// components near the largest value, so a finite tangential velocity was
// reported as an infinite speed (domain error); guards the projection in units
// of the largest component.  Expected: the result of v/1024 (ε is finite and
// the caps' 𝓕 = 1, 𝓣 = τ at any finite ε > 0), and the law itself:
// F = −μN v_t/|v_t|, T = −μN a τ n (ω·n > 0), with v_t = v − (v·n)n.
TEST(ContactLaw, RegressionTangentialProjectionNearTheLargestValue) {
  const double tau = 36827858.5685185343027;
  const contact_law<uncoupled_caps<double>> law(uncoupled_caps<double>(tau),
                                                velocity_scale<double>{1e-6});
  const double th = 0.88733783351099559944, ph = 0.000766989708598497842498;
  const vec3 n{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
  const vec3 w{1.00000000000000022204, max_d, 0.666666666666666629659};
  const double a = 6.36050773210021198955e-300, N = 0.0549016181728579980015, mu = max_d;
  const vec3 v{max_d, -6.26433498638888716604e+194, max_d};
  const auto r = law(v, w, contact_normal{n}, contact_of(a, N, mu));
  const auto scaled =
      law(vec3{v[0] / 1024, v[1] / 1024, v[2] / 1024}, w, contact_normal{n}, contact_of(a, N, mu));
  using big = boost::multiprecision::cpp_bin_float_50;
  big vn = 0, wn = 0, vt_len2 = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    vn += big(v[i]) * n[i];
    wn += big(w[i]) * n[i];
  }
  std::array<big, 3> vt;
  for (std::size_t i = 0; i < 3; ++i) {
    vt[i] = v[i] - vn * n[i];
    vt_len2 += vt[i] * vt[i];
  }
  ASSERT_GT(wn, 0);
  const big muN = big(mu) * N, vt_len = sqrt(vt_len2);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(r.force[i], scaled.force[i], 1e-14 * mu * N) << i;
    EXPECT_EQ(r.torque[i], scaled.torque[i]) << i;
    EXPECT_NEAR(r.force[i], static_cast<double>(-muN * vt[i] / vt_len), 1e-14 * mu * N) << i;
    const double t = static_cast<double>(-muN * a * tau * n[i]);
    EXPECT_NEAR(r.torque[i], t, 1e-14 * std::fabs(t)) << i;
  }
}

// fuzz_contact (the campaign): with subnormal velocity components v/|v| was
// a quotient of subnormals and |F| exceeded μN by 0.3%; guards v/|v| in units
// of the largest component.  v = (20, 61) times the smallest subnormal and no
// spin: 𝓕 = 1 along the direction (20, 61)/√(20² + 61²), and 𝓣(∞) = 0.
TEST(ContactLaw, RegressionDirectionOfASubnormalVelocity) {
  const double d = std::numeric_limits<double>::denorm_min();
  const double N = 1.16923918684000595184e-228, mu = 0.685007878938989844819;
  const contact_law<boussinesq<double>> law(boussinesq<double>(), velocity_scale<double>{0.0});
  const auto r = law(vec2{20 * d, 61 * d}, 0.0, contact_of(1.31672823561030010652e-38, N, mu));
  const double len = std::hypot(20.0, 61.0);
  EXPECT_NEAR(r.force[0] / (mu * N), -20 / len, 1e-15);
  EXPECT_NEAR(r.force[1] / (mu * N), -61 / len, 1e-15);
  EXPECT_EQ(r.torque, 0);
}

// fuzz_contact (sanitize preset): a NaN velocity component beside a zero one
// gave |v| = 0 (std::max drops the NaN), so no domain error; guards |v| = NaN
// for a NaN component.
TEST(ContactLaw, RegressionNaNVelocityComponentBesideAZero) {
  const contact_law<> law(uniform_disk<>(), velocity_scale<double>{1e-6});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(law(vec2{0, nan}, 0.0, contact_of(2.0, 0.5, 2.0 / 3)), std::domain_error);
  EXPECT_THROW(law(vec3{0, nan, 0}, vec3{0, 0, 0}, contact_normal{vec3{0, 0, 1}},
                   contact_of(2.0, 0.5, 2.0 / 3)),
               std::domain_error);
}

// fuzz_contact (the campaign of 2026-11-23): 𝓕 of a ring-quadrature annulus
// and of a weighted sum rounded to 1 + 2⁻⁵² at a large ratio, so μN𝓕
// overflowed to ∞ for μN = DBL_MAX and the 3-D force had a NaN component
// (∞ · 0 along the normal); guards the clamp 𝓕 ≤ 1 (the profiles' side:
// Annulus.RegressionForceRoundedAboveOneAtLargeRatios).  At ε = 2e87 and
// 5e31, 𝓕 = 1 to rounding (within 2 ulp, the quadrature's level) and
// ε𝓣 = ⟨r²⟩/2 (the limits (L)), so F = −μN v_t/|v_t| and
// T = −sign(ω_n) μN a ⟨r²⟩/(2ε), with ⟨r²⟩ by quadrature of each load.
TEST(ContactLaw, RegressionForceOfAProfileRoundedAboveOne) {
  const double b = 0.635197164334527664131, scale = 0.937500000000852762305;
  const double w1 = 0.173717571710168772192, w2 = 541249.376203841762617;
  const annulus<double> ann(b);
  const auto sum = weighted_sum(
      {w1, w2}, scaled<uniform_disk<double>>(uniform_disk<double>(), scale), ring<double>());
  const contact_normal<vec3> n{vec3{0, 0, 1}};
  const double a_ann = 6.93531866257113469774e-88;
  const contact_law<annulus<double>> law_a(ann, velocity_scale<double>{9.99999999999999954748e-07});
  const auto a = law_a(vec3{1, 1, 1}, vec3{1, 0.556884765625, 1}, n, contact_of(a_ann, max_d, 1.0));
  const double a_sum = 0.999999999999999888978, v0 = 0.666666666666666629659,
               v1 = 3.61069398448143300918e+307, w_n = -6.98211634151446680426e+275;
  const contact_law<decltype(sum)> law_s(sum, velocity_scale<double>{0.666666666666666629659});
  const auto s = law_s(vec3{v0, v1, 0.666666666666666629659}, vec3{max_d, 0, w_n}, n,
                       contact_of(a_sum, 1.0, max_d));
  for (const auto* f : {&a.force, &s.force}) {
    EXPECT_TRUE(std::isfinite((*f)[0]) && std::isfinite((*f)[1]) && (*f)[2] == 0);
    // |F| ≤ μN = DBL_MAX, in units of it.
    EXPECT_LE(std::hypot((*f)[0] / max_d, (*f)[1] / max_d), 1.0);
  }
  const double e = 4 * double_eps;
  // The annulus: v_t = (1, 1), ω_n = 1, ε = √2/a = 2e87.
  EXPECT_NEAR(a.force[0] / max_d, -1 / std::sqrt(2.0), e);
  EXPECT_NEAR(a.force[1] / max_d, -1 / std::sqrt(2.0), e);
  const long double sq_ann = spinslide_test::annulus_moments(b).mean_square_radius;
  const long double t_ann = -max_d * (static_cast<long double>(a_ann) * a_ann) * sq_ann /
                            (2 * std::sqrt(2.0L));  // μN a ⟨r²⟩/(2ε), ε = √2/a
  EXPECT_NEAR(a.torque[2], double(t_ann), 1e-12 * -double(t_ann));
  // The sum: v_t = (v0, v1), ε = |v_t|/(a|ω_n|) = 5e31; the moments of a
  // weighted sum are the load-weighted means, of a scaled disk a²/2.
  const double dir0 = v0 / v1;  // v₀/|v|
  EXPECT_NEAR(s.force[0] / max_d, -dir0, e * dir0);
  EXPECT_NEAR(s.force[1] / max_d, -1.0, e);
  const long double sq_sum = (w1 * (static_cast<long double>(scale) * scale *
                                    spinslide_test::uniform_disk_moments().mean_square_radius) +
                              w2 * 1.0L) /
                             (static_cast<long double>(w1) + w2);
  const long double t_sum = max_d * static_cast<long double>(a_sum) * a_sum * -w_n * sq_sum /
                            (2 * std::hypot(static_cast<long double>(v0), v1));
  EXPECT_NEAR(s.torque[2], double(t_sum), 1e-12 * double(t_sum));
}

}  // namespace
