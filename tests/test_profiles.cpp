//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Pressure profiles (profile.hpp), the coupling curve (coupling.hpp) and the
// tabulated profile (tabulated.hpp), against the 2-D area-integral reference
// (tests/reference/profile_reference.csv), exact limits and identities.
#include <gtest/gtest.h>

#include <spinslide/spinslide.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/relative_difference.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "quadrature_moments.hpp"
#include "reference/csv.hpp"
#include "reference_table.hpp"

namespace {

using namespace spinslide;
using boost::math::relative_difference;
const double pi = boost::math::constants::pi<double>();

struct ref_point {
  double eps, force, torque;
};

const std::map<std::string, std::vector<ref_point>>& reference() {
  static const auto table = [] {
    std::map<std::string, std::vector<ref_point>> t;
    // profile,eps_hex,eps,force,torque
    for (const auto& f : spinslide_reference::read_csv_rows(SPINSLIDE_PROFILE_REFERENCE, "profile"))
      t[f.at(0)].push_back({std::strtod(f.at(1).c_str(), nullptr),
                            static_cast<double>(std::strtold(f.at(3).c_str(), nullptr)),
                            static_cast<double>(std::strtold(f.at(4).c_str(), nullptr))});
    // The uniform disk's own area-integral table (the 2-D profile generator
    // was checked against it to 5e-28).
    for (const auto& r : spinslide_test::load_disk_reference(SPINSLIDE_DISK_REFERENCE))
      t["uniform"].push_back({r.eps, static_cast<double>(std::strtold(r.force.c_str(), nullptr)),
                              static_cast<double>(std::strtold(r.torque.c_str(), nullptr))});
    return t;
  }();
  return table;
}

auto two_tier() {
  // 60% of the load on r < 1/2, 40% on 1/2 < r < 1, uniform within each.
  return weighted_sum({0.6, 0.4}, scaled<uniform_disk<>>(uniform_disk<>(), 0.5), annulus<>(0.5));
}
auto parabolic() {
  return radial_profile([](double r) { return (1 - r) * (1 + r); });
}

// Largest relative error of a profile over the reference rows in [1e-6, 1e6].
template <class P>
double worst_against_reference(const P& p, const std::string& name, double* where = nullptr) {
  const auto& rows = reference().at(name);
  double worst = 0;
  for (const auto& r : rows) {
    if (r.eps < 1e-6 || r.eps > 1e6) continue;
    const auto ft = p.force_torque(r.eps);
    const double e =
        std::max(relative_difference(ft.force, r.force), relative_difference(ft.torque, r.torque));
    if (e > worst) {
      worst = e;
      if (where) *where = r.eps;
    }
  }
  EXPECT_GE(rows.size(), 40u) << name;
  return worst;
}

#define EXPECT_PROFILE_MATCHES_REFERENCE(profile, name, tol)                             \
  do {                                                                                   \
    double at = 0;                                                                       \
    const double w = worst_against_reference(profile, name, &at);                        \
    EXPECT_LE(w, tol) << (name) << ": worst relative error " << w << " at eps = " << at; \
  } while (0)

// ---------------------------------------------------------------- accuracy

TEST(ProfileReference, BuiltInProfilesWithin1e13) {
  EXPECT_PROFILE_MATCHES_REFERENCE(uniform_disk<>(), "uniform", 1e-13);
  EXPECT_PROFILE_MATCHES_REFERENCE(annulus<>(0.125), "annulus_0.125", 1e-13);
  EXPECT_PROFILE_MATCHES_REFERENCE(hertz<>(), "hertz", 1e-13);
  EXPECT_PROFILE_MATCHES_REFERENCE(boussinesq<>(), "boussinesq", 1e-13);
  EXPECT_PROFILE_MATCHES_REFERENCE(ring<>(), "ring", 1e-13);
}

TEST(ProfileReference, WeightedSumAndCustomProfileWithin1e13) {
  EXPECT_PROFILE_MATCHES_REFERENCE(two_tier(), "two_tier", 1e-13);
  EXPECT_PROFILE_MATCHES_REFERENCE(parabolic(), "parabolic", 1e-13);
  // The uniform disk through the generic ring quadrature, not the closed forms.
  EXPECT_PROFILE_MATCHES_REFERENCE(radial_profile([](double) { return 1.0; }), "uniform", 1e-13);
  // The thin-annulus code path (ring quadrature) on the CD's annulus.
  auto cd_by_quadrature = radial_profile([](double) { return 1.0; }, 0.125);
  EXPECT_PROFILE_MATCHES_REFERENCE(cd_by_quadrature, "annulus_0.125", 1e-13);
}

// ---------------------------------------------------------------- moments and limits

// The moments against the defining integrals ⟨r^k⟩ = ∫ r^k w dr / ∫ w dr, by
// long-double quadrature (quadrature_moments.hpp), not the closed forms.
template <class P>
void expect_moments(const P& p, const spinslide_test::load_moments& m, const char* name,
                    double tol = 1e-15) {
  EXPECT_LE(relative_difference(p.mean_radius(), double(m.mean_radius)), tol) << name;
  EXPECT_LE(relative_difference(p.mean_inverse_radius(), double(m.mean_inverse_radius)), tol)
      << name;
  EXPECT_LE(relative_difference(p.mean_square_radius(), double(m.mean_square_radius)), tol) << name;
}

// The quadrature reference itself, against the exact values of docs/theory.md §6
// (∫₀¹ 2r^(k+1) dr; ∫₀^(π/2) of powers of sin and cos).
TEST(ProfileMoments, QuadratureReferenceHasTheExactValues) {
  const long double pi_l = boost::math::constants::pi<long double>();
  using spinslide_test::load_moments;
  auto expect = [](const load_moments& m, const load_moments& exact, const char* name) {
    // In long double (EXPECT_NEAR would compare doubles): 1e-18 is ~10 ulp.
    EXPECT_LE(std::fabs(m.mean_radius - exact.mean_radius), 1e-18L) << name;
    EXPECT_LE(std::fabs(m.mean_inverse_radius - exact.mean_inverse_radius), 1e-18L) << name;
    EXPECT_LE(std::fabs(m.mean_square_radius - exact.mean_square_radius), 1e-18L) << name;
  };
  // {⟨r⟩, ⟨1/r⟩, ⟨r²⟩}
  expect(spinslide_test::uniform_disk_moments(), {2.0L / 3, 2, 0.5L}, "uniform");
  expect(spinslide_test::hertz_moments(), {3 * pi_l / 16, 3 * pi_l / 4, 0.4L}, "hertz");
  expect(spinslide_test::boussinesq_moments(), {pi_l / 4, pi_l / 2, 2.0L / 3}, "boussinesq");
  // An annulus with no hole is the disk.
  expect(spinslide_test::annulus_moments(0), {2.0L / 3, 2, 0.5L}, "annulus(0)");
}

TEST(ProfileMoments, ClosedFormsAndQuadratureAgree) {
  expect_moments(uniform_disk<>(), spinslide_test::uniform_disk_moments(), "uniform");
  for (const double b : {0.125, 0.5, 0.9})
    expect_moments(annulus<>(b), spinslide_test::annulus_moments(b), "annulus");
  expect_moments(hertz<>(), spinslide_test::hertz_moments(), "hertz");
  expect_moments(boussinesq<>(), spinslide_test::boussinesq_moments(), "boussinesq");
  // The ring is the load δ(r − 1): every moment is 1.
  expect_moments(ring<>(), {1, 1, 1}, "ring");
  // radial_profile computes its moments by its own quadrature: the same numbers.
  auto h = radial_profile([](double r) { return std::sqrt((1 - r) * (1 + r)); });
  // The rim singularity needs 1 − r exactly: the two-argument form.
  auto bq = radial_profile(
      [](double r, double one_minus_r) { return 1 / std::sqrt(one_minus_r * (1 + r)); });
  // With p(r) alone the lost sliver 1 − r < 1e-16 costs ~1e-8 (documented).
  auto bq1 = radial_profile([](double r) { return 1 / std::sqrt((1 - r) * (1 + r)); });
  EXPECT_LE(relative_difference(bq1.mean_radius(), pi / 4), 1e-7);
  expect_moments(h, spinslide_test::hertz_moments(), "radial hertz", 1e-14);
  expect_moments(bq, spinslide_test::boussinesq_moments(), "radial boussinesq", 1e-12);
  // Weighted sums and scaling: the moments are load-weighted means.  The
  // two-tier load: 60% as w = 2r/0.25 on r < 1/2, 40% as w = 2r/0.75 on 1/2 < r < 1.
  const auto two_tier_moments = spinslide_test::moments_of(
      {{spinslide_test::identity, [](long double r) { return 0.6L * 2 * r / 0.25L; }, 0, 0.5L},
       {spinslide_test::identity, [](long double r) { return 0.4L * 2 * r / 0.75L; }, 0.5L, 1}});
  expect_moments(two_tier(), two_tier_moments, "two-tier");
}

// 𝓕′(0) = ⟨1/r⟩/2, 𝓣(0) = ⟨r⟩, ε𝓣(ε) → ⟨r²⟩/2, 𝓕(∞) = 1 (docs/theory.md §6):
// approached at ε = 1e-7 and 1e7, and exact at 0 and ∞.
template <class P>
void expect_limits_approached(const P& p, const char* name) {
  const double small = 1e-7, large = 1e7;
  EXPECT_LE(relative_difference(p.force(small) / small, p.mean_inverse_radius() / 2), 1e-9) << name;
  EXPECT_LE(relative_difference(p.torque(small), p.mean_radius()), 1e-9) << name;
  EXPECT_LE(relative_difference(large * p.torque(large), p.mean_square_radius() / 2), 1e-9) << name;
  EXPECT_LE(relative_difference(p.force(large), 1.0), 1e-12) << name;
}

template <class P>
void expect_limits_exact(const P& p, const char* name) {
  EXPECT_EQ(p.force(0.0), 0.0) << name;
  EXPECT_EQ(p.torque(0.0), p.mean_radius()) << name;
  EXPECT_EQ(p.force(INFINITY), 1.0) << name;
  EXPECT_EQ(p.torque(INFINITY), 0.0) << name;
}

template <class P>
void expect_limits(const P& p, const char* name) {
  expect_limits_approached(p, name);
  expect_limits_exact(p, name);
}

TEST(ProfileLimits, EveryProfile) {
  expect_limits(uniform_disk<>(), "uniform");
  expect_limits(annulus<>(0.125), "annulus 0.125");
  expect_limits(annulus<>(0.9), "annulus 0.9");
  expect_limits(hertz<>(), "hertz");
  expect_limits(boussinesq<>(), "boussinesq");
  expect_limits(ring<>(), "ring");
  expect_limits(two_tier(), "two-tier");
  expect_limits(parabolic(), "parabolic");
}

TEST(ProfileLimits, AnnulusTendsToTheUniformDisk) {
  const annulus<> zero(0.0);
  for (double e : {1e-3, 0.3, 1.0, 3.0, 1e3}) {
    EXPECT_EQ(zero.force(e), spinslide::force(e));
    EXPECT_EQ(zero.torque(e), spinslide::torque(e));
    double prev = 1;
    for (double b : {1e-1, 1e-2, 1e-3, 1e-4}) {
      // The hole removes a fraction b² of the load: differences shrink like b².
      const annulus<> a(b);
      const double d = std::max(std::fabs(a.force(e) - spinslide::force(e)),
                                std::fabs(a.torque(e) - spinslide::torque(e)));
      EXPECT_LE(d, 2 * b * b) << "b = " << b << " eps = " << e;
      EXPECT_LT(d, prev);
      prev = d;
    }
  }
}

TEST(ProfileLimits, AnnulusCodePathsMeetAtHalf) {
  // b <= 1/2 uses the closed forms, b > 1/2 the ring quadrature.
  const annulus<> closed(0.5), quad(std::nextafter(0.5, 1.0));
  for (double e : {1e-4, 0.3, 0.5, 0.7, 1.0, 2.0, 1e4}) {
    EXPECT_LE(relative_difference(closed.force(e), quad.force(e)), 1e-13) << e;
    EXPECT_LE(relative_difference(closed.torque(e), quad.torque(e)), 1e-13) << e;
  }
}

// ---------------------------------------------------------------- special identities

TEST(ProfileIdentities, RingForceIsTorqueAtReciprocal) {
  const ring<> r;
  for (double e : {1e-5, 0.01, 0.3, 0.7, 0.999, 1.5, 20.0}) {
    EXPECT_LE(relative_difference(r.force(e), r.torque(1 / e)), 1e-15) << e;
  }
  EXPECT_LE(relative_difference(r.force(1.0), 2 / pi), 2e-16);
  EXPECT_LE(relative_difference(r.torque(1.0), 2 / pi), 2e-16);
}

// Boussinesq's pressure by the ring quadrature (a radial_profile; boussinesq<>
// itself evaluates these closed forms).
auto boussinesq_by_quadrature() {
  return radial_profile(
      [](double r, double one_minus_r) { return 1 / std::sqrt(one_minus_r * (1 + r)); });
}

// For ε ≤ 1 the Boussinesq force is exactly πε/4 (theory (B2), proved there
// from the plane potential; found first in the 2-D reference table).
TEST(ProfileIdentities, BoussinesqForceBelowOneIsLinear) {
  const auto b = boussinesq_by_quadrature();
  for (double e : {1e-6, 0.01, 0.3, 0.5, 0.9, 0.999, 1.0})
    EXPECT_LE(relative_difference(b.force(e), pi * e / 4), 1e-13) << e;
}

// For ε ≥ 1 the Boussinesq force is elementary: (asin k/k + √(1−k²))/2, k = 1/ε.
TEST(ProfileIdentities, BoussinesqForceAboveOneIsElementary) {
  const auto b = boussinesq_by_quadrature();
  for (double e : {1.0, 1.0001, 1.5, 2.0, 8.0, 100.0, 1e5}) {
    const double k = 1 / e;
    EXPECT_LE(
        relative_difference(b.force(e), (std::asin(k) / k + std::sqrt((1 - k) * (1 + k))) / 2),
        1e-13)
        << e;
  }
}

// (I2) for every profile: the limit curve has slope d𝓣/d𝓕 = −ε.
TEST(ProfileIdentities, LimitCurveSlopeIsMinusEpsilon) {
  const hertz<> h;
  for (double e : {0.1, 0.653, 1.7}) {
    const double dh = 1e-5 * e;
    const double dT = h.torque(e + dh) - h.torque(e - dh);
    const double dF = h.force(e + dh) - h.force(e - dh);
    EXPECT_NEAR(dT / dF, -e, 1e-6 * e) << e;
  }
}

// ---------------------------------------------------------------- errors

// ---------------------------------------------------------------- singular ratios

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

TEST(ProfileErrors, BadInputIsADomainError) {
  EXPECT_THROW(annulus<>(-0.1), std::domain_error);
  EXPECT_THROW(annulus<>(1.0), std::domain_error);
  EXPECT_THROW(annulus<>(NAN), std::domain_error);
  EXPECT_THROW(hertz<>().force(-1.0), std::domain_error);
  EXPECT_THROW(ring<>().torque(NAN), std::domain_error);
  EXPECT_THROW((scaled<uniform_disk<>>(uniform_disk<>(), 0.0)), std::domain_error);
  EXPECT_THROW((scaled<uniform_disk<>>(uniform_disk<>(), 1.5)), std::domain_error);
  EXPECT_THROW(weighted_sum({-1.0, 2.0}, ring<>(), hertz<>()), std::domain_error);
  EXPECT_THROW(weighted_sum({0.0, 0.0}, ring<>(), hertz<>()), std::domain_error);
  EXPECT_THROW(radial_profile([](double r) { return r - 0.5; }), std::domain_error);
  EXPECT_THROW(radial_profile([](double) { return 0.0; }), std::domain_error);
  EXPECT_THROW(radial_profile([](double) { return 1.0; }, 1.0), std::domain_error);
  try {
    annulus<>(2.0);
    ADD_FAILURE();
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("inner_ratio = 2"), std::string::npos) << e.what();
  }
}

