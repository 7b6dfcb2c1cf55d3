//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The spring-history law (spring_friction.hpp), against independent results:
// under steady slip it must give the Contensou law, μN(𝓕(ε), a𝓣(ε)) at the
// slip's own ratio, from the profile's force_torque (itself held to 50-digit
// quadrature references); below the limit the springs are Hooke's law
// exactly; after a slip the springs hold the capped force.

#include <gtest/gtest.h>

#include <spinslide/contact/spring_friction.hpp>
#include <spinslide/values/profile.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace {

using namespace spinslide;
using vec2 = std::array<double, 2>;

force_contact<double> contact(double radius, double normal, double mu) {
  return {patch_radius<double>{radius}, normal_force<double>{normal},
          friction_coefficient<double>{mu}};
}

struct steady {
  vec2 force;
  double torque;
  bool sticking;
};

// Constant increments (ε a Δφ along the direction θ, and Δφ) until the
// springs have slipped for a long time: the last step's friction.
template <class P>
steady steady_slip(const P& p, double eps, const spring_stiffness<double>& k, double theta) {
  const double a = 0.01, dphi = 1e-4;
  const vec2 dxi{eps * a * dphi * std::cos(theta), eps * a * dphi * std::sin(theta)};
  spring_history<vec2, double> h{{0, 0}, 0, {}};
  friction_result<vec2, double> r{};
  for (int k_step = 0; k_step < 3000; ++k_step)
    r = spring_history_friction(p, h, dxi, dphi, k, contact(a, 10, 0.3));
  return {r.force, r.torque, r.sticking};
}

template <class P>
void expect_contensou_under_steady_slip(const P& p, const spring_stiffness<double>& k) {
  const double a = 0.01, load = 0.3 * 10;
  for (double eps : {0.05, 0.3, 0.653, 1.0, 3.0, 20.0}) {
    const double theta = 0.7;
    const steady s = steady_slip(p, eps, k, theta);
    ASSERT_FALSE(s.sticking) << eps;
    const auto ft = p.force_torque(eps);
    EXPECT_NEAR(s.force[0], -load * ft.force * std::cos(theta), 1e-12 * load) << eps;
    EXPECT_NEAR(s.force[1], -load * ft.force * std::sin(theta), 1e-12 * load) << eps;
    EXPECT_NEAR(s.torque, -load * a * ft.torque, 1e-12 * load * a) << eps;
  }
}

TEST(SpringFriction, SteadySlipIsTheContensouLaw) {
  const double a = 0.01;
  const auto mindlin = mindlin_springs(tangential_stiffness<double>{1e5}, patch_radius<double>{a});
  const spring_stiffness<double> stiff_twist{tangential_stiffness<double>{1e5},
                                             twisting_stiffness<double>{1e5 * a * a * 10}};
  expect_contensou_under_steady_slip(uniform_disk<>(), mindlin);
  expect_contensou_under_steady_slip(uniform_disk<>(), stiff_twist);
  expect_contensou_under_steady_slip(hertz<>(), mindlin);
  expect_contensou_under_steady_slip(hertz<>(), stiff_twist);
}

// Issue 17's figures for a Hertz contact slipping steadily at ε = 0.653: the
// exact point is (𝓕, 𝓣)(0.653) = (0.687, 0.378), where a prototype's radial
// cap of the trial state gave (0.578, 0.442).
TEST(SpringFriction, MatchesTheIssueFiguresForHertz) {
  const auto k = mindlin_springs(tangential_stiffness<double>{1e5}, patch_radius<double>{0.01});
  const steady s = steady_slip(hertz<>(), 0.653, k, 0);
  EXPECT_NEAR(-s.force[0] / 3, 0.687, 5e-4);
  EXPECT_NEAR(-s.torque / (3 * 0.01), 0.378, 5e-4);
}

TEST(SpringFriction, BelowTheLimitTheSpringsAreHookesLaw) {
  const auto k = mindlin_springs(tangential_stiffness<double>{2e4}, patch_radius<double>{0.01});
  spring_history<vec2, double> h{{0, 0}, 0, {}};
  const vec2 dxi{1e-6, -2e-6};
  for (int step = 1; step <= 10; ++step) {
    const auto r = spring_history_friction(hertz<>(), h, dxi, 1e-3, k, contact(0.01, 10, 0.3));
    ASSERT_TRUE(r.sticking);
    EXPECT_DOUBLE_EQ(r.force[0], -2e4 * 1e-6 * step);
    EXPECT_DOUBLE_EQ(r.force[1], 2e4 * 2e-6 * step);
    EXPECT_DOUBLE_EQ(r.torque, -k.twisting.value * 1e-3 * step);
    EXPECT_DOUBLE_EQ(h.displacement[0], 1e-6 * step);
  }
}

