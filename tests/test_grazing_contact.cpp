//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The impulse law for every patch radius from a = 0 up (issue 27: a grazing
// contact, a patch that grows from nothing; docs/theory.md §11, "A patch
// that starts at zero").  Against independent results: the least kinetic
// energy over a dense scan of the limit set's surface (the law's defining
// property), point friction at a = 0 from a scan of the circle |P| = μΛ and
// a bisection for its multiplier, and the law's own conditions.

#include <gtest/gtest.h>

#include <spinslide/contact/impulse_friction.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "foot_metric.hpp"
#include "random_metric.hpp"

namespace {

using namespace spinslide;
using vec2 = std::array<double, 2>;
using vec3 = std::array<double, 3>;
using matrix = planar_metric<double>::matrix;

constexpr double pi = 3.14159265358979323846;

impulse_contact<double> contact(double radius, double normal, double mu) {
  return {patch_radius<double>{radius}, normal_impulse<double>{normal},
          friction_coefficient<double>{mu}};
}

// ½ (z − p)ᵀ W (z − p) for the stopping impulse z = −W⁻¹s: the kinetic
// energy the impulse p leaves (½ (s + Wp)ᵀ W⁻¹ (s + Wp)).
double energy_left(const matrix& w, const vec3& z, const vec3& p) {
  const double d[3] = {z[0] - p[0], z[1] - p[1], z[2] - p[2]};
  double e = 0;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) e += d[i] * w[i][j] * d[j];
  return e / 2;
}

vec3 stopping_impulse(const planar_metric<double>& w, const vec3& s) {
  vec3 z{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) z[i] -= w.inverse()[i][j] * s[j];
  return z;
}

// The least energy_left over the surface of μΛ·{(f, a t)}: |P| = μΛ𝓕(ε),
// L = ±μΛa𝓣(ε), for 720 directions and ε = 10^(−6 … 8) in 4000 steps and
// ∞, and over the stopping impulse itself if it lies inside.  A scan: its
// minimum is at or above the true one, by the scan's resolution.
template <class Profile>
double least_energy_by_scan(const Profile& profile, const matrix& w, const vec3& z, double a,
                            double bound) {
  std::vector<double> f, t;
  for (int i = 0; i <= 4000; ++i) {
    const auto ft = profile.force_torque(std::pow(10.0, -6 + 14.0 * i / 4000));
    f.push_back(ft.force);
    t.push_back(ft.torque);
  }
  f.push_back(1);
  t.push_back(0);
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 720; ++k) {
    const double c = std::cos(2 * pi * k / 720), s = std::sin(2 * pi * k / 720);
    for (std::size_t i = 0; i < f.size(); ++i)
      for (const double sign : {-1.0, 1.0}) {
        const vec3 p{bound * f[i] * c, bound * f[i] * s, sign * bound * a * t[i]};
        best = std::min(best, energy_left(w, z, p));
      }
  }
  return best;
}

// Point friction at a = 0, independently: P* = −W_ff⁻¹ v by the 2×2
// inverse if |P*| ≤ μΛ; else P(λ) = −(W_ff + λI)⁻¹ v on the circle |P| =
// μΛ, λ > 0 by 200 bisections in long double between 0 and |v|/(μΛ).
vec2 point_friction_by_bisection(const matrix& w, const vec3& s, double bound) {
  auto at = [&](long double lambda) {
    const long double p = w[0][0] + lambda, q = w[1][1] + lambda, b = w[0][1];
    const long double det = p * q - b * b;
    return std::array<long double, 2>{-(q * s[0] - b * s[1]) / det, -(p * s[1] - b * s[0]) / det};
  };
  auto size = [](const std::array<long double, 2>& x) { return std::hypot(x[0], x[1]); };
  if (size(at(0)) <= bound) return {double(at(0)[0]), double(at(0)[1])};
  long double lo = 0, hi = std::hypot(s[0], s[1]) / bound;
  for (int i = 0; i < 200; ++i) {
    const long double mid = (lo + hi) / 2;
    (size(at(mid)) > bound ? lo : hi) = mid;
  }
  const auto p = at((lo + hi) / 2);
  return {double(p[0]), double(p[1])};
}

