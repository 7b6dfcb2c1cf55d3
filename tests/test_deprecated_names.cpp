//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The names that issue 26 replaced stay for one release as deprecated
// aliases (docs/contact.md, "Results and warm starts"): code written against
// them compiles (with a deprecation warning, silenced here) and gets the
// same numbers, bit for bit, as the new names give.  `starting_ratio{ε}` is
// `curve_point{ε}`; `friction_impulse` and `spring_friction` convert from
// the laws' friction_result ({linear, angular} are its {force, torque}).

#include <gtest/gtest.h>

#include <spinslide/spinslide.hpp>

#include <array>
#include <cstddef>
#include <type_traits>

#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif

namespace {

using namespace spinslide;
using vec2 = std::array<double, 2>;

TEST(DeprecatedNames, StartingRatioIsARatioOnlyCurvePoint) {
  const hertz<> p;
  const auto old_2d = project_to_limit_set(p, 0.9, 0.4, 2.0, starting_ratio<double>{0.7});
  const auto new_2d = project_to_limit_set(p, 0.9, 0.4, 2.0, curve_point<double>{0.7});
  ASSERT_FALSE(new_2d.sticking);
  EXPECT_EQ(old_2d.force, new_2d.force);
  EXPECT_EQ(old_2d.torque, new_2d.torque);
  EXPECT_EQ(old_2d.ratio, new_2d.ratio);

  const planar_metric<double> m({{{2, 0.3, 0.1}, {0.3, 1, 0}, {0.1, 0, 0.5}}});
  const tangent_wrench<double> z{0.8, -0.5, 0.6};
  const auto old_3d = project_to_limit_set(p, z, m, starting_ratio<double>{0.7});
  const auto new_3d = project_to_limit_set(p, z, m, curve_point<double>{0.7});
  ASSERT_FALSE(new_3d.sticking);
  EXPECT_EQ(old_3d.point.force_x, new_3d.point.force_x);
  EXPECT_EQ(old_3d.point.force_y, new_3d.point.force_y);
  EXPECT_EQ(old_3d.point.torque, new_3d.point.torque);
}

TEST(DeprecatedNames, FrictionImpulseIsTheImpulseLawsResult) {
  const uniform_disk<> p;
  const planar_metric<double> w({{{1, 0, 0}, {0, 1, 0}, {0, 0, 2}}});
  const impulse_contact<double> c{patch_radius<double>{1}, normal_impulse<double>{0.01},
                                  friction_coefficient<double>{1}};
  const friction_impulse<vec2, double> old =
      impulse_friction(p, vec2{0.3, 0.1}, 0.5, w, c, starting_ratio<double>{0.6});
  const friction_result<vec2, double> now =
      impulse_friction(p, vec2{0.3, 0.1}, 0.5, w, c, curve_point<double>{0.6});
  ASSERT_FALSE(now.sticking);
  EXPECT_EQ(old.linear[0], now.force[0]);
  EXPECT_EQ(old.linear[1], now.force[1]);
  EXPECT_EQ(old.angular, now.torque);
  EXPECT_EQ(old.sticking, now.sticking);
  EXPECT_EQ(old.ratio, now.ratio);
}

TEST(DeprecatedNames, SpringFrictionIsTheSpringLawsResult) {
  const auto k = mindlin_springs(tangential_stiffness<double>{2e4}, patch_radius<double>{0.01});
  const force_contact<double> c{patch_radius<double>{0.01}, normal_force<double>{10},
                                friction_coefficient<double>{0.3}};
  spring_history<vec2, double> h1{{0, 0}, 0, {}}, h2 = h1;
  const spring_friction<vec2, double> old =
      spring_history_friction(hertz<>(), h1, vec2{1e-3, 0}, 0.5, k, c);
  const friction_result<vec2, double> now =
      spring_history_friction(hertz<>(), h2, vec2{1e-3, 0}, 0.5, k, c);
  ASSERT_FALSE(now.sticking);
  EXPECT_EQ(old.force[0], now.force[0]);
  EXPECT_EQ(old.torque, now.torque);
  EXPECT_EQ(old.ratio, now.ratio);
  EXPECT_EQ(h1.curve.ratio, h2.curve.ratio);
}

}  // namespace

// issue 27 moved pair_friction and its settings from spinslide::engines into
// the core: the old names are the same types.
static_assert(std::is_same<engines::pair_friction, pair_friction>::value, "");
static_assert(std::is_same<engines::hertz_radius, hertz_radius>::value, "");
static_assert(std::is_same<engines::patch_profile, patch_profile>::value, "");

