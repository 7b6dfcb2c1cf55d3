//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Throws of profiles of other real types than double (dynamics.hpp): float,
// long double and cpp_bin_float_50, whose integration runs in double.
#include <gtest/gtest.h>

#include <spinslide/motion/dynamics.hpp>
#include <spinslide/motion/terminal.hpp>
#include <spinslide/values/approximations.hpp>
#include <spinslide/values/profile.hpp>

#include <boost/math/special_functions/relative_difference.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace {

using namespace spinslide;
using boost::math::relative_difference;

}  // namespace

// The integration runs in double whatever the profile's type (docs/theory.md
// §9): float, long double and cpp_bin_float_50 profiles give the double
// results (which test_throw_reference holds to 1e-12 against 100-digit
// quadrature) to their own or double's precision.
TEST(SimulateThrow, EveryRealTypeGivesTheDoubleResult) {
  using big = boost::multiprecision::cpp_bin_float_50;
  for (const double ei : {0.01, 0.7, 3.0, 100.0}) {
    const auto d = simulate_throw(uniform_disk<double>(), 0.5, ei, 1.0);
    const auto f = simulate_throw(uniform_disk<float>(), 0.5f, static_cast<float>(ei), 1.0f);
    const auto l =
        simulate_throw(uniform_disk<long double>(), 0.5L, static_cast<long double>(ei), 1.0L);
    const auto b = simulate_throw(uniform_disk<big>(), big(0.5), big(ei), big(1));
    EXPECT_NEAR(double(f.time) / d.time, 1, 1e-5) << ei;
    EXPECT_NEAR(double(f.distance) / d.distance, 1, 1e-5) << ei;
    EXPECT_NEAR(double(l.time) / d.time, 1, 1e-13) << ei;
    EXPECT_NEAR(double(l.angle) / d.angle, 1, 1e-13) << ei;
    EXPECT_NEAR(static_cast<double>(b.time) / d.time, 1, 1e-13) << ei;
    EXPECT_NEAR(static_cast<double>(b.distance) / d.distance, 1, 1e-13) << ei;
    EXPECT_NEAR(static_cast<double>(b.angle) / d.angle, 1, 1e-13) << ei;
  }
}

namespace {

// Issue 28: a float profile's throws, against the double throw from the same
// (float) inputs, over ε0 from 1e-12 to 1e12 and γ across the window and one
// float step either side of its edges.  Before, float threw or returned
// ∞ or NaN: uncoupled_caps<float> from ordinary starts (a panel in u whose
// collocation left the numbers passed NaN to the profile); Hertz, the ring,
// the disk and Boussinesq within float's rounding of a window edge (the
// panel error dropped a NaN estimate, and accepted a panel over which the
// rounded flow is 0 that jumped u to 1e7 with a NaN time); terminal_motion
// threw at the edges (test_terminal).  Measured after: at most 9.4e-7 relative (the ring).
template <class DoubleProfile>
std::vector<float> float_gammas(const DoubleProfile& pd, bool with_edges) {
  std::vector<float> gammas{0.05f, 0.3f, 0.5f, 1.5f, 10.0f};
  const auto window = terminal_window(pd);
  for (const double edge : {window.lower, window.upper}) {
    const auto e = static_cast<float>(edge);
    if (with_edges)
      gammas.insert(gammas.end(), {std::nextafter(e, 0.0f), e, std::nextafter(e, 10.0f)});
  }
  return gammas;
}

template <class FloatProfile, class DoubleProfile>
void expect_float_throws_match(const FloatProfile& pf, const DoubleProfile& pd, const char* name,
                               bool with_edges = true) {
  for (const float gamma : float_gammas(pd, with_edges)) {
    for (int i = 0; i <= 24; ++i) {
      const auto eps = static_cast<float>(std::pow(10.0, -12 + i));
      const auto f = simulate_throw(pf, gamma, eps, 1.0f);
      const auto d = simulate_throw(pd, double(gamma), double(eps), 1.0);
      const double worst = std::max({relative_difference(double(f.time), d.time),
                                     relative_difference(double(f.distance), d.distance),
                                     relative_difference(double(f.angle), d.angle)});
      EXPECT_LE(worst, 2e-6) << name << ", gamma " << gamma << ", eps0 " << eps;
    }
  }
}

TEST(SimulateThrow, RegressionFloatThrowsMatchDoubleAcrossAndAtTheWindowEdges) {
  expect_float_throws_match(uniform_disk<float>(), uniform_disk<>(), "disk");
  expect_float_throws_match(annulus<float>(0.125f), annulus<>(0.125), "annulus");
  expect_float_throws_match(ring<float>(), ring<>(), "ring");
  expect_float_throws_match(hertz<float>(), hertz<>(), "hertz");
  expect_float_throws_match(boussinesq<float>(), boussinesq<>(), "boussinesq");
  expect_float_throws_match(elliptic_limit_surface<float>(), elliptic_limit_surface<>(),
                            "elliptic");
  expect_float_throws_match(pade_approximation<float>(), pade_approximation<>(), "pade");
  // Its window is empty (⟨r²⟩ = ∞): no edges.
  expect_float_throws_match(uncoupled_caps<float>(), uncoupled_caps<>(), "caps", false);
}

// Issue 28: the integration runs in double, so a long double γ below
// double's range was accepted and then ran "No stop found after 20000
// panels" or returned NaN; it is now an argument error, as above the range.
TEST(SimulateThrow, RegressionLongDoubleInertiaRatioOutsideDoublesRangeIsRefused) {
  const long double below = std::numeric_limits<long double>::min();
  const long double above = 1e300L;
  EXPECT_THROW(simulate_throw(uniform_disk<long double>(), below, 1.0L, 1.0L), std::domain_error);
  EXPECT_THROW(simulate_throw(uniform_disk<long double>(), above, 1.0L, 1.0L), std::domain_error);
  EXPECT_NO_THROW(simulate_throw(uniform_disk<long double>(), 1e-300L, 1.0L, 1.0L));
}

}  // namespace
