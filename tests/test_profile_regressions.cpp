//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Regression tests of the pressure profiles (profile.hpp): what the fuzz
// harnesses found in them (below).
#include <gtest/gtest.h>

#include <spinslide/values/profile.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/policies/policy.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace {

using namespace spinslide;
const double pi = boost::math::constants::pi<double>();

// ---------------------------------------------------------------- regressions
//
// Each failure a fuzz harness (fuzz/) found in the profiles, with the input it
// reported and an independent expectation; docs/reliability.md lists them.

constexpr double max_d = std::numeric_limits<double>::max();
constexpr double double_eps = std::numeric_limits<double>::epsilon();

// fuzz_profiles: Boost's R_F and R_D return NaN for a subnormal argument, met
// by a quadrature node within ~1e-308 of r = ε (annulus<float>(1 − 2⁻²⁴) at
// ε = 1); guards the ring kernel's y → 0 limit.  A ring at r = ε = 1 is the
// kernel at c = 1, where (R1) and (R2) give 𝓕 = 𝓣 = 2E(1)/π = 2/π.
TEST(RingKernel, RegressionSubnormalDistanceToTheSplitGivesTheLimit) {
  using P = detail::kernel_policy<boost::math::policies::policy<>>;
  for (const double d : {5e-324, 1e-310, 1e-300}) {
    const auto k = detail::ring_kernel(1.0 - d, 1.0, d, P());
    EXPECT_NEAR(k.force, 2 / pi, 1e-14) << d;  // Boost R_D: ~12 ulp at y = 2e-300
    EXPECT_NEAR(k.torque, 2 / pi, 1e-14) << d;
  }
  const float b = std::nextafter(1.0f, 0.0f);
  const auto ft = annulus<float>(b).force_torque(1.0f);
  EXPECT_NEAR(ft.force, float(2 / pi), 1e-6f);
  EXPECT_NEAR(ft.torque, float(2 / pi), 1e-6f);
}

// fuzz_profiles: p = DBL_MAX overflowed tanh_sinh's sums (evaluation_error);
// guards dividing a custom pressure by its value mid-support.  p and λp are
// the same profile: the uniform disk's moments (∫₀¹ 2r^(k+1) dr) and 𝓕, 𝓣.
TEST(RadialProfile, RegressionPressureOfAnySizeIsTheSameProfile) {
  for (const double c : {max_d, 1.0, 1e-300}) {
    const auto p = radial_profile([c](double) { return c; });
    EXPECT_NEAR(p.mean_radius(), 2.0 / 3, 1e-14) << c;
    EXPECT_NEAR(p.mean_inverse_radius(), 2.0, 1e-13) << c;
    EXPECT_NEAR(p.mean_square_radius(), 0.5, 1e-14) << c;
    EXPECT_NEAR(p.force(0.7), force(0.7), 1e-13) << c;
    EXPECT_NEAR(p.torque(0.7), torque(0.7), 1e-13) << c;
  }
  // A total that overflows even so is the documented domain error.
  EXPECT_THROW(radial_profile([](double r) { return r < 0.5 ? max_d : 1e-300; }),
               std::domain_error);
}

// fuzz_profiles: a pressure of subnormal values (c/√(1 − r), c = 5e-324, on
// [0.696, 1]) is a staircase of multiples of 5e-324, and its moments missed
// by 1 %: ⟨r⟩² > ⟨r²⟩, which no load allows (Jensen).  Guards refusing a load
// per unit width below the smallest normal number, and keeping the same
// pressure scaled into the normal range: its moments are the exact ones,
// ∫ r^n/√(1 − r) dr over [b, 1] = 2∫ (1 − u²)^n du over [0, √(1 − b)]
// (u = √(1 − r)).
TEST(RadialProfile, RegressionSubnormalPressureIsRefused) {
  const double b = 0.696;
  const auto rim = [](double scale) {
    return [scale](double, double one_minus_r) { return scale / std::sqrt(one_minus_r); };
  };
  for (const double c : {5e-324, 1e-320, 1e-310}) {
    try {
      radial_profile(rim(c), b);
      ADD_FAILURE() << c;
    } catch (const std::domain_error& e) {
      EXPECT_NE(std::string(e.what()).find("subnormal"), std::string::npos) << e.what();
    }
  }
  const double w = std::sqrt(1 - b);  // m_n = ∫ r^n/√(1 − r) dr, by the binomial theorem
  const double m1 = 2 * (w - w * w * w / 3);
  const double m2 = 2 * (w - 2 * std::pow(w, 3) / 3 + std::pow(w, 5) / 5);
  const double m3 = 2 * (w - std::pow(w, 3) + 3 * std::pow(w, 5) / 5 - std::pow(w, 7) / 7);
  const double m0 = 2 * w;  // ∫ 1/√(1 − r) dr, ⟨1/r⟩'s numerator
  for (const double c : {3e-308, 1.0}) {
    const auto p = radial_profile(rim(c), b);
    EXPECT_NEAR(p.mean_radius(), m2 / m1, 1e-14) << c;
    EXPECT_NEAR(p.mean_square_radius(), m3 / m1, 1e-14) << c;
    EXPECT_NEAR(p.mean_inverse_radius(), m0 / m1, 1e-14) << c;
  }
}

