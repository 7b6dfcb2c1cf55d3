//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The projection onto the 3-D limit set in a general metric (limit_set.hpp,
// contact/detail/metric_projector.hpp), against independent computations: the 2-D
// projection of magnitudes where the metric is isotropic in the force, a
// brute-force search over the limit surface, and the optimality conditions
// of a convex problem (on the curve, and the metric's displacement along the
// normal), which together prove the nearest point.

#include <gtest/gtest.h>

#include <spinslide/contact/limit_set.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "random_metric.hpp"

namespace {

using namespace spinslide;
using matrix = planar_metric<double>::matrix;

// Entries of order one, condition numbers up to about 10⁴.
matrix random_metric(std::mt19937_64& rng) { return spinslide_test::random_spd(rng, 1e-4, 0.1); }

// A 3-D projection's point (its 2-vector force and its torque) as a wrench.
tangent_wrench<double> wrench_of(const friction_result<std::array<double, 2>, double>& r) {
  return {r.force[0], r.force[1], r.torque};
}

double metric_distance(const matrix& m, const tangent_wrench<double>& a,
                       const tangent_wrench<double>& b) {
  const double d[3] = {a.force_x - b.force_x, a.force_y - b.force_y, a.torque - b.torque};
  double s = 0;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) s += d[i] * m[i][j] * d[j];
  return s;
}

// The nearest of the limit surface's points (𝓕(ε) (cos φ, sin φ), ±𝓣(ε)) on a
// grid of 720 directions and 1200 ratios log-spaced over [1e-4, 1e4] (and
// both ends), refined by a second grid around the best.
template <class P>
double brute_force_distance(const P& p, const matrix& m, const tangent_wrench<double>& z) {
  const double pi = 3.14159265358979323846;
  double best = std::numeric_limits<double>::infinity(), best_phi = 0, best_log = 0;
  auto try_point = [&](double phi, double log_eps, double sign) {
    const auto ft = p.force_torque(std::exp(log_eps));
    const tangent_wrench<double> c{ft.force * std::cos(phi), ft.force * std::sin(phi),
                                   sign * ft.torque};
    const double d = metric_distance(m, c, z);
    if (d < best) {
      best = d;
      best_phi = phi;
      best_log = log_eps;
    }
  };
  const double lo = std::log(1e-4), hi = std::log(1e4);
  for (double sign : {-1.0, 1.0}) {
    for (int i = 0; i < 720; ++i)
      for (int j = 0; j <= 1200; ++j) try_point(2 * pi * i / 720, lo + (hi - lo) * j / 1200, sign);
  }
  const double sign = z.torque >= 0 ? 1.0 : -1.0;
  for (int round = 0; round < 3; ++round) {
    const double dphi = 2 * pi / 720 / std::pow(40.0, round),
                 dlog = (hi - lo) / 1200 / std::pow(40.0, round);
    const double phi0 = best_phi, log0 = best_log;
    for (int i = -40; i <= 40; ++i)
      for (int j = -40; j <= 40; ++j)
        for (double s : {sign, -sign}) try_point(phi0 + i * dphi / 20, log0 + j * dlog / 20, s);
  }
  return best;
}

struct case_data {
  matrix m;
  tangent_wrench<double> z;
};

std::vector<case_data> random_cases(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::vector<case_data> out;
  while (static_cast<int>(out.size()) < n) {
    const tangent_wrench<double> z{u(rng), u(rng), u(rng)};
    out.push_back({random_metric(rng), z});
  }
  return out;
}

double frobenius(const matrix& m) {
  double s = 0;
  for (const auto& row : m)
    for (double x : row) s += x * x;
  return std::sqrt(s);
}

// The outward normal of L₃ at the projection's point, (ε f̂, σ) scaled to
// unit length; at ε = ∞ (f̂, 0).
std::array<double, 3> outward_normal(const friction_result<std::array<double, 2>, double>& r) {
  const double f = std::hypot(r.force[0], r.force[1]);
  const double fx = f > 0 ? r.force[0] / f : 0, fy = f > 0 ? r.force[1] / f : 0;
  const double sigma = r.torque >= 0 ? 1 : -1;
  if (std::isinf(r.ratio)) return {fx, fy, 0};
  const double len = std::hypot(r.ratio, 1.0);
  return {r.ratio * fx / len, r.ratio * fy / len, sigma / len};
}

