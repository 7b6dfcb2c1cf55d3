//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The coupling curve (coupling.hpp): the ratio from a force or a torque, and
// 𝓣 as a function of 𝓕 and back, to a few ulp; with the fuzzers' findings in
// it (docs/reliability.md).
#include <gtest/gtest.h>

#include <spinslide/values/approximations.hpp>
#include <spinslide/values/coupling.hpp>
#include <spinslide/values/profile.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/relative_difference.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace {

using namespace spinslide;
using boost::math::relative_difference;
const double pi = boost::math::constants::pi<double>();

constexpr double max_d = std::numeric_limits<double>::max();
constexpr double double_eps = std::numeric_limits<double>::epsilon();

// ---------------------------------------------------------------- coupling curve

// 𝓕(ratio_from_force(F)) = F to `ulps` over the whole range of 𝓕.
template <class P>
void expect_force_round_trips(const P& p, const char* name, double ulps) {
  for (double F : {1e-300, 1e-9, 0.01, 0.3, 0.6, 0.9, 0.999, 0.999999, 1 - 1e-12}) {
    const double e = ratio_from_force(p, F);
    EXPECT_LE(boost::math::epsilon_difference(p.force(e), F), ulps) << name << " F = " << F;
  }
}

// 𝓣(ratio_from_torque(T)) = T to `ulps` over the whole range of 𝓣, (0, ⟨r⟩).
template <class P>
void expect_torque_round_trips(const P& p, const char* name, double ulps) {
  const double top = p.mean_radius();
  for (double T : {1e-300, 1e-9, 0.01 * top, 0.3 * top, 0.9 * top, 0.999999 * top}) {
    const double e = ratio_from_torque(p, T);
    EXPECT_LE(boost::math::epsilon_difference(p.torque(e), T), ulps) << name << " T = " << T;
  }
}

template <class P>
void expect_round_trips(const P& p, const char* name, double ulps) {
  expect_force_round_trips(p, name, ulps);
  expect_torque_round_trips(p, name, ulps);
  const double top = p.mean_radius();
  EXPECT_EQ(ratio_from_force(p, 0.0), 0.0);
  EXPECT_EQ(ratio_from_torque(p, top), 0.0);
  EXPECT_EQ(torque_at_force(p, 0.0), top);
}

TEST(Coupling, RoundTripsToAFewUlp) {
  expect_round_trips(uniform_disk<>(), "uniform", 4);
  expect_round_trips(annulus<>(0.125), "annulus", 4);
  expect_round_trips(ring<>(), "ring", 4);
  expect_round_trips(hertz<>(), "hertz", 8);
  expect_round_trips(boussinesq<>(), "boussinesq", 8);
}

TEST(Coupling, RatioRoundTripWhereWellConditioned) {
  const uniform_disk<> u;
  for (double e = 1e-3; e < 1e3; e *= 1.37) {
    // Condition number of ε ↦ 𝓕 ↦ ε is 𝓕/(ε𝓕′); of the torque side 𝓣/(ε|𝓣′|).
    const double cf = u.force(e) / (e * force_derivative(e));
    const double ct = u.torque(e) / (e * -torque_derivative(e));
    EXPECT_LE(boost::math::epsilon_difference(ratio_from_force(u, u.force(e)), e), 4 + 4 * cf) << e;
    EXPECT_LE(boost::math::epsilon_difference(ratio_from_torque(u, u.torque(e)), e), 4 + 4 * ct)
        << e;
  }
}

TEST(Coupling, CurveMatchesTheProfileAndItsSlope) {
  const annulus<> cd(0.125);
  for (double e : {0.05, 0.653, 2.0}) {
    const double F = cd.force(e);
    EXPECT_LE(relative_difference(torque_at_force(cd, F), cd.torque(e)), 1e-13);
    EXPECT_LE(relative_difference(force_at_torque(cd, cd.torque(e)), F), 1e-13);
  }
}

TEST(Coupling, OutOfRangeIsADomainError) {
  const uniform_disk<> u;
  for (double F : {-0.1, 1.0, 1.5, double(NAN)})
    EXPECT_THROW(ratio_from_force(u, F), std::domain_error) << F;
  for (double T : {0.0, -1.0, 2.0 / 3 + 1e-9, double(NAN)})
    EXPECT_THROW(ratio_from_torque(u, T), std::domain_error) << T;
  EXPECT_THROW(torque_at_force(u, 1.0), std::domain_error);
}