// ---------------------------------------------------------------- regressions
//
// Each failure a fuzz harness (fuzz/) found in the profiles, with the input it
// reported and an independent expectation; docs/reliability.md lists them.

constexpr double max_d = std::numeric_limits<double>::max();
constexpr double double_eps = std::numeric_limits<double>::epsilon();

// fuzz_profiles: Boost's R_F and R_D return NaN for a subnormal argument, met
// by a quadrature node within ~1e-308 of r = ε (annulus<float>(1 − 2⁻²⁴) at
// ε = 1); guards the ring kernel's y → 0 limit.  A ring at r = ε = 1 is the
// kernel at c = 1, where (R1) and (R2) give 𝓕 = 𝓣 = 2E(1)/π = 2/π.
TEST(RingKernel, RegressionSubnormalDistanceToTheSplitGivesTheLimit) {
  using P = detail::kernel_policy<boost::math::policies::policy<>>;
  for (const double d : {5e-324, 1e-310, 1e-300}) {
    const auto k = detail::ring_kernel(1.0 - d, 1.0, d, P());
    EXPECT_NEAR(k.force, 2 / pi, 1e-14) << d;  // Boost R_D: ~12 ulp at y = 2e-300
    EXPECT_NEAR(k.torque, 2 / pi, 1e-14) << d;
  }
  const float b = std::nextafter(1.0f, 0.0f);
  const auto ft = annulus<float>(b).force_torque(1.0f);
  EXPECT_NEAR(ft.force, float(2 / pi), 1e-6f);
  EXPECT_NEAR(ft.torque, float(2 / pi), 1e-6f);
}