// The optimality conditions: the point is on the curve at its ratio (to a
// few ulp), and M(z − p) is along the outward normal (to 1e-12 of its
// length, plus what the rounding of p alone moves it by, 4 ulp of |p| times
// ‖M‖: where z lies within 1e-4 of the curve, p's last bit is already
// 1e-12 of z − p).  For a convex set these prove the nearest point.
template <class P>
void expect_optimal(const P& p, const matrix& m, const tangent_wrench<double>& z,
                    const friction_result<std::array<double, 2>, double>& r) {
  ASSERT_FALSE(r.sticking);
  const auto ft = p.force_torque(r.ratio);
  EXPECT_NEAR(std::hypot(r.force[0], r.force[1]), ft.force, 4e-16 * (1 + ft.force));
  EXPECT_NEAR(std::fabs(r.torque), ft.torque, 4e-16 * (1 + ft.torque));
  const double d[3] = {z.force_x - r.force[0], z.force_y - r.force[1], z.torque - r.torque};
  double s[3] = {0, 0, 0};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) s[i] += m[i][j] * d[j];
  const std::array<double, 3> n = outward_normal(r);
  const double slen = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  const double along = s[0] * n[0] + s[1] * n[1] + s[2] * n[2];
  EXPECT_GT(along, 0) << "the slip points outwards";
  const double across[3] = {s[0] - along * n[0], s[1] - along * n[1], s[2] - along * n[2]};
  const double off =
      std::sqrt(across[0] * across[0] + across[1] * across[1] + across[2] * across[2]);
  const double representable = 4 * 2.2204460492503131e-16 * frobenius(m) *
                               (1 + std::hypot(r.force[0], r.force[1], r.torque));
  EXPECT_LE(off, 1e-12 * slen + representable) << "normality, ratio " << r.ratio;
}

template <class P>
void expect_against_brute_force(const P& p, const std::string& name) {
  int slipping = 0;
  for (const case_data& c : random_cases(12, 5)) {
    const planar_metric<double> metric(c.m);
    const auto r = project_to_limit_set(p, c.z, metric);
    if (r.sticking) continue;
    ++slipping;
    expect_optimal(p, c.m, c.z, r);
    const double ours = metric_distance(c.m, wrench_of(r), c.z);
    const double grid = brute_force_distance(p, c.m, c.z);
    EXPECT_LE(ours, grid * (1 + 1e-12)) << name << ": the grid found a nearer point";
    EXPECT_GE(ours, grid * (1 - 1e-6)) << name << ": the grid's best is far from ours";
  }
  EXPECT_GE(slipping, 6) << name;
}

TEST(MetricProjection, GeneralMetricAgainstBruteForce) {
  expect_against_brute_force(uniform_disk<>(), "uniform_disk");
  expect_against_brute_force(hertz<>(), "hertz");
  expect_against_brute_force(tabulated_profile<>(annulus<>(0.125)), "tabulated CD");
}

TEST(MetricProjection, OptimalOnManyRandomMetrics) {
  const hertz<> h;
  const uniform_disk<> d;
  for (const case_data& c : random_cases(2000, 17)) {
    const planar_metric<double> metric(c.m);
    for (int k = 0; k < 2; ++k) {
      const auto r =
          k == 0 ? project_to_limit_set(h, c.z, metric) : project_to_limit_set(d, c.z, metric);
      if (!r.sticking) {
        if (k == 0) expect_optimal(h, c.m, c.z, r);
        if (k == 1) expect_optimal(d, c.m, c.z, r);
      }
    }
  }
}

// A metric isotropic in the force (any rotation of diag(m, m, m w)) keeps the
// force's direction: the answer is the 2-D projection of the magnitudes.
TEST(MetricProjection, IsotropicMetricIsTheProjectionOfMagnitudes) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-2, 2), lw(-3, 3);
  const uniform_disk<> p;
  int slipping = 0;
  for (int i = 0; i < 500; ++i) {
    const double scale = std::exp(lw(rng)), w = std::exp(lw(rng));
    const planar_metric<double> metric(matrix{{{scale, 0, 0}, {0, scale, 0}, {0, 0, scale * w}}});
    const tangent_wrench<double> z{u(rng), u(rng), u(rng)};
    const auto r = project_to_limit_set(p, z, metric);
    const double zf = std::hypot(z.force_x, z.force_y);
    const auto flat = project_to_limit_set(p, zf, std::fabs(z.torque), w);
    ASSERT_EQ(r.sticking, flat.sticking);
    if (r.sticking) {
      EXPECT_EQ(r.force[0], z.force_x);
      EXPECT_EQ(r.force[1], z.force_y);
      EXPECT_EQ(r.torque, z.torque);
      continue;
    }
    ++slipping;
    EXPECT_NEAR(std::hypot(r.force[0], r.force[1]), flat.force, 2e-14);
    EXPECT_NEAR(std::fabs(r.torque), flat.torque, 2e-14);
    EXPECT_NEAR(r.force[0] * z.force_y - r.force[1] * z.force_x, 0, 1e-14)
        << "the force keeps the direction of z's";
    EXPECT_GE(r.torque * z.torque, 0) << "and the torque its sign";
    if (std::isfinite(flat.ratio) && flat.ratio > 0) {
      EXPECT_NEAR(r.ratio / flat.ratio, 1, 1e-11);
    }
  }
  EXPECT_GE(slipping, 200);
}

