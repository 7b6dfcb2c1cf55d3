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
// Distance and angle within their bounds (check_path), for any ratio v0/ω0.

#include "zoo.hpp"

#include <spinslide/motion/dynamics.hpp>
#include <spinslide/motion/tabulated_throw.hpp>

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

// Distance and angle: not NaN, and within the bounds that 0 ≤ 𝓕 ≤ 1 and
// 0 ≤ 𝓣 ≤ ⟨r⟩ give: v0²/2 ≤ s ≤ v0 t* and γω0²/(2⟨r⟩) ≤ θ ≤ ω0 t* (to 1e-9,
// in long double, where no bound overflows; ∞ where the true value overflows).
void check_path(double s, double theta, double t, double v0, double w0, double gamma, double top,
                const char* call) {
  check(!std::isnan(s) && s >= 0, call, "distance NaN or < 0");
  check(!std::isnan(theta) && theta >= 0, call, "angle NaN or < 0");
  const long double lo = 1 - 1e-9L, hi = 1 + 1e-9L, floor = 1e-300L;
  const long double v = v0, w = w0, tt = t;
  if (v0 == 0) check(s == 0, call, "distance != 0 without sliding");
  if (w0 == 0) check(theta == 0, call, "angle != 0 without spin");
  if (std::isfinite(s)) {
    check(s >= v * v / 2 * lo - floor, call, "distance < v0^2/2, but F <= 1");
    if (std::isfinite(t))
      check(s <= v * tt * hi + floor, call, "distance > v0 t*, but the speed is <= v0");
  }
  if (std::isfinite(theta)) {
    check(theta >= gamma * (w * w / (2 * static_cast<long double>(top))) * lo - floor, call,
          "angle < gamma omega0^2/(2<r>), but T <= <r>");
    if (std::isfinite(t))
      check(theta <= w * tt * hi + floor, call, "angle > omega0 t*, but the spin is <= omega0");
  }
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
        expect(v, "simulate_throw", [&] {
          const auto r = spinslide::simulate_throw(p, gamma, v0, w0);
          check_time(r.time, v0, w0, gamma, p.mean_radius(), "simulate_throw");
          check_path(r.distance, r.angle, r.time, v0, w0, gamma, p.mean_radius(), "simulate_throw");
          check(r.time == spinslide::stop_time(p, gamma, v0, w0), "stop_time(profile, ...)",
                "differs from simulate_throw(...).time");
        });
      });
      break;
  }
  return 0;
}
