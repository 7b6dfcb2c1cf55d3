//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The paper's claims about 𝓕 and 𝓣, exact limits, identities derived in
// docs/theory.md, and the error contract.  Expected values are exact
// constants, independent series, or identities; never values taken from the
// code under test.
#include <gtest/gtest.h>

#include <spinslide/values/disk.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/math/special_functions/next.hpp>
#include <boost/math/special_functions/relative_difference.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using mp = boost::multiprecision::cpp_bin_float_50;
using boost::math::epsilon_difference;
using boost::math::constants::pi;

const double inf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------- limits

TEST(PaperClaims, ForceVanishesForPureSpinning) { EXPECT_EQ(spinslide::force(0.0), 0.0); }
TEST(PaperClaims, ForceIsOneForPureSliding) { EXPECT_EQ(spinslide::force(inf), 1.0); }
TEST(PaperClaims, TorqueIsTwoThirdsForPureSpinning) {
  EXPECT_EQ(spinslide::torque(0.0), 2.0 / 3.0);
  EXPECT_EQ(spinslide::torque(mp(0)), mp(2) / 3);
}
TEST(PaperClaims, TorqueVanishesForPureSliding) { EXPECT_EQ(spinslide::torque(inf), 0.0); }

TEST(PaperClaims, LimitsAreApproachedContinuously) {
  // 𝓕 = ε + O(ε³), 𝓣 = 2/3 − ε²/2 + O(ε⁴), 𝓕 = 1 − 1/(8ε²) + ..., 𝓣 = 1/(4ε) + ...
  EXPECT_LE(epsilon_difference(spinslide::force(1e-200), 1e-200), 1);
  EXPECT_LE(epsilon_difference(spinslide::torque(1e-200), 2.0 / 3.0), 1);
  EXPECT_LE(epsilon_difference(spinslide::force(1e200), 1.0), 1);
  EXPECT_LE(epsilon_difference(spinslide::torque(1e200), 0.25e-200), 1);
}

// ---------------------------------------------------------------- ε = 1

template <class Real>
void expect_values_at_one(double tolerance) {
  const Real one = 1;
  EXPECT_LE(epsilon_difference(spinslide::force(one), 8 / (3 * pi<Real>())), tolerance);
  EXPECT_LE(epsilon_difference(spinslide::torque(one), 8 / (9 * pi<Real>())), tolerance);
  EXPECT_LE(epsilon_difference(spinslide::force_derivative(one), 4 / (3 * pi<Real>())), tolerance);
  EXPECT_LE(epsilon_difference(spinslide::torque_derivative(one), -4 / (3 * pi<Real>())),
            tolerance);
}

TEST(PaperClaims, ForceAndTorqueAtOne) {
  expect_values_at_one<float>(1);
  expect_values_at_one<double>(1);
  expect_values_at_one<long double>(2);
  expect_values_at_one<mp>(2);
}

// The two branches of each closed form meet at ε = 1 with equal value and
// slope: approach 1 from both sides in 50 digits.  Value errors must shrink
// like h, slope errors like h·log(1/h) (𝓕'' has a log singularity at 1).
TEST(PaperClaims, ValueAndSlopeContinuousAtOneFromBothSides) {
  const mp F1 = 8 / (3 * pi<mp>()), T1 = 8 / (9 * pi<mp>()), S = 4 / (3 * pi<mp>());
  for (int e = 4; e <= 40; e += 4) {
    const mp h = pow(mp(10), -e);
    for (int side : {-1, 1}) {
      const mp x = 1 + side * h;
      const mp bound_value = 2 * h, bound_slope = 2 * h * (1 + e * log(mp(10)));
      EXPECT_LT(abs(spinslide::force(x) - F1), bound_value) << "side " << side << " h=1e-" << e;
      EXPECT_LT(abs(spinslide::torque(x) - T1), bound_value) << "side " << side << " h=1e-" << e;
      EXPECT_LT(abs(spinslide::force_derivative(x) - S), bound_slope) << side << " 1e-" << e;
      EXPECT_LT(abs(spinslide::torque_derivative(x) + S), bound_slope) << side << " 1e-" << e;
      // One-sided difference quotients from the values alone; their rounding
      // error is ~1e-50/h, so the quotient checks stop at h = 1e-20.
      if (e <= 20) {
        const mp dF = (spinslide::force(x) - F1) / (side * h);
        const mp dT = (spinslide::torque(x) - T1) / (side * h);
        EXPECT_LT(abs(dF - S), bound_slope) << "side " << side << " h=1e-" << e;
        EXPECT_LT(abs(dT + S), bound_slope) << "side " << side << " h=1e-" << e;
      }
    }
  }
}