TEST(MetricProjection, AStartingRatioGivesTheSameProjection) {
  const hertz<> h;
  for (const case_data& c : random_cases(200, 23)) {
    const planar_metric<double> metric(c.m);
    const auto r = project_to_limit_set(h, c.z, metric);
    if (r.sticking) continue;
    for (double start : {1e-3, 0.5, 3.0, 1e4}) {
      const auto s = project_to_limit_set(h, c.z, metric, curve_point<double>{start});
      EXPECT_NEAR(s.force[0], r.force[0], 1e-14);
      EXPECT_NEAR(s.force[1], r.force[1], 1e-14);
      EXPECT_NEAR(s.torque, r.torque, 1e-14);
    }
    // From the curve point the answer left (its values save an evaluation),
    // and from a wrong point (only a worse start): the same answer.
    const curve_point<double> wrong{0.5, 0.9, 0.1, 1.0, 0.0};
    for (const curve_point<double>& from : {r.curve(), wrong}) {
      const auto s = project_to_limit_set(h, c.z, metric, from);
      EXPECT_FALSE(s.sticking);
      EXPECT_NEAR(s.force[0], r.force[0], 1e-14);
      EXPECT_NEAR(s.force[1], r.force[1], 1e-14);
      EXPECT_NEAR(s.torque, r.torque, 1e-14);
    }
  }
}

TEST(MetricProjection, BadMetricOrPointIsADomainError) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(planar_metric<double>(matrix{{{1, 0, 0}, {0, 1, 0}, {0, 0, nan}}}),
               std::domain_error);
  EXPECT_THROW(planar_metric<double>(matrix{{{1, 0.5, 0}, {0, 1, 0}, {0, 0, 1}}}),
               std::domain_error);  // not symmetric
  EXPECT_THROW(planar_metric<double>(matrix{{{1, 2, 0}, {2, 1, 0}, {0, 0, 1}}}),
               std::domain_error);  // indefinite
  EXPECT_THROW(planar_metric<double>(matrix{{{1, 0, 0}, {0, 0, 0}, {0, 0, 1}}}),
               std::domain_error);  // singular
  EXPECT_THROW(planar_metric<double>(matrix{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1e-8}}}),
               std::domain_error);  // conditioned 1e8 (> 6.7e7)
  EXPECT_NO_THROW(planar_metric<double>(matrix{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1e-7}}}));
  const planar_metric<double> identity(matrix{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}});
  EXPECT_THROW(project_to_limit_set(uniform_disk<>(), tangent_wrench<double>{nan, 0, 0}, identity),
               std::domain_error);
  EXPECT_THROW(project_to_limit_set(
                   uniform_disk<>(),
                   tangent_wrench<double>{0, std::numeric_limits<double>::infinity(), 0}, identity),
               std::domain_error);
  EXPECT_THROW(project_to_limit_set(uniform_disk<>(), tangent_wrench<double>{2, 0, 0}, identity,
                                    curve_point<double>{-1}),
               std::domain_error);
}

// Pure sliding and pure spinning targets land on the curve's ends exactly.
TEST(MetricProjection, EndsOfTheCurve) {
  const planar_metric<double> identity(matrix{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}});
  const uniform_disk<> p;
  const auto slide = project_to_limit_set(p, tangent_wrench<double>{0, -3, 0}, identity);
  EXPECT_EQ(slide.force[0], 0);
  EXPECT_EQ(slide.force[1], -1);
  EXPECT_EQ(slide.torque, 0);
  EXPECT_TRUE(std::isinf(slide.ratio));
  const auto spin = project_to_limit_set(p, tangent_wrench<double>{0, 0, -3}, identity);
  EXPECT_EQ(spin.force[0], 0);
  EXPECT_EQ(spin.force[1], 0);
  EXPECT_DOUBLE_EQ(spin.torque, -p.mean_radius());
  EXPECT_EQ(spin.ratio, 0);
}

// issue 26 - the fuzzer's stall (fuzz_impulse, a libFuzzer campaign of a
// minute): with this metric Newton's method stalled with ∇Ψ ≈ 1e-7, its line
// search on Ψ's values below their rounding, and raised evaluation_error
// ("did not converge") from inside a step.  The line search now goes by the
// sign of Ψ's slope (contact/detail/metric_projector.hpp); the other types:
// test_projection_precision.cpp.
TEST(MetricProjection, RegressionStallWithANearlySingularMetric) {
  const planar_metric<double> metric(matrix{
      {{3.6685618490186893434e-05, 6.05685714625876865029e-05, 5.97917196785922641492e-05},
       {6.05685714625876865029e-05, 0.000100134811990465087336, 9.50470879699144067555e-05},
       {5.97917196785922641492e-05, 9.50470879699144067555e-05, 0.000297451352951397230123}}});
  const tangent_wrench<double> z{1, 0.97463330898909816824, 0.636651730873736165783};
  const uniform_disk<> p;
  const auto r = project_to_limit_set(p, z, metric);
  expect_optimal(p, metric.entries(), z, r);
}

