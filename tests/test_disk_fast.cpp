//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The fast path of force, torque and force_torque for double and float
// (values/detail/disk_fast.hpp, tables from tools/generate_disk_tables.cpp), densely,
// against the long double evaluation of the Carlson forms and series (an
// independent algorithm, itself checked against the quadrature table in
// test_disk_reference.cpp; its error, ≤ 8 long double eps, is 1/256 of a
// double ulp).  Goals (issue 6): ≤ 4 ulp for double, ≤ 2 ulp for float.
#include <gtest/gtest.h>

#include <spinslide/values/disk.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

// |computed − exact| in units of the spacing of Real at the exact value.
template <class Real>
long double ulps(Real computed, long double exact) {
  int e;
  std::frexp(exact, &e);
  const long double ulp = std::ldexp(1.0L, e - std::numeric_limits<Real>::digits);
  return std::fabs(static_cast<long double>(computed) - exact) / ulp;
}

struct worst {
  long double error = 0;
  double at = 0;
  void add(long double e, double x) {
    if (e > error) {
      error = e;
      at = x;
    }
  }
};

// ≥ 10⁶ ratios: log-uniform over the whole range, log-uniform over the
// working range, clustered at ε = 1 (where K diverges and the table's finest
// pieces are), and uniform on [0, 4].
template <class Real>
std::vector<Real> dense_ratios() {
  std::vector<Real> e;
  e.reserve(300000 + 300000 + 300000 + 200000);
  std::mt19937_64 rng(6);
  const double lo = std::log10(static_cast<double>(std::numeric_limits<Real>::min())) + 1;
  std::uniform_real_distribution<double> all(lo, -lo), working(-3, 3), unit(-1, 1), wide(0, 4);
  for (int i = 0; i < 300000; ++i) e.push_back(static_cast<Real>(std::pow(10.0, all(rng))));
  for (int i = 0; i < 300000; ++i) e.push_back(static_cast<Real>(std::pow(10.0, working(rng))));
  for (int i = 0; i < 300000; ++i) {
    const int j = i % std::numeric_limits<Real>::digits;
    e.push_back(static_cast<Real>(1 + std::ldexp(unit(rng), -j)));
  }
  for (int i = 0; i < 200000; ++i) e.push_back(static_cast<Real>(wide(rng)));
  return e;
}

template <class Real>
void check_dense(double budget) {
  worst f, t;
  std::size_t n = 0;
  for (const Real x : dense_ratios<Real>()) {
    const auto r = spinslide::force_torque(x);
    const auto exact = spinslide::force_torque(static_cast<long double>(x));
    f.add(ulps(r.force, exact.force), static_cast<double>(x));
    t.add(ulps(r.torque, exact.torque), static_cast<double>(x));
    // force() and torque() alone are the same computation.
    ASSERT_EQ(spinslide::force(x), r.force) << x;
    ASSERT_EQ(spinslide::torque(x), r.torque) << x;
    ++n;
  }
  EXPECT_GE(n, 1000000u);
  EXPECT_LE(f.error, budget) << "force: worst at eps = " << f.at;
  EXPECT_LE(t.error, budget) << "torque: worst at eps = " << t.at;
  std::printf("%zu ratios: force %.3Lf ulp (eps = %.17g), torque %.3Lf ulp (eps = %.17g)\n", n,
              f.error, f.at, t.error, t.at);
  ::testing::Test::RecordProperty("force_max_ulp", std::to_string(static_cast<double>(f.error)));
  ::testing::Test::RecordProperty("torque_max_ulp", std::to_string(static_cast<double>(t.error)));
}

TEST(DiskFast, DoubleWithinFourUlpOnAMillionRatios) { check_dense<double>(4); }

TEST(DiskFast, FloatWithinTwoUlpOnAMillionRatios) { check_dense<float>(2); }

// The vectorizable form (detail::disk_fast_vector) that force_torque_batch
// uses on AVX-512 targets, called directly so that it is tested on every
// target, with the same budgets.
template <class Real>
void check_vector_form_dense(double budget) {
  worst f, t;
  std::size_t n = 0;
  for (const Real x : dense_ratios<Real>()) {
    Real rf, rt;
    spinslide::detail::disk_fast_vector(x, rf, rt);
    const auto exact = spinslide::force_torque(static_cast<long double>(x));
    f.add(ulps(rf, exact.force), static_cast<double>(x));
    t.add(ulps(rt, exact.torque), static_cast<double>(x));
    ++n;
  }
  EXPECT_GE(n, 1000000u);
  EXPECT_LE(f.error, budget) << "force: worst at eps = " << f.at;
  EXPECT_LE(t.error, budget) << "torque: worst at eps = " << t.at;
  std::printf(
      "vector form, %zu ratios: force %.3Lf ulp (eps = %.17g), torque %.3Lf ulp (eps = %.17g)\n", n,
      f.error, f.at, t.error, t.at);
}

TEST(DiskFast, VectorFormDoubleWithinFourUlpOnAMillionRatios) {
  check_vector_form_dense<double>(4);
}
TEST(DiskFast, VectorFormFloatWithinTwoUlpOnAMillionRatios) { check_vector_form_dense<float>(2); }