// fuzz_profiles: p = DBL_MAX overflowed tanh_sinh's sums (evaluation_error);
// guards dividing a custom pressure by its value mid-support.  p and λp are
// the same profile: the uniform disk's moments (∫₀¹ 2r^(k+1) dr) and 𝓕, 𝓣.
TEST(RadialProfile, RegressionPressureOfAnySizeIsTheSameProfile) {
  for (const double c : {max_d, 1.0, 1e-300}) {
    const auto p = radial_profile([c](double) { return c; });
    EXPECT_NEAR(p.mean_radius(), 2.0 / 3, 1e-14) << c;
    EXPECT_NEAR(p.mean_inverse_radius(), 2.0, 1e-13) << c;
    EXPECT_NEAR(p.mean_square_radius(), 0.5, 1e-14) << c;
    EXPECT_NEAR(p.force(0.7), force(0.7), 1e-13) << c;
    EXPECT_NEAR(p.torque(0.7), torque(0.7), 1e-13) << c;
  }
  // A total that overflows even so is the documented domain error.
  EXPECT_THROW(radial_profile([](double r) { return r < 0.5 ? max_d : 1e-300; }),
               std::domain_error);
}

// fuzz_profiles: a pressure of subnormal values (c/√(1 − r), c = 5e-324, on
// [0.696, 1]) is a staircase of multiples of 5e-324, and its moments missed
// by 1 %: ⟨r⟩² > ⟨r²⟩, which no load allows (Jensen).  Guards refusing a load
// per unit width below the smallest normal number, and keeping the same
// pressure scaled into the normal range: its moments are the exact ones,
// ∫ r^n/√(1 − r) dr over [b, 1] = 2∫ (1 − u²)^n du over [0, √(1 − b)]
// (u = √(1 − r)).
TEST(RadialProfile, RegressionSubnormalPressureIsRefused) {
  const double b = 0.696;
  const auto rim = [](double scale) {
    return [scale](double, double one_minus_r) { return scale / std::sqrt(one_minus_r); };
  };
  for (const double c : {5e-324, 1e-320, 1e-310}) {
    try {
      radial_profile(rim(c), b);
      ADD_FAILURE() << c;
    } catch (const std::domain_error& e) {
      EXPECT_NE(std::string(e.what()).find("subnormal"), std::string::npos) << e.what();
    }
  }
  const double w = std::sqrt(1 - b);  // m_n = ∫ r^n/√(1 − r) dr, by the binomial theorem
  const double m1 = 2 * (w - w * w * w / 3);
  const double m2 = 2 * (w - 2 * std::pow(w, 3) / 3 + std::pow(w, 5) / 5);
  const double m3 = 2 * (w - std::pow(w, 3) + 3 * std::pow(w, 5) / 5 - std::pow(w, 7) / 7);
  const double m0 = 2 * w;  // ∫ 1/√(1 − r) dr, ⟨1/r⟩'s numerator
  for (const double c : {3e-308, 1.0}) {
    const auto p = radial_profile(rim(c), b);
    EXPECT_NEAR(p.mean_radius(), m2 / m1, 1e-14) << c;
    EXPECT_NEAR(p.mean_square_radius(), m3 / m1, 1e-14) << c;
    EXPECT_NEAR(p.mean_inverse_radius(), m0 / m1, 1e-14) << c;
  }
}

