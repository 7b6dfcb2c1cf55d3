//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The closed forms of the Hertz and Boussinesq profiles (profile.hpp,
// values/detail/elastic_closed_forms.hpp; docs/theory.md §6) against
//  - tests/reference/elastic_reference.csv: ring-kernel quadrature in
//    cpp_bin_float_50 (generate_elastic_reference.cpp), 229 ratios per
//    profile including both sides of every branch point, with 𝓕′ by
//    finite differences of the quadrature;
//  - tests/reference/profile_reference.csv: the 2-D area integrals;
//  - exact values and limits: 𝓕(1), 𝓣(1), ε𝓣 → ⟨r²⟩/2, ε³𝓕′ → 2a₁;
// in float, double, long double and cpp_bin_float_50, and densely in double
// against the cpp_bin_float_50 evaluation (itself checked against the
// quadrature to 1e-38).
#include <gtest/gtest.h>

#include <spinslide/values/profile.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/next.hpp>
#include <boost/math/special_functions/ulp.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "reference/csv.hpp"

#ifndef SPINSLIDE_ELASTIC_REFERENCE
#error "SPINSLIDE_ELASTIC_REFERENCE must name tests/reference/elastic_reference.csv"
#endif

namespace {

using namespace spinslide;
using big = boost::multiprecision::cpp_bin_float_50;

struct elastic_row {
  std::string profile;
  double eps;
  big force, torque, force_derivative;
};

const std::vector<elastic_row>& elastic_reference() {
  static const std::vector<elastic_row> rows = [] {
    std::vector<elastic_row> r;
    for (const auto& c : spinslide_reference::read_csv_rows(SPINSLIDE_ELASTIC_REFERENCE))
      r.push_back({c.at(0), std::strtod(c.at(1).c_str(), nullptr), big(c.at(2)), big(c.at(3)),
                   big(c.at(4))});
    return r;
  }();
  return rows;
}

// |computed − exact| in ulps of the result type at the exact value.
template <class Real>
double ulps(Real computed, const big& exact) {
  const Real rounded = static_cast<Real>(exact);
  const big fraction = (exact - big(rounded)) / big(boost::math::ulp(rounded));
  return std::fabs(static_cast<double>(boost::math::float_distance(computed, rounded)) +
                   static_cast<double>(fraction));
}

// The largest error of each of 𝓕, 𝓣, 𝓕′, 𝓣′ over the reference, in ulps of Real.
struct worst_ulps {
  double force = 0, torque = 0, force_derivative = 0, torque_derivative = 0;
};

template <class Real, class Profile>
void accumulate(const Profile& p, const elastic_row& row, worst_ulps& w) {
  const Real e = static_cast<Real>(row.eps);
  ASSERT_EQ(static_cast<double>(e), row.eps) << "the reference ratio must be exact in the type";
  const auto ft = p.force_torque(e);
  const big e_big = row.eps;
  w.force = std::max(w.force, ulps(ft.force, row.force));
  w.torque = std::max(w.torque, ulps(ft.torque, row.torque));
  w.force_derivative =
      std::max(w.force_derivative, ulps(p.force_derivative(e), row.force_derivative));
  w.torque_derivative = std::max(w.torque_derivative,
                                 ulps(p.torque_derivative(e), big(-e_big * row.force_derivative)));
}

// The row at `row.eps` rounded to Real, from the cpp_bin_float_50 evaluation
// (checked against the quadrature to 1e-38 below) where rounding changes ε.
template <class Real>
elastic_row at_ratio_of(const elastic_row& row) {
  const Real e = static_cast<Real>(row.eps);
  if (static_cast<double>(e) == row.eps) return row;
  const big eb = static_cast<double>(e);
  if (row.profile == "hertz") {
    const auto ft = hertz<big>().force_torque(eb);
    return {row.profile, static_cast<double>(e), ft.force, ft.torque,
            hertz<big>().force_derivative(eb)};
  }
  const auto ft = boussinesq<big>().force_torque(eb);
  return {row.profile, static_cast<double>(e), ft.force, ft.torque,
          boussinesq<big>().force_derivative(eb)};
}

void expect_worst(const worst_ulps& w, const char* name, const char* type, double values,
                  double derivatives) {
  EXPECT_LE(w.force, values) << name;
  EXPECT_LE(w.torque, values) << name;
  EXPECT_LE(w.force_derivative, derivatives) << name;
  EXPECT_LE(w.torque_derivative, derivatives) << name;
  std::printf("%-10s %-12s largest error in ulps: F %.2f  T %.2f  F' %.2f  T' %.2f\n", name, type,
              w.force, w.torque, w.force_derivative, w.torque_derivative);
}

template <class Real>
void expect_within(double values, double derivatives) {
  worst_ulps h, b;
  for (const auto& r : elastic_reference()) {
    const elastic_row row = at_ratio_of<Real>(r);
    if (row.profile == "hertz") accumulate<Real>(hertz<Real>(), row, h);
    if (row.profile == "boussinesq") accumulate<Real>(boussinesq<Real>(), row, b);
  }
  expect_worst(h, "hertz", typeid(Real).name(), values, derivatives);
  expect_worst(b, "boussinesq", typeid(Real).name(), values, derivatives);
}

TEST(ElasticProfiles, ReferenceCoversBothProfilesAndEveryBranchPoint) {
  std::size_t hertz_rows = 0, boussinesq_rows = 0, at_branch_points = 0;
  for (const auto& row : elastic_reference()) {
    hertz_rows += row.profile == "hertz";
    boussinesq_rows += row.profile == "boussinesq";
    for (double x : {1.0, 1.3, 1.5})
      at_branch_points +=
          row.eps == x || row.eps == std::nextafter(x, 0.0) || row.eps == std::nextafter(x, 2.0);
  }
  EXPECT_EQ(hertz_rows, 229U);
  EXPECT_EQ(boussinesq_rows, 229U);
  // 1, 13/10, 3/2 and their neighbours, for both profiles; 1 is also on the log grid.
  EXPECT_EQ(at_branch_points, 20U);
}

TEST(ElasticProfiles, DoubleWithinFourUlpDerivativesWithinSixteen) { expect_within<double>(4, 16); }

TEST(ElasticProfiles, FloatCorrectlyRoundedButForHalfAnUlp) { expect_within<float>(1, 1); }

TEST(ElasticProfiles, LongDoubleWithinFourUlpDerivativesWithinSixteen) {
  expect_within<long double>(4, 16);
}

// The quadrature is good to about 1e-40 (𝓕, 𝓣) and 1e-23 (its finite
// difference, 𝓕′): cpp_bin_float_50 is checked to those.
TEST(ElasticProfiles, MultiprecisionAgreesWithTheQuadrature) {
  for (const auto& row : elastic_reference()) {
    const big e = row.eps;
    const bool is_hertz = row.profile == "hertz";
    const auto ft = is_hertz ? hertz<big>().force_torque(e) : boussinesq<big>().force_torque(e);
    const big d =
        is_hertz ? hertz<big>().force_derivative(e) : boussinesq<big>().force_derivative(e);
    EXPECT_LT(abs(ft.force / row.force - 1), big("1e-38")) << row.profile << " " << row.eps;
    EXPECT_LT(abs(ft.torque / row.torque - 1), big("1e-38")) << row.profile << " " << row.eps;
    EXPECT_LT(abs(d / row.force_derivative - 1), big("1e-21")) << row.profile << " " << row.eps;
  }
}

// The 2-D area integrals, independent of the ring kernel.
TEST(ElasticProfiles, DoubleAgreesWithTheAreaIntegrals) {
  std::size_t rows = 0;
  for (const auto& c : spinslide_reference::read_csv_rows(SPINSLIDE_PROFILE_REFERENCE, "profile")) {
    if (c.at(0) != "hertz" && c.at(0) != "boussinesq") continue;
    const double e = std::strtod(c.at(1).c_str(), nullptr);
    const auto ft = c.at(0) == "hertz" ? hertz<>().force_torque(e) : boussinesq<>().force_torque(e);
    EXPECT_LE(ulps(ft.force, big(c.at(3))), 4) << c.at(0) << " " << e;
    EXPECT_LE(ulps(ft.torque, big(c.at(4))), 4) << c.at(0) << " " << e;
    ++rows;
  }
  EXPECT_EQ(rows, 134U);
}

// Between the reference ratios: 4000 log-uniform ratios in [1e-3, 1e6] and
// 2000 uniform in [1, 3] (both sides of every branch), double against the
// cpp_bin_float_50 evaluation.
TEST(ElasticProfiles, DenselyWithinFourUlpOfMultiprecision) {
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> decades(-3, 6), near_one(1, 3);
  worst_ulps h, b;
  for (int i = 0; i < 6000; ++i) {
    const double e = i < 4000 ? std::pow(10.0, decades(rng)) : near_one(rng);
    const big eb = e;
    const auto hf = hertz<big>().force_torque(eb);
    const auto bf = boussinesq<big>().force_torque(eb);
    const elastic_row hr{"hertz", e, hf.force, hf.torque, hertz<big>().force_derivative(eb)};
    const elastic_row br{"boussinesq", e, bf.force, bf.torque,
                         boussinesq<big>().force_derivative(eb)};
    accumulate<double>(hertz<>(), hr, h);
    accumulate<double>(boussinesq<>(), br, b);
  }
  expect_worst(h, "hertz", "dense double", 4, 16);
  expect_worst(b, "boussinesq", "dense double", 4, 16);
}

// docs/theory.md (H1), (B2): 𝓕(1) and 𝓣(1) exactly, and the contact of the
// two sides of ε = 1.
TEST(ElasticProfiles, ValuesAtOneAreExact) {
  const double pi = boost::math::constants::pi<double>();
  EXPECT_LE(ulps(boussinesq<>().force(1.0), boost::math::constants::pi<big>() / 4), 1);
  EXPECT_LE(ulps(boussinesq<>().torque(1.0), boost::math::constants::pi<big>() / 8), 1);
  EXPECT_LE(ulps(hertz<>().force(1.0), 9 * boost::math::constants::pi<big>() / 32), 1);
  EXPECT_LE(ulps(hertz<>().torque(1.0), 9 * boost::math::constants::pi<big>() / 128), 1);
  const double above = std::nextafter(1.0, 2.0);
  EXPECT_NEAR(boussinesq<>().torque(above), pi / 8, 4e-16);
  EXPECT_NEAR(hertz<>().torque(above), 9 * pi / 128, 4e-16);
}

// As ε → ∞: 1 − 𝓕 = a₁/ε² + …, ε𝓣 → ⟨r²⟩/2, ε³𝓕′ → 2a₁, with a₁ = 1/10
// (Hertz) and 1/6 (Boussinesq) from the expansion of E (theory (H3)).
TEST(ElasticProfiles, LimitsAtLargeRatios) {
  const big e("1e12");
  const big h_one_minus_f = (1 - hertz<big>().force(e)) * e * e;
  const big b_one_minus_f = (1 - boussinesq<big>().force(e)) * e * e;
  EXPECT_LT(abs(h_one_minus_f * 10 - 1), big("1e-22"));
  EXPECT_LT(abs(b_one_minus_f * 6 - 1), big("1e-22"));
  EXPECT_LT(abs(hertz<big>().torque(e) * e * 5 - 1), big("1e-22"));
  EXPECT_LT(abs(boussinesq<big>().torque(e) * e * 3 - 1), big("1e-22"));
  EXPECT_LT(abs(hertz<big>().force_derivative(e) * e * e * e * 5 - 1), big("1e-22"));
  EXPECT_LT(abs(boussinesq<big>().force_derivative(e) * e * e * e * 3 - 1), big("1e-22"));
  for (double x : {1e100, 1e300}) {
    EXPECT_DOUBLE_EQ(hertz<>().torque(x) * x, 0.2);
    EXPECT_DOUBLE_EQ(boussinesq<>().torque(x) * (x / 3), 1.0 / 9);
  }
}

TEST(ElasticProfiles, DerivativesAtTheEndsAndBadRatios) {
  const double pi = boost::math::constants::pi<double>();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ(hertz<>().force_derivative(0.0), hertz<>().mean_inverse_radius() / 2);
  EXPECT_DOUBLE_EQ(boussinesq<>().force_derivative(0.0), pi / 4);
  EXPECT_EQ(hertz<>().torque_derivative(0.0), 0.0);
  EXPECT_EQ(hertz<>().force_derivative(inf), 0.0);
  EXPECT_EQ(boussinesq<>().torque_derivative(inf), 0.0);
  EXPECT_THROW(hertz<>().force_derivative(-1.0), std::domain_error);
  EXPECT_THROW(boussinesq<>().torque_derivative(std::nan("")), std::domain_error);
  using quiet = boost::math::policies::policy<
      boost::math::policies::domain_error<boost::math::policies::ignore_error>>;
  EXPECT_TRUE(std::isnan(hertz<double, quiet>().force_derivative(-1.0)));
}

}  // namespace

