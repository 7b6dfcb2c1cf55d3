//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Fuzz harness: stop_time(v0, ω0) of the paper's disk, stop_time(profile,
// γ, v0, ω0) and simulate_throw on the profiles of zoo.hpp (the engine models
// included), and a shared tabulated_throw (uniform disk, γ = 1/2).
// Valid: min ≤ γ ≤ max·epsilon, v0 and ω0 finite and ≥ 0.  Then the stop time is
// ≥ 0, not NaN, and at least each one-sided bound: t* ≥ v0 (𝓕 ≤ 1) and
// t* ≥ γω0/⟨r⟩ (𝓣 ≤ ⟨r⟩), to 1e-9; it is finite whenever those bounds and
// the inputs are moderate (|·| ≤ 1e100), where no result can overflow.

#include "zoo.hpp"

#include <spinslide/dynamics.hpp>

namespace {

using namespace spinslide_fuzz;

void check_time(double t, double v0, double w0, double gamma, double top, const char* call) {
  check(!std::isnan(t), call, "t* is NaN");
  check(t >= 0, call, "t* < 0");
  const bool moderate = v0 <= 1e100 && w0 <= 1e100 && gamma <= 1e100 && gamma >= 1e-100 &&
                        top >= 1e-100 && top <= 1e100;
  if (moderate) check_finite(t, call, "t*");
  // (1e-300: below it the subnormals round too coarsely for a relative bound.)
  check(t >= v0 * (1 - 1e-9) - 1e-300, call, "t* < v0, but F <= 1");
  const double spin_bound = gamma * w0 / top;
  if (std::isfinite(spin_bound))
    check(t >= spin_bound * (1 - 1e-9) - 1e-300, call, "t* < gamma omega0/<r>, but T <= <r>");
}

const spinslide::tabulated_throw<spinslide::uniform_disk<double>>& shared_throw() {
  static const spinslide::tabulated_throw<spinslide::uniform_disk<double>> table(
      spinslide::uniform_disk<double>(), 0.5);
  return table;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz_input in(data, size);
  context().clear();
  const double v0 = in.real<double>(), w0 = in.real<double>();
  describe("v0", v0);
  describe("omega0", w0);
  const bool speeds_ok = v0 >= 0 && std::isfinite(v0) && w0 >= 0 && std::isfinite(w0);
  switch (in.choice(3)) {
    case 0:
      expect(valid_if(speeds_ok), "stop_time(v0, omega0)", [&] {
        check_time(spinslide::stop_time(v0, w0), v0, w0, 0.5, 2.0 / 3, "stop_time(v0, omega0)");
      });
      break;
    case 1:
      expect(valid_if(speeds_ok), "tabulated_throw", [&] {
        const auto& t = shared_throw();
        check_time(t.stop_time(v0, w0), v0, w0, 0.5, 2.0 / 3, "tabulated_throw::stop_time");
        const double s = t.distance(v0, w0);
        check(!std::isnan(s) && s >= 0, "tabulated_throw::distance", "distance NaN or < 0");
      });
      break;
    default:
      with_profile(in, [&](const auto& p, const char* name, bool) {
        context() += std::string(" profile=") + name;
        const double gamma = in.real<double>();
        describe("gamma", gamma);
        const double gamma_max = std::numeric_limits<double>::max() * 0x1p-52;  // max·epsilon
        const validity v = valid_if(speeds_ok && gamma >= std::numeric_limits<double>::min() &&
                                    gamma <= gamma_max);
        const double ratio = v0 / w0;
        const bool extreme = !(v0 == 0 || w0 == 0 || (ratio < 1e100 && ratio > 1e-100));
        // Known limit (docs/reliability.md, open): the state is scaled by
        // ω0 (or v0), so for ε0 = v0/ω0 beyond ~1e100 or below 1e-100 the
        // scaled state over- or underflows.  There the fuzzer found a wrong
        // stop time (t* = v0 where it is γω0/<r>), NaN distances and
        // angles, "no stop found" (evaluation_error) and a quadrature
        // profile taking 67 s; so the harness only checks the domain errors.
        if (extreme && v == validity::valid) return;
        expect(v, "simulate_throw", [&] {
          const auto r = spinslide::simulate_throw(p, gamma, v0, w0);
          check_time(r.time, v0, w0, gamma, p.mean_radius(), "simulate_throw");
          // Distances and angles grow like v0², γω0²: checked where they cannot
          // overflow (docs/reliability.md, known and open).
          if (v0 <= 1e100 && w0 <= 1e100 && gamma <= 1e100) {
            check(!std::isnan(r.distance) && r.distance >= 0, "simulate_throw",
                  "distance NaN or < 0");
            check(!std::isnan(r.angle) && r.angle >= 0, "simulate_throw", "angle NaN or < 0");
          }
          check(r.time == spinslide::stop_time(p, gamma, v0, w0), "stop_time(profile, ...)",
                "differs from simulate_throw(...).time");
        });
      });
      break;
  }
  return 0;
}
