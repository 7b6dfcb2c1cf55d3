//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The engine models of approximations.hpp: their defining properties, and
// what they imply for the end of a throw.
#include <gtest/gtest.h>

#include <spinslide/approximations.hpp>
#include <spinslide/spinslide.hpp>

#include <cmath>

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

}  // namespace