namespace {

// Issue 28: terminal_ratios(profile, γ), the flow's zeros, is now
// ratio_flow_zeros (it read as a plural of terminal_ratio(), the paper's ε₀).
TEST(DeprecatedNames, TerminalRatiosIsRatioFlowZeros) {
  const spinslide::hertz<> p;
  for (const double gamma : {0.3, 0.45}) {
    const auto old_zeros = spinslide::terminal_ratios(p, gamma);
    const auto new_zeros = spinslide::ratio_flow_zeros(p, gamma);
    ASSERT_EQ(old_zeros.size(), new_zeros.size());
    ASSERT_FALSE(new_zeros.empty());
    for (std::size_t i = 0; i < new_zeros.size(); ++i) {
      EXPECT_EQ(old_zeros[i].ratio, new_zeros[i].ratio);
      EXPECT_EQ(old_zeros[i].attracting, new_zeros[i].attracting);
    }
  }
}

// Issue 28: simulate_throw_si's six numbers in a row are named inputs now
// (throw_inputs.hpp); the old overload gives the same numbers.
TEST(DeprecatedNames, SimulateThrowSiWithSixNumbersIsTheNamedOverload) {
  using namespace spinslide;
  const annulus<> cd(0.125);
  const auto old_throw = simulate_throw_si(cd, 0.06, 0.2, 9.81, 0.5078125, 0.8, 20.0);
  const auto new_throw =
      simulate_throw_si(cd, disk_radius{0.06}, friction_coefficient{0.2}, gravity{9.81}, 0.5078125,
                        initial_speed{0.8}, initial_spin{20.0});
  EXPECT_EQ(old_throw.time, new_throw.time);
  EXPECT_EQ(old_throw.distance, new_throw.distance);
  EXPECT_EQ(old_throw.angle, new_throw.angle);
  EXPECT_EQ(old_throw.terminal.ratio, new_throw.terminal.ratio);
}

}  // namespace

namespace {

// Issue 28: profiles are built one way, by class template argument
// deduction; make_weighted_sum and make_radial_profile build the same.
TEST(DeprecatedNames, MakeHelpersBuildWhatDeductionBuilds) {
  using namespace spinslide;
  const auto old_sum = make_weighted_sum<double>({0.6, 0.4}, uniform_disk<>(), ring<>());
  const auto new_sum = weighted_sum({0.6, 0.4}, uniform_disk<>(), ring<>());
  static_assert(std::is_same<decltype(old_sum), decltype(new_sum)>::value);
  auto p = [](double r) { return 1 - r * r; };
  const auto old_radial = make_radial_profile<double>(p, 0.125);
  const auto new_radial = radial_profile(p, 0.125);
  static_assert(std::is_same<decltype(old_radial), decltype(new_radial)>::value);
  static_assert(std::is_same<decltype(radial_profile(p, 0))::value_type, double>::value);
  static_assert(std::is_same<decltype(radial_profile(p, 0.5f))::value_type, float>::value);
  for (const double eps : {0.1, 1.0, 7.0}) {
    EXPECT_EQ(old_sum.force(eps), new_sum.force(eps));
    EXPECT_EQ(old_radial.torque(eps), new_radial.torque(eps));
  }
}

}  // namespace

namespace {

// Issue 28: the 3-D contact law takes its normal as contact_normal{n}; the
// old call with three plain vectors in a row gives the same friction.
TEST(DeprecatedNames, ContactLawWithAPlainNormalIsTheNamedOverload) {
  using namespace spinslide;
  using vec3 = std::array<double, 3>;
  const contact_law<hertz<>> law(hertz<>(), velocity_scale<double>{1e-3});
  const force_contact<double> c{patch_radius<double>{0.01}, normal_force<double>{10.0},
                                friction_coefficient<double>{0.3}};
  const vec3 n{0.6, 0.0, 0.8};
  for (const double v : {0.0, 1e-4, 0.05, 2.0}) {
    const vec3 vel{v, 0.2 * v, -0.1}, w{0.0, 1.0, 2.0};
    const auto old_call = law(vel, w, n, c);
    const auto new_call = law(vel, w, contact_normal{n}, c);
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(old_call.force[i], new_call.force[i]);
      EXPECT_EQ(old_call.torque[i], new_call.torque[i]);
    }
  }
}

}  // namespace
