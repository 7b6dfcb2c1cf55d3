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