// fuzz_profiles: on the support [1 − 2⁻⁵³, 1], whose middle rounds to 1, the
// pressure was asked at 1 − r = 0 (where it is infinite); guards asking it at
// 1 − r = half the width.  Every moment of a load on [inner, 1] lies between
// the values of r^k at the two ends.
TEST(RadialProfile, RegressionSupportThinnerThanItsMidpoint) {
  const double inner = std::nextafter(1.0, 0.0);
  const auto thin =
      radial_profile([](double, double one_minus_r) { return 1 / std::sqrt(one_minus_r); }, inner);
  EXPECT_NEAR(thin.mean_radius(), 1.0, 1e-15);
  EXPECT_GE(thin.mean_radius(), inner);
  EXPECT_LE(thin.mean_radius(), 1.0);
  EXPECT_GE(thin.mean_inverse_radius(), 1.0);
  EXPECT_LE(thin.mean_inverse_radius(), 1 / inner);
  EXPECT_GE(thin.mean_square_radius(), inner * inner);
  EXPECT_LE(thin.mean_square_radius(), 1.0);
}

// fuzz_profiles: weights whose sum overflows were normalised to 0; guards
// dividing by the largest weight first.  Equal weights: the mean of the disk's
// and the ring's moments (2/3, 2, 1/2 and 1, 1, 1) and of their 𝓕, 𝓣.
TEST(WeightedSum, RegressionWeightsWhoseSumOverflows) {
  const auto w = weighted_sum({max_d, max_d}, uniform_disk<double>(), ring<double>());
  EXPECT_DOUBLE_EQ(w.weights()[0], 0.5);
  EXPECT_DOUBLE_EQ(w.weights()[1], 0.5);
  EXPECT_DOUBLE_EQ(w.mean_radius(), (2.0 / 3 + 1) / 2);
  EXPECT_DOUBLE_EQ(w.mean_inverse_radius(), (2.0 + 1) / 2);
  EXPECT_DOUBLE_EQ(w.mean_square_radius(), (0.5 + 1) / 2);
  EXPECT_DOUBLE_EQ(w.force(0.7), (force(0.7) + ring<double>().force(0.7)) / 2);
  EXPECT_DOUBLE_EQ(w.torque(0.7), (torque(0.7) + ring<double>().torque(0.7)) / 2);
}

