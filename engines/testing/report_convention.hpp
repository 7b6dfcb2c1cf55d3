//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The convention every adapter's pair_report keeps (pair_report.hpp), checked
// against what the test itself sees in the engine: a unit normal from the
// first body to the second, a friction impulse in the tangent plane that
// does no positive work on the pair's relative motion after the step (the
// law dissipates: P·v + L ω ≤ 0, with v and ω the first body's motion
// against the second's at the patch centre), a ratio that is NaN exactly
// when the pair sticks or is apart, and the forces as the impulses over the
// step.
#ifndef SPINSLIDE_TESTS_ENGINES_REPORT_CONVENTION_HPP
#define SPINSLIDE_TESTS_ENGINES_REPORT_CONVENTION_HPP

#include <gtest/gtest.h>
#include <spinslide/contact/pair_report.hpp>

#include <array>
#include <cmath>

namespace report_convention {

using vec3 = std::array<double, 3>;

inline double dot(const vec3& a, const vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double norm(const vec3& a) { return std::sqrt(dot(a, a)); }

/// A pair apart: no ratio, no impulse.
inline void expect_apart(const spinslide::pair_report& r) {
  EXPECT_TRUE(std::isnan(r.ratio));
  EXPECT_EQ(norm(r.friction_impulse), 0.0);
}

/// A touching pair's numbers: a step, a unit normal, a normal impulse, the
/// forces as the impulses over the step.
inline void expect_units(const spinslide::pair_report& r) {
  ASSERT_GT(r.step, 0.0);
  EXPECT_NEAR(norm(r.normal), 1.0, 1e-12);
  EXPECT_GT(r.normal_impulse, 0.0);
  EXPECT_EQ(r.normal_force(), r.normal_impulse / r.step);
  EXPECT_EQ(r.friction_torque(), r.spin_impulse / r.step);
}

/// A touching pair's friction: in the tangent plane, on a patch of radius
/// ≥ 0, the ratio NaN exactly when sticking and never negative.
inline void expect_friction(const spinslide::pair_report& r) {
  EXPECT_GE(r.patch_radius, 0.0);
  EXPECT_LE(std::fabs(dot(r.friction_impulse, r.normal)),
            1e-12 * norm(r.friction_impulse) + 1e-300);
  EXPECT_EQ(r.sticking, std::isnan(r.ratio));
  EXPECT_FALSE(r.ratio < 0);
}

/// The friction does no positive work on the pair's motion after the step,
/// and, while the pair slips, clearly negative work (it is on its limit set,
/// against the motion, not beside it).
inline void expect_dissipative(const spinslide::pair_report& r, const vec3& slip,
                               const vec3& spin) {
  const double spin_n = dot(spin, r.normal);
  const double power = dot(r.friction_impulse, slip) + r.spin_impulse * spin_n;
  const double scale = norm(r.friction_impulse) * norm(slip) + std::fabs(r.spin_impulse * spin_n);
  EXPECT_LE(power, 1e-6 * scale + 1e-15) << "friction did positive work on the pair";
  if (!r.sticking && scale > 0) {
    EXPECT_LT(power, -0.5 * scale * 1e-3);
  }
}

/// Checks `r` against the convention; `slip` and `spin` are the first body's
/// velocity and angular velocity against the second's after the step (the
/// velocity at the patch centre).
inline void expect_kept(const spinslide::pair_report& r, const vec3& slip, const vec3& spin) {
  if (!r.touching()) {
    expect_apart(r);
    return;
  }
  expect_units(r);
  expect_friction(r);
  expect_dissipative(r, slip, spin);
}

inline vec3 negated(const vec3& v) { return {-v[0], -v[1], -v[2]}; }

/// True if `ba`, the report asked the other way round, is the same step as
/// `ab`: the same numbers, the normal and the friction impulse reversed.
inline bool reversed_equal(const spinslide::pair_report& ab, const spinslide::pair_report& ba) {
  return ab.contacts == ba.contacts && ab.normal_impulse == ba.normal_impulse &&
         ab.spin_impulse == ba.spin_impulse && ab.sticking == ba.sticking &&
         ab.centre == ba.centre && ab.normal == negated(ba.normal) &&
         ab.friction_impulse == negated(ba.friction_impulse);
}

}  // namespace report_convention

#endif  // SPINSLIDE_TESTS_ENGINES_REPORT_CONVENTION_HPP
