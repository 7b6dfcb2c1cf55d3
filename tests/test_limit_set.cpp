//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// project_to_limit_set against independent computations:
//  - brute force: the nearest point of the curve by a dense scan of
//    ε = τ/(1 − τ) over τ ∈ [0, 1] and a golden-section refinement, and
//    "inside L" by bisection of 𝓕(ε) = f and comparison with 𝓣 there;
//  - exact constructions: a point P = C(ε) + λ(wε, 1) (λ > 0) projects to
//    C(ε) at ratio ε (the normal of the curve at ε is (ε, 1));
//  - exact cases: the corners (1, 0) and (0, ⟨r⟩), the uncoupled caps' box
//    (a clamp), the boundary and the inside.
// Starts from the last step (a ratio or a curve point), and the evaluations
// they save, are tested in test_limit_set_starts.cpp.
#include <gtest/gtest.h>

#include <spinslide/contact/limit_set.hpp>
#include <spinslide/values/approximations.hpp>
#include <spinslide/values/coupling.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include <boost/math/policies/policy.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cerrno>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "limit_set_points.hpp"

namespace {

using namespace spinslide;
using spinslide_test::expect_normal_projects_to_foot;
using spinslide_test::random_points;

// The squared distance in the metric from (x, y) to C(ε), ε = τ/(1 − τ).
template <class P>
double squared_distance(const P& p, double tau, double x, double y, double w) {
  const double eps = tau >= 1 ? std::numeric_limits<double>::infinity() : tau / (1 - tau);
  const auto c = p.force_torque(eps);
  return (c.force - x) * (c.force - x) + w * (c.torque - y) * (c.torque - y);
}

// The smallest squared distance from (x, y) to the curve, by brute force.
template <class P>
double brute_force_squared_distance(const P& p, double x, double y, double w) {
  const int n = 4000;
  int best = 0;
  double d_best = squared_distance(p, 0, x, y, w);
  for (int i = 1; i <= n; ++i) {
    const double d = squared_distance(p, double(i) / n, x, y, w);
    if (d < d_best) {
      d_best = d;
      best = i;
    }
  }
  double a = std::max(0.0, double(best - 1) / n), b = std::min(1.0, double(best + 1) / n);
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int k = 0; k < 80; ++k) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (squared_distance(p, c, x, y, w) < squared_distance(p, d, x, y, w))
      b = d;
    else
      a = c;
  }
  return std::min(d_best, squared_distance(p, (a + b) / 2, x, y, w));
}

// How far (x, y) lies above the curve at f = x (negative: below, inside L);
// +∞ for x > 1.  By bisection of 𝓕 in τ.
template <class P>
double height_above_curve(const P& p, double x, double y) {
  if (x > 1) return std::numeric_limits<double>::infinity();
  double a = 0, b = 1;
  for (int k = 0; k < 200 && b - a > 1e-17; ++k) {
    const double m = (a + b) / 2;
    (p.force(m / (1 - m)) < x ? a : b) = m;
  }
  const double tau = (a + b) / 2;
  return y - p.torque(tau / (1 - tau));
}

void expect_unchanged(const friction_result<double, double>& r, double x, double y,
                      const std::string& where) {
  EXPECT_EQ(r.force, x) << where;
  EXPECT_EQ(r.torque, y) << where;
  EXPECT_TRUE(std::isnan(r.ratio)) << where;
}

// One point against brute force; returns whether it sticks (or nothing for a
// point on the curve to rounding, where either answer is right).
enum class outcome { sticking, sliding, either };
template <class P>
outcome expect_point_matches_brute_force(const P& p, double x, double y, double w,
                                         const std::string& where) {
  const auto r = project_to_limit_set(p, x, y, w);
  const double height = height_above_curve(p, x, y);
  if (std::fabs(height) < 1e-9) return outcome::either;
  EXPECT_EQ(r.sticking, height < 0) << where;
  if (r.sticking) {
    expect_unchanged(r, x, y, where);
    return outcome::sticking;
  }
  const double d2 = (r.force - x) * (r.force - x) + w * (r.torque - y) * (r.torque - y);
  const double best = brute_force_squared_distance(p, x, y, w);
  // An ulp of 𝓕 or 𝓣 moves d2 by about 2·distance·1.1e-16: the bound allows a few.
  EXPECT_LE(d2, best * (1 + 1e-12) + 1e-15 * std::sqrt(best)) << where;
  EXPECT_GE(d2, best * (1 - 1e-9)) << where << " (closer than the curve's nearest point?)";
  return outcome::sliding;
}

