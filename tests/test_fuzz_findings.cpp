//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Every failure the fuzz harnesses (fuzz/) found, as a regression test with
// the input the fuzzer reported and an independent expectation: an exact
// limit, a scale invariance or a bound.  docs/reliability.md lists them.

#include <spinslide/spinslide.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace {

using namespace spinslide;
constexpr double max_d = std::numeric_limits<double>::max();
constexpr double min_d = std::numeric_limits<double>::min();
const double two_over_pi = 2 / boost::math::constants::pi<double>();

// fuzz_profiles: Boost's R_F and R_D return NaN for a subnormal argument, met
// by a quadrature node within ~1e-308 of r = ε.  A thin annulus at r = 1 and
// ε = 1 is the ring kernel at y = 0: 𝓕 = 𝓣 = 2/π.
TEST(FuzzFindings, RingKernelAtSubnormalDistance) {
  using P = detail::kernel_policy<boost::math::policies::policy<>>;
  for (const double d : {5e-324, 1e-310, 1e-300}) {
    const auto k = detail::ring_kernel(1.0 - d, 1.0, d, P());
    EXPECT_NEAR(k.force, two_over_pi, 1e-14) << d;  // Boost R_D: ~12 ulp at y = 2e-300
    EXPECT_NEAR(k.torque, two_over_pi, 1e-14) << d;
  }
  const float b = std::nextafter(1.0f, 0.0f);
  const auto ft = annulus<float>(b).force_torque(1.0f);
  EXPECT_NEAR(ft.force, float(two_over_pi), 1e-6f);
  EXPECT_NEAR(ft.torque, float(two_over_pi), 1e-6f);
}

// fuzz_profiles: p = DBL_MAX overflowed tanh_sinh's sums (evaluation_error).
// p and λp are the same profile: the uniform disk's moments and 𝓕, 𝓣.
TEST(FuzzFindings, CustomPressureOfAnySizeIsTheSameProfile) {
  for (const double c : {max_d, 1.0, 1e-300}) {
    const auto p = make_radial_profile<double>([c](double) { return c; });
    EXPECT_NEAR(p.mean_radius(), 2.0 / 3, 1e-14) << c;
    EXPECT_NEAR(p.mean_inverse_radius(), 2.0, 1e-13) << c;
    EXPECT_NEAR(p.mean_square_radius(), 0.5, 1e-14) << c;
    EXPECT_NEAR(p.force(0.7), force(0.7), 1e-13) << c;
    EXPECT_NEAR(p.torque(0.7), torque(0.7), 1e-13) << c;
  }
  // A support so thin that its middle rounds to 1: the pressure is asked at
  // 1 − r = half the width, not at 1 − r = 0 (where it is infinite).
  const double inner = std::nextafter(1.0, 0.0);
  const auto thin = make_radial_profile<double>(
      [](double, double one_minus_r) { return 1 / std::sqrt(one_minus_r); }, inner);
  EXPECT_NEAR(thin.mean_radius(), 1.0, 1e-15);
  // A total that overflows even so is the documented domain error.
  EXPECT_THROW(make_radial_profile<double>([](double r) { return r < 0.5 ? max_d : 1e-300; }),
               std::domain_error);
}

// fuzz_profiles: weights whose sum overflows were normalised to 0.
TEST(FuzzFindings, WeightsWhoseSumOverflows) {
  const auto w = make_weighted_sum<double>({max_d, max_d}, uniform_disk<double>(), ring<double>());
  EXPECT_DOUBLE_EQ(w.weights()[0], 0.5);
  EXPECT_DOUBLE_EQ(w.weights()[1], 0.5);
  EXPECT_DOUBLE_EQ(w.mean_radius(), (2.0 / 3 + 1) / 2);
}

// fuzz_profiles: τ² overflowed in the elliptic cone, ⟨r⟩⟨r²⟩ in the Padé form.
// Both torques are ≤ their 𝓣(0) and → it as ε → 0.
TEST(FuzzFindings, EngineModelsWithExtremeParameters) {
  const auto e = elliptic_limit_surface<double>(max_d).force_torque(min_d);
  EXPECT_EQ(e.torque, max_d);
  EXPECT_EQ(e.force, 0.0);  // ε/τ = 1.2e-616: underflows
  const pade_approximation<double> p(1e300, 1e-300, 1e300);
  const auto ft = p.force_torque(1e-300);
  EXPECT_DOUBLE_EQ(ft.torque, 1e300 / (1 + 2e-300));
  EXPECT_TRUE(std::isfinite(ft.force));
  EXPECT_DOUBLE_EQ(p.force(1e300), 1.0 / 3);  // ε/(ε + 2/<1/r>) = 1e300/3e300
}

// fuzz_profiles (sanitize preset, second run): in the Padé form 2ε overflowed
// where <r>/<r²> underflows to 0 (∞ · 0 = NaN torque).
TEST(FuzzFindings, PadeAtTheLargestRatio) {
  const pade_approximation<double> big(7.56851905622497924774e-103, max_d, max_d);
  const auto ft = big.force_torque(max_d);
  // <r>/(1 + 2ε<r>/<r²>) with ε<r>/<r²> ~ 1e-103: <r>.
  EXPECT_DOUBLE_EQ(ft.torque, 7.56851905622497924774e-103);
  EXPECT_EQ(ft.force, 1.0);
}

