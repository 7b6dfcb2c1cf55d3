//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The 3-D projection onto the limit set (limit_set.hpp, detail/
// metric_projector.hpp) in every floating type: float, double, long double
// and cpp_bin_float_50, over random metrics up to the condition number each
// type accepts (planar_metric: 1/√ε_mach, 4.1e3 in float, 6.7e7 in double),
// and the metric the fuzzer found a stall with (issue 26).  It must answer
// every call (no exception: it runs inside a simulation's step), and its
// answer must be the nearest point: on the curve at its ratio, and the slip
// M(z − p) along the outward normal there.  For a convex set these two
// conditions prove the nearest point; they are checked in 50 digits from
// the returned values.  The bound of the normality is the rounding the
// problem itself carries: an error of δ in p moves M(z − p) by ‖M‖δ, and p
// is known to about κ ε_mach (the metric's condition κ), so the test
// allows 16 κ ε_mach ‖M‖ (|z| + 1) off the normal, absolutely.

#include <gtest/gtest.h>

#include <spinslide/contact/limit_set.hpp>
#include <spinslide/values/coupling.hpp>
#include <spinslide/values/profile.hpp>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "random_metric.hpp"

namespace {

using namespace spinslide;
using big = boost::multiprecision::cpp_bin_float_50;

template <class Real>
using matrix_of = typename planar_metric<Real>::matrix;

// Condition numbers to test per type: a well-conditioned one, a middle one
// and the largest the type's planar_metric accepts with a margin (the
// Frobenius bound it checks is up to 3× the condition number).
template <class Real>
struct precision_plan;
template <>
struct precision_plan<float> {
  static std::vector<double> kappas() { return {5, 100, 1e3}; }
  static int cases() { return 600; }
};
template <>
struct precision_plan<double> {
  static std::vector<double> kappas() { return {10, 1e4, 2e7}; }
  static int cases() { return 600; }
};
template <>
struct precision_plan<long double> {
  static std::vector<double> kappas() { return {10, 1e6, 1e9}; }
  static int cases() { return 300; }
};
template <>
struct precision_plan<big> {
  // (The metrics are built in double: beyond about 1e12 its rounding would
  // make them indefinite.)
  static std::vector<double> kappas() { return {10, 1e6, 1e12}; }
  static int cases() { return 12; }
};

template <class Real>
big to_big(const Real& x) {
  return big(x);
}

template <class Real>
std::string name_of() {
  if (std::is_same<Real, float>::value) return "float";
  if (std::is_same<Real, double>::value) return "double";
  if (std::is_same<Real, long double>::value) return "long double";
  return "cpp_bin_float_50";
}

// A sticking answer: z unchanged, and (|z_f|, |z_t|) not above the curve
// (the torque the curve gives at that force).
template <class Profile>
void expect_sticking(const Profile& profile, const tangent_wrench<typename Profile::value_type>& z,
                     const friction_result<std::array<typename Profile::value_type, 2>,
                                           typename Profile::value_type>& r,
                     const std::string& where) {
  using Real = typename Profile::value_type;
  using std::fabs;
  const Real eps = std::numeric_limits<Real>::epsilon();
  EXPECT_EQ(r.force[0], z.force_x) << where;
  EXPECT_EQ(r.torque, z.torque) << where;
  const Real f = Real(hypot(to_big(z.force_x), to_big(z.force_y)));
  ASSERT_LE(f, Real(1)) << where;
  EXPECT_LE(fabs(z.torque), torque_at_force(profile, f) * (1 + 64 * eps) + 64 * eps) << where;
}

// The unit outward normal of L₃ at the answer: (ε f̂, σ)/√(ε² + 1), or
// (f̂, 0) at ε = ∞.
template <class Real>
std::array<big, 3> unit_normal(const friction_result<std::array<Real, 2>, Real>& r) {
  const big fx = to_big(r.force[0]), fy = to_big(r.force[1]);
  const big f = sqrt(fx * fx + fy * fy);
  const big dx = f > 0 ? fx / f : big(1), dy = f > 0 ? fy / f : big(0);
  if ((boost::math::isinf)(r.ratio)) return {dx, dy, big(0)};
  const big e = to_big(r.ratio), len = sqrt(e * e + 1);
  const big sigma = r.torque >= 0 ? 1 : -1;
  return {e * dx / len, e * dy / len, sigma / len};
}

// s = M(z − p) in 50 digits, and ‖M‖_F.
template <class Real>
std::array<big, 3> slip_of(const planar_metric<Real>& m, const tangent_wrench<Real>& z,
                           const friction_result<std::array<Real, 2>, Real>& r, big& norm_m) {
  const big d[3] = {to_big(z.force_x) - to_big(r.force[0]), to_big(z.force_y) - to_big(r.force[1]),
                    to_big(z.torque) - to_big(r.torque)};
  std::array<big, 3> s{};
  norm_m = 0;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      const big mij = to_big(m.entries()[i][j]);
      s[i] += mij * d[j];
      norm_m += mij * mij;
    }
  norm_m = sqrt(norm_m);
  return s;
}