// Every random point against brute force, for one profile and weight.
template <class P>
void expect_matches_brute_force(const P& p, double w, const std::string& name) {
  const auto& pts = random_points();
  int sticking = 0, sliding = 0;
  for (std::size_t i = 0; i < pts.x.size(); ++i) {
    const std::string where = name + " w=" + std::to_string(w) + " at (" +
                              std::to_string(pts.x[i]) + ", " + std::to_string(pts.y[i]) + ")";
    const outcome o = expect_point_matches_brute_force(p, pts.x[i], pts.y[i], w, where);
    sticking += o == outcome::sticking;
    sliding += o == outcome::sliding;
  }
  EXPECT_GT(sticking, 20) << name;
  EXPECT_GT(sliding, 20) << name;
}

TEST(LimitSet, MatchesBruteForceOnEveryProfile) {
  for (const double w : {0.1, 1.0, 10.0}) {
    expect_matches_brute_force(uniform_disk<>(), w, "disk");
    expect_matches_brute_force(hertz<>(), w, "hertz");
    expect_matches_brute_force(boussinesq<>(), w, "boussinesq");
    expect_matches_brute_force(ring<>(), w, "ring");
    expect_matches_brute_force(annulus<>(0.5), w, "annulus 0.5");
    expect_matches_brute_force(elliptic_limit_surface<>(), w, "ellipse");
  }
}

TEST(LimitSet, MatchesBruteForceOnATabulatedProfile) {
  const tabulated_profile<> cd{annulus<>(0.125)};
  for (const double w : {0.1, 1.0, 10.0}) expect_matches_brute_force(cd, w, "tabulated CD");
}

template <class P>
void expect_exact_normals(const P& p, double ratio_tolerance, const std::string& name) {
  for (const double w : {0.05, 1.0, 20.0})
    for (const double eps : {1e-6, 1e-3, 0.1, 0.5, 0.653, 1.0, 1.5, 3.0, 30.0, 1e3, 1e6})
      for (const double lambda : {1e-3, 0.1, 2.0})
        expect_normal_projects_to_foot(p, w, eps, lambda, ratio_tolerance, name);
}

TEST(LimitSet, PointsOnANormalProjectToItsFoot) {
  expect_exact_normals(uniform_disk<>(), 1e-10, "disk");
  expect_exact_normals(hertz<>(), 1e-10, "hertz");
  expect_exact_normals(boussinesq<>(), 1e-10, "boussinesq");
  expect_exact_normals(tabulated_profile<>(annulus<>(0.125)), 1e-8, "tabulated CD");
}

// Normality to 1e-12: (x − 𝓕) = wε(y − 𝓣) relative to the displacement, at
// points at least 1e-3 from the curve.
template <class Real, class P>
double worst_normality(const P& p, Real w) {
  double worst = 0;
  const auto& pts = random_points();
  for (std::size_t i = 0; i < pts.x.size(); ++i) {
    const Real x = Real(pts.x[i]) + 1, y = Real(pts.y[i]) + Real(0.7);  // outside L
    const auto r = project_to_limit_set(p, x, y, w);
    EXPECT_FALSE(r.sticking);
    const Real along = x - r.force, up = w * r.ratio * (y - r.torque);
    using std::fabs;
    worst = std::max(worst, static_cast<double>(fabs(along - up) / (along + up)));
  }
  return worst;
}

TEST(LimitSet, NormalTo1e12) {
  for (const double w : {0.1, 1.0, 10.0}) {
    EXPECT_LE(worst_normality(uniform_disk<>(), w), 1e-12) << w;
    EXPECT_LE(worst_normality(hertz<>(), w), 1e-12) << w;
    EXPECT_LE(worst_normality(boussinesq<>(), w), 1e-12) << w;
    EXPECT_LE(worst_normality(tabulated_profile<>(annulus<>(0.125)), w), 1e-12) << w;
  }
}

TEST(LimitSet, EveryRealType) {
  EXPECT_LE(worst_normality(uniform_disk<float>(), 1.0f), 1e-5);
  EXPECT_LE(worst_normality(hertz<long double>(), 1.0L), 1e-15);
  using big = boost::multiprecision::cpp_bin_float_50;
  EXPECT_LE(worst_normality(boussinesq<big>(), big(2)), 1e-40);
}