// In double the neighbours of 1 differ from 1 by δ ≈ 1e-16: 𝓕 and 𝓣 move by
// ~δ (half an ulp), while 𝓕' moves by ~δ·log(1/δ) (tens of ulps, as the
// reference table confirms), so only the values are compared with ε = 1 here.
TEST(PaperClaims, ValueContinuousAtOneInDouble) {
  const double below = boost::math::float_prior(1.0), above = boost::math::float_next(1.0);
  const double F1 = 8 / (3 * pi<double>()), T1 = 8 / (9 * pi<double>());
  for (double x : {below, above}) {
    EXPECT_LE(epsilon_difference(spinslide::force(x), F1), 4) << x;
    EXPECT_LE(epsilon_difference(spinslide::torque(x), T1), 4) << x;
  }
}

// ---------------------------------------------------------------- monotonicity

TEST(PaperClaims, ForceStrictlyIncreasingTorqueStrictlyDecreasing) {
  double prev_f = spinslide::force(1e-6), prev_t = spinslide::torque(1e-6);
  int steps = 0;
  for (double e = 1e-6 * 1.01; e <= 1e6; e *= 1.01, ++steps) {
    const double f = spinslide::force(e), t = spinslide::torque(e);
    ASSERT_GT(f, prev_f) << "at eps = " << e;
    ASSERT_LT(t, prev_t) << "at eps = " << e;
    prev_f = f;
    prev_t = t;
  }
  EXPECT_GT(steps, 2500);
}

TEST(PaperClaims, DerivativeSignsEverywhere) {
  // Until 1/(4ε³) underflows (ε ≈ 1e102 in double).
  for (double e = 1e-300; e <= 1e100; e *= 1.7) {
    ASSERT_GT(spinslide::force_derivative(e), 0.0) << e;
    ASSERT_LT(spinslide::torque_derivative(e), 0.0) << e;
  }
}

// ---------------------------------------------------------------- identities

// 𝓕(ε) = ε 𝓕(1/ε) (theory (I1)): the two sides use different branches.
TEST(Identities, ForceInversionSymmetry) {
  for (double e = 1e-6; e <= 1; e *= 1.13) {
    const mp x = e;
    const mp lhs = spinslide::force(x), rhs = x * spinslide::force(1 / x);
    EXPECT_LE(epsilon_difference(lhs, rhs), 16) << e;
    const double ld = spinslide::force(e), rd = e * spinslide::force(1 / e);
    EXPECT_LE(epsilon_difference(ld, rd), 4) << e;
  }
}

// 𝓣' = −ε𝓕' (theory (I2)), and both derivatives against central differences
// of the values in 50 digits (error ~ h² = 1e-36 relative).
// The step is h = 1e-18·ε; the rounding error of a quotient is about
// 1e-50·|f| / (h |f'|), added to the tolerance.
TEST(Identities, DerivativesMatchCentralDifferences) {
  for (double e : {1e-4, 0.01, 0.3, 0.653, 0.9, 0.999, 1.001, 1.3, 2.0, 5.0, 40.0, 1e4}) {
    const mp x = e, h = x * mp("1e-18");
    const mp dF = (spinslide::force(x + h) - spinslide::force(x - h)) / (2 * h);
    const mp dT = (spinslide::torque(x + h) - spinslide::torque(x - h)) / (2 * h);
    const mp Fp = spinslide::force_derivative(x), Tp = spinslide::torque_derivative(x);
    const mp tol_F = mp("1e-28") + mp("1e-49") * spinslide::force(x) / (h * Fp);
    const mp tol_T = mp("1e-28") + mp("1e-49") * spinslide::torque(x) / (h * abs(Tp));
    EXPECT_LT(abs(dF / Fp - 1), tol_F) << e;
    EXPECT_LT(abs(dT / Tp - 1), tol_T) << e;
    EXPECT_LE(
        epsilon_difference(spinslide::torque_derivative(x), -x * spinslide::force_derivative(x)),
        16)
        << e;
  }
}

