//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The engine models of approximations.hpp: their defining properties, and
// what they imply for the end of a throw.
#include <gtest/gtest.h>

#include <spinslide/motion/dynamics.hpp>
#include <spinslide/motion/tabulated_throw.hpp>
#include <spinslide/motion/terminal.hpp>
#include <spinslide/motion/terminal_state.hpp>
#include <spinslide/values/approximations.hpp>
#include <spinslide/values/coupling.hpp>
#include <spinslide/values/profile.hpp>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cmath>
#include <limits>
#include <utility>

namespace {

using namespace spinslide;

TEST(UncoupledCaps, ConstantWhileMovingAndStopsAreNotSimultaneous) {
  const uncoupled_caps<> caps(2.0 / 3);
  for (double e : {1e-9, 0.3, 5.0, 1e9}) {
    EXPECT_EQ(caps.force(e), 1.0);
    EXPECT_EQ(caps.torque(e), 2.0 / 3);
  }
  EXPECT_EQ(caps.force(0.0), 0.0);
  EXPECT_EQ(caps.torque(INFINITY), 0.0);
  // Spin (γω0/⟨r⟩ = 0.75) stops before sliding (v0 = 1): ε runs away.
  EXPECT_THROW(terminal_motion(caps, 0.5), std::domain_error);  // both ends attract
  EXPECT_EQ(terminal_motion(caps, 0.5, 1.0).regime, terminal_regime::pure_sliding);
  EXPECT_NEAR(stop_time(caps, 0.5, 1.0, 1.0), 1.0, 1e-12);
  EXPECT_THROW(uncoupled_caps<>(0.0), std::domain_error);
}

TEST(EllipticLimitSurface, OnTheEllipseWithTheMaximumDissipationNormal) {
  const double tau = 2.0 / 3;
  const elliptic_limit_surface<> el(tau);
  for (double e : {1e-6, 0.1, 0.653, 1.0, 7.0, 1e6}) {
    const auto ft = el.force_torque(e);
    EXPECT_NEAR(ft.force * ft.force + ft.torque * ft.torque / (tau * tau), 1.0, 1e-15) << e;
    // The curve's normal (𝓕, 𝓣/τ²) is along (ε, 1).
    EXPECT_NEAR(ft.force / (ft.torque / (tau * tau)), e, 1e-12 * e) << e;
  }
  // f(ε) = ε(1 − γ/τ²): linear, no finite ε₀.
  for (double e : {0.1, 1.0, 10.0})
    EXPECT_NEAR(ratio_flow(el, e, 0.5), e * (1 - 0.5 / (tau * tau)), 1e-14 * e);
  EXPECT_EQ(terminal_motion(el, 0.5).regime, terminal_regime::pure_spinning);
  EXPECT_EQ(terminal_motion(el, 0.3).regime, terminal_regime::pure_sliding);
}

TEST(PadeApproximation, HasTheExactLimitsAndWindow) {
  const uniform_disk<> u;
  const auto p = pade_approximation<>::matching(u);
  // The limits (L) with the disk's moments ⟨r⟩ = 2/3, ⟨1/r⟩ = 2, ⟨r²⟩ = 1/2
  // (∫₀¹ 2r^(k+1) dr): 𝓕/ε → 1, 𝓣(0) = 2/3, ε𝓣 → 1/4.
  EXPECT_NEAR(p.force(1e-9) / 1e-9, 1.0, 1e-8);
  EXPECT_NEAR(p.torque(1e-9), 2.0 / 3, 1e-8);
  EXPECT_NEAR(1e9 * p.torque(1e9), 0.25, 1e-8);
  EXPECT_NEAR(p.force(1e9), 1.0, 1e-8);
  const auto wp = terminal_window(p), wu = terminal_window(u);
  EXPECT_DOUBLE_EQ(wp.lower, wu.lower);
  EXPECT_DOUBLE_EQ(wp.upper, wu.upper);
  // Its ε₀ for γ = 1/2 solves 2(1 + ε) = 3/2 + 4ε: exactly 1/4.
  EXPECT_NEAR(terminal_motion(p, 0.5).ratio, 0.25, 1e-15);
}

// ---------------------------------------------------------------- regressions
//
// Each failure a fuzz harness (fuzz/) found in the engine models, with the
// input it reported; docs/reliability.md lists them.

constexpr double max_d = std::numeric_limits<double>::max();
constexpr double min_d = std::numeric_limits<double>::min();

// fuzz_profiles: τ² overflowed in the elliptic cone (𝓣 = ∞ for τ = DBL_MAX);
// guards computing τ(τ/h).  On the ellipse with normal along (ε, 1),
// 𝓣 = τ²/√(ε² + τ²) = τ to rounding for ε ≪ τ, and 𝓕 = ε/√(ε² + τ²) =
// 1.2e-616 underflows to 0.
TEST(EllipticLimitSurface, RegressionLargestTau) {
  const auto e = elliptic_limit_surface<double>(max_d).force_torque(min_d);
  EXPECT_EQ(e.torque, max_d);
  EXPECT_EQ(e.force, 0.0);
}

// The Padé form, by its definition (approximations.hpp): with x = ε⟨r⟩/⟨r²⟩
// and y = ε⟨1/r⟩/2, 𝓣 = ⟨r⟩/(1 + 2x) and 𝓕 = y/(1 + y), evaluated in
// cpp_bin_float_50, whose exponent range holds every intermediate.
std::pair<double, double> pade_reference(double r, double inv, double sq, double eps) {
  using big = boost::multiprecision::cpp_bin_float_50;
  const big x = big(eps) * r / sq, y = big(eps) * inv / 2;
  return {static_cast<double>(y / (1 + y)), static_cast<double>(big(r) / (1 + 2 * x))};
}

// fuzz_profiles: ⟨r⟩⟨r²⟩ and ε + 2/⟨1/r⟩ overflowed in the Padé form; guards
// the form written without them.  At ε = 1e-300: x = 1e-300, so 𝓣 = 1e300/(1 +
// 2e-300), and y = 5e-601, so 𝓕 = y/(1 + y) underflows to 0; at ε = 1e300,
// y = 1/2 and 𝓕 = 1/3.
TEST(PadeApproximation, RegressionExtremeMoments) {
  const pade_approximation<double> p(1e300, 1e-300, 1e300);
  const auto ft = p.force_torque(1e-300);
  EXPECT_DOUBLE_EQ(ft.torque, 1e300 / (1 + 2e-300));
  EXPECT_EQ(ft.force, 0.0);
  EXPECT_DOUBLE_EQ(p.force(1e300), 1.0 / 3);
}

// fuzz_profiles (sanitize preset, second run): at ε = DBL_MAX, 2ε overflowed
// where ⟨r⟩/⟨r²⟩ underflows to 0 (∞ · 0 = NaN torque); guards 2(ε(⟨r⟩/⟨r²⟩)).
// x = ε⟨r⟩/⟨r²⟩ = 7.6e-103, so 𝓣 = ⟨r⟩ to rounding, and y = ε⟨1/r⟩/2 ≈ 1.6e616:
// 𝓕 = 1 to rounding.
TEST(PadeApproximation, RegressionTorqueAtTheLargestRatio) {
  const pade_approximation<double> big(7.56851905622497924774e-103, max_d, max_d);
  const auto ft = big.force_torque(max_d);
  EXPECT_DOUBLE_EQ(ft.torque, 7.56851905622497924774e-103);
  EXPECT_EQ(ft.force, 1.0);
}

// fuzz_coupling (the campaign): 2ε⟨r⟩/⟨r²⟩ overflowed for ε > 7.6e288 with
// ⟨r⟩/⟨r²⟩ = 2.3e19, so 𝓣 was 0 where it is ⟨r²⟩/(2ε) = 8.3e-317 (ε𝓣 →
// ⟨r²⟩/2), and ratio_from_torque missed that target; guards the x > 1 form
// (⟨r²⟩/(2ε))/(1 + 1/(2x)).
TEST(PadeApproximation, RegressionTorqueWhereTwoXOverflows) {
  const double sq = 4.21696503428580530731e-10;
  const pade_approximation<double> steep(9887988544.66558456421, 9957489837.05406570435, sq);
  const double eps = 2.5437e306;
  EXPECT_NEAR(steep.torque(eps), sq / 2 / eps, 1e-322);
  const double target = 8.28904556439244913966e-317;
  EXPECT_NEAR(steep.torque(ratio_from_torque(steep, target)), target, 1e-322);
}

// fuzz_profiles (CI, sanitize preset): ⟨r⟩/⟨r²⟩ overflowed where ε is
// subnormal, so x = ε⟨r⟩/⟨r²⟩ was ∞ and 𝓣 = ⟨r²⟩/(2ε) = ∞ where it is ≈ ⟨r⟩
// = DBL_MAX; guards x and y as three-factor products.  Expected: the
// definition in cpp_bin_float_50 (pade_reference), to 4 ulp.
TEST(PadeApproximation, RegressionHugeMeanRadiusAtASubnormalRatio) {
  const double sub = std::numeric_limits<double>::denorm_min();
  const struct {
    double r, inv, sq, eps;
  } cases[] = {{max_d, 0.5, 0.5, sub},                              // the CI input
               {max_d, 9.13981932194904406104e+152, 0.5, 2 * sub},  // seed 2
               {max_d, max_d, min_d, 1e-300},   // x ≈ 1.8e316: 𝓣 = <r²>/(2ε)
               {min_d, min_d, max_d, max_d},    // x ≈ 2.2e-308
               {1e-300, 1e300, 1e300, 1e300}};  // y ≈ 5e599: 𝓕 = 1
  for (const auto& c : cases) {
    const pade_approximation<double> p(c.r, c.inv, c.sq);
    const auto ft = p.force_torque(c.eps);
    const auto ref = pade_reference(c.r, c.inv, c.sq, c.eps);
    EXPECT_TRUE(std::isfinite(ft.force) && std::isfinite(ft.torque)) << c.r << ' ' << c.eps;
    EXPECT_NEAR(ft.force, ref.first, 4 * std::numeric_limits<double>::epsilon() * ref.first);
    EXPECT_NEAR(ft.torque, ref.second, 4 * std::numeric_limits<double>::epsilon() * ref.second)
        << c.r << ' ' << c.sq << ' ' << c.eps;
  }
}

}  // namespace
