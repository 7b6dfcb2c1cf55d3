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
#include <gtest/gtest.h>

#include <spinslide/contact/limit_set.hpp>
#include <spinslide/spinslide.hpp>

#include <boost/math/policies/policy.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cerrno>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace spinslide;

// The profile, with every evaluation counted (a friction profile itself).
template <class P>
class counted {
 public:
  using value_type = typename P::value_type;
  using policy_type = typename P::policy_type;
  explicit counted(P p) : p_(std::move(p)) {}
  force_torque_result<value_type> force_torque(value_type e) const {
    ++calls;
    return p_.force_torque(e);
  }
  value_type force(value_type e) const { return force_torque(e).force; }
  value_type torque(value_type e) const { return force_torque(e).torque; }
  // 𝓕′ where P has it in closed form (then the projection takes Newton
  // steps; otherwise secants), counted apart.
  template <class Q = P>
  auto force_derivative(value_type e) const
      -> decltype(std::declval<const Q&>().force_derivative(e)) {
    ++slopes;
    return p_.force_derivative(e);
  }
  value_type mean_radius() const { return p_.mean_radius(); }
  value_type mean_inverse_radius() const { return p_.mean_inverse_radius(); }
  value_type mean_square_radius() const { return p_.mean_square_radius(); }
  mutable int calls = 0, slopes = 0;

 private:
  P p_;
};

// Hertz with its fused evaluation counted (below, in fused_value_slope).
struct fused_hertz : hertz<> {};

}  // namespace

template <>
struct spinslide::detail::fused_value_slope<counted<fused_hertz>> : std::true_type {
  static constexpr bool bounded_curvature = true;
  template <bool Curvature = true>
  static elastic_value_slope<double> at(const counted<fused_hertz>& p, double eps) {
    ++p.calls;
    return fused_value_slope<hertz<>>::at<Curvature>(hertz<>(), eps);
  }
};

