//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Fuzz harness: the contact law, planar and 3-D, and contact_friction, on the
// profiles of zoo.hpp, with a fuzzed regularization v_s.
// Valid: v_s finite and ≥ 0; radius a finite and > 0; N, μ ≥ 0 with μN
// finite; velocities and spin finite, and |v| too (a speed that overflows is
// a domain error); a unit normal (from two fuzzed angles).
// Then no output is NaN; every output is finite when every input is at most
// 1e100 in size (no true result can overflow there); |F| ≤ μN and
// |T| ≤ μNa⟨r⟩ (to 1e-12); and the law dissipates: F·v + T·ω ≤ 0.

#include "zoo.hpp"

#include <spinslide/contact/contact_law.hpp>

namespace {

using namespace spinslide_fuzz;

bool moderate(std::initializer_list<double> xs) {
  for (const double x : xs)
    if (!(std::fabs(x) <= 1e100)) return false;
  return true;
}

void check_outputs(const double* force, std::size_t n, double torque, double muN, double a,
                   double top, double power, bool expect_finite, const char* call) {
  // |F|² in long double: a component above ~1e154 squares beyond double's range
  // (the 1e7-input campaign found a false report there, |F| = 5.7e157).
  long double f2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    check(!std::isnan(force[i]), call, "a force component is NaN");
    if (expect_finite) check_finite(force[i], call, "a force component");
    f2 += static_cast<long double>(force[i]) * force[i];
  }
  check(!std::isnan(torque), call, "the torque is NaN");
  if (!expect_finite) return;
  check_finite(torque, call, "the torque");
  const double tol = 1 + 1e-12;
  // (1e-300: the rounding of subnormal results.)
  check(std::sqrt(f2) <= static_cast<long double>(muN) * tol + 1e-300L, call, "|F| > mu N");
  check(std::fabs(torque) <= muN * a * top * tol + 1e-300, call, "|T| > mu N a <r>");
  check(!(power > 0), call, "F.v + T.omega > 0: the law does work");
}