// fuzz_contact (the campaign of 2026-11-23): 𝓕 of a ring-quadrature annulus
// and of a weighted sum rounded to 1 + 2⁻⁵² at a large ratio (and μN𝓕
// overflowed in the contact law: ContactLaw.RegressionForceOfAProfileRoundedAboveOne);
// guards the clamp 𝓕 ≤ 1 after general().  1 − 𝓕 ≈ ⟨r²⟩/(4ε²) ((R1): f_F =
// (2/π)E(r/ε) ≈ 1 − r²/(4ε²)) is far below an ulp at ε = 2e87 and 5e31: 𝓕 is
// 1 to rounding, within the 2 ulp (1 − 2⁻⁵²) at which the ring quadrature
// levels off.
TEST(Annulus, RegressionForceRoundedAboveOneAtLargeRatios) {
  const annulus<double> ann(0.635197164334527664131);
  const auto sum =
      weighted_sum({0.173717571710168772192, 541249.376203841762617},
                   scaled<uniform_disk<double>>(uniform_disk<double>(), 0.937500000000852762305),
                   ring<double>());
  for (const double f : {ann.force(std::sqrt(2.0) / 6.93531866257113469774e-88),
                         sum.force(3.61069398448143300918e+307 / 6.98211634151446680426e+275)}) {
    EXPECT_LE(f, 1.0);
    EXPECT_GE(f, 1 - double_eps);
  }
}

// Found by fuzz_profiles (CI run, sanitize preset): scaled(hertz) at radius
// a = 2.7e-162 gave ⟨r²⟩ = a²⟨r²⟩_P = 0 (a² underflowed), so ⟨r⟩² > ⟨r²⟩.
// Guards the shrink radius's domain [√min_value, 1]: at its lower end the
// moments keep their relative accuracy (exact powers of two times ⟨r^k⟩_P).
TEST(Scaled, RegressionRadiusWhoseSquareUnderflowsIsADomainError) {
  EXPECT_THROW((scaled<hertz<double>>(hertz<double>(), 2.66952910647346144157e-162)),
               std::domain_error);
  const double a = std::sqrt(std::numeric_limits<double>::min());  // 2^-511, exact
  const hertz<double> h;
  const scaled<hertz<double>> s(h, a);
  EXPECT_EQ(s.mean_radius(), std::ldexp(h.mean_radius(), -511));
  EXPECT_EQ(s.mean_square_radius(), std::ldexp(h.mean_square_radius(), -1022));
  EXPECT_EQ(s.mean_inverse_radius(), std::ldexp(h.mean_inverse_radius(), 511));
  EXPECT_LE(s.mean_radius() * s.mean_radius(), s.mean_square_radius());
}

// ---------------------------------------------------------------- coupling curve