// The issue's humanoid grazing contact (a = 2.7e-8 m threw "contact.radius
// = 2.7e-08 ... condition number") and every radius from 0 to 1000 m: an
// answer in the set that leaves no more energy than the best point of a
// dense scan of the set's surface.  Two loads: sliding (1e-3) and the
// foot's linear slip stopped while it spins (1).
TEST(GrazingContact, EveryPatchRadiusFromZeroUpIsValidAndOptimal) {
  const matrix w = spinslide_test::foot_inverse_mass();
  const planar_metric<double> inverse_mass(w);
  const hertz<> sphere;
  const uniform_disk<> disk;
  const vec3 s{0.3, -0.1, 2.0};
  const vec3 z = stopping_impulse(inverse_mass, s);
  for (const double a : {0.0, 1e-300, 1e-30, 1e-14, 2.7e-8, 1e-6, 1e-3, 0.03, 0.3, 3.0, 1e3})
    for (const double load : {1e-3, 1.0}) {
      const double bound = 0.5 * load;
      const auto r =
          impulse_friction(sphere, vec2{s[0], s[1]}, s[2], inverse_mass, contact(a, load, 0.5));
      const auto q =
          impulse_friction(disk, vec2{s[0], s[1]}, s[2], inverse_mass, contact(a, load, 0.5));
      const vec3 p{r.force[0], r.force[1], r.torque}, pd{q.force[0], q.force[1], q.torque};
      EXPECT_LE(std::hypot(p[0], p[1]), bound * (1 + 1e-12)) << a;
      EXPECT_LE(std::fabs(p[2]), bound * a * sphere.mean_radius() * (1 + 1e-12)) << a;
      const double e = energy_left(w, z, p), scan = least_energy_by_scan(sphere, w, z, a, bound);
      const double ed = energy_left(w, z, pd), scan_d = least_energy_by_scan(disk, w, z, a, bound);
      const double slack = 1e-12 * energy_left(w, z, vec3{});
      if (r.sticking) {
        EXPECT_NEAR(e, 0, slack) << a;
      } else {
        EXPECT_LE(e, scan + slack) << "a = " << a << ", load = " << load;
        EXPECT_GE(e, scan * (1 - 1e-3) - slack) << "the scan's resolution: " << a;
      }
      if (!q.sticking) {
        EXPECT_LE(ed, scan_d + slack) << "disk, a = " << a << ", load = " << load;
      }
    }
}

// At a = 0 the law is point friction: P from the 2×2 problem alone, no
// angular impulse, the ratio of a slide that goes on ∞ (a = 0), of one that
// stopped 0 (while the spin goes on).
TEST(GrazingContact, ZeroRadiusIsPointFriction) {
  std::mt19937_64 rng(27);
  std::uniform_real_distribution<double> u(-1, 1);
  const hertz<> sphere;
  int slides = 0, stops = 0;
  for (int n = 0; n < 300; ++n) {
    const matrix w = spinslide_test::random_spd(rng, 0.05, 0);
    const planar_metric<double> inverse_mass(w);
    const vec3 s{u(rng), u(rng), u(rng)};
    const double load = std::exp(3 * u(rng));
    const auto r =
        impulse_friction(sphere, vec2{s[0], s[1]}, s[2], inverse_mass, contact(0, load, 0.5));
    const vec2 expected = point_friction_by_bisection(w, s, 0.5 * load);
    EXPECT_NEAR(r.force[0], expected[0], 1e-14 * load) << n;
    EXPECT_NEAR(r.force[1], expected[1], 1e-14 * load) << n;
    EXPECT_EQ(r.torque, 0);
    EXPECT_FALSE(r.sticking);  // the spin is never stopped: nothing resists it
    if (std::hypot(expected[0], expected[1]) < 0.5 * load * (1 - 1e-9)) {
      ++stops;
      EXPECT_EQ(r.ratio, 0) << n;
    } else {
      ++slides;
      EXPECT_EQ(r.ratio, std::numeric_limits<double>::infinity()) << n;
    }
  }
  EXPECT_GE(slides, 50);
  EXPECT_GE(stops, 30);
}

