//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The fast path of the metric projection (contact/detail/slip_newton.hpp,
// round_dissipation.hpp; issue 41) on its own, against the optimality
// conditions of the convex problem (the point on the curve at its ratio,
// and M(z − p) along the outward normal there), which prove the nearest
// point independently of how it was found; that it declines where it must
// (z inside the set, a slip out of its range), never claiming an answer;
// and how often it answers random problems alone (the careful iteration
// of metric_projector.hpp takes the rest).
#include <spinslide/spinslide.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>

#include "random_metric.hpp"

namespace {

using namespace spinslide;
using spinslide::detail::matrix3;
using spinslide::detail::vector3;

template <class Real>
struct problem {
  matrix3<Real> m, inverse;  // M, and M⁻¹
  vector3<Real> z;
};

// A random metric of condition κ (at a random scale, then divided by its
// largest diagonal entry as the projector does) and a target z at distance
// `far` from the origin in a random direction.
template <class Real>
problem<Real> random_problem(std::mt19937_64& rng, double kappa, double far) {
  const planar_metric<double> w(spinslide_test::random_spd_with_condition(rng, kappa));
  const double top = std::max({w.entries()[0][0], w.entries()[1][1], w.entries()[2][2]});
  problem<Real> p;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      p.m[i][j] = Real(w.entries()[i][j] / top);
      p.inverse[i][j] = Real(w.inverse()[i][j] * top);
    }
  std::normal_distribution<double> normal(0, 1);
  const double d[3] = {normal(rng), normal(rng), normal(rng)};
  const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  for (std::size_t i = 0; i < 3; ++i) p.z[i] = Real(far * d[i] / len);
  return p;
}

// The fast path's answer: the point ∇D(s) + ∇²D(s)δ and the ratio of s + δ;
// `answered` false where it declined.
template <class Real>
struct fast_answer {
  bool answered = false;
  vector3<Real> point{};
  Real ratio = 0;
  Real slope = 0;
};

// From the support guess |(Mz)_f|/|(Mz)_t| (as metric_projector does without
// a start) or from the profile's values at `start`.
template <class Profile, class Real = typename Profile::value_type>
fast_answer<Real> fast_path(const Profile& profile, const problem<Real>& p, Real start = 0) {
  using round = spinslide::detail::round_dissipation<Profile>;
  const round d(profile);
  const vector3<Real> u = spinslide::detail::multiply(p.m, p.z);
  const Real guess = std::sqrt(u[0] * u[0] + u[1] * u[1]) / std::fabs(u[2]);
  typename round::point x;
  vector3<Real> ms, step;
  fast_answer<Real> out;
  if (!d.start(p.z, p.m, p.inverse, d.at_ratio(start > 0 ? start : guess), x, ms) ||
      !spinslide::detail::slip_newton(d, p.z, p.inverse, x, ms, true, step))
    return out;
  out.answered = true;
  const vector3<Real> dp = spinslide::detail::multiply(x.hessian, step);
  for (std::size_t i = 0; i < 3; ++i) out.point[i] = x.grad[i] + dp[i];
  out.ratio = round::ratio_of(spinslide::detail::shifted(x.s, step, Real(1)));
  out.slope = x.slope;
  return out;
}

// The optimality conditions, in double from the answer's Real: |p_f| and
// |p_t| are the profile's 𝓕 and 𝓣 at the answer's ratio (to `ulps` of the
// type's epsilon), and M(z − p) lies along the outward normal (ε p̂_f,
// sign p_t) to `ulps` of its length times M's condition (plus what p's own
// rounding moves it by).
template <class Profile, class Real>
void expect_optimal(const Profile& profile, const problem<Real>& p, const fast_answer<Real>& a,
                    double ulps) {
  const double eps = std::numeric_limits<Real>::epsilon();
  const auto ft = profile.force_torque(a.ratio);
  const double f = std::hypot(double(a.point[0]), double(a.point[1]));
  EXPECT_NEAR(f, double(ft.force), ulps * eps * (1 + double(ft.force))) << "ratio " << a.ratio;
  EXPECT_NEAR(std::fabs(double(a.point[2])), double(ft.torque),
              ulps * eps * (1 + double(ft.torque)))
      << "ratio " << a.ratio;
  double s[3] = {0, 0, 0}, norm_m = 0;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      s[i] += double(p.m[i][j]) * (double(p.z[j]) - double(a.point[j]));
      norm_m += double(p.m[i][j]) * double(p.m[i][j]);
    }
  const double e = double(a.ratio), sigma = a.point[2] < 0 ? -1 : 1;
  const double len = std::hypot(e, 1.0);
  const double n[3] = {e * a.point[0] / f / len, e * a.point[1] / f / len, sigma / len};
  const double slen = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  const double along = s[0] * n[0] + s[1] * n[1] + s[2] * n[2];
  EXPECT_GT(along, 0) << "the slip points outwards";
  const double off = std::sqrt(std::pow(s[0] - along * n[0], 2) + std::pow(s[1] - along * n[1], 2) +
                               std::pow(s[2] - along * n[2], 2));
  EXPECT_LE(off, ulps * eps * (slen + std::sqrt(norm_m) * (1 + f)))
      << "normality, ratio " << a.ratio;
}