// The projection of z for a load concentrated within radius 1e-6 (weight
// `load`) plus a ring (weight `ring_weight`) in the metric m: optimal, with
// the force along z's; returns it.
friction_result<std::array<double, 2>, double> expect_nearest_for_a_concentrated_load(
    double load, double ring_weight, const matrix& m, const tangent_wrench<double>& z) {
  const auto p =
      weighted_sum({load, ring_weight},
                   scaled<uniform_disk<double>>(uniform_disk<double>(), 9.99999999999999954748e-07),
                   ring<double>());
  const auto r = project_to_limit_set(p, z, planar_metric<double>(m));
  expect_optimal(p, m, z, r);
  EXPECT_GT(r.force[0] * z.force_x + r.force[1] * z.force_y, 0) << "the force along z's";
  return r;
}

// issue 26 - a load concentrated within radius 1e-6 plus a ring (fuzz_impulse,
// after the line search first went by the slope's sign): D has a near-corner
// at ε ≈ 1e-6, the line search's secant crawled there, and the answer came
// out with the force reversed, 600 times farther than the nearest point.
TEST(MetricProjection, RegressionNearCornerOfAConcentratedLoad) {
  expect_nearest_for_a_concentrated_load(
      41.8390708471192738216, 7.81116904277345813767,
      {{{9.79873218838664696218e-33, 9.89884952324594475011e-33, 9.87951583277085400931e-33},
        {9.89884952324594475011e-33, 1.89223252399063083355e-32, 1.94262695312499979925e-32},
        {9.87951583277085400931e-33, 1.94262695312499979925e-32, 2.01172356469797618285e-32}}},
      {0.5, -1, 0.56249964096966920124});
}

// issue 26 - the same kind of profile in another metric the fuzzer found
// (fuzz_impulse, seed 95): D is a cone in the force's slip beyond
// |s_f| ≈ 1e-6|s_t|, and Newton's steps zig-zagged across s_f = 0 for 100
// iterations, ending at ε = 0.027 on the far side, 150 times farther (in the
// metric) than the nearest point at ε = 5.4e-7, which 4e97082 found.  A
// step past s_f's nearest approach to 0 now goes first as far as that
// approach.
TEST(MetricProjection, RegressionConeOfAConcentratedLoad) {
  const auto r = expect_nearest_for_a_concentrated_load(
      31.6227766016838920393, 7.81116904277355406094,
      {{{9.70437632621352464096e-31, 9.85107352142570704785e-32, -8.50862389679481222685e-32},
        {9.85107352142570704785e-32, 2.00000085843897353057e-32, 1.3609218471852611338e-33},
        {-8.50862389679481222685e-32, 1.3609218471852611338e-33, 2.74565797735634131411e-32}}},
      {0.5, -1, 0.97647058823529420124});
  EXPECT_LT(r.ratio, 1e-6);
}

// issue 26 - a point 1e-14 beyond the corner (1, 0) in a metric conditioned
// 1e7 (fuzz_precision): the convergence test summed the rounding of every
// component of ∇Ψ, so the force's (of size 1) hid the torque's (1e-11), and
// Newton stopped at ε = 3e9 with a torque of 8e-11, 1e15 times farther (in
// the metric) than the nearest point, the corner itself to rounding.
TEST(MetricProjection, RegressionJustBeyondTheSlidingCorner) {
  const matrix m{{{3.60824494955364454278e-05, 0.0360498030912404995862, 0.0116453197301683609999},
                  {0.0360498030912404995862, 72.2172559404022962326, 47.6583507286468943676},
                  {0.0116453197301683609999, 47.6583507286468943676, 135.123387023362909076}}};
  const tangent_wrench<double> z{1, 1.30385149454959074868e-07, 3.4932955679265537702e-137};
  const double zf = std::hypot(z.force_x, z.force_y);
  const tangent_wrench<double> corner{z.force_x / zf, z.force_y / zf, 0};
  for (int k = 0; k < 2; ++k) {
    const auto r = k == 0 ? project_to_limit_set(uniform_disk<>(), z, planar_metric<double>(m))
                          : project_to_limit_set(hertz<>(), z, planar_metric<double>(m));
    ASSERT_FALSE(r.sticking);
    EXPECT_GT(r.ratio, 1e15);
    EXPECT_LE(metric_distance(m, wrench_of(r), z), metric_distance(m, corner, z) * (1 + 1e-9));
  }
}

}  // namespace
