//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Fuzz harness: terminal_motion (both overloads) and ratio_flow on the
// profiles of zoo.hpp, with fuzzed inertia ratios γ and initial ratios.
// Valid: γ finite and > 0; an initial ratio ≥ 0 (+∞ included); for
// ratio_flow a finite ε ≥ 0.  The two-argument terminal_motion reports a
// domain error also where both ε → 0 and ε → ∞ attract (the outcome then
// depends on the start), and wherever the flow has several attractors (ends
// or attracting zeros of ratio_flow_zeros, whose zeros are checked too).
// Then: pure sliding ends at ε = +∞, pure spinning at 0, and sliding and
// spinning at a finite ε₀ > 0 where the flow f(ε₀) = ε₀ − γ𝓕/𝓣 vanishes
// (|f| ≤ 1e-6 of its larger term); ratio_flow is finite.

#include "zoo.hpp"

#include <spinslide/motion/terminal.hpp>

#include <algorithm>
#include <vector>

namespace {

using namespace spinslide_fuzz;

template <class Profile>
void check_state(const Profile& p, double gamma, const spinslide::terminal_state<double>& s,
                 const char* call) {
  using spinslide::terminal_regime;
  switch (s.regime) {
    case terminal_regime::pure_sliding:
      check(s.ratio == std::numeric_limits<double>::infinity(), call, "pure sliding, ratio != inf");
      break;
    case terminal_regime::pure_spinning:
      check(s.ratio == 0, call, "pure spinning, ratio != 0");
      break;
    case terminal_regime::sliding_and_spinning: {
      check_finite(s.ratio, call, "eps0");
      check(s.ratio > 0, call, "eps0 <= 0");
      const auto ft = p.force_torque(s.ratio);
      // Relative to its terms: where γ = <r²>/2 the flow is flat at large ε.
      const double pull = gamma * ft.force / ft.torque;
      // (Among subnormal or near-overflowing ratios 𝓕/𝓣 has too few digits.)
      if (s.ratio > 1e-290 && s.ratio < 1e290)
        check(std::fabs(s.ratio - pull) <= 1e-6 * std::fmax(s.ratio, pull), call,
              "the flow does not vanish at eps0");
      break;
    }
  }
}

// ratio_flow_zeros: ascending, each a zero of f, attracting and repelling in turn.
template <class Profile>
void check_zeros(const Profile& p, double gamma,
                 const std::vector<spinslide::ratio_flow_zero<double>>& zeros) {
  for (std::size_t i = 0; i < zeros.size(); ++i) {
    const auto& z = zeros[i];
    check(z.ratio > 0 && std::isfinite(z.ratio), "ratio_flow_zeros", "a zero not finite and > 0");
    if (i == 0) continue;
    check(zeros[i - 1].ratio < z.ratio, "ratio_flow_zeros", "zeros not ascending");
    check(zeros[i - 1].attracting != z.attracting, "ratio_flow_zeros",
          "two attracting or two repelling zeros in a row");
  }
  for (const auto& z : zeros)
    check_state(p, gamma, {spinslide::terminal_regime::sliding_and_spinning, z.ratio},
                "ratio_flow_zeros");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz_input in(data, size);
  context().clear();
  with_profile(in, [&](const auto& p, const char* name, bool) {
    context() += std::string(" profile=") + name;
    const double gamma = in.real<double>(), start = in.real<double>(), eps = in.real<double>();
    describe("gamma", gamma);
    describe("initial_ratio", start);
    describe("eps", eps);
    const bool gamma_ok = gamma > 0 && std::isfinite(gamma);
    validity v2 = valid_if(gamma_ok);
    if (gamma_ok) {
      const auto ends = spinslide::detail::attracting_ends(p, gamma);
      const auto zeros = spinslide::ratio_flow_zeros(p, gamma);
      check_zeros(p, gamma, zeros);
      const auto attractors =
          std::count_if(zeros.begin(), zeros.end(), [](const auto& z) { return z.attracting; }) +
          int(ends.first) + int(ends.second);
      if (attractors > 1) v2 = validity::invalid;
    }
    expect(v2, "terminal_motion(profile, gamma)", [&] {
      check_state(p, gamma, spinslide::terminal_motion(p, gamma),
                  "terminal_motion(profile, gamma)");
    });
    expect(valid_if(gamma_ok && start >= 0), "terminal_motion(profile, gamma, initial_ratio)", [&] {
      check_state(p, gamma, spinslide::terminal_motion(p, gamma, start),
                  "terminal_motion(profile, gamma, initial_ratio)");
    });
    expect(valid_if(gamma_ok && eps >= 0 && std::isfinite(eps)), "ratio_flow", [&] {
      const double f = spinslide::ratio_flow(p, eps, gamma);
      // f = ε − γ𝓕/𝓣 overflows only where γ/𝓣 does.
      const auto ft = p.force_torque(eps);
      if (static_cast<long double>(gamma) * ft.force / ft.torque < 1e300L)
        check_finite(f, "ratio_flow", "f");
      check(!std::isnan(f), "ratio_flow", "f is NaN");
    });
  });
  return 0;
}