// The optimality conditions of the answer r for z in the metric m, in 50
// digits: on the curve (to 8 ulp of the type), and M(z − p) along the
// outward normal (to the problem's rounding, see the file's comment) and
// pointing outwards.
template <class Profile>
void expect_nearest(const Profile& profile, const planar_metric<typename Profile::value_type>& m,
                    const tangent_wrench<typename Profile::value_type>& z,
                    const friction_result<std::array<typename Profile::value_type, 2>,
                                          typename Profile::value_type>& r,
                    const std::string& where) {
  using Real = typename Profile::value_type;
  if (r.sticking) return expect_sticking(profile, z, r, where);
  const double eps = static_cast<double>(std::numeric_limits<Real>::epsilon());
  const big f = hypot(to_big(r.force[0]), to_big(r.force[1]));
  const auto c = profile.force_torque(r.ratio);
  EXPECT_LE(static_cast<double>(abs(f - to_big(c.force))), 8 * eps) << where;
  EXPECT_LE(static_cast<double>(abs(abs(to_big(r.torque)) - to_big(c.torque))), 8 * eps) << where;
  big norm_m;
  const std::array<big, 3> s = slip_of(m, z, r, norm_m), n = unit_normal(r);
  const big along = s[0] * n[0] + s[1] * n[1] + s[2] * n[2];
  big off = 0;
  for (std::size_t i = 0; i < 3; ++i) off += (s[i] - along * n[i]) * (s[i] - along * n[i]);
  off = sqrt(off);
  const big size =
      1 + sqrt(to_big(z.force_x) * to_big(z.force_x) + to_big(z.force_y) * to_big(z.force_y) +
               to_big(z.torque) * to_big(z.torque));
  const big allowed = 16 * to_big(m.condition_bound()) * big(eps) * norm_m * size;
  EXPECT_LE(static_cast<double>(off / allowed), 1.0) << where << ": off the normal by " << off;
  EXPECT_GE(static_cast<double>(along), -static_cast<double>(allowed)) << where << ": inwards";
}

template <class Profile>
void project_random_cases(const Profile& profile, const std::string& profile_name) {
  using Real = typename Profile::value_type;
  std::mt19937_64 rng(26);
  std::uniform_real_distribution<double> u(-1.5, 1.5), decade(-4, 4);
  for (double kappa : precision_plan<Real>::kappas()) {
    int slipping = 0;
    for (int k = 0; k < precision_plan<Real>::cases(); ++k) {
      const auto md = spinslide_test::random_spd_with_condition(rng, kappa);
      matrix_of<Real> m{};
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) m[i][j] = Real(md[i][j]);
      const planar_metric<Real> metric(m);
      // Mostly O(1) targets; every fourth scaled by 10^±4 (far outside, or
      // near the origin and inside).
      const double scale = k % 4 == 3 ? std::pow(10.0, decade(rng)) : 1.0;
      const tangent_wrench<Real> z{Real(scale * u(rng)), Real(scale * u(rng)),
                                   Real(scale * u(rng))};
      const std::string where = name_of<Real>() + " " + profile_name + ", condition " +
                                std::to_string(kappa) + ", case " + std::to_string(k);
      const friction_result<std::array<Real, 2>, Real> r = project_to_limit_set(profile, z, metric);
      expect_nearest(profile, metric, z, r, where);
      slipping += r.sticking ? 0 : 1;
    }
    EXPECT_GE(slipping, precision_plan<Real>::cases() / 2) << name_of<Real>() << " " << kappa;
  }
}

