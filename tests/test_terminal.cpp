//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The flow of the ratio ε and the terminal regimes (terminal.hpp).
#include <gtest/gtest.h>

#include <spinslide/motion/terminal.hpp>

#include <boost/math/special_functions/relative_difference.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "flow_zeros_reference.hpp"
#include "quadrature_moments.hpp"
#include "reference/csv.hpp"

namespace {

using namespace spinslide;
using mp = boost::multiprecision::cpp_bin_float_50;
using spinslide_reference::expected_attractor;
using spinslide_reference::flow_case;
using spinslide_reference::reference_flow_cases;
using spinslide_reference::with_load;

// ε₀ from tests/reference/terminal_ratio.txt: the zero of ε − 𝓕/(2𝓣) with 𝓕,
// 𝓣 from 100-digit quadrature of the area integrals.
std::string reference_terminal_ratio() {
  const auto rows = spinslide_reference::read_csv_rows(SPINSLIDE_TERMINAL_RATIO_REFERENCE);
  if (rows.empty() || rows[0].empty())
    throw std::runtime_error("no value in " SPINSLIDE_TERMINAL_RATIO_REFERENCE);
  return rows[0][0];
}

TEST(TerminalRatio, PaperValueToOneUlpInDoubleAnd40DigitsInMultiprecision) {
  const std::string ref = reference_terminal_ratio();
  EXPECT_LE(
      boost::math::epsilon_difference(terminal_ratio<double>(), std::strtod(ref.c_str(), nullptr)),
      1);
  EXPECT_LE(boost::math::epsilon_difference(terminal_ratio<long double>(),
                                            std::strtold(ref.c_str(), nullptr)),
            4);
  EXPECT_LE(
      boost::math::epsilon_difference(terminal_ratio<float>(), std::strtof(ref.c_str(), nullptr)),
      1);
  const mp e = terminal_ratio<mp>();
  EXPECT_LT(abs(e / mp(ref) - 1), mp("1e-40"));
  EXPECT_EQ(terminal_ratio<double>(), terminal_ratio());  // default is double
  EXPECT_NEAR(terminal_ratio(), 0.653, 5e-4);             // the paper's "0.653"
}

TEST(RatioFlow, PaperAsymptotesForHalf) {
  const uniform_disk<> u;
  // f(ε) ≈ ε/4 as ε → 0 and ≈ −ε as ε → ∞ (the paper, after Eq. (5)).
  EXPECT_NEAR(ratio_flow(u, 1e-6, 0.5) / 1e-6, 0.25, 1e-11);
  EXPECT_NEAR(ratio_flow(u, 1e6, 0.5) / 1e6, -1.0, 1e-11);
  EXPECT_EQ(ratio_flow(u, 0.0, 0.5), 0.0);
  // Positive below ε₀, negative above; ε₀ attracts (f′(ε₀) < 0).
  const double e0 = terminal_ratio();
  for (double e = 1e-4; e < 1e4; e *= 1.1) {
    if (std::fabs(e - e0) < 1e-9) continue;
    EXPECT_EQ(ratio_flow(u, e, 0.5) > 0, e < e0) << e;
  }
  EXPECT_LT(ratio_flow(u, e0 + 1e-6, 0.5) - ratio_flow(u, e0 - 1e-6, 0.5), 0);
}

// f(ε)/ε → g(0) = 1 − γ⟨1/r⟩/(2⟨r⟩) as ε → 0 and g(∞) = 1 − 2γ/⟨r²⟩ as ε → ∞
// (docs/theory.md §8), with Hertz's moments from quadrature of its load
// (3π/4, 3π/16 and 2/5: g(0) = 1 − 2γ, g(∞) = 1 − 5γ).
TEST(RatioFlow, GeneralGammaAsymptotes) {
  const hertz<> h;
  const auto m = spinslide_test::hertz_moments();
  for (double g : {0.1, 0.3, 0.7}) {
    const double a = double(1 - g * m.mean_inverse_radius / (2 * m.mean_radius));
    const double c = double(1 - 2 * g / m.mean_square_radius);
    EXPECT_NEAR(ratio_flow(h, 1e-6, g) / 1e-6, a, 1e-9) << g;
    EXPECT_NEAR(ratio_flow(h, 1e6, g) / 1e6, c, 1e-9) << g;
  }
}

// Just below the window's lower edge γ the motion ends in pure sliding, just
// above it in both with a large ε₀.
template <class P>
void expect_lower_edge(const P& p, double lower, const char* name) {
  const double d = 1e-6;
  EXPECT_EQ(terminal_motion(p, lower * (1 - d)).regime, terminal_regime::pure_sliding) << name;
  const auto in_low = terminal_motion(p, lower * (1 + d));
  EXPECT_EQ(in_low.regime, terminal_regime::sliding_and_spinning) << name;
  EXPECT_GT(in_low.ratio, 10) << name;  // just inside: ε₀ is large
}

// Just below the window's upper edge γ the motion ends in both with a small
// ε₀, just above it in pure spinning.
template <class P>
void expect_upper_edge(const P& p, double upper, const char* name) {
  const double d = 1e-6;
  const auto in_high = terminal_motion(p, upper * (1 - d));
  EXPECT_EQ(in_high.regime, terminal_regime::sliding_and_spinning) << name;
  EXPECT_LT(in_high.ratio, 0.1) << name;  // just inside: ε₀ is small
  EXPECT_EQ(terminal_motion(p, upper * (1 + d)).regime, terminal_regime::pure_spinning) << name;
}

// In the window ε₀ is a zero of f and attracts.
template <class P>
void expect_attracting_zero(const P& p, double g, const char* name) {
  const auto t = terminal_motion(p, g);
  EXPECT_LE(std::fabs(ratio_flow(p, t.ratio, g)), 1e-13 * t.ratio) << name;
  EXPECT_GT(ratio_flow(p, t.ratio * 0.99, g), 0) << name;
  EXPECT_LT(ratio_flow(p, t.ratio * 1.01, g), 0) << name;
}

template <class P>
void expect_window_edges(const P& p, const char* name) {
  const auto w = terminal_window(p);
  ASSERT_LT(w.lower, w.upper) << name;
  expect_lower_edge(p, w.lower, name);
  expect_upper_edge(p, w.upper, name);
  expect_attracting_zero(p, (w.lower + w.upper) / 2, name);
}

TEST(TerminalMotion, RegimesOnBothSidesOfEachWindowEdge) {
  expect_window_edges(uniform_disk<>(), "uniform");
  expect_window_edges(annulus<>(0.125), "cd");
  expect_window_edges(hertz<>(), "hertz");
  expect_window_edges(boussinesq<>(), "boussinesq");
  expect_window_edges(ring<>(), "ring");
}

TEST(TerminalMotion, WindowOfTheUniformDisk) {
  const auto w = terminal_window(uniform_disk<>());
  EXPECT_EQ(w.lower, 0.25);
  EXPECT_DOUBLE_EQ(w.upper, 2.0 / 3);
  // Exactly at γ = 1/4, g(∞) = 0 and the next order, 𝓕/(ε𝓣) ≈ 4(1 − 5/(24ε²)) < 4,
  // makes ε grow: pure sliding (docs/theory.md §8).
  EXPECT_EQ(terminal_motion(uniform_disk<>(), 0.25).regime, terminal_regime::pure_sliding);
  // The CD's own γ = (1 + b²)/2 lies in the CD's window.
  const annulus<> cd(0.125);
  const auto t = terminal_motion(cd, (1 + 0.125 * 0.125) / 2);
  EXPECT_EQ(t.regime, terminal_regime::sliding_and_spinning);
  EXPECT_NEAR(t.ratio, terminal_ratio(), 0.05);
}

// Boussinesq: 𝓕(1) = π/4 (theory (B1)) and 𝓣(1) = π/8, so for γ = 1/2 the
// terminal ratio is exactly 1.  Hertz and the ring sit on an edge at γ = 1/2.
TEST(TerminalMotion, SpecialCasesAtHalf) {
  const double pi = boost::math::constants::pi<double>();
  EXPECT_LE(boost::math::relative_difference(boussinesq<>().torque(1.0), pi / 8), 1e-15);
  const auto b = terminal_motion(boussinesq<>(), 0.5);
  EXPECT_EQ(b.regime, terminal_regime::sliding_and_spinning);
  EXPECT_NEAR(b.ratio, 1.0, 1e-14);
  EXPECT_EQ(terminal_motion(hertz<>(), 0.5).regime, terminal_regime::pure_spinning);
  EXPECT_EQ(terminal_motion(ring<>(), 0.5).regime, terminal_regime::pure_sliding);
}

TEST(TerminalMotion, FromAnInitialRatio) {
  const uniform_disk<> u;
  for (double e : {1e-8, 0.1, 0.653, 2.0, 1e8})
    EXPECT_NEAR(terminal_motion(u, 0.5, e).ratio, terminal_ratio(), 1e-15) << e;
  EXPECT_EQ(terminal_motion(u, 0.5, 0.0).regime, terminal_regime::pure_spinning);
  EXPECT_EQ(terminal_motion(u, 0.5, double(INFINITY)).regime, terminal_regime::pure_sliding);
  EXPECT_EQ(terminal_motion(u, 0.1, 0.5).regime, terminal_regime::pure_sliding);
  EXPECT_EQ(terminal_motion(u, 1.0, 0.5).regime, terminal_regime::pure_spinning);
}

// Half the load on a tiny central disk and half on the rim: the window is
// empty (2⟨r⟩/⟨1/r⟩ < ⟨r²⟩/2) and between the two edges both ends attract.
TEST(TerminalMotion, BistableProfileDependsOnTheInitialRatio) {
  const auto p = weighted_sum({0.5, 0.5}, scaled<uniform_disk<>>(uniform_disk<>(), 0.01), ring<>());
  const auto w = terminal_window(p);
  ASSERT_GT(w.lower, w.upper);
  const double g = std::sqrt(w.lower * w.upper);
  EXPECT_THROW(terminal_motion(p, g), std::domain_error);
  EXPECT_EQ(terminal_motion(p, g, 1e-6).regime, terminal_regime::pure_spinning);
  EXPECT_EQ(terminal_motion(p, g, 1e6).regime, terminal_regime::pure_sliding);
}

TEST(RatioFlowZeros, EveryZeroMatchesTheIndependentScanOfTheRingIntegral) {
  const auto cases = reference_flow_cases();
  ASSERT_EQ(cases.size(), 10u);
  for (const auto& c : cases) {
    with_load(c.load, [&](const auto& p) {
      const auto zeros = ratio_flow_zeros(p, c.gamma);
      ASSERT_EQ(zeros.size(), c.zeros.size()) << c.load << " " << c.gamma;
      for (std::size_t i = 0; i < zeros.size(); ++i) {
        EXPECT_LE(boost::math::relative_difference(zeros[i].ratio, c.zeros[i].ratio), 1e-12)
            << c.load << " " << c.gamma << " zero " << i;
        EXPECT_EQ(zeros[i].attracting, c.zeros[i].attracting) << c.load << " " << c.gamma;
      }
    });
  }
}

// terminal_motion(p, γ, e) against the reference attractor of e.
template <class P>
void expect_reaches(const P& p, const flow_case& c, double e) {
  const double expected = expected_attractor(c, e);
  const auto t = terminal_motion(p, c.gamma, e);
  const std::string where =
      c.load + " gamma " + std::to_string(c.gamma) + " from " + std::to_string(e);
  const terminal_regime regime = expected == 0          ? terminal_regime::pure_spinning
                                 : std::isinf(expected) ? terminal_regime::pure_sliding
                                                        : terminal_regime::sliding_and_spinning;
  EXPECT_EQ(t.regime, regime) << where;
  if (regime == terminal_regime::sliding_and_spinning) {
    EXPECT_LE(boost::math::relative_difference(t.ratio, expected), 1e-12) << where;
  }
}

// The example: from ε = 0.05 the flow stops at the first zero, 0.1005.
TEST(TerminalMotion, FromAnInitialRatioStopsAtTheFirstZeroItMeets) {
  const auto cases = reference_flow_cases();
  for (const auto& c : cases) {
    std::vector<double> starts{0.05, c.zeros.front().ratio / 2, c.zeros.back().ratio * 2};
    for (std::size_t i = 0; i + 1 < c.zeros.size(); ++i)
      starts.push_back(std::sqrt(c.zeros[i].ratio * c.zeros[i + 1].ratio));
    with_load(c.load, [&](const auto& p) {
      for (double e : starts) expect_reaches(p, c, e);
    });
  }
}

// The number of attractors of a reference case: its attracting zeros, and
// ε → 0 or ε → ∞ where the limits g(0), g(∞) of docs/theory.md §8 say so,
// from ⟨r⟩, ⟨1/r⟩, ⟨r²⟩ of each load by hand (a ring of radius a has a,
// 1/a, a²; a uniform disk of radius a has 2a/3, 2/a, a²/2).
long attractors_of(const flow_case& c) {
  struct moments {
    double mean, inverse, square;
  };
  moments m{0.1 * 2 * 0.15 / 3 + 0.9, 0.1 * 2 / 0.15 + 0.9, 0.1 * 0.15 * 0.15 / 2 + 0.9};
  if (c.load == "two_rings") m = {0.1 * 0.1 + 0.9, 0.1 / 0.1 + 0.9, 0.1 * 0.01 + 0.9};
  if (c.load == "three_rings")
    m = {0.01 * 0.01 + 0.09 * 0.1 + 0.9, 0.01 / 0.01 + 0.09 / 0.1 + 0.9,
         0.01 * 1e-4 + 0.09 * 0.01 + 0.9};
  const bool zero_attracts = 1 - c.gamma * m.inverse / (2 * m.mean) < 0;
  const bool infinity_attracts = 1 - 2 * c.gamma / m.square > 0;
  return std::count_if(c.zeros.begin(), c.zeros.end(), [](const auto& z) { return z.attracting; }) +
         int(zero_attracts) + int(infinity_attracts);
}

// Without an initial ratio: a domain error wherever the flow has more than one
// attractor, else that attractor.
template <class P>
void expect_domain_error(const P& p, const flow_case& c) {
  EXPECT_THROW(terminal_motion(p, c.gamma), std::domain_error) << c.load << " " << c.gamma;
}

template <class P>
void expect_outcome(const P& p, const flow_case& c, bool many) {
  if (many) {
    expect_domain_error(p, c);
    return;
  }
  ASSERT_EQ(c.zeros.size(), 1u);
  const auto t = terminal_motion(p, c.gamma);
  EXPECT_EQ(t.regime, terminal_regime::sliding_and_spinning);
  EXPECT_LE(boost::math::relative_difference(t.ratio, c.zeros[0].ratio), 1e-12) << c.load;
}

TEST(TerminalMotion, SeveralAttractorsAreADomainError) {
  int unique = 0, several = 0;
  for (const auto& c : reference_flow_cases()) {
    const bool many = attractors_of(c) > 1;
    (many ? several : unique) += 1;
    with_load(c.load, [&](const auto& p) { expect_outcome(p, c, many); });
  }
  EXPECT_EQ(unique, 3);
  EXPECT_EQ(several, 7);
}

// The zeros of the built-in profiles in their windows: one, attracting, the
// ε₀ of terminal_motion; outside the windows none (and the paper's ε₀).
TEST(RatioFlowZeros, OneAttractingZeroInTheWindowOfEveryBuiltInProfile) {
  const auto disk = ratio_flow_zeros(uniform_disk<>(), 0.5);
  ASSERT_EQ(disk.size(), 1u);
  EXPECT_TRUE(disk[0].attracting);
  EXPECT_LE(boost::math::epsilon_difference(
                disk[0].ratio, std::strtod(reference_terminal_ratio().c_str(), nullptr)),
            2);
  EXPECT_TRUE(ratio_flow_zeros(uniform_disk<>(), 0.2).empty());  // below the window
  EXPECT_TRUE(ratio_flow_zeros(uniform_disk<>(), 0.7).empty());  // above it
  const auto b = ratio_flow_zeros(boussinesq<>(), 0.5);
  ASSERT_EQ(b.size(), 1u);
  // docs/theory.md §8: ε₀ = 1.  Boussinesq's quadrature is accurate to ~1e-13,
  // and the march's bracket is not terminal_motion's: 1e-12 here.
  EXPECT_NEAR(b[0].ratio, 1.0, 1e-12);
  EXPECT_TRUE(ratio_flow_zeros(ring<>(), 0.5).empty());  // the lower edge: pure sliding
}

TEST(RatioFlowZeros, BadInputIsADomainError) {
  for (double g : {0.0, -1.0, double(NAN), double(INFINITY)})
    EXPECT_THROW(ratio_flow_zeros(uniform_disk<>(), g), std::domain_error) << g;
}

TEST(TerminalMotion, BadInputIsADomainError) {
  const uniform_disk<> u;
  for (double g : {0.0, -1.0, double(NAN), double(INFINITY)}) {
    EXPECT_THROW(terminal_motion(u, g), std::domain_error) << g;
    EXPECT_THROW(ratio_flow(u, 0.5, g), std::domain_error) << g;
  }
  EXPECT_THROW(ratio_flow(u, -1.0, 0.5), std::domain_error);
  EXPECT_THROW(ratio_flow(u, double(NAN), 0.5), std::domain_error);
  EXPECT_THROW(terminal_motion(u, 0.5, -1.0), std::domain_error);
}

// fuzz_terminal: a Padé form's 𝓣 underflowed to 0 at ε = 1e300, so the flow
// g = 1 − γ𝓕/(ε𝓣) was −∞ there, a false zero was bracketed and
// terminal_motion evaluated 𝓕 at a NaN ratio; guards detail::flow_terms_at
// (𝓕/ε and ε𝓣 take their limits where 𝓕 or 𝓣 is not a normal number).
// Expected from the moments alone (docs/theory.md §8): g(0) = 1 − γ⟨1/r⟩/(2⟨r⟩)
// > 0 and g(∞) = 1 − 2γ/⟨r²⟩ > 0, so ε → ∞ from any start: pure sliding.
TEST(TerminalMotion, RegressionPadeFormWithExtremeMomentsSlides) {
  const pade_approximation<double> p(2922, 765, 1.7e-9);
  const double gamma = 2.2e-16;
  ASSERT_GT(1 - gamma * 765 / (2 * 2922.0), 0);
  ASSERT_GT(1 - 2 * gamma / 1.7e-9, 0);
  const double inf = std::numeric_limits<double>::infinity();
  for (const auto& t : {terminal_motion(p, gamma, 1e132), terminal_motion(p, gamma),
                        terminal_motion(p, gamma, 1e-300)}) {
    EXPECT_EQ(t.regime, terminal_regime::pure_sliding);
    EXPECT_EQ(t.ratio, inf);
  }
}

// issue 28 - at the exact edges of a profile's window (f's limit g(0) or
// g(∞) is 0, so f's departure from 0 at that end is below rounding), the
// overload with a start reported rounding noise as a zero (Hertz at γ = 1/5
// from ε = 0.5, 1e7 or 1e9: ε₀ ≈ 4e7) or the start itself (Hertz at γ = 1/2
// and the disk at γ = 2/3 from 1e-9; the disk at γ = 1/4 from 1e9), where
// the one-argument call, from the next-order term, says pure sliding or
// pure spinning.  With one attractor they now agree from every start.
template <class Profile, class Real = typename Profile::value_type>
void expect_starts_agree(const Profile& p, Real gamma, const char* name) {
  const terminal_state<Real> whole = terminal_motion(p, gamma);
  const Real tolerance = std::is_same<Real, float>::value ? Real(1e-5) : Real(1e-12);
  for (const long double start : {1e-300L, 1e-30L, 1e-12L, 1e-9L, 1e-3L, 0.5L, 1.0L, 2.0L, 1e3L,
                                  1e7L, 1e9L, 1e12L, 1e30L, 1e300L}) {
    if (start < std::numeric_limits<Real>::min() || start > std::numeric_limits<Real>::max())
      continue;
    const terminal_state<Real> from = terminal_motion(p, gamma, static_cast<Real>(start));
    EXPECT_EQ(from.regime, whole.regime) << name << ", gamma " << gamma << ", from " << start;
    if (whole.regime == terminal_regime::sliding_and_spinning) {
      EXPECT_NEAR(from.ratio, whole.ratio, tolerance * whole.ratio) << name << ", from " << start;
    }
  }
}

template <class Profile, class Real = typename Profile::value_type>
void expect_edges_agree(const Profile& p, const char* name) {
  const auto window = terminal_window(p);
  for (const Real gamma : {window.lower, window.upper, Real((window.lower + window.upper) / 2)})
    expect_starts_agree(p, gamma, name);
}

TEST(TerminalMotion, RegressionStartsAgreeWithTheWholeFlowAtWindowEdges) {
  expect_starts_agree(hertz<>(), 0.2, "hertz");
  expect_starts_agree(hertz<>(), 0.5, "hertz");
  expect_starts_agree(uniform_disk<>(), 2.0 / 3, "disk");
  expect_starts_agree(uniform_disk<>(), 0.25, "disk");
  expect_edges_agree(uniform_disk<>(), "disk");
  expect_edges_agree(hertz<>(), "hertz");
  expect_edges_agree(boussinesq<>(), "boussinesq");
  expect_edges_agree(annulus<>(0.5), "annulus 0.5");
}

// issue 28 - in float, within the rounding of a window's edge, the march
// and the walk find no sign change of the flow and the ends' limits g(0),
// g(∞) round to a value of the wrong sign or 0: terminal_motion(profile, γ)
// threw "No zero of the ratio flow found" for Hertz at γ = 1/5 and 1/2, the
// ring at 1/2 and 2, the disk at 2/3 and Boussinesq at 1.  Where the flow has
// no sign change at all it now reports the end it runs to, and every start
// agrees with it, at each edge and one float step to either side.
template <class Profile>
std::vector<float> float_steps_around_edges(const Profile& p) {
  const auto window = terminal_window(p);
  std::vector<float> gammas;
  for (const float edge : {window.lower, window.upper})
    gammas.insert(gammas.end(), {std::nextafter(edge, 0.0f), edge, std::nextafter(edge, 10.0f)});
  return gammas;
}

template <class Profile>
void expect_float_edges_answer(const Profile& p, const char* name) {
  for (const float gamma : float_steps_around_edges(p)) {
    EXPECT_NO_THROW(terminal_motion(p, gamma)) << name << ", gamma " << gamma;
    expect_starts_agree(p, gamma, name);
  }
}

TEST(TerminalMotion, RegressionFloatAnswersAtEveryWindowEdge) {
  expect_float_edges_answer(uniform_disk<float>(), "disk");
  expect_float_edges_answer(annulus<float>(0.5f), "annulus 0.5");
  expect_float_edges_answer(ring<float>(), "ring");
  expect_float_edges_answer(hertz<float>(), "hertz");
  expect_float_edges_answer(boussinesq<float>(), "boussinesq");
}

}  // namespace