// A patch that grows from nothing: the impulse tends to point friction's
// as a → 0, about as κk (k = a/c, c = W's length scale, κ W's condition):
// no jump where the law switches to the limit (k = 16√κ ε_mach) beyond that.
TEST(GrazingContact, ImpulseTendsToPointFrictionAsThePatchShrinks) {
  const matrix w = spinslide_test::foot_inverse_mass();
  const planar_metric<double> inverse_mass(w);
  const double c = std::sqrt((w[0][0] + w[1][1]) / (2 * w[2][2]));
  const double kappa = inverse_mass.condition_bound();
  const hertz<> sphere;
  for (const vec3& s : {vec3{0.3, -0.1, 2.0}, vec3{0.01, 0.02, -3.0}, vec3{-0.5, 0.4, 0.1}})
    for (const double load : {1e-3, 0.1, 1.0}) {
      const auto point =
          impulse_friction(sphere, vec2{s[0], s[1]}, s[2], inverse_mass, contact(0, load, 0.5));
      for (double k = 1e-2; k > 1e-17; k /= 10) {
        const auto r = impulse_friction(sphere, vec2{s[0], s[1]}, s[2], inverse_mass,
                                        contact(k * c, load, 0.5));
        const double gap = std::hypot(r.force[0] - point.force[0], r.force[1] - point.force[1]);
        EXPECT_LE(gap, 10 * kappa * k * 0.5 * load + 1e-15 * load) << "k = " << k;
        EXPECT_LE(std::fabs(r.torque), 0.5 * load * k * c * sphere.mean_radius() * (1 + 1e-12));
      }
    }
}

// Random inverse masses whose angular block is far from the linear one's
// scale (ρ from 1e-3 to 1e3: a body's radius of gyration in metres), every
// patch radius from 0 and 1e-40 to 1e4: never an exception or a NaN, never
// more kinetic energy, the impulse inside the set; where the set is thick
// (a ≥ 1e-3 c), the law's conditions: |P| = μΛ𝓕(ε), |L| = μΛa𝓣(ε) at the
// slip's own ratio, against the slip.
template <class Matrix>
bool accepted(const Matrix& m) {
  try {
    planar_metric<typename Matrix::value_type::value_type>{m};
    return true;
  } catch (const std::domain_error&) {
    return false;
  }
}

// One random case: W (its angular row and column divided by ρ), the slip
// and the contact.
template <class Real>
struct random_case {
  planar_metric<Real> w;
  Real rho, a, vx, vy, spin, load;
};

template <class Real>
random_case<Real> draw(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1), u01(0, 1);
  typename planar_metric<Real>::matrix m{};
  double rho = 1;
  do {  // until planar_metric accepts the condition (within 1/√ε_mach)
    const matrix md = spinslide_test::random_spd_with_condition(rng, std::pow(10.0, 3 * u01(rng)));
    rho = std::pow(10.0, 3 * u(rng));
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j)
        m[i][j] = Real(md[i][j] / (i == 2 ? rho : 1.0) / (j == 2 ? rho : 1.0));
  } while (!accepted(m));
  // a from 0 and 1e-40 to 1e3 times W's own length scale (beyond 1/(16√κ
  // ε_mach) of it, 5e5/√κ in float, a patch is a domain error).
  const double own = std::sqrt(static_cast<double>((m[0][0] + m[1][1]) / (2 * m[2][2])));
  const Real a = u01(rng) < 0.05 ? Real(0) : Real(own * std::pow(10.0, -40 + 43 * u01(rng)));
  const Real vx = Real(u(rng)), vy = Real(u(rng)), spin = Real(u(rng) / rho);
  return {planar_metric<Real>(m), Real(rho), a, vx, vy, spin, Real(std::pow(10.0, 2 * u(rng)))};
}

// The slip after the impulse p, in long double.
template <class Real>
std::array<long double, 3> slip_after(const planar_metric<Real>& w,
                                      const std::array<long double, 3>& s,
                                      const std::array<long double, 3>& p) {
  std::array<long double, 3> after{};
  for (std::size_t i = 0; i < 3; ++i)
    after[i] =
        s[i] + w.entries()[i][0] * p[0] + w.entries()[i][1] * p[1] + w.entries()[i][2] * p[2];
  return after;
}

template <class Real>
long double energy_of(const planar_metric<Real>& w, const std::array<long double, 3>& s) {
  long double e = 0;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) e += s[i] * w.inverse()[i][j] * s[j];
  return e;
}