// y = 0 (ε = 1) and y = 1 (ε = 0, ∞) give the anchors themselves.
template <class Real>
void check_vector_form_exact() {
  const long double pi = boost::math::constants::pi<long double>();
  const Real inf = std::numeric_limits<Real>::infinity();
  const Real cases[][3] = {
      {Real(0), Real(0), static_cast<Real>(2.0L / 3)},
      {Real(1), static_cast<Real>(8 / (3 * pi)), static_cast<Real>(8 / (9 * pi))},
      {inf, Real(1), Real(0)}};
  for (const auto& c : cases) {
    Real f, t;
    spinslide::detail::disk_fast_vector(c[0], f, t);
    EXPECT_EQ(f, c[1]) << c[0];
    EXPECT_EQ(t, c[2]) << c[0];
  }
}
// The same anchors through force_torque_batch, in a group of the batch's
// width with a tail (five ratios), on the form this target selects.
template <class Real>
void check_batch_exact() {
  const long double pi = boost::math::constants::pi<long double>();
  const Real inf = std::numeric_limits<Real>::infinity();
  const std::vector<Real> e = {Real(0), Real(1), inf, Real(-0.0), Real(1)};
  const std::vector<Real> force = {Real(0), static_cast<Real>(8 / (3 * pi)), Real(1), Real(0),
                                   static_cast<Real>(8 / (3 * pi))};
  const std::vector<Real> torque = {static_cast<Real>(2.0L / 3), static_cast<Real>(8 / (9 * pi)),
                                    Real(0), static_cast<Real>(2.0L / 3),
                                    static_cast<Real>(8 / (9 * pi))};
  std::vector<Real> f(e.size()), t(e.size());
  spinslide::force_torque_batch(e.data(), e.size(), f.data(), t.data());
  EXPECT_EQ(f, force);
  EXPECT_EQ(t, torque);
}
TEST(DiskFast, BatchExactValuesDouble) { check_batch_exact<double>(); }
TEST(DiskFast, BatchExactValuesFloat) { check_batch_exact<float>(); }

TEST(DiskFast, VectorFormExactValuesDouble) { check_vector_form_exact<double>(); }
TEST(DiskFast, VectorFormExactValuesFloat) { check_vector_form_exact<float>(); }

// Every float in [2^-24, 2^24] with its low 4 mantissa bits zero (about 6e7
// ratios), against the double fast path: its error is 2^-29 of a float ulp.
TEST(DiskFast, FloatSweep) {
  worst f, t;
  for (float x = std::ldexp(1.0f, -24); x <= std::ldexp(1.0f, 24);
       x = std::nextafter(x + x * std::ldexp(1.0f, -20), 2 * x)) {
    const auto r = spinslide::force_torque(x);
    const auto d = spinslide::force_torque(static_cast<double>(x));
    f.add(ulps(r.force, d.force), x);
    t.add(ulps(r.torque, d.torque), x);
  }
  EXPECT_LE(f.error, 2) << "force: worst at eps = " << f.at;
  EXPECT_LE(t.error, 2) << "torque: worst at eps = " << t.at;
  std::printf("float sweep: force %.3Lf ulp (eps = %.9g), torque %.3Lf ulp (eps = %.9g)\n", f.error,
              f.at, t.error, t.at);
}

// force_torque at x within 4 ulp of the long double evaluation, force and
// torque (`where` says which case failed).
template <class Real>
void expect_within_four_ulp(Real x, const std::string& where) {
  const auto r = spinslide::force_torque(x);
  const auto exact = spinslide::force_torque(static_cast<long double>(x));
  EXPECT_LE(ulps(r.force, exact.force), 4) << where << x;
  EXPECT_LE(ulps(r.torque, exact.torque), 4) << where << x;
}

// Where the pieces meet: y = 1 − k² at each piece boundary, both sides, on
// both sides of ε = 1.
template <class Real>
void check_boundary(int i) {
  using table = spinslide::detail::disk_table<Real>;
  const int per = 1 << table::index_bits;
  const int j = i >> table::index_bits, s = i & (per - 1);
  const long double y = std::ldexp(1.0L + static_cast<long double>(s) / per, j - table::binades);
  const std::string where = "piece " + std::to_string(i) + ", eps = ";
  for (const long double eps : {std::sqrt(1 - y), 1 / std::sqrt(1 - y)}) {
    Real x = static_cast<Real>(eps);
    for (int step = 0; step < 3; ++step, x = std::nextafter(x, Real(2) * x))
      expect_within_four_ulp(x, where);
  }
}

template <class Real>
void check_boundaries() {
  for (int i = 1; i < spinslide::detail::disk_table<Real>::pieces; ++i) check_boundary<Real>(i);
}

TEST(DiskFast, PieceBoundariesDouble) { check_boundaries<double>(); }
TEST(DiskFast, PieceBoundariesFloat) { check_boundaries<float>(); }

