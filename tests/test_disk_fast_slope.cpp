//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The uniform disk's fused step for the limit-set projections (issue 41;
// values/detail/disk_fast.hpp, disk_fast_slope; force_slope.hpp,
// fused_value_slope): 𝓕 and 𝓣 bit for bit force_torque's, 𝓕′ and 𝓕″
// against 50-digit references from the closed form of 𝓕′ in K and E
// (docs/theory.md §2; Boost's ellint_1 and ellint_2 in cpp_bin_float_50, an
// algorithm independent of the tables), 𝓕″ as its central difference at
// 50 digits (step 1e-20 relative: its error near 1e-36).
#include <gtest/gtest.h>

#include <spinslide/values/profile.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

namespace {

using mp = boost::multiprecision::cpp_bin_float_50;

// 𝓕′(ε) for 0 < ε < ∞ (docs/theory.md §2).
mp reference_slope(const mp& eps) {
  using boost::math::ellint_1;
  using boost::math::ellint_2;
  using boost::math::constants::pi;
  if (eps <= 1) {
    const mp m = eps * eps;
    return 4 * ((1 - m) * ellint_1(eps) - (1 - 2 * m) * ellint_2(eps)) / (3 * pi<mp>() * m);
  }
  const mp k = 1 / eps, m = k * k;
  return 4 * ((2 - m) * ellint_2(k) - 2 * (1 - m) * ellint_1(k)) / (3 * pi<mp>() * k);
}
// 𝓕″(ε), the central difference of 𝓕′ (ε ≠ 1 by more than the step).
mp reference_curvature(const mp& eps) {
  const mp h = eps * mp("1e-20");
  return (reference_slope(eps + h) - reference_slope(eps - h)) / (2 * h);
}

// Log-uniform ratios over [1e-6, 1e6], and ratios clustered at ε = 1 from
// both sides, 1 ± 2^-j·u for j up to the type's digits.
template <class Real>
std::vector<Real> ratios() {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> decades(-6, 6), unit(0.5, 1);
  std::vector<Real> v;
  v.reserve(600 + 12 * std::numeric_limits<Real>::digits);
  for (int i = 0; i < 600; ++i) v.push_back(static_cast<Real>(std::pow(10.0, decades(rng))));
  for (int j = 1; j < std::numeric_limits<Real>::digits; ++j)
    for (int side = -1; side <= 1; side += 2)
      for (int i = 0; i < 6; ++i)
        v.push_back(static_cast<Real>(1 + side * std::ldexp(unit(rng), -j)));
  return v;
}

template <class Real>
auto fused(Real eps) {
  using disk = spinslide::uniform_disk<Real>;
  return spinslide::detail::fused_value_slope<disk>::template at<true>(disk(), eps);
}

template <class Real>
void values_are_force_torques() {
  const spinslide::uniform_disk<Real> disk;
  std::vector<Real> all = ratios<Real>();
  for (const Real e : {Real(1), std::numeric_limits<Real>::min(),
                       std::numeric_limits<Real>::denorm_min(), std::numeric_limits<Real>::max()})
    all.push_back(e);
  for (const Real e : all) {
    const auto f = fused(e);
    const auto ft = disk.force_torque(e);
    EXPECT_EQ(f.value.force, ft.force) << e;  // (exact: no NaN, no −0 here)
    EXPECT_EQ(f.value.torque, ft.torque) << e;
  }
}

struct bounds {
  double slope_far, slope_at_one, curvature;
};

// The largest errors: 𝓕′ relative, away from ε = 1 (|ε − 1| ≥ 1e-10) and
// near it; 𝓕″ relative to |𝓕″| + 𝓕′/ε (𝓕″ crosses 0) where it is given,
// and NaN exactly where y = 1 − min(ε, 1/ε)² < 2^-12.
struct errors {
  double far = 0, near = 0, curvature = 0;
};
// Adds the errors at the ratio e to `worst`.
template <class Real>
void add_errors(Real e, errors& worst) {
  const auto f = fused(e);
  const mp x(e);
  const double s = static_cast<double>(reference_slope(x));
  const double rel = std::fabs(static_cast<double>(f.slope) - s) / s;
  double& slope = std::fabs(double(e) - 1) >= 1e-10 ? worst.far : worst.near;
  slope = std::max(slope, rel);
  const double k = std::min(double(e), 1 / double(e)), y = (1 - k) * (1 + k);
  if (y < 1.0 / 4096) {
    EXPECT_TRUE(std::isnan(double(f.curvature))) << e;
    return;
  }
  const double c = static_cast<double>(reference_curvature(x));
  worst.curvature = std::max(worst.curvature,
                             std::fabs(double(f.curvature) - c) / (std::fabs(c) + s / double(e)));
}

template <class Real>
void derivatives_against_the_closed_form(bounds b) {
  errors worst;
  for (const Real e : ratios<Real>()) add_errors(e, worst);
  const double far = worst.far, near = worst.near, curvature = worst.curvature;
  EXPECT_LE(far, b.slope_far);
  EXPECT_LE(near, b.slope_at_one);
  EXPECT_LE(curvature, b.curvature);
  std::printf("slope %.3g (|eps - 1| >= 1e-10), %.3g (nearer); curvature %.3g\n", far, near,
              curvature);
}

template <class Real>
void exact_at_the_ends() {
  // 𝓕′(0) = 1 and 𝓕″(0) = 0; 𝓕′ = 𝓕″ = 0 at ∞ (the projection never
  // asks at 0 or ∞, but the table's ends give them exactly).
  const auto zero = spinslide::detail::disk_fast_slope<Real, true>(Real(0));
  EXPECT_EQ(zero.slope, 1.0);
  EXPECT_EQ(zero.curvature, 0.0);
  const auto end =
      spinslide::detail::disk_fast_slope<Real, true>(std::numeric_limits<Real>::infinity());
  EXPECT_EQ(end.slope, 0.0);
  EXPECT_EQ(end.curvature, 0.0);
  // 𝓕′(1) = 4/(3π), within the bounds above.
  const auto one = fused(Real(1));
  const double exact = 4 / (3 * boost::math::constants::pi<double>());
  EXPECT_NEAR(double(one.slope), exact, (sizeof(Real) == 4 ? 5e-6 : 1e-11) * exact);
}

}  // namespace

TEST(DiskFastSlope, ValuesAreForceTorqueBitForBitDouble) { values_are_force_torques<double>(); }
TEST(DiskFastSlope, ValuesAreForceTorqueBitForBitFloat) { values_are_force_torques<float>(); }
TEST(DiskFastSlope, DerivativesAgainstTheClosedFormDouble) {
  // Measured: 5.0e-13, 4.2e-12, 2.5e-7.
  derivatives_against_the_closed_form<double>({1e-12, 1e-11, 1e-6});
}
TEST(DiskFastSlope, DerivativesAgainstTheClosedFormFloat) {
  // Measured: 1.4e-6 (the float table is fitted to float's precision), 0
  // (no float ratio is that near 1 but 1 itself), 7.0e-5.
  derivatives_against_the_closed_form<float>({5e-6, 5e-6, 3e-4});
}
TEST(DiskFastSlope, ExactAtTheEnds) {
  exact_at_the_ends<double>();
  exact_at_the_ends<float>();
}