// fuzz_profiles: on the support [1 − 2⁻⁵³, 1], whose middle rounds to 1, the
// pressure was asked at 1 − r = 0 (where it is infinite); guards asking it at
// 1 − r = half the width.  Every moment of a load on [inner, 1] lies between
// the values of r^k at the two ends.
TEST(RadialProfile, RegressionSupportThinnerThanItsMidpoint) {
  const double inner = std::nextafter(1.0, 0.0);
  const auto thin =
      radial_profile([](double, double one_minus_r) { return 1 / std::sqrt(one_minus_r); }, inner);
  EXPECT_NEAR(thin.mean_radius(), 1.0, 1e-15);
  EXPECT_GE(thin.mean_radius(), inner);
  EXPECT_LE(thin.mean_radius(), 1.0);
  EXPECT_GE(thin.mean_inverse_radius(), 1.0);
  EXPECT_LE(thin.mean_inverse_radius(), 1 / inner);
  EXPECT_GE(thin.mean_square_radius(), inner * inner);
  EXPECT_LE(thin.mean_square_radius(), 1.0);
}

// fuzz_profiles: weights whose sum overflows were normalised to 0; guards
// dividing by the largest weight first.  Equal weights: the mean of the disk's
// and the ring's moments (2/3, 2, 1/2 and 1, 1, 1) and of their 𝓕, 𝓣.
TEST(WeightedSum, RegressionWeightsWhoseSumOverflows) {
  const auto w = weighted_sum({max_d, max_d}, uniform_disk<double>(), ring<double>());
  EXPECT_DOUBLE_EQ(w.weights()[0], 0.5);
  EXPECT_DOUBLE_EQ(w.weights()[1], 0.5);
  EXPECT_DOUBLE_EQ(w.mean_radius(), (2.0 / 3 + 1) / 2);
  EXPECT_DOUBLE_EQ(w.mean_inverse_radius(), (2.0 + 1) / 2);
  EXPECT_DOUBLE_EQ(w.mean_square_radius(), (0.5 + 1) / 2);
  EXPECT_DOUBLE_EQ(w.force(0.7), (force(0.7) + ring<double>().force(0.7)) / 2);
  EXPECT_DOUBLE_EQ(w.torque(0.7), (torque(0.7) + ring<double>().torque(0.7)) / 2);
}

// fuzz_contact (the campaign of 2026-11-23): 𝓕 of a ring-quadrature annulus
// and of a weighted sum rounded to 1 + 2⁻⁵² at a large ratio (and μN𝓕
// overflowed in the contact law: ContactLaw.RegressionForceOfAProfileRoundedAboveOne);
// guards the clamp 𝓕 ≤ 1 after general().  1 − 𝓕 ≈ ⟨r²⟩/(4ε²) ((R1): f_F =
// (2/π)E(r/ε) ≈ 1 − r²/(4ε²)) is far below an ulp at ε = 2e87 and 5e31: 𝓕 is
// 1 to rounding, within the 2 ulp (1 − 2⁻⁵²) at which the ring quadrature
// levels off.
TEST(Annulus, RegressionForceRoundedAboveOneAtLargeRatios) {
  const annulus<double> ann(0.635197164334527664131);
  const auto sum =
      weighted_sum({0.173717571710168772192, 541249.376203841762617},
                   scaled<uniform_disk<double>>(uniform_disk<double>(), 0.937500000000852762305),
                   ring<double>());
  for (const double f : {ann.force(std::sqrt(2.0) / 6.93531866257113469774e-88),
                         sum.force(3.61069398448143300918e+307 / 6.98211634151446680426e+275)}) {
    EXPECT_LE(f, 1.0);
    EXPECT_GE(f, 1 - double_eps);
  }
}

// Found by fuzz_profiles (CI run, sanitize preset): scaled(hertz) at radius
// a = 2.7e-162 gave ⟨r²⟩ = a²⟨r²⟩_P = 0 (a² underflowed), so ⟨r⟩² > ⟨r²⟩.
// Guards the shrink radius's domain [√min_value, 1]: at its lower end the
// moments keep their relative accuracy (exact powers of two times ⟨r^k⟩_P).
TEST(Scaled, RegressionRadiusWhoseSquareUnderflowsIsADomainError) {
  EXPECT_THROW((scaled<hertz<double>>(hertz<double>(), 2.66952910647346144157e-162)),
               std::domain_error);
  const double a = std::sqrt(std::numeric_limits<double>::min());  // 2^-511, exact
  const hertz<double> h;
  const scaled<hertz<double>> s(h, a);
  EXPECT_EQ(s.mean_radius(), std::ldexp(h.mean_radius(), -511));
  EXPECT_EQ(s.mean_square_radius(), std::ldexp(h.mean_square_radius(), -1022));
  EXPECT_EQ(s.mean_inverse_radius(), std::ldexp(h.mean_inverse_radius(), 511));
  EXPECT_LE(s.mean_radius() * s.mean_radius(), s.mean_square_radius());
}

}  // namespace