// Small-ε Maclaurin series (theory (S1), (S2)), summed here independently of
// the library, which evaluates Carlson forms there:
//   𝓕 = Σ a_n ε^{2n+1} / ((n+1)(1−2n)),  𝓣 = 2/3 + Σ_{n≥1} a_{n−1} (2n−1) ε^{2n} / (2n²(2n−3)).
TEST(Identities, SmallEpsilonSeries) {
  for (double e : {1e-8, 1e-5, 1e-3, 0.01, 0.05, 0.1}) {
    const mp x = e, m = x * x;
    mp a = 1, mn = 1, F = 0, T = mp(2) / 3;
    for (int n = 0; n < 200; ++n) {
      F += a * mn * x / ((n + 1) * (1 - 2 * n));
      // term n+1 of 𝓣 uses a_n
      const int N = n + 1;
      T += a * mn * m * (2 * N - 1) / (2 * N * N * (2 * N - 3));
      a *= mp(2 * n + 1) * (2 * n + 1) / (mp(2 * n + 2) * (2 * n + 2));
      mn *= m;
    }
    EXPECT_LE(epsilon_difference(spinslide::force(x), F), 8) << e;
    EXPECT_LE(epsilon_difference(spinslide::torque(x), T), 8) << e;
  }
}

// Leading asymptotes as ε → ∞: 𝓕 = 1 − 1/(8ε²) − 1/(64ε⁴), 𝓣 = 1/(4ε) + 1/(48ε³),
// 𝓕' = 1/(4ε³); at ε = 1e8 the omitted terms are below 1e-32 relative.
TEST(Identities, LargeEpsilonAsymptotes) {
  const double e = 1e8;
  EXPECT_LE(epsilon_difference(spinslide::force(e), 1 - 1 / (8 * e * e)), 1);
  EXPECT_LE(epsilon_difference(spinslide::torque(e), 1 / (4 * e) + 1 / (48 * e * e * e)), 2);
  EXPECT_LE(epsilon_difference(spinslide::force_derivative(e), 1 / (4 * e * e * e)), 2);
  EXPECT_LE(epsilon_difference(spinslide::torque_derivative(e), -1 / (4 * e * e)), 2);
}

// ---------------------------------------------------------------- the printed formulas

// The paper's closed forms, literally, with Boost's K(k), E(k) (modulus k),
// evaluated in 50 digits so that their cancellation at large ε does not hide
// the comparison.
mp printed_force(const mp& e) {
  using boost::math::ellint_1;
  using boost::math::ellint_2;
  if (e <= 1)
    return 4 * ((e * e + 1) * ellint_2(e) + (e * e - 1) * ellint_1(e)) / (3 * e * pi<mp>());
  return 4 * ((e * e + 1) * ellint_2(1 / e) - (e * e - 1) * ellint_1(1 / e)) / (3 * pi<mp>());
}
mp printed_torque(const mp& e) {
  using boost::math::ellint_1;
  using boost::math::ellint_2;
  if (e <= 1)
    return 4 * ((4 - 2 * e * e) * ellint_2(e) + (e * e - 1) * ellint_1(e)) / (9 * pi<mp>());
  return 4 * ((4 - 2 * e * e) * ellint_2(1 / e) + (2 * e * e - 5 + 3 / (e * e)) * ellint_1(1 / e)) /
         (9 * e * pi<mp>());
}

TEST(PrintedFormulas, ForceAndSmallEpsilonTorqueAgreeWithTheIntegral) {
  for (double e : {0.1, 0.3, 0.653, 0.9, 1.5, 3.0, 10.0}) {
    EXPECT_LT(abs(printed_force(e) / spinslide::force(mp(e)) - 1), mp("1e-40")) << e;
    if (e < 1) {
      EXPECT_LT(abs(printed_torque(e) / spinslide::torque(mp(e)) - 1), mp("1e-40")) << e;
    }
  }
}

// docs/theory.md, "Corrections to the paper": the printed ε ≥ 1 torque is
// short by exactly a factor ε².
TEST(PrintedFormulas, LargeEpsilonTorqueIsMissingAFactorEpsilonSquared) {
  for (double e : {1.5, 2.0, 3.0, 10.0}) {
    const mp x = e;
    EXPECT_GT(abs(printed_torque(x) / spinslide::torque(x) - 1), mp("0.5")) << e;
    EXPECT_LT(abs(x * x * printed_torque(x) / spinslide::torque(x) - 1), mp("1e-40")) << e;
  }
}

