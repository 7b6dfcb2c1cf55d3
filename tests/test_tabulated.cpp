//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The tabulated profile (tabulated.hpp) against its source: values, the
// derivative of its interpolant, sharing between threads, and the clamp a
// fuzzer's finding guards.
#include <gtest/gtest.h>

#include <spinslide/values/profile.hpp>

#include <boost/math/special_functions/relative_difference.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <thread>
#include <vector>

#include "profile_loads.hpp"
#include "quadrature_moments.hpp"

namespace {

using namespace spinslide;
using boost::math::relative_difference;
using spinslide_test::two_tier;

// ---------------------------------------------------------------- tabulated

// The largest relative difference of 𝓕 or 𝓣 between two profiles, and the ε
// where it is.
struct largest_difference {
  double worst = 0, at = 0;
  template <class P, class Q>
  void add(const P& p, const Q& q, double e) {
    const auto a = p.force_torque(e), b = q.force_torque(e);
    const double d =
        std::max(relative_difference(a.force, b.force), relative_difference(a.torque, b.torque));
    if (d > worst) {
      worst = d;
      at = e;
    }
  }
};

// The tabulated profile against its source: ε from 1e-12 to 1e12, densely
// around 1 (where the kernel is singular) and at the extremes.
template <class P>
largest_difference tabulated_difference(const tabulated_profile<>& tab, const P& p) {
  largest_difference d;
  for (double e = 1e-12; e < 1e12; e *= 1.031) d.add(tab, p, e);
  for (double e = 0.999; e < 1.001; e += 3.7e-6) d.add(tab, p, e);  // where the kernel is singular
  for (double e : {1e-300, 1e-30, 1e30, 1e300}) d.add(tab, p, e);
  return d;
}

// A negative ratio is a domain error for the tabulated profile too.
void expect_negative_ratio_is_a_domain_error(const tabulated_profile<>& tab) {
  EXPECT_THROW(tab.force(-1.0), std::domain_error);
}

template <class P>
void expect_tabulated(const P& p, const char* name) {
  const tabulated_profile<> tab(p);
  const largest_difference d = tabulated_difference(tab, p);
  EXPECT_LE(d.worst, 1e-10) << name << ": worst " << d.worst << " at eps = " << d.at;
  EXPECT_EQ(tab.force(0.0), 0.0);
  EXPECT_EQ(tab.force(INFINITY), 1.0);
  expect_negative_ratio_is_a_domain_error(tab);
}

TEST(Tabulated, Within1e10EverywhereForEveryProfile) {
  expect_tabulated(uniform_disk<>(), "uniform");
  expect_tabulated(annulus<>(0.125), "annulus");
  expect_tabulated(hertz<>(), "hertz");
  expect_tabulated(boussinesq<>(), "boussinesq");
  expect_tabulated(ring<>(), "ring");
  expect_tabulated(two_tier(), "two-tier");
}

// The table's 𝓕′ (the derivative of its interpolant) against the closed-form
// 𝓕′ of the source: the disk's force_derivative (Carlson forms) and Hertz's
// and Boussinesq's (elementary), over ε from 1e-9 to 1e9 and across ε = 1
// (where Boussinesq's 𝓕″ is singular); exact ends.
template <class Slope>
double worst_tabulated_slope(const tabulated_profile<>& tab, Slope exact) {
  double worst = 0;
  for (double e = 1e-9; e < 1e9; e *= 1.0173)
    worst = std::max(worst, relative_difference(tab.force_derivative(e), exact(e)));
  for (double e = 0.99; e < 1.01; e += 1.3e-4)
    worst = std::max(worst, relative_difference(tab.force_derivative(e), exact(e)));
  return worst;
}

TEST(Tabulated, ForceDerivativeOfTheTable) {
  const tabulated_profile<> disk{uniform_disk<>()}, h{hertz<>()}, b{boussinesq<>()};
  EXPECT_LE(worst_tabulated_slope(disk, [](double e) { return force_derivative(e); }), 1e-7);
  EXPECT_LE(worst_tabulated_slope(h, [](double e) { return hertz<>().force_derivative(e); }), 1e-7);
  EXPECT_LE(worst_tabulated_slope(b, [](double e) { return boussinesq<>().force_derivative(e); }),
            1e-7);
  EXPECT_NEAR(disk.force_derivative(0.0), 1.0, 1e-12);  // ⟨1/r⟩/2
  EXPECT_EQ(disk.force_derivative(INFINITY), 0.0);
  EXPECT_THROW(disk.force_derivative(-1.0), std::domain_error);
  EXPECT_THROW(disk.force_derivative(NAN), std::domain_error);
}

// The projections' fused step (issue 41; force_slope.hpp, fused_value_slope):
// one piece gives force_torque's 𝓕 and 𝓣 and force_derivative's 𝓕′, bit for
// bit, in double and float; no 𝓕″.
template <class Real>
void fused_step_at(const tabulated_profile<Real>& tab, Real e) {
  const auto f = detail::fused_value_slope<tabulated_profile<Real>>::template at<true>(tab, e);
  const auto ft = tab.force_torque(e);
  EXPECT_EQ(f.value.force, ft.force) << e;
  EXPECT_EQ(f.value.torque, ft.torque) << e;
  EXPECT_EQ(f.slope, tab.force_derivative(e)) << e;
  EXPECT_TRUE(std::isnan(f.curvature)) << e;
}

template <class Real>
void fused_step_is_force_torque_and_slope() {
  const tabulated_profile<Real> tab{annulus<Real>(Real(0.3)),
                                    Real(sizeof(Real) == 4 ? 1e-6 : 1e-13)};
  using fused = detail::fused_value_slope<tabulated_profile<Real>>;
  static_assert(fused::value && !fused::bounded_curvature, "a table's step is fused, Newton's");
  for (int i = 0; i <= 2000; ++i)
    fused_step_at(tab, static_cast<Real>(std::pow(10.0, -6 + 12.0 * i / 2000)));
}

TEST(Tabulated, FusedStepIsForceTorqueAndForceDerivative) {
  fused_step_is_force_torque_and_slope<double>();
  fused_step_is_force_torque_and_slope<float>();
}

TEST(Tabulated, SharedBetweenThreadsGivesTheSerialResults) {
  const tabulated_profile<> tab{hertz<>()};
  std::vector<double> xs;
  for (double e = 1e-6; e < 1e6; e *= 1.01) xs.push_back(e);
  std::vector<double> serial(xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) serial[i] = tab.force(xs[i]) + 7 * tab.torque(xs[i]);
  std::vector<std::vector<double>> out(4, std::vector<double>(xs.size()));
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (std::size_t i = 0; i < xs.size(); ++i)
        out[t][i] = tab.force(xs[i]) + 7 * tab.torque(xs[i]);
    });
  for (auto& th : threads) th.join();
  for (const auto& o : out) EXPECT_EQ(o, serial);
}