// The law's conditions at a slip after the step that is resolved (not
// nearly stopped: its ratio and direction carry the impulse's error times
// W, about κ ε_mach of s): |P| = μΛ𝓕(ε), |L| = μΛa𝓣(ε) at its own ratio,
// against it.  False if the case is not resolved.
template <class Real>
bool law_holds(const random_case<Real>& c, const impulse_result<std::array<Real, 2>, Real>& r,
               const std::array<long double, 3>& s, const std::array<long double, 3>& p,
               const std::array<long double, 3>& after, double tolerance) {
  const long double speed = std::hypot(after[0], after[1]);
  const long double resolved = 10 * std::sqrt(tolerance);
  if (speed < resolved * std::hypot(s[0], s[1]) || std::fabs(after[2]) < resolved * std::fabs(s[2]))
    return false;
  const hertz<Real> sphere;
  const long double bound = 0.5L * c.load;
  const Real ratio = Real(speed / (c.a * std::fabs(after[2])));
  EXPECT_NEAR(static_cast<double>(r.ratio / ratio), 1, 1e5 * tolerance);
  const auto ft = sphere.force_torque(ratio);
  EXPECT_NEAR(static_cast<double>(std::hypot(p[0], p[1]) / bound), double(ft.force),
              1e3 * tolerance);
  EXPECT_NEAR(static_cast<double>(std::fabs(p[2]) / (bound * c.a)), double(ft.torque),
              1e3 * tolerance);
  EXPECT_LE(static_cast<double>(p[0] * after[0] + p[1] * after[1]), 0);
  EXPECT_LE(static_cast<double>(p[2] * after[2]), 0);
  return true;
}

// The checks of one case: a finite impulse inside the set that leaves no
// more kinetic energy; where the set is thick (a ≥ 1e-3 of W's scale) and
// the slip resolved, the law's conditions.  True if those were checked.
template <class Real>
bool check_case(const random_case<Real>& c, const impulse_result<std::array<Real, 2>, Real>& r,
                double tolerance) {
  const hertz<Real> sphere;
  const std::array<long double, 3> s{c.vx, c.vy, c.spin}, p{r.force[0], r.force[1], r.torque};
  EXPECT_TRUE(std::isfinite(static_cast<double>(p[0] + p[1] + p[2])));
  const auto after = slip_after(c.w, s, p);
  EXPECT_LE(energy_of(c.w, after), energy_of(c.w, s) * (1 + tolerance)) << "a = " << c.a;
  const long double bound = 0.5L * c.load;
  EXPECT_LE(std::hypot(p[0], p[1]), bound * (1 + tolerance));
  // (Plus the type's least subnormal: a torque bound μΛa⟨r⟩ below the
  // normal numbers, 1e-42 in float, is rounded to it.)
  EXPECT_LE(std::fabs(p[2]), bound * c.a * sphere.mean_radius() * (1 + tolerance) +
                                 std::numeric_limits<Real>::denorm_min());
  const auto& e = c.w.entries();
  const double own = std::sqrt(static_cast<double>((e[0][0] + e[1][1]) / (2 * e[2][2])));
  return !r.sticking && c.a >= 1e-3 * own && law_holds(c, r, s, p, after, tolerance);
}

template <class Real>
void random_patches(int count, double tolerance) {
  std::mt19937_64 rng(270);
  const hertz<Real> sphere;
  int checked = 0;
  for (int n = 0; n < count; ++n) {
    const random_case<Real> c = draw<Real>(rng);
    const auto r = impulse_friction(
        sphere, std::array<Real, 2>{c.vx, c.vy}, c.spin, c.w,
        impulse_contact<Real>{patch_radius<Real>{c.a}, normal_impulse<Real>{c.load},
                              friction_coefficient<Real>{Real(0.5)}});
    SCOPED_TRACE(n);
    checked += check_case(c, r, tolerance) ? 1 : 0;
  }
  EXPECT_GE(checked, count / 30);
}

TEST(GrazingContact, RandomPatchesInFloat) { random_patches<float>(20000, 1e-4); }
TEST(GrazingContact, RandomPatchesInDouble) { random_patches<double>(60000, 1e-11); }
TEST(GrazingContact, RandomPatchesInLongDouble) { random_patches<long double>(20000, 1e-11); }

}  // namespace

namespace {

// The kinetic energy ½ sᵀW⁻¹s before and after the impulse r.
template <class Impulse>
std::array<double, 2> energies(const spinslide::planar_metric<double>& w,
                               const std::array<double, 3>& s, const Impulse& r) {
  std::array<double, 3> after = s;
  for (std::size_t i = 0; i < 3; ++i)
    after[i] += w.entries()[i][0] * r.force[0] + w.entries()[i][1] * r.force[1] +
                w.entries()[i][2] * r.torque;
  double e0 = 0, e1 = 0;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      e0 += s[i] * w.inverse()[i][j] * s[j];
      e1 += after[i] * w.inverse()[i][j] * after[j];
    }
  return {e0, e1};
}