// 𝓕(ratio_from_force(F)) = F to `ulps` over the whole range of 𝓕.
template <class P>
void expect_force_round_trips(const P& p, const char* name, double ulps) {
  for (double F : {1e-300, 1e-9, 0.01, 0.3, 0.6, 0.9, 0.999, 0.999999, 1 - 1e-12}) {
    const double e = ratio_from_force(p, F);
    EXPECT_LE(boost::math::epsilon_difference(p.force(e), F), ulps) << name << " F = " << F;
  }
}

// 𝓣(ratio_from_torque(T)) = T to `ulps` over the whole range of 𝓣, (0, ⟨r⟩).
template <class P>
void expect_torque_round_trips(const P& p, const char* name, double ulps) {
  const double top = p.mean_radius();
  for (double T : {1e-300, 1e-9, 0.01 * top, 0.3 * top, 0.9 * top, 0.999999 * top}) {
    const double e = ratio_from_torque(p, T);
    EXPECT_LE(boost::math::epsilon_difference(p.torque(e), T), ulps) << name << " T = " << T;
  }
}

template <class P>
void expect_round_trips(const P& p, const char* name, double ulps) {
  expect_force_round_trips(p, name, ulps);
  expect_torque_round_trips(p, name, ulps);
  const double top = p.mean_radius();
  EXPECT_EQ(ratio_from_force(p, 0.0), 0.0);
  EXPECT_EQ(ratio_from_torque(p, top), 0.0);
  EXPECT_EQ(torque_at_force(p, 0.0), top);
}

TEST(Coupling, RoundTripsToAFewUlp) {
  expect_round_trips(uniform_disk<>(), "uniform", 4);
  expect_round_trips(annulus<>(0.125), "annulus", 4);
  expect_round_trips(ring<>(), "ring", 4);
  expect_round_trips(hertz<>(), "hertz", 8);
  expect_round_trips(boussinesq<>(), "boussinesq", 8);
}

TEST(Coupling, RatioRoundTripWhereWellConditioned) {
  const uniform_disk<> u;
  for (double e = 1e-3; e < 1e3; e *= 1.37) {
    // Condition number of ε ↦ 𝓕 ↦ ε is 𝓕/(ε𝓕′); of the torque side 𝓣/(ε|𝓣′|).
    const double cf = u.force(e) / (e * force_derivative(e));
    const double ct = u.torque(e) / (e * -torque_derivative(e));
    EXPECT_LE(boost::math::epsilon_difference(ratio_from_force(u, u.force(e)), e), 4 + 4 * cf) << e;
    EXPECT_LE(boost::math::epsilon_difference(ratio_from_torque(u, u.torque(e)), e), 4 + 4 * ct)
        << e;
  }
}

TEST(Coupling, CurveMatchesTheProfileAndItsSlope) {
  const annulus<> cd(0.125);
  for (double e : {0.05, 0.653, 2.0}) {
    const double F = cd.force(e);
    EXPECT_LE(relative_difference(torque_at_force(cd, F), cd.torque(e)), 1e-13);
    EXPECT_LE(relative_difference(force_at_torque(cd, cd.torque(e)), F), 1e-13);
  }
}

TEST(Coupling, OutOfRangeIsADomainError) {
  const uniform_disk<> u;
  for (double F : {-0.1, 1.0, 1.5, double(NAN)})
    EXPECT_THROW(ratio_from_force(u, F), std::domain_error) << F;
  for (double T : {0.0, -1.0, 2.0 / 3 + 1e-9, double(NAN)})
    EXPECT_THROW(ratio_from_torque(u, T), std::domain_error) << T;
  EXPECT_THROW(torque_at_force(u, 1.0), std::domain_error);
}

// fuzz_coupling: a force target among the subnormal ratios could not be
// bracketed (evaluation_error); guards the bracket [0, ε] there.  Boussinesq's
// 𝓕 is exactly πε/4 for ε ≤ 1 (B2), so the ratio is 4F/π to the resolution of
// the subnormals (one denorm_min in ε moves 𝓕 by π/4 of one).
TEST(Coupling, RegressionForceTargetAmongSubnormalRatios) {
  const boussinesq<double> b;
  const double dmin = std::numeric_limits<double>::denorm_min();
  const double F = 9.88131291682493088353e-323;  // 20 denorm_min
  const double e = ratio_from_force(b, F);
  EXPECT_NEAR(e, 4 * F / pi, 1.5 * dmin);
  EXPECT_NEAR(b.force(e), F, dmin);
}

// fuzz_coupling: a torque reached only beyond the largest double ratio
// returned a wrong ratio; guards the domain error.  For the disk 𝓣 > 0 falls
// to 𝓣(DBL_MAX) ≈ 1/(4 DBL_MAX) = 1.4e-309 (ε𝓣 → ⟨r²⟩/2 = 1/4), above the
// target 1e-320.
TEST(Coupling, RegressionTorqueBeyondTheLargestRatioIsADomainError) {
  ASSERT_GT(0.25 / max_d, 1e-320);
  EXPECT_THROW(ratio_from_torque(uniform_disk<double>(), 1e-320), std::domain_error);
}

