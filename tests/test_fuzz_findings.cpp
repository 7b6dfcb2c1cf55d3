//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Every failure the fuzz harnesses (fuzz/) found, as a regression test with
// the input the fuzzer reported and an independent expectation: an exact
// limit, a scale invariance or a bound.  docs/reliability.md lists them.

#include <spinslide/spinslide.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace {

using namespace spinslide;
constexpr double max_d = std::numeric_limits<double>::max();
constexpr double min_d = std::numeric_limits<double>::min();

// fuzz_stop_time: ∞ · 0 and ∞ − ∞ in distances and angles; a subnormal or
// huge γ.
TEST(FuzzFindings, ThrowsAtTheEdgesOfDouble) {
  const tabulated_throw<uniform_disk<double>> table(uniform_disk<double>(), 0.5);
  EXPECT_GE(table.distance(min_d, max_d), 0);
  EXPECT_GE(table.distance(min_d, 1), 0);
  // Pure spinning at the largest spin: the stop time γω0/⟨r⟩ and the angle
  // overflow (∞), and the distance is exactly 0.
  const auto spin = simulate_throw(boussinesq<double>(), 1.0, 0.0, max_d);
  EXPECT_EQ(spin.distance, 0);
  EXPECT_EQ(spin.angle, std::numeric_limits<double>::infinity());
  // γ ω0/⟨r⟩ with ⟨r⟩/γ overflowing.
  const double gamma = 1e-300;
  EXPECT_DOUBLE_EQ(simulate_throw(uniform_disk<double>(), gamma, 0.0, 1e10).time,
                   gamma * 1e10 / (2.0 / 3));
  // The scaled state of a finite-ratio throw at the largest spin: no ∞ · 0.
  const auto r = simulate_throw(boussinesq<double>(), 6.0840221749458591037e-14,
                                2.22044604925031308085e-16, max_d);
  EXPECT_FALSE(std::isnan(r.distance));
  EXPECT_THROW(simulate_throw(ring<double>(), max_d, 0.5, 0.5), std::domain_error);
  EXPECT_THROW(simulate_throw(ring<double>(), 3e-322, 0.5, 0.5), std::domain_error);
  EXPECT_THROW(stop_time(ring<double>(), 1e300, 0.5, 0.5), std::domain_error);
  EXPECT_NO_THROW(stop_time(ring<double>(), 1e290, 0.5, 0.5));
}