TEST(SpringFriction, ASlipRewritesTheSprings) {
  const auto k = mindlin_springs(tangential_stiffness<double>{2e4}, patch_radius<double>{0.01});
  spring_history<vec2, double> h{{0, 0}, 0, {}};
  const auto r =
      spring_history_friction(hertz<>(), h, vec2{1e-3, 0}, 0.5, k, contact(0.01, 10, 0.3));
  ASSERT_FALSE(r.sticking);
  EXPECT_NEAR(h.displacement[0], -r.force[0] / 2e4, 1e-15);
  EXPECT_EQ(h.displacement[1], 0);
  EXPECT_NEAR(h.twist, -r.torque / k.twisting.value, 1e-15);
  EXPECT_EQ(h.curve.ratio, r.ratio);
  const auto ft = hertz<>().force_torque(r.ratio);
  EXPECT_NEAR(-r.force[0], 3 * ft.force, 1e-14);
  EXPECT_NEAR(-r.torque, 3 * 0.01 * ft.torque, 1e-16);
}

// A slip keeps where it left the curve (history.curve: the ratio, 𝓕 and 𝓣
// of the result in units of μN and μNa, 𝓕′ there); the next step starts from
// it, and ends where a start from the ratio alone ends (to rounding).
TEST(SpringFriction, ASlipKeepsItsCurvePointForTheNextStep) {
  const auto k = mindlin_springs(tangential_stiffness<double>{2e4}, patch_radius<double>{0.01});
  const hertz<> p;
  spring_history<vec2, double> h{{0, 0}, 0, {}};
  EXPECT_EQ(h.curve.ratio, 0);
  EXPECT_TRUE(std::isnan(h.curve.slope));
  auto r = spring_history_friction(p, h, vec2{1e-3, 0}, 0.5, k, contact(0.01, 10, 0.3));
  ASSERT_FALSE(r.sticking);
  EXPECT_EQ(h.curve.ratio, r.ratio);
  EXPECT_EQ(r.curve().ratio, r.ratio);
  EXPECT_EQ(r.curve().force, h.curve.force);
  EXPECT_NEAR(h.curve.force, -r.force[0] / 3, 1e-15);
  EXPECT_NEAR(h.curve.torque, -r.torque / (3 * 0.01), 1e-15);
  EXPECT_NEAR(h.curve.slope / p.force_derivative(h.curve.ratio), 1, 1e-9);
  int slips = 0;
  for (int step = 0; step < 20; ++step) {
    // the next step, from the kept point and from the ratio alone
    auto by_ratio = h;
    by_ratio.curve = curve_point<double>{h.curve.ratio};  // the ratio alone
    const vec2 inc{2e-5 * std::cos(step), 1e-5 * std::sin(step)};
    const double twist = 0.02 * std::cos(0.3 * step);
    const auto a = spring_history_friction(p, h, inc, twist, k, contact(0.01, 10, 0.3));
    const auto b = spring_history_friction(p, by_ratio, inc, twist, k, contact(0.01, 10, 0.3));
    ASSERT_EQ(a.sticking, b.sticking) << step;
    EXPECT_NEAR(a.force[0], b.force[0], 1e-14) << step;
    EXPECT_NEAR(a.force[1], b.force[1], 1e-14) << step;
    EXPECT_NEAR(a.torque, b.torque, 1e-16) << step;
    if (!a.sticking) {
      ++slips;
      EXPECT_NEAR(a.ratio / b.ratio, 1, 1e-12) << step;
    }
  }
  EXPECT_GE(slips, 10);
}

TEST(SpringFriction, MindlinTwistingStiffness) {
  const auto k = mindlin_springs(tangential_stiffness<double>{3e4}, patch_radius<double>{0.02});
  EXPECT_DOUBLE_EQ(k.twisting.value, 3e4 * 0.02 * 0.02 / 2);
}

TEST(SpringFriction, BadInputIsADomainErrorAndLeavesTheHistory) {
  const auto k = mindlin_springs(tangential_stiffness<double>{3e4}, patch_radius<double>{0.02});
  spring_history<vec2, double> h{{1e-6, 0}, 1e-3, curve_point<double>{0.5}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(
      spring_history_friction(uniform_disk<>(), h, vec2{nan, 0}, 0.0, k, contact(0.02, 1, 0.3)),
      std::domain_error);
  const spring_stiffness<double> bad{tangential_stiffness<double>{-1},
                                     twisting_stiffness<double>{1}};
  EXPECT_THROW(
      spring_history_friction(uniform_disk<>(), h, vec2{0, 0}, 0.0, bad, contact(0.02, 1, 0.3)),
      std::domain_error);
  EXPECT_THROW(
      spring_history_friction(uniform_disk<>(), h, vec2{0, 0}, 0.0, k, contact(0.02, -1, 0.3)),
      std::domain_error);
  EXPECT_EQ(h.displacement[0], 1e-6);
  EXPECT_EQ(h.twist, 1e-3);
  EXPECT_EQ(h.curve.ratio, 0.5);
}

}  // namespace