spinslide::planar_metric<double> metric_of(const std::array<double, 9>& m) {
  return spinslide::planar_metric<double>(spinslide::planar_metric<double>::matrix{
      {{m[0], m[1], m[2]}, {m[3], m[4], m[5]}, {m[6], m[7], m[8]}}});
}

}  // namespace

// issue 27, fuzz_impulse campaign (seeds 2701-2866, on the first version of
// the patch's frame): a spin without slide at a = 0 gave NaN (v/|v| of 0);
// a slip of 1.8e308 at a = 0 an infinite impulse (P from its units as
// P'·|v|/W_xx); a patch 1e98 times W's length scale (and others from 1e41)
// an impulse that added energy (its torque axis was clamped).  Now: no
// impulse for no slide, the impulse of point friction without overflow, and
// a domain error for a patch beyond 1/(16√κ ε) of W's scale.
TEST(GrazingContact, RegressionPointFrictionAtTheEdgesOfDouble) {
  using spinslide::impulse_friction;
  const auto pure_spin = impulse_friction(
      spinslide::boussinesq<>(), std::array<double, 2>{-0.0, -0.0}, 0.0669685139302527293603,
      metric_of({0.0535342564398159151406, -0.00200522875326848530608, 0.227675833812460065575,
                 -0.00200522875326848530608, 0.000150222321855049840414, -0.0123198611309739969322,
                 0.227675833812460065575, -0.0123198611309739969322, 2.01884015636515856684}),
      contact(0, 2932912241447943.5, 0.000121702336669193847082));
  EXPECT_EQ(pure_spin.force[0], 0);
  EXPECT_EQ(pure_spin.force[1], 0);
  EXPECT_EQ(pure_spin.torque, 0);
  const double huge = std::numeric_limits<double>::max();
  const auto w = metric_of({1568.79123798539058043, -3960.78431372549039224, -3960.7830300342807277,
                            -3960.78431372549039224, 20000.0100000000020373, 19999.9967589974403381,
                            -3960.7830300342807277, 19999.9967589974403381, 21568.13258064852198});
  const auto fast = impulse_friction(spinslide::annulus<>(0.301960784011764682422),
                                     std::array<double, 2>{huge, huge}, huge, w,
                                     contact(0, huge, 0.55585171583125159156));
  EXPECT_TRUE(std::isfinite(fast.force[0]) && std::isfinite(fast.force[1])) << fast.force[0];
  EXPECT_LE(std::hypot(fast.force[0] / huge, fast.force[1] / huge), 0.5559 * (1 + 1e-12));
  EXPECT_THROW(impulse_friction(spinslide::uniform_disk<>(), std::array<double, 2>{1.0, 1.0}, 0.5,
                                w, contact(1e98, 0.5, 3.22586402035085524775e-12)),
               std::domain_error);
}

// issue 27, the second fuzz_impulse campaign (seeds 2901-2938): a spin
// without slide on a thin set (a = 3.5e-10 m, k = 6e-12) started from the
// flat cap and added energy (the thin start had no ratio for P = 0; it is
// now near pure spin); μΛ·W_xx/|v| overflowed at |v| = 2.5e307, μΛ =
// 2.2e304, and the impulse was 1.3 μΛ.
TEST(GrazingContact, RegressionThinSetSpinningWithoutSlideAndAnOverflowingBound) {
  using spinslide::impulse_friction;
  const auto w = metric_of(
      {0.0099999921747106236547, -0.0436887351706173321375, -9.01957063308911279227e-05,
       -0.0436887351706173321375, 0.38174363217178214347, 0.000838420424211758046062,
       -9.01957063308911279227e-05, 0.000838420424211758046062, 5.07388371495222646984e-05});
  const std::array<double, 3> s{-0.0, 0.0, 0.847100007243188124484};
  const auto r = impulse_friction(
      spinslide::tabulated_profile<>(spinslide::hertz<>()), std::array<double, 2>{s[0], s[1]}, s[2],
      w, contact(3.51314465097633716147e-10, 2.18024280024411210022, 0.584313725490196111956));
  const auto e = energies(w, s, r);
  EXPECT_LE(e[1], e[0] * (1 + 1e-12));
  const auto big =
      metric_of({85.5625996155675494492, 823.559284161241748734, 80.9329340938424621754,
                 823.559284161241748734, 16464.9081788275543659, 1633.70741069645168864,
                 80.9329340938424621754, 1633.70741069645168864, 241.361397815526601107});
  const double load = std::numeric_limits<double>::max(), mu = 0.00012207007966924533738;
  const auto q = impulse_friction(
      spinslide::boussinesq<>(), std::array<double, 2>{0.5, 2.52147372693665684655e+307},
      0.999999571595758363074, big, contact(6.10455749468675460613e-310, load, mu));
  EXPECT_LE(std::hypot(q.force[0], q.force[1]), load * mu * (1 + 1e-12));
}

