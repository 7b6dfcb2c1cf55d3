//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The contact law for simulators (contact.hpp).
#include <gtest/gtest.h>

#include <spinslide/spinslide.hpp>

#include <boost/math/special_functions/relative_difference.hpp>

#include <array>
#include <cmath>
#include <random>

namespace {

using namespace spinslide;
using boost::math::relative_difference;
using vec2 = std::array<double, 2>;
using vec3 = std::array<double, 3>;

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
  const contact_law<> law;
  const double a = 0.05, N = 2.0, mu = 0.5;
  for (double angle : {0.0, 1.0, 2.5, -2.0}) {
    for (double w : {-30.0, -1.0, 0.5, 8.0}) {
      const double speed = 0.7;
      const vec2 v = {speed * std::cos(angle), speed * std::sin(angle)};
      const auto r = law(v, w, a, N, mu);
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
  const contact_law<> law;
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
  const auto r3 = law(v, w, n, 0.02, 3.0, 0.4);
  const auto r2 = law(vec2{vt1, vt2}, wn, 0.02, 3.0, 0.4);
  // Removing the normal part (|v_n| = 5 against |v_t| = 0.36) costs ~4 bits.
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(r3.force[i], r2.force[0] * t1[i] + r2.force[1] * t2[i], 1e-14);
    EXPECT_NEAR(r3.torque[i], r2.torque * n[i], 1e-14);
  }
}

TEST(ContactLaw, UsersVectorTypes) {
  const contact_law<uniform_disk<float>> lawf;
  const auto b = lawf(member_vec2{0.3f, 0.4f}, 10.0f, 0.05f, 2.0f, 0.5f);
  const auto s = lawf(std::array<float, 2>{0.3f, 0.4f}, 10.0f, 0.05f, 2.0f, 0.5f);
  EXPECT_EQ(b.force.x, s.force[0]);
  EXPECT_EQ(b.force.y, s.force[1]);
  EXPECT_EQ(b.torque, s.torque);
  const contact_law<> law;
  const auto e =
      law(eigen_like3(0.3, 0.4, 0), eigen_like3(0, 0, 10), eigen_like3(0, 0, 1), 0.05, 2.0, 0.5);
  const auto a = law(vec3{0.3, 0.4, 0}, vec3{0, 0, 10}, vec3{0, 0, 1}, 0.05, 2.0, 0.5);
  for (int i = 0; i < 3; ++i) {  // eigen_like3 is indexed by int, std::array by std::size_t
    EXPECT_EQ(e.force[i], a.force[static_cast<std::size_t>(i)]);
    EXPECT_EQ(e.torque[i], a.torque[static_cast<std::size_t>(i)]);
  }
  EXPECT_EQ(e.force.x(), a.force[0]);
}

TEST(ContactLaw, HertzProfileForSphereContacts) {
  // A sphere of effective radius R* pressed by δ: contact radius a = √(R*δ).
  const double Rstar = 0.01, delta = 1e-5, a = std::sqrt(Rstar * delta);
  const contact_law<hertz<>> law;
  const auto r = law(vec2{0.001, 0.0}, 5.0, a, 1.0, 0.3);
  const double eps = 0.001 / (a * 5.0);
  EXPECT_LE(relative_difference(-r.force[0], 0.3 * hertz<>().force(eps)), 1e-15);
  EXPECT_LE(relative_difference(-r.torque, 0.3 * a * hertz<>().torque(eps)), 1e-15);
}

TEST(Regularization, ExactAboveTheScaleContinuousAndZeroAtRest) {
  const double vs = 1e-3;
  const contact_law<> law(uniform_disk<>(), vs);
  const double a = 0.1;
  // Above the scale: the exact law.
  const auto hi = law(vec2{2e-3, 0}, 3e-2, a, 1, 1);
  EXPECT_LE(relative_difference(-hi.force[0], force(2e-3 / (a * 3e-2))), 4e-16);
  // Continuous across ρ = v_s along a ray, and → 0 at rest along any direction.
  for (double dir : {0.0, 0.7, 1.5707963267948966}) {
    const double c = std::cos(dir), s = std::sin(dir);
    auto at = [&](double rho) { return law(vec2{rho * c, 0}, rho * s / a, a, 1, 1); };
    const auto below = at(vs * (1 - 1e-12)), above = at(vs * (1 + 1e-12));
    EXPECT_NEAR(below.force[0], above.force[0], 1e-11);
    EXPECT_NEAR(below.torque, above.torque, 1e-11);
    const auto tiny = at(1e-12);
    EXPECT_LE(std::fabs(tiny.force[0]) + std::fabs(tiny.torque), 2e-9);
  }
  const auto rest = law(vec2{0, 0}, 0.0, a, 1, 1);
  EXPECT_EQ(rest.force[0], 0);
  EXPECT_EQ(rest.torque, 0);
}

// The friction never does positive work: −(F·v + T·ω) ≥ 0, for 10⁵ random
// states spanning the regularized and the exact regime.
TEST(Regularization, AlwaysDissipative) {
  const contact_law<> law(uniform_disk<>(), 1e-2);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1), e(-6, 2);
  for (int i = 0; i < 100000; ++i) {
    const vec2 v = {u(rng) * std::pow(10.0, e(rng)), u(rng) * std::pow(10.0, e(rng))};
    const double w = u(rng) * std::pow(10.0, e(rng)), a = std::pow(10.0, e(rng));  // a > 0
    const auto r = law(v, w, a, 1.0, 0.5);
    const double power = r.force[0] * v[0] + r.force[1] * v[1] + r.torque * w;
    ASSERT_LE(power, 0) << i;
    ASSERT_TRUE(std::isfinite(r.force[0]) && std::isfinite(r.force[1]) && std::isfinite(r.torque));
  }
}

TEST(Regularization, FiniteForEveryFiniteInput) {
  const contact_law<> law;
  const double big = 1e300, tiny = 1e-300;
  for (double vx : {0.0, tiny, 1.0, big, -big})
    for (double w : {0.0, tiny, -1.0, big})
      for (double a : {tiny, 0.05, big}) {
        const auto r = law(vec2{vx, vx / 2}, w, a, 1.0, 0.5);
        EXPECT_TRUE(std::isfinite(r.force[0]) && std::isfinite(r.force[1]) &&
                    std::isfinite(r.torque))
            << vx << " " << w << " " << a;
      }
}

TEST(ContactLaw, BadInputIsADomainError) {
  const contact_law<> law;
  EXPECT_THROW(law(vec2{1, 0}, 1.0, -0.1, 1.0, 0.5), std::domain_error);
  EXPECT_THROW(law(vec2{1, 0}, 1.0, 0.0, 1.0, 0.5), std::domain_error);  // a <= 0
  EXPECT_THROW(law(vec2{1, 0}, 1.0, 0.1, -1.0, 0.5), std::domain_error);
  EXPECT_THROW(law(vec2{1, 0}, 1.0, 0.1, 1.0, -0.5), std::domain_error);
  EXPECT_THROW(law(vec2{std::nan(""), 0}, 1.0, 0.1, 1.0, 0.5), std::domain_error);
  EXPECT_THROW(law(vec2{1, 0}, std::nan(""), 0.1, 1.0, 0.5), std::domain_error);
  EXPECT_THROW(law(vec2{1, 0}, 1.0, 0.1, std::nan(""), 0.5), std::domain_error);
  EXPECT_THROW(contact_law<>(uniform_disk<>(), -1.0), std::domain_error);
}

}  // namespace