// ---------------------------------------------------------------- the error contract

TEST(Errors, NanAndNegativeAreDomainErrorsNamingFunctionAndValue) {
  const double bad[] = {-1.0, -1e-300, -inf, std::numeric_limits<double>::quiet_NaN()};
  for (double e : bad) {
    try {
      spinslide::force(e);
      ADD_FAILURE() << "no exception for " << e;
    } catch (const std::domain_error& ex) {
      const std::string what = ex.what();
      EXPECT_NE(what.find("spinslide::force<double>"), std::string::npos) << what;
      if (e == -1.0) {
        EXPECT_NE(what.find("eps = -1"), std::string::npos) << what;
      }
    }
    EXPECT_THROW(spinslide::torque(e), std::domain_error);
    EXPECT_THROW(spinslide::force_derivative(e), std::domain_error);
    EXPECT_THROW(spinslide::torque_derivative(e), std::domain_error);
    EXPECT_THROW(spinslide::force_torque(e), std::domain_error);
    if (static_cast<float>(e) != 0) {  // -1e-300 rounds to -0.0f, which is valid
      EXPECT_THROW(spinslide::force(static_cast<float>(e)), std::domain_error);
    }
    EXPECT_THROW(spinslide::force(mp(e)), std::domain_error);
  }
}

TEST(Errors, NegativeZeroIsPureSpinning) {
  EXPECT_EQ(spinslide::force(-0.0), 0.0);
  EXPECT_FALSE(std::signbit(spinslide::force(-0.0)));
  EXPECT_EQ(spinslide::torque(-0.0), 2.0 / 3.0);
  EXPECT_EQ(spinslide::force_derivative(-0.0), 1.0);
  const auto ft = spinslide::force_torque(-0.0);
  EXPECT_EQ(ft.force, 0.0);
  EXPECT_EQ(ft.torque, 2.0 / 3.0);
}

TEST(Errors, PoliciesOtherThanThrow) {
  using namespace boost::math::policies;
  using errno_policy = policy<domain_error<errno_on_error>>;
  errno = 0;
  EXPECT_TRUE(std::isnan(spinslide::force(-1.0, errno_policy())));
  EXPECT_EQ(errno, EDOM);
  using ignore_policy = policy<domain_error<ignore_error>>;
  EXPECT_TRUE(std::isnan(spinslide::torque(-1.0, ignore_policy())));
  const auto ft = spinslide::force_torque(std::nan(""), ignore_policy());
  EXPECT_TRUE(std::isnan(ft.force));
  EXPECT_TRUE(std::isnan(ft.torque));
}

TEST(Types, IntegerArgumentsPromoteToDouble) {
  static_assert(std::is_same<decltype(spinslide::force(1)), double>::value, "");
  static_assert(std::is_same<decltype(spinslide::torque(2L)), double>::value, "");
  static_assert(std::is_same<decltype(spinslide::force(1.0f)), float>::value, "");
  static_assert(std::is_same<decltype(spinslide::force_torque(1).force), double>::value, "");
  EXPECT_EQ(spinslide::force(1), spinslide::force(1.0));
  EXPECT_EQ(spinslide::torque(3u), spinslide::torque(3.0));
}

// Within 2 ulp of the reference rounded to Real, or 2 denorm_min where the
// result is subnormal.
template <class Real>
::testing::AssertionResult close_to(Real got, const mp& reference) {
  using lim = std::numeric_limits<Real>;
  const Real want = static_cast<Real>(reference);
  using std::fabs;
  if (fabs(got - want) <= (std::max)(2 * lim::epsilon() * fabs(want), 2 * lim::denorm_min()))
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << got << " where the reference is " << want;
}

// The ε of the sweep: the ends of the type, the neighbours of 1, and every
// eighth binade from the smallest normal number up.
template <class Real>
std::vector<Real> extreme_ratios() {
  using lim = std::numeric_limits<Real>;
  std::vector<Real> xs = {lim::denorm_min(),
                          lim::min(),
                          lim::epsilon(),
                          Real(0.5),
                          Real(1),
                          boost::math::float_prior(Real(1)),
                          boost::math::float_next(Real(1)),
                          Real(2),
                          1 / lim::epsilon(),
                          lim::max()};
  for (Real e = lim::min(); e < lim::max() / 8; e *= 8) xs.push_back(e);
  return xs;
}