// issue 27, the third fuzz_impulse campaign (seed 3201): a load
// concentrated within radius 1e-6 plus a ring (𝓕 rises within ε ≈ 1e-6) on a
// patch of 6.7e-14 m: the set is thin at k·1e-6 ≈ 7e-20, below what the
// 3-D projection resolves, though k itself was above the threshold; the
// impulse added energy.  The threshold now takes the profile's own width
// 2/⟨1/r⟩ into account.
TEST(GrazingContact, RegressionThinPatchOfAConcentratedLoad) {
  const auto profile =
      spinslide::weighted_sum({4387.06194918419896567, 341.301477989606269148},
                              spinslide::scaled<spinslide::uniform_disk<>>(
                                  spinslide::uniform_disk<>(), 9.99999999999999954748e-07),
                              spinslide::ring<>());
  const auto w =
      metric_of({17.6071742022299098096, -31.4294502114571265849, 9.30044809071360312203,
                 -31.4294502114571265849, 62.342698174256646837, -3.76222331749995753114,
                 9.30044809071360312203, -3.76222331749995753114, 40.4514087138348941153});
  const std::array<double, 3> s{-1, 0.5, 3.87031576221226901545e-204};
  const auto r = spinslide::impulse_friction(
      profile, std::array<double, 2>{s[0], s[1]}, s[2], w,
      contact(6.66084629080915816834e-14, 1.2392140197186438666, 0.505876144711100206308));
  const auto e = energies(w, s, r);
  EXPECT_LE(e[1], e[0] * (1 + 1e-12));
  EXPECT_LE(std::hypot(r.force[0], r.force[1]),
            1.2392140197186438666 * 0.505876144711100206308 * (1 + 1e-12));
}

// issue 41, fuzz_impulse after the thin set's kernel (thin_set.hpp): a
// patch of 6.7e-97 m in an inverse mass of size 1e-40 with a linear slip of
// 7.7e49: the kernel's misses overflowed at the ends of its bracket, TOMS
// 748 interpolated a ratio that was not a number, and the profile raised a
// domain error inside the step.  Now such a search ends, and the answer is
// point friction's, the limit's guaranteed one: no exception, no energy
// added, within the load.
TEST(GrazingContact, RegressionThinSetSearchWhoseMissesOverflow) {
  const auto profile =
      spinslide::weighted_sum({18147.7809862788089958, 18147.7809863932707231},
                              spinslide::scaled<spinslide::uniform_disk<>>(
                                  spinslide::uniform_disk<>(), 0.603921568627451943456),
                              spinslide::ring<>());
  const auto w = metric_of(
      {5.03822607074202414446e-41, 5.03821607074202367717e-41, -6.65441656952315104034e-41,
       5.03821607074202367717e-41, 1.00752068349840169231e-40, -9.1866897868907220724e-41,
       -6.65441656952315104034e-41, -9.1866897868907220724e-41, 1.13356611213521740219e-40});
  const std::array<double, 3> s{7.68463292285583707332e+49, 6.6608462908091579737e-140,
                                6.6608462908091579737e-140};
  const double normal = 6.701283273246188529e-98, mu = 0.854879940258665538266;
  spinslide::impulse_result<std::array<double, 2>, double> r{};
  ASSERT_NO_THROW(r = spinslide::impulse_friction(profile, std::array<double, 2>{s[0], s[1]}, s[2],
                                                  w,
                                                  contact(6.65710292151228178857e-97, normal, mu)));
  const auto e = energies(w, s, r);
  EXPECT_LE(e[1], e[0] * (1 + 1e-12));
  EXPECT_LE(std::hypot(r.force[0], r.force[1]), normal * mu * (1 + 1e-12));
}