// The named inputs (a, N, μ) of a contact, from plain numbers in this order.
spinslide::force_contact<double> contact_of(double radius, double normal, double mu) {
  return {spinslide::patch_radius<double>{radius}, spinslide::normal_force<double>{normal},
          spinslide::friction_coefficient<double>{mu}};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz_input in(data, size);
  context().clear();
  with_profile(in, [&](const auto& p, const char* name, bool) {
    using law_type = spinslide::contact_law<std::decay_t<decltype(p)>>;
    context() += std::string(" profile=") + name;
    const double vs = in.byte() % 2 ? 1e-6 : in.real<double>();
    const double a = in.real<double>(), N = in.real<double>(), mu = in.unit<double>();
    const double vx = in.real<double>(), vy = in.real<double>(), vz = in.real<double>();
    const double spin = in.real<double>(), wx = in.real<double>(), wy = in.real<double>();
    const double theta = 3.14159 * in.uniform01<double>(), phi = 6.28318 * in.uniform01<double>();
    for (const auto& [k, x] : {std::pair<const char*, double>{"v_s", vs},
                               {"a", a},
                               {"N", N},
                               {"mu", mu},
                               {"vx", vx},
                               {"vy", vy},
                               {"vz", vz},
                               {"spin", spin},
                               {"wx", wx},
                               {"wy", wy},
                               {"theta", theta},
                               {"phi", phi}})
      describe(k, x);
    const bool law_ok = vs >= 0 && std::isfinite(vs);
    const bool planar_ok = a > 0 && std::isfinite(a) && N >= 0 && mu >= 0 &&
                           std::isfinite(mu * N) && std::isfinite(vx) && std::isfinite(vy) &&
                           std::isfinite(spin);
    const bool args_ok = planar_ok && std::isfinite(vz) && std::isfinite(wx) && std::isfinite(wy);
    // A velocity whose magnitude overflows is outside the domain as well.
    const long double planar_speed = std::hypot(static_cast<long double>(vx), vy);
    const double top = p.mean_radius();
    const double muN = mu * N;
    const bool finite_expected =
        moderate({a, N, mu, vx, vy, vz, spin, wx, wy}) && top <= 1e100 && muN * a <= 1e100;
    expect(valid_if(law_ok), "contact_law", [&] {
      const law_type law(p, spinslide::velocity_scale<double>{vs});
      const auto c = contact_of(a, N, mu);
      const validity vp = !planar_ok                                          ? validity::invalid
                          : planar_speed > std::numeric_limits<double>::max() ? validity::ambiguous
                                                                              : validity::valid;
      expect(vp, "contact_law(planar)", [&] {
        const auto r = law(std::array<double, 2>{vx, vy}, spin, c);
        const double power = r.force[0] * vx + r.force[1] * vy + r.torque * spin;
        check_outputs(r.force.data(), 2, r.torque, muN, a, top, power, finite_expected,
                      "contact_law(planar)");
      });
      // A unit normal n; ω = (wx, wy, spin) in the frame where only spin is along n.
      const std::array<double, 3> n{std::sin(theta) * std::cos(phi),
                                    std::sin(theta) * std::sin(phi), std::cos(theta)};
      const std::array<double, 3> v{vx, vy, vz}, w{wx, wy, spin};
      const long double vn_l = static_cast<long double>(vx) * n[0] +
                               static_cast<long double>(vy) * n[1] +
                               static_cast<long double>(vz) * n[2];
      const long double tx = vx - vn_l * n[0], ty = vy - vn_l * n[1], tz = vz - vn_l * n[2];
      const long double wn_l = static_cast<long double>(wx) * n[0] +
                               static_cast<long double>(wy) * n[1] +
                               static_cast<long double>(spin) * n[2];
      // Near the largest doubles the projection itself may overflow: either outcome.
      const bool big =
          std::sqrt(tx * tx + ty * ty + tz * tz) > std::numeric_limits<double>::max() / 4 ||
          std::fabs(wn_l) > std::numeric_limits<double>::max() / 4;
      const validity v3 = !args_ok ? validity::invalid
                          : big    ? validity::ambiguous
                                   : validity::valid;
      expect(v3, "contact_law(3-D)", [&] {
        const auto r = law(v, w, spinslide::contact_normal{n}, c);
        const double vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
        const double wn = w[0] * n[0] + w[1] * n[1] + w[2] * n[2];
        double power = 0;
        for (std::size_t i = 0; i < 3; ++i) power += r.force[i] * (v[i] - vn * n[i]);
        const double tn = r.torque[0] * n[0] + r.torque[1] * n[1] + r.torque[2] * n[2];
        check_outputs(r.force.data(), 3, tn, muN, a, top, power + tn * wn, finite_expected,
                      "contact_law(3-D)");
      });
    });
  });
  // The free function: the uniform disk, regularized below 1e-6.
  const double vx = in.real<double>(), vy = in.real<double>(), spin = in.real<double>();
  const double a = in.real<double>(), N = in.real<double>(), mu = in.unit<double>();
  const bool ok = a > 0 && std::isfinite(a) && N >= 0 && mu >= 0 && std::isfinite(mu * N) &&
                  std::isfinite(vx) && std::isfinite(vy) && std::isfinite(spin);
  const validity vf =
      !ok ? validity::invalid
      : std::hypot(static_cast<long double>(vx), vy) > std::numeric_limits<double>::max()
          ? validity::ambiguous
          : validity::valid;
  expect(vf, "contact_friction", [&] {
    const auto r =
        spinslide::contact_friction(std::array<double, 2>{vx, vy}, spin, contact_of(a, N, mu),
                                    spinslide::velocity_scale<double>{1e-6});
    const double power = r.force[0] * vx + r.force[1] * vy + r.torque * spin;
    check_outputs(r.force.data(), 2, r.torque, mu * N, a, 2.0 / 3, power,
                  moderate({vx, vy, spin, a, N, mu}), "contact_friction");
  });
  return 0;
}