// fuzz_coupling: a force target among the subnormal ratios could not be
// bracketed (evaluation_error).  𝓕 ≈ ε⟨1/r⟩/2 there.
TEST(FuzzFindings, CouplingInverseAmongSubnormals) {
  const boussinesq<double> b;
  const double F = 9.88131291682493088353e-323;
  const double e = ratio_from_force(b, F);
  EXPECT_GT(e, 0);
  const double linear = F / (b.mean_inverse_radius() / 2);  // 25 denorm_min: ±4% resolution
  EXPECT_NEAR(e, linear, 0.1 * linear);
  // A torque reached only beyond the largest double ratio: a domain error now.
  EXPECT_THROW(ratio_from_torque(uniform_disk<double>(), 1e-320), std::domain_error);
  // The uncoupled caps take no force in (0, 1): the jump at ε = 0.
  EXPECT_LT(ratio_from_force(uncoupled_caps<double>(), 0.5), 1e-300);
}

// fuzz_coupling: the tabulated Hertz profile gave 𝓕 = 1 + 2e-15 at ε = 4.4e11.
TEST(FuzzFindings, TabulatedForceNeverAboveOne) {
  const tabulated_profile<double> t{hertz<double>()};
  for (double e = 1e6; e < 1e300; e *= 3.7) {
    ASSERT_LE(t.force(e), 1.0) << e;
    ASSERT_LE(t.torque(1 / e), t.mean_radius()) << e;
  }
  EXPECT_LE(force_at_torque(t, 4.54747350886464118958e-13), 1.0);
}

// fuzz_stop_time: ∞ · 0 and ∞ − ∞ in distances and angles; a subnormal or
// huge γ.
TEST(FuzzFindings, ThrowsAtTheEdgesOfDouble) {
  const tabulated_throw<uniform_disk<double>> table(uniform_disk<double>(), 0.5);
  EXPECT_GE(table.distance(min_d, max_d), 0);
  EXPECT_GE(table.distance(min_d, 1), 0);
  // Pure spinning at the largest spin: the stop time γω0/⟨r⟩ and the angle
  // overflow (∞), and the distance is exactly 0.
  const auto spin = simulate_throw(boussinesq<double>(), 1.0, 0.0, max_d);
  EXPECT_EQ(spin.distance, 0);
  EXPECT_EQ(spin.angle, std::numeric_limits<double>::infinity());
  // γ ω0/⟨r⟩ with ⟨r⟩/γ overflowing.
  const double gamma = 1e-300;
  EXPECT_DOUBLE_EQ(simulate_throw(uniform_disk<double>(), gamma, 0.0, 1e10).time,
                   gamma * 1e10 / (2.0 / 3));
  // The scaled state of a finite-ratio throw at the largest spin: no ∞ · 0.
  const auto r = simulate_throw(boussinesq<double>(), 6.0840221749458591037e-14,
                                2.22044604925031308085e-16, max_d);
  EXPECT_FALSE(std::isnan(r.distance));
  EXPECT_THROW(simulate_throw(ring<double>(), max_d, 0.5, 0.5), std::domain_error);
  EXPECT_THROW(simulate_throw(ring<double>(), 3e-322, 0.5, 0.5), std::domain_error);
  EXPECT_THROW(stop_time(ring<double>(), 1e300, 0.5, 0.5), std::domain_error);
  EXPECT_NO_THROW(stop_time(ring<double>(), 1e290, 0.5, 0.5));
}

// fuzz_contact: f/|v| overflowed for a tiny sliding speed (3-D), and μN a
// overflowed times 𝓣 = 0 (planar, no spin).
TEST(FuzzFindings, ContactLawAtTheEdgesOfDouble) {
  const contact_law<> law;
  const auto r3 = law(std::array<double, 3>{9.88131291682493088353e-323, 0, 0},
                      std::array<double, 3>{0, 0, 0}, std::array<double, 3>{0, 0, 1}, 1.0,
                      8.98846567431157854073e+307, 4.58359719837098179601e-05);
  for (const double f : r3.force) EXPECT_TRUE(std::isfinite(f));
  EXPECT_LE(std::fabs(r3.force[0]), 8.98846567431157854073e+307 * 4.58359719837098179601e-05);
  EXPECT_EQ(r3.force[1], 0);
  const auto r2 =
      law(std::array<double, 2>{3.4e-13, 0}, 0.0, max_d, max_d, 0.156875143087110618945);
  EXPECT_EQ(r2.torque, 0);
  EXPECT_TRUE(std::isfinite(r2.force[0]));
}

// fuzz_contact (sanitize preset): a NaN velocity component beside a zero one
// gave |v| = 0 (std::max drops the NaN), so no domain error.
TEST(FuzzFindings, ContactLawNaNVelocityComponent) {
  const contact_law<> law;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(law(std::array<double, 2>{0, nan}, 0.0, 2.0, 0.5, 2.0 / 3), std::domain_error);
  EXPECT_THROW(law(std::array<double, 3>{0, nan, 0}, std::array<double, 3>{0, 0, 0},
                   std::array<double, 3>{0, 0, 1}, 2.0, 0.5, 2.0 / 3),
               std::domain_error);
}

}  // namespace