TEST(LimitSet, CornersAndEdges) {
  const hertz<> p;
  const double top = p.mean_radius();
  for (const double x : {1.0 + 1e-15, 1.5, 1e300}) {
    const auto r = project_to_limit_set(p, x, 0.0, 1.0);
    EXPECT_FALSE(r.sticking);
    EXPECT_EQ(r.force, 1);
    EXPECT_EQ(r.torque, 0);
    EXPECT_EQ(r.ratio, std::numeric_limits<double>::infinity());
  }
  for (const double y : {top * (1 + 1e-15), 1.0, 1e300}) {
    const auto r = project_to_limit_set(p, 0.0, y, 2.0);
    EXPECT_FALSE(r.sticking);
    EXPECT_EQ(r.force, 0);
    EXPECT_EQ(r.torque, top);
    EXPECT_EQ(r.ratio, 0);
  }
  // On the axes and the corners: sticking.
  for (const auto& c : {force_torque_result<double>{0, 0}, {1, 0}, {0, top}, {0.5, 0}, {0, 0.3}}) {
    const auto r = project_to_limit_set(p, c.force, c.torque, 1.0);
    EXPECT_TRUE(r.sticking) << c.force << ", " << c.torque;
    EXPECT_EQ(r.force, c.force);
    EXPECT_EQ(r.torque, c.torque);
  }
  // On the curve, to rounding: sticking, or the point itself.
  for (const double eps : {1e-3, 0.653, 1.0, 40.0, 1e4}) {
    const auto c = p.force_torque(eps);
    const auto r = project_to_limit_set(p, c.force, c.torque, 1.0);
    EXPECT_NEAR(r.force, c.force, 1e-15) << eps;
    EXPECT_NEAR(r.torque, c.torque, 1e-15) << eps;
  }
}

// The uncoupled caps' set is the box [0, 1] × [0, cap]: the projection clamps.
TEST(LimitSet, UncoupledCapsClamp) {
  const uncoupled_caps<> caps(0.5);
  const auto& pts = random_points();
  for (std::size_t i = 0; i < pts.x.size(); ++i) {
    const double x = 2 * pts.x[i], y = 2 * pts.y[i];
    const auto r = project_to_limit_set(caps, x, y, 3.0);
    const bool inside = x <= 1 && y <= 0.5;
    EXPECT_EQ(r.sticking, inside) << x << ", " << y;
    EXPECT_NEAR(r.force, std::min(x, 1.0), 1e-15) << x << ", " << y;
    EXPECT_NEAR(r.torque, std::min(y, 0.5), 1e-15) << x << ", " << y;
  }
}

TEST(LimitSet, BadInputIsADomainError) {
  const uniform_disk<> p;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  // A sticking result's curve point (ratio NaN), or a negative ratio.
  for (const double bad : {nan, -1.0})
    EXPECT_THROW(project_to_limit_set(hertz<>(), 1.0, 1.0, 1.0,
                                      curve_point<double>{bad, 0.5, 0.5, -0.1, -0.1}),
                 std::domain_error)
        << bad;
  for (const double bad : {-1.0, -0.0 - 1e-300, nan, inf}) {
    EXPECT_THROW(project_to_limit_set(p, bad, 0.5, 1.0), std::domain_error) << bad;
    EXPECT_THROW(project_to_limit_set(p, 0.5, bad, 1.0), std::domain_error) << bad;
  }
  for (const double bad : {0.0, -1.0, nan, inf})
    EXPECT_THROW(project_to_limit_set(p, 0.5, 0.5, bad), std::domain_error) << bad;
  for (const double bad : {-1.0, nan})
    EXPECT_THROW(project_to_limit_set(p, 0.5, 0.5, 1.0, curve_point<double>{bad}),
                 std::domain_error)
        << bad;
  try {
    project_to_limit_set(p, 0.5, -2.0, 1.0);
    FAIL() << "no exception";
  } catch (const std::domain_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("project_to_limit_set"), std::string::npos) << what;
    EXPECT_NE(what.find("torque"), std::string::npos) << what;
  }
}

TEST(LimitSet, BadInputUnderErrnoIsNaN) {
  using errno_policy = boost::math::policies::policy<
      boost::math::policies::domain_error<boost::math::policies::errno_on_error>>;
  const uniform_disk<double, errno_policy> p;
  errno = 0;
  const auto r = project_to_limit_set(p, 0.5, 0.5, -1.0);
  EXPECT_EQ(errno, EDOM);
  EXPECT_TRUE(std::isnan(r.force));
  EXPECT_TRUE(std::isnan(r.torque));
  EXPECT_TRUE(std::isnan(r.ratio));
  EXPECT_FALSE(r.sticking);
}

}  // namespace