// The metric of the fuzzer's stall (fuzz_impulse; it threw "did not
// converge" before the line search went by the slope's sign), in the type.
template <class Real>
matrix_of<Real> the_fuzzers_metric() {
  return {{{Real(3.6685618490186893434e-05L), Real(6.05685714625876865029e-05L),
            Real(5.97917196785922641492e-05L)},
           {Real(6.05685714625876865029e-05L), Real(0.000100134811990465087336L),
            Real(9.50470879699144067555e-05L)},
           {Real(5.97917196785922641492e-05L), Real(9.50470879699144067555e-05L),
            Real(0.000297451352951397230123L)}}};
}

// Conditioned 2e4, beyond float's 1/√ε = 4.1e3: refused at set-up.
void expect_refused_in_float() {
  EXPECT_THROW(planar_metric<float>{the_fuzzers_metric<float>()}, std::domain_error);
}

template <class Real>
void project_the_fuzzers_metric() {
  const matrix_of<Real> m = the_fuzzers_metric<Real>();
  if (std::is_same<Real, float>::value) return expect_refused_in_float();
  const planar_metric<Real> metric(m);
  const tangent_wrench<Real> z{Real(1), Real(0.97463330898909816824L),
                               Real(0.636651730873736165783L)};
  const uniform_disk<Real> p;
  const auto r = project_to_limit_set(p, z, metric);
  expect_nearest(p, metric, z, r, name_of<Real>() + " the fuzzer's metric");
}

template <class Real>
class ProjectionPrecision : public ::testing::Test {};
using Types = ::testing::Types<float, double, long double, big>;
// Test names per type (for CTest, without spaces).
struct TypeNames {
  template <class T>
  static std::string GetName(int) {
    std::string n = name_of<T>();
    for (char& c : n)
      if (c == ' ') c = '_';
    return n;
  }
};
TYPED_TEST_SUITE(ProjectionPrecision, Types, TypeNames);

TYPED_TEST(ProjectionPrecision, UniformDiskOverRandomMetrics) {
  project_random_cases(uniform_disk<TypeParam>(), "uniform_disk");
}

TYPED_TEST(ProjectionPrecision, HertzOverRandomMetrics) {
  project_random_cases(hertz<TypeParam>(), "hertz");
}

TYPED_TEST(ProjectionPrecision, AnnulusOverRandomMetrics) {
  project_random_cases(annulus<TypeParam>(TypeParam(0.125)), "annulus(0.125)");
}

TYPED_TEST(ProjectionPrecision, TheFuzzersMetric) { project_the_fuzzers_metric<TypeParam>(); }

// The same answers in every type: float's and long double's against
// double's, to the coarser type's rounding times the condition number.
TEST(ProjectionPrecision, TheTypesAgree) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int k = 0; k < 300; ++k) {
    const auto md = spinslide_test::random_spd_with_condition(rng, 100);
    matrix_of<float> mf{};
    matrix_of<long double> ml{};
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) {
        mf[i][j] = static_cast<float>(md[i][j]);
        ml[i][j] = md[i][j];
      }
    const tangent_wrench<double> z{u(rng), u(rng), u(rng)};
    const auto rd = project_to_limit_set(hertz<double>(), z, planar_metric<double>(md));
    const auto rf = project_to_limit_set(
        hertz<float>(), tangent_wrench<float>{float(z.force_x), float(z.force_y), float(z.torque)},
        planar_metric<float>(mf));
    const auto rl = project_to_limit_set(
        hertz<long double>(), tangent_wrench<long double>{z.force_x, z.force_y, z.torque},
        planar_metric<long double>(ml));
    if (rd.sticking != rf.sticking) continue;  // z on the boundary to float's rounding
    EXPECT_EQ(rd.sticking, rl.sticking);
    EXPECT_NEAR(rf.force[0], rd.force[0], 100 * 64 * 6e-8) << k;
    EXPECT_NEAR(rf.torque, rd.torque, 100 * 64 * 6e-8) << k;
    EXPECT_NEAR(double(rl.force[0]), rd.force[0], 100 * 64 * 1.1e-16) << k;
    EXPECT_NEAR(double(rl.torque), rd.torque, 100 * 64 * 1.1e-16) << k;
  }
}

}  // namespace