// fuzz_coupling (writing the campaign's regression test): the uncoupled caps
// (𝓕 = 0 at ε = 0, 1 for every ε > 0) returned ε ≈ 0 for 𝓕 = 1/2; guards the
// documented domain error for a target inside the jump.
TEST(Coupling, RegressionForceInsideTheJumpOfUncoupledCapsIsADomainError) {
  EXPECT_THROW(ratio_from_force(uncoupled_caps<double>(), 0.5), std::domain_error);
}

// fuzz_coupling (the campaign): a thin annulus's quadrature 𝓕 levels off at
// 1 − 2⁻⁵², so the valid target 1 − 2⁻⁵³ was "not reached" (domain error);
// guards answering a target within 4 ulp of that level.  Expected: a ratio
// whose 𝓕 is the target to 4 ulp, and large, since 1 − 𝓕 ≈ ⟨r²⟩/(4ε²) ≈ 1/(4ε²)
// is still 2.5e-13 at ε = 1e6.
TEST(Coupling, RegressionForceTargetAtTheTopOfAThinAnnulus) {
  const annulus<double> thin(0.999999632134875304779);
  const double target = 0.999999999999999888978;
  const double e = ratio_from_force(thin, target);
  EXPECT_NEAR(thin.force(e), target, 4 * double_eps);
  EXPECT_GT(e, 1e6);
}

// fuzz_coupling (the campaign, twice): subnormal targets of a steep elliptic
// cone were rejected as a jump; guards telling a steep 𝓕 from a jump.  The
// cone's 𝓕 = ε/√(ε² + τ²) (on the ellipse 𝓕² + 𝓣²/τ² = 1 with normal along
// (ε, 1)) is ε/τ for ε ≪ τ: ε = τF to the subnormals' resolution.
TEST(Coupling, RegressionSubnormalForceTargetsOfASteepEllipticCone) {
  // τ = 0.017: 57 subnormals of 𝓕 per step of ε.
  const double tau = 0.0173969741280550205254, tiny = 3.75489890839347373574e-322;
  EXPECT_NEAR(ratio_from_force(elliptic_limit_surface<double>(tau), tiny), tau * tiny, 2e-323);
  // τ = 1e-10: 𝓕 steps by 1e10 subnormals per step of ε.
  const double steep = 1.00703517801109410927e-10, small = 5.9100901405666000387e-314;
  EXPECT_NEAR(ratio_from_force(elliptic_limit_surface<double>(steep), small), steep * small,
              2e-323);
}

// ---------------------------------------------------------------- the paper's CD

// The paper: for the CD (a hole of b = 0.125) "deviation from the full disk
// case is not significant".  docs/profiles.md tabulates the largest
// differences; here they are bounded by (A1) (|Δ𝓕| ≤ b²/(1−b²),
// |Δ𝓣| ≤ (2/3)b²/(1−b²)) and agree with the 2-D reference for the annulus.
TEST(PaperClaims, CdHoleChangesForceAndTorqueByUnderTwoPercent) {
  const annulus<> cd(0.125);
  const uniform_disk<> disk;
  double dF = 0, dT = 0;
  for (double e = 1e-4; e < 1e4; e *= 1.01) {
    dF = std::max(dF, std::fabs(cd.force(e) - disk.force(e)));
    dT = std::max(dT, std::fabs(cd.torque(e) - disk.torque(e)));
  }
  const double b = 0.125;
  EXPECT_LE(dF, b * b / (1 - b * b));
  EXPECT_LE(dT, 2.0 / 3 * b * b / (1 - b * b));
  EXPECT_GT(dF, 0.01);  // but not negligible either: 0.012 near eps = 0.17
  EXPECT_GE(dT, cd.mean_radius() - disk.mean_radius());  // at least the eps = 0 difference
  for (const auto& r : reference().at("annulus_0.125")) {
    EXPECT_NEAR(cd.force(r.eps) - disk.force(r.eps), r.force - disk.force(r.eps), 1e-14) << r.eps;
    EXPECT_NEAR(cd.torque(r.eps) - disk.torque(r.eps), r.torque - disk.torque(r.eps), 1e-14)
        << r.eps;
  }
}

// ---------------------------------------------------------------- tabulated

// The largest relative difference of 𝓕 or 𝓣 between two profiles, and the ε
// where it is.
struct largest_difference {
  double worst = 0, at = 0;
  template <class P, class Q>
  void add(const P& p, const Q& q, double e) {
    const auto a = p.force_torque(e), b = q.force_torque(e);
    const double d =
        std::max(relative_difference(a.force, b.force), relative_difference(a.torque, b.torque));
    if (d > worst) {
      worst = d;
      at = e;
    }
  }
};

// The tabulated profile against its source: ε from 1e-12 to 1e12, densely
// around 1 (where the kernel is singular) and at the extremes.
template <class P>
largest_difference tabulated_difference(const tabulated_profile<>& tab, const P& p) {
  largest_difference d;
  for (double e = 1e-12; e < 1e12; e *= 1.031) d.add(tab, p, e);
  for (double e = 0.999; e < 1.001; e += 3.7e-6) d.add(tab, p, e);  // where the kernel is singular
  for (double e : {1e-300, 1e-30, 1e30, 1e300}) d.add(tab, p, e);
  return d;
}

// A negative ratio is a domain error for the tabulated profile too.
void expect_negative_ratio_is_a_domain_error(const tabulated_profile<>& tab) {
  EXPECT_THROW(tab.force(-1.0), std::domain_error);
}