// The projection takes 𝓕, 𝓣 and 𝓕′ of Hertz and Boussinesq from one call
// (detail::fused_value_slope, with 𝓕″ or without); it must give force_torque's and
// force_derivative's values bit for bit (those are held to the references
// above), on every branch: ε ≤ 1, the elementary forms below the derivative's
// series start (13/10), the values' elementary forms with the derivative's
// series (13/10 to 3/2), the series, and the branch points themselves.
template <class Real, class Profile>
void expect_fused_equals_separate(const Profile& p) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> log_eps(-6, 6);
  std::vector<Real> ratios{Real(1), Real(13) / 10, Real(3) / 2};
  for (const Real b : std::vector<Real>(ratios)) {
    ratios.push_back(boost::math::float_prior(b));
    ratios.push_back(boost::math::float_next(b));
  }
  for (int i = 0; i < 20000; ++i) ratios.push_back(static_cast<Real>(std::pow(10.0, log_eps(rng))));
  int mismatches = 0;
  for (const Real e : ratios) {
    const auto both = spinslide::detail::fused_value_slope<Profile>::at(p, e);
    const auto lean = spinslide::detail::fused_value_slope<Profile>::template at<false>(p, e);
    const auto ft = p.force_torque(e);
    const Real slope = p.force_derivative(e);
    if (!(both.value.force == ft.force && both.value.torque == ft.torque && both.slope == slope))
      ++mismatches;
    if (!(lean.value.force == ft.force && lean.value.torque == ft.torque && lean.slope == slope))
      ++mismatches;
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(ElasticProfiles, FusedValuesAndSlopeAreTheSeparateOnesBitForBit) {
  expect_fused_equals_separate<double>(spinslide::hertz<double>());
  expect_fused_equals_separate<double>(spinslide::boussinesq<double>());
  expect_fused_equals_separate<float>(spinslide::hertz<float>());
  expect_fused_equals_separate<long double>(spinslide::boussinesq<long double>());
}

// 𝓕″ (fused_value_slope's curvature, for the projection's Halley steps)
// against the central difference of 𝓕′ in 50 digits (the closed forms of
// cpp_bin_float_50, which the reference table holds to the quadrature):
// step 1e-15, so that the difference's error, of order 1e-30 in both its
// truncation and its rounding, is far below double's.  Across every branch
// (ε ≤ 1, the elementary forms, the derivative's series from 13/10, the
// values' series from 3/2) and near their switch points.  Hertz's 𝓕″ is
// continuous at ε = 1 and Boussinesq's is 0 below it and −k³/w above.
template <template <class, class> class Profile>
double worst_curvature_error(double tiny_relative_floor) {
  using quiet = boost::math::policies::policy<>;
  const Profile<double, quiet> p;
  const Profile<big, quiet> q;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> log_eps(-4, 4);
  std::vector<double> ratios{0.5, 0.999, 1.0000001, 1.2999, 1.3001, 1.4999, 1.5001, 3.0, 1e3};
  for (int i = 0; i < 400; ++i) ratios.push_back(std::pow(10.0, log_eps(rng)));
  double worst = 0;
  for (const double e : ratios) {
    const double c =
        spinslide::detail::fused_value_slope<Profile<double, quiet>>::at(p, e).curvature;
    const big h = big(e) * big("1e-15");
    const big exact = (q.force_derivative(big(e) + h) - q.force_derivative(big(e) - h)) / (2 * h);
    const double err =
        static_cast<double>(abs(big(c) - exact) / (std::max)(abs(exact), big(tiny_relative_floor)));
    worst = (std::max)(worst, err);
  }
  return worst;
}

TEST(ElasticProfiles, CurvatureAgreesWithTheDifferenceOfTheSlope) {
  // Within 1e-14 relative (measured 8e-16 for Hertz, 6e-16 for Boussinesq);
  // Boussinesq's 𝓕″ = 0 for ε ≤ 1, so relative to the larger of |𝓕″| and 1e-3.
  EXPECT_LT(worst_curvature_error<spinslide::hertz>(0.0), 1e-14);
  EXPECT_LT(worst_curvature_error<spinslide::boussinesq>(1e-3), 1e-14);
}

// Hertz's fast path (hertz_fast.hpp; tools/generate_hertz_tables.cpp), which
// double and float take from ε = 13/10 on, against the cpp_bin_float_50
// closed forms and series: at both ends and the middle of every piece of its
// table (and one ulp of ε either side of each end), at its first ratio, and
// at large ratios up to ∞ (where k and z underflow).  Measured: 𝓕 0.54,
// 𝓣 2.10, 𝓕′ 3.43 ulp and 𝓕″ 2.41 epsilon (relative); the errors of k = 1/ε
// and z = k² carry into 𝓣 = kA₂ and 𝓕′ = kzA₃.
TEST(ElasticProfiles, HertzFastPathAtEveryPieceOfItsTable) {
  using layout = spinslide::detail::hertz_table_layout;
  using quiet = boost::math::policies::policy<>;
  std::vector<double> ratios{1.3, 1e8, 1e150, 1e160, 1e300, std::numeric_limits<double>::max()};
  const big top = big(100) / 169;
  for (int i = 0; i <= 2 * layout::pieces; ++i) {
    const double e = static_cast<double>(1 / sqrt(top * i / (2 * layout::pieces)));
    if (!(e < std::numeric_limits<double>::infinity())) continue;
    for (const double r : {boost::math::float_prior(e), e, boost::math::float_next(e)})
      if (r >= 1.3) ratios.push_back(r);
  }
  ASSERT_GT(ratios.size(), std::size_t(3 * 2 * layout::pieces));
  double worst[4] = {0, 0, 0, 0};
  const spinslide::hertz<double, quiet> h;
  for (const double e : ratios) {
    const auto got = spinslide::detail::hertz_fast<true, true, true>(e);
    const auto exact =
        spinslide::detail::elastic_value_and_slope<spinslide::detail::hertz_load, true>(big(e));
    const double err[4] = {
        ulps(got.force, exact.value.force), ulps(got.torque, exact.value.torque),
        ulps(got.slope, exact.slope),
        // 𝓕″ relative, where it is a normal double (it underflows beyond ε ≈ 1e77)
        abs(exact.curvature) < big(std::numeric_limits<double>::min()) / std::pow(2.0, -52)
            ? 0.0
            : static_cast<double>(abs((big(got.curvature) - exact.curvature) / exact.curvature) /
                                  std::numeric_limits<double>::epsilon())};
    for (int f = 0; f < 4; ++f) {
      worst[f] = std::max(worst[f], err[f]);
      EXPECT_LE(err[f], f == 0 ? 1 : f == 1 ? 3 : 6) << "function " << f << " at " << e;
    }
    // Through the profile, as force_torque and the derivatives give them.
    EXPECT_EQ(h.force_torque(e).force, got.force) << e;
    EXPECT_EQ(h.force_torque(e).torque, got.torque) << e;
    EXPECT_EQ(h.force_derivative(e), got.slope) << e;
  }
  std::printf(
      "Hertz's fast path at its pieces' ends, largest error: F %.2f, T %.2f, F' %.2f ulp,"
      " F'' %.2f epsilon\n",
      worst[0], worst[1], worst[2], worst[3]);
  const auto at_infinity =
      spinslide::detail::hertz_fast<true, true, true>(std::numeric_limits<double>::infinity());
  EXPECT_EQ(at_infinity.force, 1.0);
  EXPECT_EQ(at_infinity.torque, 0.0);
  EXPECT_EQ(at_infinity.slope, 0.0);
  EXPECT_EQ(at_infinity.curvature, -0.0);
}
