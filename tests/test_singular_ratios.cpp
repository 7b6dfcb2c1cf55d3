//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The singular ratios of the pressure profiles (values/detail/singular_ratios.hpp):
// the ratios where 𝓕 and 𝓣 are not analytic (the edges of the support),
// which the stop integrator takes as breakpoints (docs/theory.md §9).
#include <gtest/gtest.h>

#include <spinslide/values/profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace {

using namespace spinslide;

TEST(SingularRatios, ListIsAscendingDistinctFiniteAndPositive) {
  detail::ratio_list<double> r(1.0);
  for (double e : {0.5, 1.0, 0.25, 0.0, -1.0, std::numeric_limits<double>::infinity(),
                   std::numeric_limits<double>::quiet_NaN(), 0.5})
    r.add(e);
  ASSERT_EQ(r.size(), 3U);
  EXPECT_EQ(r[0], 0.25);
  EXPECT_EQ(r[1], 0.5);
  EXPECT_EQ(r[2], 1.0);
  detail::ratio_list<double> full;
  for (std::size_t i = 0; i < detail::ratio_list<double>::capacity + 3; ++i)
    full.add(1.0 / double(i + 1));
  EXPECT_EQ(full.size(), detail::ratio_list<double>::capacity);  // the rest dropped
}

// (𝓕(ε + h) − 2𝓕(ε) + 𝓕(ε − h))/h²: it tends to 𝓕″ where 𝓕 is smooth and
// grows like ln(1/h) at an edge of the support (for a uniform edge by 1.49 a
// decade, measured).
template <class P>
double force_curvature(const P& p, double eps, double h) {
  return (p.force(eps + h) - 2 * p.force(eps) + p.force(eps - h)) / (h * h);
}

// Whether ε lies within 0.03 of a listed ratio (where the second difference
// at h = 1e-3 is still far from 𝓕″).
template <class Real>
bool near_a_listed_ratio(const detail::ratio_list<Real>& r, double eps) {
  for (std::size_t i = 0; i < r.size(); ++i)
    if (std::fabs(eps - r[i]) < 0.03) return true;
  return false;
}

// 𝓕″ converges at points away from the listed ratios.
template <class P, class Real>
void expect_smooth_between(const P& p, const detail::ratio_list<Real>& r) {
  for (double e : {0.07, 0.2, 0.3, 0.45, 0.7, 0.9, 1.3, 2.0}) {
    if (near_a_listed_ratio(r, e)) continue;
    EXPECT_LT(std::fabs(force_curvature(p, e, 1e-5) - force_curvature(p, e, 1e-3)), 2e-3)
        << "at " << e;
  }
}

// Each listed ratio is singular, and 𝓕″ converges at points between them.
template <class P>
void expect_singular_exactly_at(const P& p, const std::vector<double>& expected) {
  const auto r = detail::singular_ratios(p);
  ASSERT_EQ(r.size(), expected.size());
  for (std::size_t i = 0; i < r.size(); ++i) {
    EXPECT_DOUBLE_EQ(r[i], expected[i]);
    EXPECT_GT(std::fabs(force_curvature(p, r[i], 1e-5) - force_curvature(p, r[i], 1e-3)), 1.5)
        << "at the listed ratio " << r[i];
  }
  expect_smooth_between(p, r);
}

TEST(SingularRatios, AreTheEdgesOfTheSupport) {
  expect_singular_exactly_at(uniform_disk<>(), {1.0});
  expect_singular_exactly_at(annulus<>(0.125), {0.125, 1.0});
  expect_singular_exactly_at(annulus<>(0.6), {0.6, 1.0});
  expect_singular_exactly_at(scaled<uniform_disk<>>(uniform_disk<>(), 0.5), {0.5});
  expect_singular_exactly_at(
      weighted_sum({0.75, 0.25}, ring<>(), scaled<uniform_disk<>>(uniform_disk<>(), 0.125)),
      {0.125, 1.0});
  expect_singular_exactly_at(radial_profile([](double) { return 1.0; }, 0.3), {0.3, 1.0});
}

TEST(SingularRatios, ATableKeepsItsSources) {
  const annulus<> cd(0.125);
  const tabulated_profile<> table(cd);
  const auto r = table.singular_ratios();
  ASSERT_EQ(r.size(), 2U);
  EXPECT_EQ(r[0], 0.125);
  EXPECT_EQ(r[1], 1.0);
  EXPECT_EQ(detail::singular_ratios(tabulated_profile<>(hertz<>())).size(), 1U);
}

}  // namespace