// fuzz_coupling: the tabulated Hertz profile gave 𝓕 = 1 + 2e-15 at ε = 4.4e11;
// guards the clamp of the tabulated 𝓕 to ≤ 1 and 𝓣 to ≤ ⟨r⟩.  Expected, to
// the table's 1e-10 (Tabulated.Within1e10EverywhereForEveryProfile), the
// limits (L) with Hertz's moments (⟨r²⟩ = 2/5, ⟨r⟩ = 3π/16, ⟨1/r⟩ = 3π/4):
// 1 − 𝓕(ε) ≈ ⟨r²⟩/(4ε²) = 0.1/ε² and 𝓣(δ) ≈ ⟨r⟩ − δ²⟨1/r⟩/4 (f_T = (2/π) r E(δ/r)).
TEST(Tabulated, RegressionHertzForceNeverAboveOne) {
  const tabulated_profile<double> t{hertz<double>()};
  const auto m = spinslide_test::hertz_moments();
  for (double e = 1e6; e < 1e300; e *= 3.7) {
    ASSERT_LE(t.force(e), 1.0) << e;
    ASSERT_NEAR(t.force(e), double(1 - m.mean_square_radius / 4 / e / e), 1e-10) << e;
    ASSERT_LE(t.torque(1 / e), t.mean_radius()) << e;
    ASSERT_NEAR(t.torque(1 / e), double(m.mean_radius), 1e-10 * double(m.mean_radius)) << e;
  }
  // 𝓣 = 4.5e-13 is reached at ε ≈ ⟨r²⟩/(2𝓣) = 4.4e11, where 1 − 𝓕 ≈ 5e-25.
  const double F = force_at_torque(t, 4.54747350886464118958e-13);
  EXPECT_LE(F, 1.0);
  EXPECT_NEAR(F, 1.0, 1e-10);
}

}  // namespace