// 𝓕(0) = 0 (also at −0, with a positive sign), 𝓣(0) = 2/3, 𝓕(∞) = 1,
// 𝓣(∞) = 0, exactly.
template <class Real>
void check_ends_of_the_range() {
  const Real inf = std::numeric_limits<Real>::infinity();
  EXPECT_EQ(spinslide::force(Real(0)), 0);
  EXPECT_EQ(spinslide::torque(Real(0)), Real(2) / 3);
  EXPECT_EQ(spinslide::force(-Real(0)), 0);
  EXPECT_FALSE(std::signbit(spinslide::force(-Real(0))));
  EXPECT_EQ(spinslide::force(inf), 1);
  EXPECT_EQ(spinslide::torque(inf), 0);
}

// The values at ε = 1 are pinned in the tables to the correctly rounded ones.
template <class Real>
void check_values_at_one() {
  EXPECT_EQ(spinslide::force(Real(1)),
            static_cast<Real>(8 / (3 * boost::math::constants::pi<long double>())));
  EXPECT_EQ(spinslide::torque(Real(1)),
            static_cast<Real>(8 / (9 * boost::math::constants::pi<long double>())));
}

// Force within 4 ulp of the long double evaluation; torque too, or, where
// the exact torque is subnormal in Real, within one subnormal ulp (absolute).
template <class Real>
void check_extreme_ratio(Real x) {
  const auto r = spinslide::force_torque(x);
  const auto exact = spinslide::force_torque(static_cast<long double>(x));
  EXPECT_LE(ulps(r.force, exact.force), 4) << x;
  if (exact.torque >= std::numeric_limits<Real>::min()) {
    EXPECT_LE(ulps(r.torque, exact.torque), 4) << x;
  } else {  // a subnormal result: an absolute error of a subnormal ulp
    EXPECT_LE(std::fabs(r.torque - exact.torque), std::numeric_limits<Real>::denorm_min()) << x;
  }
}

// The ends of the type: subnormal ε, the largest ε, ε at and around the
// cap 2^64 of the fast path's y.
template <class Real>
void check_ends_of_the_type() {
  const Real inf = std::numeric_limits<Real>::infinity();
  const Real big = std::numeric_limits<Real>::max();
  const Real tiny = std::numeric_limits<Real>::denorm_min();
  for (const Real x : {tiny, std::numeric_limits<Real>::min(), Real(18446744073709551616.0),
                       std::nextafter(Real(18446744073709551616.0), Real(0)),
                       std::nextafter(Real(18446744073709551616.0), inf), big})
    check_extreme_ratio(x);
}

template <class Real>
void check_special_values() {
  check_ends_of_the_range<Real>();
  check_values_at_one<Real>();
  check_ends_of_the_type<Real>();
}

TEST(DiskFast, SpecialValuesDouble) { check_special_values<double>(); }
TEST(DiskFast, SpecialValuesFloat) { check_special_values<float>(); }

// The batch, in place (outputs aliasing the input), with a count that is not
// a multiple of the vectorized form's block, for double and float.
template <class Real>
void check_batch_in_place() {
  auto e = dense_ratios<Real>();
  e.resize(1000);
  std::vector<Real> t(e.size()), in_place = e;
  spinslide::force_torque_batch(in_place.data(), in_place.size(), in_place.data(), t.data());
  for (std::size_t i = 0; i < e.size(); ++i) {
    const auto exact = spinslide::force_torque(static_cast<long double>(e[i]));
    ASSERT_LE(ulps(in_place[i], exact.force), 4) << e[i];
    ASSERT_LE(ulps(t[i], exact.torque), 4) << e[i];
  }
}
TEST(DiskFast, BatchInPlaceDouble) { check_batch_in_place<double>(); }
TEST(DiskFast, BatchInPlaceFloat) { check_batch_in_place<float>(); }

// force_torque_batch itself on the dense ratios, with the budgets of the
// scalar path: whichever form this target's flags select (the scalar loop,
// the compiler's vectorization on AVX-512, the AVX2 intrinsics; CMake also
// builds this file as test_disk_fast_avx2 with -mavx2 -mfma -mno-avx512f).
template <class Real>
void check_batch_dense(double budget) {
  const auto e = dense_ratios<Real>();
  std::vector<Real> f(e.size()), t(e.size());
  spinslide::force_torque_batch(e.data(), e.size(), f.data(), t.data());
  worst wf, wt;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const auto exact = spinslide::force_torque(static_cast<long double>(e[i]));
    wf.add(ulps(f[i], exact.force), static_cast<double>(e[i]));
    wt.add(ulps(t[i], exact.torque), static_cast<double>(e[i]));
  }
  EXPECT_LE(wf.error, budget) << "force: worst at eps = " << wf.at;
  EXPECT_LE(wt.error, budget) << "torque: worst at eps = " << wt.at;
  std::printf("batch, %zu ratios: force %.3Lf ulp (eps = %.17g), torque %.3Lf ulp (eps = %.17g)\n",
              e.size(), wf.error, wf.at, wt.error, wt.at);
}
TEST(DiskFast, BatchDoubleWithinFourUlpOnAMillionRatios) { check_batch_dense<double>(4); }
TEST(DiskFast, BatchFloatWithinTwoUlpOnAMillionRatios) { check_batch_dense<float>(2); }

}  // namespace