// What fuzz_limit_set found (docs/reliability.md): extreme weights, starts
// and points.  Each answer against an independent expectation.
namespace {
using spinslide::friction_result;

// y and w so large that the nearest point keeps t = ⟨r⟩ (a NaN on the edge:
// w·py·dt overflowed; a point 1e59 above L called sticking: the chord beside
// C(0) is 1e-308 long and its dt a rounding), or x so small that the ratio is below the normal
// numbers (200 iterations: w·ε underflowed where w·ε·(y − 𝓣) did not): (0, ⟨r⟩).
template <class P>
void expect_top_corner(const P& p, double x, double y, double w, double start) {
  const auto r = project_to_limit_set(p, x, y, w, curve_point<double>{start});
  EXPECT_FALSE(r.sticking);
  EXPECT_LE(r.force, 1e-300);
  EXPECT_NEAR(r.torque, p.mean_radius(), 4e-16);
  EXPECT_LE(r.ratio, 1e-300);
}

TEST(LimitSet, RegressionExtremeWeightsAndStarts) {
  expect_top_corner(boussinesq<>(), 1.95348765586094685887, 1.15351090092546449726e+296,
                    2.11026362537199988824e+175, 1.37052415512338026281e+119);
  expect_top_corner(annulus<>(0.799043829558668927682), 0.815145591850808037826,
                    4.23061598482764408254e+59, 8.54771847257657087713e+255,
                    2.04377665386919251697e-318);
  expect_top_corner(boussinesq<>(), 1.03654972497493524968e-320, 5.06284469171929408671e+186,
                    1.2570722610211577088e-187, 0.0);
  // w = 8e194: the nearest point has t = y to rounding (a false convergence at
  // ε = 1e77: w·ε² overflowed); its force from the coupling inverse.
  const ring<> ring_profile;
  const double y = 0.962379485841000303914;
  const auto r = project_to_limit_set(ring_profile, 1.0, y, 8.27153894899409705595e+194,
                                      curve_point<double>{9.35149256916424780703e+133});
  EXPECT_NEAR(r.torque, y, 4e-16);
  EXPECT_NEAR(r.force, force_at_torque(ring_profile, y), 1e-14);
  // ε ≈ 8e14, where 𝓕 rounds to 1 - 1e-15 (a secant over a wide gap gave a
  // small step far from the root): from a far start as from none.
  const elliptic_limit_surface<> ellipse(38402850.280619814992);
  const double x = 1.8269463011837359101, t = 1.84345448077861973069, w = 0.0581650085310874212507;
  const auto cold = project_to_limit_set(ellipse, x, t, w);
  const auto warm =
      project_to_limit_set(ellipse, x, t, w, curve_point<double>{8.33894707852520555541e+107});
  EXPECT_NEAR(warm.ratio / cold.ratio, 1, 1e-9);
  EXPECT_NEAR(warm.torque, cold.torque, 1e-12);
}

TEST(LimitSet, RegressionTinyWeights) {
  // w = 6.9e-321 (libFuzzer): w(y − 𝓣) in the slope was subnormal and the
  // search took 200 steps.  The nearest point has 𝓕 = 1 to rounding.
  const boussinesq<> b;
  const auto r =
      project_to_limit_set(b, 1.0, 0.000488281251652677994457, 6.92680035469427654936e-321,
                           curve_point<double>{1.19708502733700794376e+303});
  EXPECT_FALSE(r.sticking);
  EXPECT_GE(r.force, 1 - 1e-15);
  // τ = 3.8e-9, w = 1.6e149 (libFuzzer): the nearest point has 𝓣 = y to
  // rounding; a start gave ε 1e-11 off (a secant of 𝓕 where 𝓕 = 1 − 1e-7).
  const elliptic_limit_surface<> e(3.80247673614897198405e-09);
  const double y = 1.65267799445700822802e-12;
  const auto warm = project_to_limit_set(e, 1.32446307038503641174, y, 1.55808650294502851528e+149,
                                         curve_point<double>{7.04537610969617571996e-321});
  EXPECT_NEAR(warm.torque, y, 4 * std::numeric_limits<double>::epsilon() * y);
}
}  // namespace