template <class P>
void expect_tabulated(const P& p, const char* name) {
  const tabulated_profile<> tab(p);
  const largest_difference d = tabulated_difference(tab, p);
  EXPECT_LE(d.worst, 1e-10) << name << ": worst " << d.worst << " at eps = " << d.at;
  EXPECT_EQ(tab.force(0.0), 0.0);
  EXPECT_EQ(tab.force(INFINITY), 1.0);
  expect_negative_ratio_is_a_domain_error(tab);
}

TEST(Tabulated, Within1e10EverywhereForEveryProfile) {
  expect_tabulated(uniform_disk<>(), "uniform");
  expect_tabulated(annulus<>(0.125), "annulus");
  expect_tabulated(hertz<>(), "hertz");
  expect_tabulated(boussinesq<>(), "boussinesq");
  expect_tabulated(ring<>(), "ring");
  expect_tabulated(two_tier(), "two-tier");
}

// The table's 𝓕′ (the derivative of its interpolant) against the closed-form
// 𝓕′ of the source: the disk's force_derivative (Carlson forms) and Hertz's
// and Boussinesq's (elementary), over ε from 1e-9 to 1e9 and across ε = 1
// (where Boussinesq's 𝓕″ is singular); exact ends.
template <class Slope>
double worst_tabulated_slope(const tabulated_profile<>& tab, Slope exact) {
  double worst = 0;
  for (double e = 1e-9; e < 1e9; e *= 1.0173)
    worst = std::max(worst, relative_difference(tab.force_derivative(e), exact(e)));
  for (double e = 0.99; e < 1.01; e += 1.3e-4)
    worst = std::max(worst, relative_difference(tab.force_derivative(e), exact(e)));
  return worst;
}

TEST(Tabulated, ForceDerivativeOfTheTable) {
  const tabulated_profile<> disk{uniform_disk<>()}, h{hertz<>()}, b{boussinesq<>()};
  EXPECT_LE(worst_tabulated_slope(disk, [](double e) { return force_derivative(e); }), 1e-7);
  EXPECT_LE(worst_tabulated_slope(h, [](double e) { return hertz<>().force_derivative(e); }), 1e-7);
  EXPECT_LE(worst_tabulated_slope(b, [](double e) { return boussinesq<>().force_derivative(e); }),
            1e-7);
  EXPECT_NEAR(disk.force_derivative(0.0), 1.0, 1e-12);  // ⟨1/r⟩/2
  EXPECT_EQ(disk.force_derivative(INFINITY), 0.0);
  EXPECT_THROW(disk.force_derivative(-1.0), std::domain_error);
  EXPECT_THROW(disk.force_derivative(NAN), std::domain_error);
}

TEST(Tabulated, SharedBetweenThreadsGivesTheSerialResults) {
  const tabulated_profile<> tab{hertz<>()};
  std::vector<double> xs;
  for (double e = 1e-6; e < 1e6; e *= 1.01) xs.push_back(e);
  std::vector<double> serial(xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) serial[i] = tab.force(xs[i]) + 7 * tab.torque(xs[i]);
  std::vector<std::vector<double>> out(4, std::vector<double>(xs.size()));
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (std::size_t i = 0; i < xs.size(); ++i)
        out[t][i] = tab.force(xs[i]) + 7 * tab.torque(xs[i]);
    });
  for (auto& th : threads) th.join();
  for (const auto& o : out) EXPECT_EQ(o, serial);
}

// fuzz_coupling: the tabulated Hertz profile gave 𝓕 = 1 + 2e-15 at ε = 4.4e11;
// guards the clamp of the tabulated 𝓕 to ≤ 1 and 𝓣 to ≤ ⟨r⟩.  Expected, to
// the table's 1e-10 (Tabulated.Within1e10EverywhereForEveryProfile), the
// limits (L) with Hertz's moments (⟨r²⟩ = 2/5, ⟨r⟩ = 3π/16, ⟨1/r⟩ = 3π/4):
// 1 − 𝓕(ε) ≈ ⟨r²⟩/(4ε²) = 0.1/ε² and 𝓣(δ) ≈ ⟨r⟩ − δ²⟨1/r⟩/4 (f_T = (2/π) r E(δ/r)).
TEST(Tabulated, RegressionHertzForceNeverAboveOne) {
  const tabulated_profile<double> t{hertz<double>()};
  const auto m = spinslide_test::hertz_moments();
  for (double e = 1e6; e < 1e300; e *= 3.7) {
    ASSERT_LE(t.force(e), 1.0) << e;
    ASSERT_NEAR(t.force(e), double(1 - m.mean_square_radius / 4 / e / e), 1e-10) << e;
    ASSERT_LE(t.torque(1 / e), t.mean_radius()) << e;
    ASSERT_NEAR(t.torque(1 / e), double(m.mean_radius), 1e-10 * double(m.mean_radius)) << e;
  }
  // 𝓣 = 4.5e-13 is reached at ε ≈ ⟨r²⟩/(2𝓣) = 4.4e11, where 1 − 𝓕 ≈ 5e-25.
  const double F = force_at_torque(t, 4.54747350886464118958e-13);
  EXPECT_LE(F, 1.0);
  EXPECT_NEAR(F, 1.0, 1e-10);
}

}  // namespace