namespace {

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

struct points {
  std::vector<double> x, y;
};
const points& random_points() {
  static const points pts = [] {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(0, 1);
    points p;
    for (int i = 0; i < 300; ++i) {
      p.x.push_back(1.6 * u(rng));
      p.y.push_back(1.2 * u(rng));
    }
    return p;
  }();
  return pts;
}

void expect_unchanged(const limit_projection<double>& r, double x, double y,
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

// P = C(ε) + λ(wε, 1) has the displacement along the curve's normal in the
// metric, so it projects to C(ε) at ratio ε; searched from `start` (0: none).
template <class P>
void expect_normal_projects_to_foot(const P& p, double w, double eps, double lambda,
                                    double ratio_tolerance, const std::string& name,
                                    double start = 0) {
  const auto c = p.force_torque(eps);
  const double x = c.force + lambda * w * eps, y = c.torque + lambda;
  const auto r = project_to_limit_set(p, x, y, w, curve_point<double>{start});
  const std::string where = name + " w=" + std::to_string(w) + " eps=" + std::to_string(eps) +
                            " lambda=" + std::to_string(lambda) + " from " + std::to_string(start);
  EXPECT_FALSE(r.sticking) << where;
  EXPECT_NEAR(r.ratio / eps, 1, ratio_tolerance) << where;
  EXPECT_NEAR(r.force, c.force, 4e-16 + 1e-13 * x) << where;
  EXPECT_NEAR(r.torque, c.torque, 4e-16 + 1e-13 * y) << where;
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

// The same from starts near the foot, as a contact's last ratio gives them:
// the warm steps (Halley's for Hertz, whose 𝓕″ is bounded; Newton's for
// Boussinesq and a table) end with the same accuracy as the safeguarded
// search, also where they give up and hand over (a start 30 % off) and
// across ε = 1, where Hertz's 𝓕‴ and Boussinesq's 𝓕″ are unbounded.
template <class P>
void expect_exact_normals_from_nearby_starts(const P& p, const std::vector<double>& weights,
                                             double ratio_tolerance, const std::string& name) {
  for (const double w : weights)
    for (const double eps : {1e-6, 1e-3, 0.1, 0.653, 0.999999, 1.0, 1.000001, 1.5, 30.0, 1e6})
      for (const double lambda : {1e-3, 0.1, 2.0})
        for (const double off : {-0.3, 1e-2, -1e-4, 1e-7, -1e-12})
          expect_normal_projects_to_foot(p, w, eps, lambda, ratio_tolerance, name, eps * (1 + off));
}

TEST(LimitSet, PointsOnANormalProjectToItsFootFromNearbyStarts) {
  const std::vector<double> weights{1e-3, 0.05, 2.0, 20.0, 1e3};
  expect_exact_normals_from_nearby_starts(hertz<>(), weights, 1e-10, "hertz");
  expect_exact_normals_from_nearby_starts(boussinesq<>(), weights, 1e-10, "boussinesq");
  // A table's 𝓣′ = −ε𝓕′ holds to its own accuracy only, which at w = 1e-3
  // moves the foot by more than the 1e-13 the values are held to here (with
  // or without a start): the weights of PointsOnANormalProjectToItsFoot.
  expect_exact_normals_from_nearby_starts(tabulated_profile<>(annulus<>(0.125)), {0.05, 2.0, 20.0},
                                          1e-8, "tabulated CD");
}

// From random nearby starts (1e-12 to 10 % off; w from 1e-3 to 1e3, ε from
// 1e-4 to 1e4, λ from 1e-3 to 1): the point returned is the profile's own
// curve point at the returned ratio, to a few ulp (Halley's last step is
// advanced to second order: to first order, as after Newton's, it would be
// off by up to 150 ulp), and the displacement is normal to 3e-10 of its
// length (measured 1e-10 for both; 1e-9 with a wrong sign in Halley's step).
template <class P>
void expect_warm_projections_on_the_curve(const P& p, const std::string& name) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  double worst_force = 0, worst_torque = 0, worst_normality = 0;
  for (int i = 0; i < 20000; ++i) {
    const double w = std::pow(10.0, -3 + 6 * u(rng)), eps = std::pow(10.0, -4 + 8 * u(rng));
    const double lambda = std::pow(10.0, -3 + 3 * u(rng));
    const double off = (u(rng) < 0.5 ? -1 : 1) * std::pow(10.0, -12 + 11 * u(rng));
    const auto c = p.force_torque(eps);
    const double x = c.force + lambda * w * eps, y = c.torque + lambda;
    const auto r = project_to_limit_set(p, x, y, w, curve_point<double>{eps * (1 + off)});
    const auto q = p.force_torque(r.ratio);
    const double ulp = std::numeric_limits<double>::epsilon();
    worst_force = std::max(worst_force, std::fabs(r.force - q.force) / (q.force * ulp));
    worst_torque = std::max(worst_torque, std::fabs(r.torque - q.torque) / (q.torque * ulp));
    const double along = x - r.force, up = w * r.ratio * (y - r.torque);
    worst_normality = std::max(worst_normality, std::fabs(along - up) / (along + up));
  }
  EXPECT_LE(worst_force, 4) << name;
  EXPECT_LE(worst_torque, 6) << name;
  EXPECT_LE(worst_normality, 3e-10) << name;
}

TEST(LimitSet, WarmProjectionsEndOnTheCurve) {
  expect_warm_projections_on_the_curve(hertz<>(), "hertz");
  expect_warm_projections_on_the_curve(boussinesq<>(), "boussinesq");
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

// Two projections of the same point: the same verdict and, sliding, the same
// ratio (relative) and values (absolute) to the given tolerances.
void expect_same_projection(const limit_projection<double>& a, const limit_projection<double>& b,
                            double ratio_tolerance, double value_tolerance, double context) {
  ASSERT_EQ(a.sticking, b.sticking) << context;
  if (a.sticking) return;
  EXPECT_NEAR(a.ratio / b.ratio, 1, ratio_tolerance) << context;
  EXPECT_NEAR(a.force, b.force, value_tolerance) << context;
  EXPECT_NEAR(a.torque, b.torque, value_tolerance) << context;
}

TEST(LimitSet, AStartingRatioGivesTheSameProjection) {
  const hertz<> p;
  const auto& pts = random_points();
  for (std::size_t i = 0; i < pts.x.size(); ++i) {
    const double x = pts.x[i] + 0.5, y = pts.y[i] + 0.3;
    const auto cold = project_to_limit_set(p, x, y, 1.0);
    for (const double start : {1e-8, 0.01, 1.0, 100.0, 1e8}) {
      const auto warm = project_to_limit_set(p, x, y, 1.0, curve_point<double>{start});
      expect_same_projection(warm, cold, 1e-12, 1e-14, start);
    }
  }
}

// With the last step's ratio, a projection that moved little converges in a
// few evaluations: with 𝓕′ in closed form (Hertz, a tabulated profile), the
// start and two Newton steps (3 of 𝓕 and 𝓣, 3 of 𝓕′); without (the uniform
// disk, whose Carlson-form 𝓕′ is not used), the start, a difference for 𝓕′
// and three secant steps (5).
template <class P>
void expect_evaluations_from_nearby_start(const P& p, int calls, int slopes) {
  for (const double eps : {0.05, 0.653, 2.0, 50.0}) {
    const auto c = p.force_torque(eps);
    const double x = c.force + 0.3 * eps, y = c.torque + 0.3;
    p.calls = p.slopes = 0;
    const auto r = project_to_limit_set(p, x, y, 1.0, curve_point<double>{eps * (1 + 1e-4)});
    EXPECT_NEAR(r.ratio / eps, 1, 1e-12) << eps;
    EXPECT_LE(p.calls, calls) << eps;
    EXPECT_LE(p.slopes, slopes) << eps;
  }
}

TEST(LimitSet, NearbyStartTakesFewEvaluations) {
  expect_evaluations_from_nearby_start(counted<hertz<>>(hertz<>()), 3, 3);
  // Hertz's fused 𝓕, 𝓣, 𝓕′ and 𝓕″, as the projection takes them from
  // hertz<> itself: Halley's steps, the start and one step (2 calls).
  expect_evaluations_from_nearby_start(counted<fused_hertz>(fused_hertz()), 2, 0);
  expect_evaluations_from_nearby_start(
      counted<tabulated_profile<>>(tabulated_profile<>(annulus<>(0.125))), 3, 3);
  expect_evaluations_from_nearby_start(counted<uniform_disk<>>(uniform_disk<>()), 5, 0);
}

// The 3-D projection from the last step's ratio 1e-3 off, in a coupled
// metric (bench_disk's impulse metric), for 32 ratios from 1e-2 to 1e2: the
// start's evaluation (which serves its ray and the ray's Newton start
// alike), then Newton's steps until one is small enough to take to first
// order (𝓕′ in closed form) or is within rounding.  The bounds are this
// commit's counts with one evaluation of margin at most and 10 in all
// (measured: at most 5 and 129 in all for Hertz, 5 and 130 for the table, 7
// and 190 for the disk; at 8afd785, before issue 26's second session: 7 and
// 176, 7 and 179, 9 and 224); the answer is the cold projection's to
// rounding.
struct evaluation_counts {
  int most = 0, total = 0;
};
// z = c + M⁻¹n: the slip n = 0.3 (ε d, 1), d = (cos ε, sin ε), from the curve
// point c at ε.
template <class P>
tangent_wrench<double> slipping_target(const P& p, const planar_metric<double>& m, double e) {
  const auto c = p.force_torque(e);
  const double d[2] = {std::cos(e), std::sin(e)};
  const double n[3] = {0.3 * e * d[0], 0.3 * e * d[1], 0.3};
  double z[3] = {c.force * d[0], c.force * d[1], c.torque};
  for (std::size_t row = 0; row < 3; ++row)
    for (std::size_t k = 0; k < 3; ++k) z[row] += m.inverse()[row][k] * n[k];
  return {z[0], z[1], z[2]};
}
void expect_same_slip(const wrench_projection<double>& a, const wrench_projection<double>& b,
                      double e) {
  EXPECT_FALSE(a.sticking || b.sticking) << e;
  EXPECT_NEAR(a.ratio / b.ratio, 1, 1e-12) << e;
  EXPECT_NEAR(a.point.force_x, b.point.force_x, 1e-14) << e;
  EXPECT_NEAR(a.point.force_y, b.point.force_y, 1e-14) << e;
  EXPECT_NEAR(a.point.torque, b.point.torque, 1e-14) << e;
}
template <class P>
evaluation_counts evaluations_in_a_metric_from_nearby_start(const P& p) {
  const planar_metric<double> m({{{2.0, 0.3, 0.2}, {0.3, 1.5, -0.1}, {0.2, -0.1, 3.0}}});
  evaluation_counts counts;
  for (int i = 0; i < 32; ++i) {
    const double e = std::pow(10.0, -2 + 4.0 * i / 31);
    const tangent_wrench<double> target = slipping_target(p, m, e);
    p.calls = p.slopes = 0;
    const auto warm = project_to_limit_set(p, target, m, curve_point<double>{e * (1 + 1e-3)});
    counts.most = std::max(counts.most, p.calls);
    counts.total += p.calls;
    EXPECT_NEAR(warm.ratio / e, 1, 1e-12) << e;
    expect_same_slip(warm, project_to_limit_set(p, target, m), e);
  }
  return counts;
}

TEST(LimitSet, NearbyStartInAMetricTakesFewEvaluations) {
  const auto fused = evaluations_in_a_metric_from_nearby_start(counted<fused_hertz>(fused_hertz()));
  EXPECT_LE(fused.most, 6);
  EXPECT_LE(fused.total, 140);
  const auto table = evaluations_in_a_metric_from_nearby_start(
      counted<tabulated_profile<>>(tabulated_profile<>(annulus<>(0.125))));
  EXPECT_LE(table.most, 6);
  EXPECT_LE(table.total, 140);
  const auto disk =
      evaluations_in_a_metric_from_nearby_start(counted<uniform_disk<>>(uniform_disk<>()));
  EXPECT_LE(disk.most, 8);
  EXPECT_LE(disk.total, 200);
}

// A sliding result's curve(): its ratio and values, with 𝓕′ there where the
// profile has it in closed form (against the profile's own, to the order of
// the last step's advance) and 𝓕″ after Halley's steps (Hertz; against the
// difference of 𝓕′); NaN otherwise, and all NaN when it sticks.
TEST(LimitSet, ASlidingResultCarriesTheCurvePoint) {
  const hertz<> h;
  for (const double eps : {0.05, 0.653, 1.2, 2.0, 50.0}) {
    const auto c = h.force_torque(eps);
    for (const double start : {0.0, eps * (1 + 1e-4)}) {
      const auto r = project_to_limit_set(h, c.force + 0.3 * eps, c.torque + 0.3, 2.0,
                                          curve_point<double>{start});
      ASSERT_FALSE(r.sticking);
      const auto p = r.curve();
      EXPECT_EQ(p.ratio, r.ratio);
      EXPECT_EQ(p.force, r.force);
      EXPECT_EQ(p.torque, r.torque);
      // Cold, the search's last step is Newton's, and 𝓕′ is the last sample's
      // (off by about that step, below 1e-10); warm, Halley's, and advanced.
      EXPECT_NEAR(p.slope / h.force_derivative(r.ratio), 1, start > 0 ? 1e-13 : 1e-9)
          << eps << " from " << start;
      if (start > 0) {  // the warm steps are Halley's
        const double d = 1e-6 * r.ratio;
        const double second =
            (h.force_derivative(r.ratio + d) - h.force_derivative(r.ratio - d)) / (2 * d);
        EXPECT_NEAR(p.curvature / second, 1, 1e-6) << eps;
      }
    }
  }
  const auto disk = project_to_limit_set(uniform_disk<>(), 1.5, 1.0, 1.0);
  ASSERT_FALSE(disk.sticking);
  EXPECT_TRUE(std::isnan(disk.slope));  // a secant's estimate is not reported
  EXPECT_TRUE(std::isnan(disk.curvature));
  const auto stick = project_to_limit_set(h, 0.1, 0.1, 1.0);
  ASSERT_TRUE(stick.sticking);
  // no start, which the next projection takes
  EXPECT_EQ(stick.curve().ratio, 0);
  EXPECT_TRUE(std::isnan(stick.curve().force));
  EXPECT_TRUE(std::isnan(stick.curve().slope));
  const auto next = project_to_limit_set(h, 1.5, 1.0, 1.0, stick.curve());
  const auto cold = project_to_limit_set(h, 1.5, 1.0, 1.0);
  EXPECT_EQ(next.ratio, cold.ratio);
}

// From the curve point of the contact's last projection, the search takes
// its first step without evaluating: one evaluation fewer than from that
// point's ratio (here the whole count: 1 where 2), the same result.
TEST(LimitSet, ACurvePointStartSavesTheFirstEvaluation) {
  const counted<fused_hertz> h{fused_hertz()};
  for (const double eps : {0.05, 0.653, 2.0, 50.0}) {
    const auto c = h.force_torque(eps);
    const double x = c.force + 0.3 * eps, y = c.torque + 0.3;
    // the last step: a point that projected a little away, at 1.0001 ε
    const auto last = project_to_limit_set(h, x * 1.001, y * 0.999, 1.0, curve_point<double>{eps});
    ASSERT_FALSE(last.sticking);
    h.calls = 0;
    const auto from_ratio = project_to_limit_set(h, x, y, 1.0, curve_point<double>{last.ratio});
    const int by_ratio = h.calls;
    h.calls = 0;
    const auto from_point = project_to_limit_set(h, x, y, 1.0, last.curve());
    EXPECT_EQ(h.calls, by_ratio - 1) << eps;
    EXPECT_LE(h.calls, 1) << eps;
    expect_same_projection(from_point, from_ratio, 1e-14, 1e-15, eps);
  }
}

// A curve point that no projection returned (the values of another ratio,
// a wrong slope or curvature, a point far off) only moves where the search
// starts: the answer is the one of a cold search, and where P sticks it
// sticks.
TEST(LimitSet, AWrongCurvePointDoesNotChangeTheAnswer) {
  const hertz<> h;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const double eps : {0.05, 0.653, 2.0, 50.0}) {
    const auto c = h.force_torque(eps);
    for (const double lambda : {0.3, -0.01}) {  // outside, and just inside (sticks)
      const double x = lambda > 0 ? c.force + lambda * eps : c.force * (1 + lambda);
      const double y = lambda > 0 ? c.torque + lambda : c.torque * (1 + lambda);
      const auto cold = project_to_limit_set(h, x, y, 1.0);
      const auto other = h.force_torque(3 * eps);
      for (const curve_point<double>& bad :
           {curve_point<double>{eps, other.force, other.torque, 0.1, -0.2},
            curve_point<double>{eps, c.force, c.torque, -5.0, 100.0},
            curve_point<double>{eps, c.force, c.torque, nan, nan},
            curve_point<double>{1e-6, 0.9, 0.0, 1.0, 1.0},
            curve_point<double>{eps, 1e300, -1e300, 1e300, nan}}) {
        const auto r = project_to_limit_set(h, x, y, 1.0, bad);
        expect_same_projection(r, cold, 1e-12, 1e-14, eps);
      }
    }
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
using spinslide::limit_projection;

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
