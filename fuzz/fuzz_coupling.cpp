//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Fuzz harness: the coupling curve and its inverses, ratio_from_force,
// ratio_from_torque, torque_at_force and force_at_torque, on the profiles of
// zoo.hpp.  Valid: F ∈ [0, 1), T ∈ (0, ⟨r⟩].  Then ε is finite and ≥ 0 and,
// for the continuous profiles, the round trip holds: 𝓕(ε(F)) = F and
// 𝓣(ε(T)) = T to 1e-9 relative.  A target the type cannot reach at a finite
// ratio (T below 𝓣 at the largest ratios, a torque the uncoupled caps never
// take) is a domain error too, so there such a T may give either; a force in
// (0, 1), which the uncoupled caps jump over, must be one.

#include "zoo.hpp"

#include <spinslide/values/coupling.hpp>

namespace {

using namespace spinslide_fuzz;

bool near(double a, double b) { return std::fabs(a - b) <= 1e-9 * std::fabs(b) + 1e-300; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz_input in(data, size);
  context().clear();
  with_profile(in, [&](const auto& p, const char* name, bool physical) {
    const bool continuous = physical || std::string(name) != "uncoupled_caps";
    context() += std::string(" profile=") + name;
    const double top = p.mean_radius();
    const double F = in.unit<double>();
    const double T = in.byte() % 2 ? in.unit<double>() * top : in.real<double>();
    describe("F", F);
    describe("T", T);
    validity vF = valid_if(F >= 0 && F < 1);
    // (Below the smallest normal value, F is answered to 1e-6 of that value:
    // ε = 0 for the uncoupled caps then, or a domain error.)
    if (!continuous && F > 0) vF = F < 1e-300 ? validity::ambiguous : validity::invalid;
    // Beyond ~1e300 the ratio, and so a tiny T, leaves what double resolves;
    // and a T at or below 𝓣(DBL_MAX) is not reached at a finite ratio (for a
    // Padé form with <r²>/<r> = 2.7e19, 𝓣(DBL_MAX) = 7.5e-290 <r>: the
    // campaign of 2026-11-23 found that this harness called such a T valid).
    validity vT = valid_if(T > 0 && T <= top);
    const double lowest = p.torque(std::numeric_limits<double>::max());
    if (vT == validity::valid && (T < 1e-290 * top || T <= 2 * lowest || !continuous))
      vT = validity::ambiguous;
    expect(vF, "ratio_from_force", [&] {
      const double e = spinslide::ratio_from_force(p, F);
      check_finite(e, "ratio_from_force", "eps");
      check(e >= 0, "ratio_from_force", "eps < 0");
      if (continuous)
        check(near(p.force(e), F), "ratio_from_force", "force(ratio_from_force(F)) != F");
    });
    expect(vF, "torque_at_force", [&] {
      const double t = spinslide::torque_at_force(p, F);
      check_finite(t, "torque_at_force", "T");
      check(t >= 0 && t <= top * (1 + 1e-12), "torque_at_force", "T outside [0, <r>]");
    });
    expect(vT, "ratio_from_torque", [&] {
      const double e = spinslide::ratio_from_torque(p, T);
      check_finite(e, "ratio_from_torque", "eps");
      check(e >= 0, "ratio_from_torque", "eps < 0");
      if (continuous)
        check(near(p.torque(e), T), "ratio_from_torque", "torque(ratio_from_torque(T)) != T");
    });
    expect(vT, "force_at_torque", [&] {
      const double f = spinslide::force_at_torque(p, T);
      check_finite(f, "force_at_torque", "F");
      check(f >= 0 && f <= 1 + 1e-15, "force_at_torque", "F outside [0, 1]");
    });
  });
  return 0;
}