// 𝓕, 𝓣, 𝓕′, 𝓣′ and force_torque's 𝓣 at e, in that order, or the exception one
// of them threw.
template <class Real>
::testing::AssertionResult evaluate_at(const Real& e, std::vector<Real>& v) {
  try {
    v = {spinslide::force(e), spinslide::torque(e), spinslide::force_derivative(e),
         spinslide::torque_derivative(e), spinslide::force_torque(e).torque};
  } catch (const std::exception& ex) {
    return ::testing::AssertionFailure() << "exception at eps = " << e << ": " << ex.what();
  }
  return ::testing::AssertionSuccess();
}

// Every value finite, 0 ≤ 𝓕 ≤ 1 and 0 ≤ 𝓣 ≤ 2/3.
template <class Real>
void assert_finite_and_in_range(const Real& e, const std::vector<Real>& v) {
  for (const Real& x : v) ASSERT_TRUE((boost::math::isfinite)(x)) << e;
  ASSERT_GE(v[0], 0);
  ASSERT_LE(v[0], 1);
  ASSERT_GE(v[1], 0);
  ASSERT_LE(v[1], Real(2) / 3);
}

// The leading terms 𝓕, 𝓣, 𝓕′ at e (see sweep_extremes); none where e is
// neither small nor large enough for them.
struct leading {
  mp force, torque, slope;
};

template <class Real>
std::optional<leading> leading_terms(const Real& e) {
  using lim = std::numeric_limits<Real>;
  using std::sqrt;
  const Real root = sqrt(lim::epsilon());
  const mp E(e);
  if (e <= root / 4) return leading{E * (1 - E * E / 8), mp(2) / 3 - E * E / 2, 1 - 3 * E * E / 8};
  if (e >= 4 / root)
    return leading{1 - 1 / (8 * E * E), (1 + 1 / (12 * E * E)) / (4 * E), 1 / (4 * E * E * E)};
  return std::nullopt;
}

template <class Real>
void expect_leading_terms(const Real& e, const std::vector<Real>& v) {
  const std::optional<leading> terms = leading_terms(e);
  if (!terms) return;
  const mp &F = terms->force, &T = terms->torque, &dF = terms->slope;
  const mp E(e);
  EXPECT_TRUE(close_to(v[0], F)) << "force at " << e;
  EXPECT_TRUE(close_to(v[1], T)) << "torque at " << e;
  EXPECT_TRUE(close_to(v[2], dF)) << "force_derivative at " << e;
  EXPECT_TRUE(close_to(v[3], mp(-E * dF))) << "torque_derivative at " << e;
  EXPECT_TRUE(close_to(v[4], T)) << "force_torque at " << e;
}

// Valid input never throws and never returns a non-finite value, including the
// extremes of each type and the neighbours of 1.  Where ε is so small or so
// large that the next term of the series is below an ulp, the four functions
// are the leading terms (S2 and docs/theory.md §8): for ε ≤ √ε_mach/4,
// 𝓕 = ε(1 − ε²/8), 𝓣 = 2/3 − ε²/2, 𝓕′ = 1 − 3ε²/8; for ε ≥ 4/√ε_mach,
// 𝓕 = 1 − 1/(8ε²), 𝓣 = (1 + 1/(12ε²))/(4ε), 𝓕′ = 1/(4ε³); and 𝓣′ = −ε𝓕′
// (I2), all evaluated in cpp_bin_float_50.  The first failed assertion on
// finiteness or range (or an exception) ends the sweep.
template <class Real>
void sweep_extremes() {
  for (const Real& e : extreme_ratios<Real>()) {
    std::vector<Real> v;
    ASSERT_TRUE(evaluate_at(e, v));
    ASSERT_NO_FATAL_FAILURE(assert_finite_and_in_range(e, v));
    expect_leading_terms(e, v);
  }
}

TEST(Types, NoExceptionAndFiniteResultsAtTheExtremes) {
  sweep_extremes<float>();
  sweep_extremes<double>();
  sweep_extremes<long double>();
}

}  // namespace