// fuzz_coupling: a force target among the subnormal ratios could not be
// bracketed (evaluation_error); guards the bracket [0, ε] there.  Boussinesq's
// 𝓕 is exactly πε/4 for ε ≤ 1 (B2), so the ratio is 4F/π to the resolution of
// the subnormals (one denorm_min in ε moves 𝓕 by π/4 of one).
TEST(Coupling, RegressionForceTargetAmongSubnormalRatios) {
  const boussinesq<double> b;
  const double dmin = std::numeric_limits<double>::denorm_min();
  const double F = 9.88131291682493088353e-323;  // 20 denorm_min
  const double e = ratio_from_force(b, F);
  EXPECT_NEAR(e, 4 * F / pi, 1.5 * dmin);
  EXPECT_NEAR(b.force(e), F, dmin);
}

// fuzz_coupling: a torque reached only beyond the largest double ratio
// returned a wrong ratio; guards the domain error.  For the disk 𝓣 > 0 falls
// to 𝓣(DBL_MAX) ≈ 1/(4 DBL_MAX) = 1.4e-309 (ε𝓣 → ⟨r²⟩/2 = 1/4), above the
// target 1e-320.
TEST(Coupling, RegressionTorqueBeyondTheLargestRatioIsADomainError) {
  ASSERT_GT(0.25 / max_d, 1e-320);
  EXPECT_THROW(ratio_from_torque(uniform_disk<double>(), 1e-320), std::domain_error);
}

// fuzz_coupling (writing the campaign's regression test): the uncoupled caps
// (𝓕 = 0 at ε = 0, 1 for every ε > 0) returned ε ≈ 0 for 𝓕 = 1/2; guards the
// documented domain error for a target inside the jump.
TEST(Coupling, RegressionForceInsideTheJumpOfUncoupledCapsIsADomainError) {
  EXPECT_THROW(ratio_from_force(uncoupled_caps<double>(), 0.5), std::domain_error);
}

// fuzz_coupling (the campaign): a thin annulus's quadrature 𝓕 levels off at
// 1 − 2⁻⁵², so the valid target 1 − 2⁻⁵³ was "not reached" (domain error);
// guards answering a target within 4 ulp of that level.  Expected: a ratio
// whose 𝓕 is the target to 4 ulp, and large, since 1 − 𝓕 ≈ ⟨r²⟩/(4ε²) ≈ 1/(4ε²)
// is still 2.5e-13 at ε = 1e6.
TEST(Coupling, RegressionForceTargetAtTheTopOfAThinAnnulus) {
  const annulus<double> thin(0.999999632134875304779);
  const double target = 0.999999999999999888978;
  const double e = ratio_from_force(thin, target);
  EXPECT_NEAR(thin.force(e), target, 4 * double_eps);
  EXPECT_GT(e, 1e6);
}

// fuzz_coupling (the campaign, twice): subnormal targets of a steep elliptic
// cone were rejected as a jump; guards telling a steep 𝓕 from a jump.  The
// cone's 𝓕 = ε/√(ε² + τ²) (on the ellipse 𝓕² + 𝓣²/τ² = 1 with normal along
// (ε, 1)) is ε/τ for ε ≪ τ: ε = τF to the subnormals' resolution.
TEST(Coupling, RegressionSubnormalForceTargetsOfASteepEllipticCone) {
  // τ = 0.017: 57 subnormals of 𝓕 per step of ε.
  const double tau = 0.0173969741280550205254, tiny = 3.75489890839347373574e-322;
  EXPECT_NEAR(ratio_from_force(elliptic_limit_surface<double>(tau), tiny), tau * tiny, 2e-323);
  // τ = 1e-10: 𝓕 steps by 1e10 subnormals per step of ε.
  const double steep = 1.00703517801109410927e-10, small = 5.9100901405666000387e-314;
  EXPECT_NEAR(ratio_from_force(elliptic_limit_surface<double>(steep), small), steep * small,
              2e-323);
}

}  // namespace