// fuzz_stop_time: throws whose ratio ε0 = v0/ω0 is beyond ~1e±100, or with γ
// near the ends of its domain, gave wrong stop times, NaN distances and angles
// or "no stop found" (the scaled state over- or underflowed, and the ratio's
// equation was stiff).  Expected: the limits where one motion is negligible.
// While v ≫ ω, 𝓣 ≈ ⟨r²⟩/(2ε), so ω = ω0 (v/v0)^k with k = ⟨r²⟩/(2γ) and
// θ = ω0 v0/(1 + k), t = v0, s = v0²/2.  While ω ≫ v, 𝓕 ≈ ε⟨1/r⟩/2, so
// v = v0 (ω/ω0)^m with m = γ⟨1/r⟩/(2⟨r⟩) and s = v0 ω0 γ/(⟨r⟩(1 + m)),
// t = γω0/⟨r⟩, θ = ω0 t/2.  (Disk: ⟨r⟩ = 2/3, ⟨1/r⟩ = 2, ⟨r²⟩ = 1/2.)
TEST(FuzzFindings, ThrowsAtExtremeRatiosAndInertia) {
  const uniform_disk<double> disk;
  const double rel = 1e-12;
  {  // ε0 = 1e350: the quotient overflows
    const auto r = simulate_throw(disk, 0.5, 1e150, 1e-200);
    EXPECT_NEAR(r.time / 1e150, 1, rel);
    EXPECT_NEAR(r.distance / 5e299, 1, rel);
    EXPECT_NEAR(r.angle / (1e-50 / (1 + 0.5)), 1, 1e-11);
  }
  {  // ε0 = 1e-350: the quotient underflows
    const auto r = simulate_throw(disk, 0.5, 1e-200, 1e150);
    EXPECT_NEAR(r.time / 0.75e150, 1, rel);
    EXPECT_NEAR(r.angle / (1e150 * 0.75e150 / 2), 1, rel);
    EXPECT_NEAR(r.distance / (1e-50 * 0.5 / ((2.0 / 3) * 1.75)), 1, 1e-11);
  }
  {  // the fuzzer's case: t* was v0 instead of γω0/⟨r⟩ = 4.2e-14
    const double gamma = 5.6e-14;
    for (const double v0 : {2e-308, 2e-200, 2e-50}) {
      const auto r = simulate_throw(disk, gamma, v0, 0.5);
      EXPECT_NEAR(r.time / (gamma * 0.5 / (2.0 / 3)), 1, rel) << v0;
      EXPECT_NEAR(r.angle / (gamma * 0.25 / (4.0 / 3)), 1, rel) << v0;
    }
  }
  {  // the largest speed and the smallest spin: θ = 4.9e-324 · 1.7e308 · 2/3
    const double v0 = 1.7e308, w0 = std::numeric_limits<double>::denorm_min();
    const auto r = simulate_throw(disk, 0.5, v0, w0);
    EXPECT_NEAR(r.time / v0, 1, rel);
    EXPECT_NEAR(r.angle / (w0 * v0 / 1.5), 1, 1e-11);
  }
  {  // γ = 1e-300: the spin dies at once, then pure sliding
    const auto r = simulate_throw(disk, 1e-300, 1.0, 1.0);
    EXPECT_NEAR(r.time, 1, rel);
    EXPECT_NEAR(r.distance, 0.5, rel);
  }
  {  // γ = 1e290: the spin hardly slows while the body slides
    const auto r = simulate_throw(disk, 1e290, 1.0, 1.0);
    EXPECT_NEAR(r.time / 1.5e290, 1, rel);
    EXPECT_NEAR(r.angle / (1.5e290 / 2), 1, rel);
  }
  {  // at the edge of the ring's window (γ = <r²>/2) the flow creeps to ∞ like
     // 1/ε²: "no stop found".  ω0 = max, v0 = min: t* = γω0/<r> (<r> = 1)
    const auto r =
        simulate_throw(ring<double>(), 0.5, std::numeric_limits<double>::denorm_min(), max_d);
    EXPECT_NEAR(r.time / (0.5 * max_d), 1, rel);
  }
  {  // γ = 1.3e256 and subnormal speeds: the spin outlasts the slide by 1e241,
     // but the stop was found when v underflowed (t* = v0)
    const tabulated_profile<double> hz{hertz<double>()};
    const double gamma = 1.31110559619016773427e+256,
                 w0 = std::numeric_limits<double>::denorm_min();
    const auto r = simulate_throw(hz, gamma, 5.56268464626800345773e-309, w0);
    EXPECT_NEAR(r.time / (gamma * w0 / hz.mean_radius()), 1, rel);
  }
  {  // pure spinning from a subnormal ω0 (v0 = −0): ω0/<r> rounded away 20%
    const boussinesq<double> b;
    const double gamma = 1.91079076817831732741e+101,
                 w0 = std::numeric_limits<double>::denorm_min();
    const auto expected =
        static_cast<double>(static_cast<long double>(gamma) * w0 / b.mean_radius());
    EXPECT_NEAR(simulate_throw(b, gamma, -0.0, w0).time / expected, 1, 1e-15);
  }
  {  // uncoupled caps (found by the random driver in the README build): with
     // 𝓕 = 1 and 𝓣 = τ both motions decelerate uniformly and independently,
     // t* = max(v0, γω0/τ), s = v0²/2, θ = γω0²/(2τ); ε0 = 7.7e35 gave
     // "no stop found" (the log of a ratio that reaches 0 at a finite time)
    struct caps_throw {
      double tau, gamma, v0, w0;
    };
    for (const caps_throw& c :
         {caps_throw{8.7843193121122449291e-10, 0.406209994126658979763, 1.6991849557249753088e20,
                     2.22e-16},
          caps_throw{0.467046984433948875193, 0.491038236470873357131, 7.46581792819842669392e+147,
                     5.38232671090365509445e-155},
          caps_throw{2.0 / 3, 0.5, 1.0, 1.0}, caps_throw{2.0 / 3, 0.5, 1.0, 3.0}}) {
      const auto r = simulate_throw(uncoupled_caps<double>(c.tau), c.gamma, c.v0, c.w0);
      EXPECT_NEAR(r.time / std::max(c.v0, c.gamma * c.w0 / c.tau), 1, rel) << c.v0;
      EXPECT_NEAR(r.distance / (c.v0 * c.v0 / 2), 1, rel) << c.v0;
      EXPECT_NEAR(r.angle / (c.gamma * c.w0 * c.w0 / (2 * c.tau)), 1, rel) << c.v0;
    }
  }
  {  // float: "no stop found" from ε0 = 1e60 (the rounding of a float
     // right-hand side forced 1e-7 steps)
    const auto r = simulate_throw(uniform_disk<float>(), 0.5f, 1e30f, 1e-30f);
    EXPECT_NEAR(r.time / 1e30f, 1, 1e-5);
    EXPECT_NEAR(r.angle / (1 / 1.5f), 1, 1e-5);
  }
}

}  // namespace