// On random problems (metrics of condition 1, 1e2 and 1e4, in float up to
// 1e3, which is what planar_metric<float> accepts; targets 2 to 1000 from
// the origin) every answer is optimal, from the support guess and from the
// answer's own ratio (a stored start); and at least `share` of the problems
// are answered from each.
template <class Profile>
void expect_optimal_on_random_problems(const Profile& profile, double ulps, double share) {
  using Real = typename Profile::value_type;
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(0, 1);
  int answered = 0, again_answered = 0, total = 0;
  for (const double kappa : {1.0, 1e2, sizeof(Real) == 4 ? 1e3 : 1e4})
    for (int i = 0; i < 300; ++i) {
      const problem<Real> p = random_problem<Real>(rng, kappa, std::pow(10.0, 3 * u(rng)) + 2);
      const fast_answer<Real> a = fast_path(profile, p);
      ++total;
      if (!a.answered) continue;
      ++answered;
      expect_optimal(profile, p, a, ulps * kappa);
      const fast_answer<Real> again = fast_path(profile, p, a.ratio);
      if (!again.answered) continue;
      ++again_answered;
      expect_optimal(profile, p, again, ulps * kappa);
    }
  EXPECT_GE(answered, share * total) << answered << " of " << total;
  EXPECT_GE(again_answered, share * total) << again_answered << " of " << total;
}

TEST(SlipNewton, OptimalOnRandomMetricsDouble) {
  expect_optimal_on_random_problems(uniform_disk<double>(), 8, 0.9);
  expect_optimal_on_random_problems(hertz<double>(), 8, 0.9);
  expect_optimal_on_random_problems(tabulated_profile<double>(annulus<double>(0.125)), 8, 0.9);
}

TEST(SlipNewton, OptimalOnRandomMetricsFloat) {
  expect_optimal_on_random_problems(uniform_disk<float>(), 8, 0.9);
  expect_optimal_on_random_problems(hertz<float>(), 8, 0.9);
}

// Inside the set (between the inner triangle and the curve: the careful
// iteration's 2-D test decides these) the minimum of Ψ is s = 0, where D has
// its kink: the fast path must decline, not answer.
TEST(SlipNewton, DeclinesInsideTheSet) {
  const hertz<double> h;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 400; ++i) {
    problem<double> p = random_problem<double>(rng, 1e2, 1);
    const double e = std::pow(10.0, 4 * u(rng) - 2), phi = 6.283185307179586 * u(rng);
    const auto c = h.force_torque(e);
    const double q = 0.9 + 0.0999 * u(rng);
    p.z = {q * c.force * std::cos(phi), q * c.force * std::sin(phi), (i % 2 ? -q : q) * c.torque};
    EXPECT_FALSE(fast_path(h, p).answered) << "z inside at ratio " << e;
    EXPECT_FALSE(fast_path(h, p, e).answered) << "z inside at ratio " << e;
  }
}

// A slip whose squares leave the normal numbers (a metric at 1e-200 of the
// targets' scale) is out of the fast path's range: it declines, and the
// projection still lands on the optimum by the careful iteration.
TEST(SlipNewton, DeclinesOutOfRangeAndTheProjectionStaysOptimal) {
  const hertz<double> h;
  problem<double> p;
  p.m = {{{1, 0.1, 0}, {0.1, 1, 0}, {0, 0, 1}}};
  const planar_metric<double> w(p.m);
  p.inverse = w.inverse();
  p.z = {3e-160, 1e-160, 2e-160};
  EXPECT_FALSE(fast_path(h, p).answered);
  const tangent_wrench<double> z{3, 1, 2};
  const auto r = project_to_limit_set(h, z, w);
  ASSERT_FALSE(r.sticking);
  fast_answer<double> a;
  a.point = {r.force[0], r.force[1], r.torque};
  a.ratio = r.ratio;
  p.z = {3, 1, 2};
  expect_optimal(h, p, a, 64);
}

// The impulse law's answer carries 𝓕′ (of its last iterate, within that
// step's first order of the answer's ratio) for the next step's start.
TEST(SlipNewton, TheAnswerCarriesTheSlope) {
  const hertz<double> h;
  const planar_metric<double> w({{{2, 0.3, 0.2}, {0.3, 1.5, -0.1}, {0.2, -0.1, 3}}});
  const impulse_contact<double> load{patch_radius<double>{1}, normal_impulse<double>{1e-3},
                                     friction_coefficient<double>{1}};
  for (const double e : {1e-3, 0.05, 0.6, 1.0, 3.0, 200.0}) {
    const auto r = impulse_friction(h, std::array<double, 2>{e, 0.5 * e}, 1.0, w, load);
    ASSERT_FALSE(r.sticking);
    const auto c = r.curve();
    EXPECT_NEAR(c.slope, h.force_derivative(c.ratio), 1e-6 * h.force_derivative(c.ratio))
        << "ratio " << c.ratio;
  }
}

}  // namespace
