//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Fuzz harness: every pressure profile, built from fuzzed parameters, and its
// force_torque, force, torque and moments at fuzzed ratios.  The profiles:
// uniform_disk, annulus(b), hertz, boussinesq, ring, scaled(p, a),
// weighted_sum, radial_profile with a fuzzed custom pressure (a polynomial
// plus a rim singularity, on [inner, 1]), a shared tabulated_profile, and
// the engine models uncoupled_caps, elliptic_limit_surface and
// pade_approximation; in double, and the annulus in float and long double.
//
// Valid parameters are the documented ones; then every moment is finite
// (uncoupled_caps: ⟨1/r⟩ = ⟨r²⟩ = ∞ by definition), 0 < ⟨r⟩ ≤ 1,
// ⟨r⟩² ≤ ⟨r²⟩ and ⟨r⟩⟨1/r⟩ ≥ 1 (Jensen) for the physical profiles, and at
// every ε ≥ 0: 0 ≤ 𝓕 ≤ 1 and 0 ≤ 𝓣 ≤ ⟨r⟩, finite.

#include "zoo.hpp"

#include <spinslide/values/approximations.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include <array>

namespace {

using namespace spinslide_fuzz;

template <class Real>
bool in_range(Real x, Real lo, Real hi) {
  const Real slack = 64 * std::numeric_limits<Real>::epsilon();
  return x >= lo - slack * std::fabs(lo) && x <= hi + slack * std::fabs(hi);
}

// `physical`: a real pressure distribution on the unit disk (not an engine model).
// `uncertain`: the profile may be invalid where the constructor did not look
// (a custom pressure negative between its quadrature nodes).
template <class Profile>
void exercise(const Profile& p, fuzz_input& in, const char* name, bool physical, bool uncertain) {
  using Real = typename Profile::value_type;
  const Real r = p.mean_radius(), inv = p.mean_inverse_radius(), sq = p.mean_square_radius();
  check_finite(r, name, "mean_radius");
  check(r > 0, name, "mean_radius <= 0");
  if (physical) {
    check_finite(inv, name, "mean_inverse_radius");
    check_finite(sq, name, "mean_square_radius");
    check(in_range(r, Real(0), Real(1)), name, "mean_radius outside (0, 1]");
    check(in_range(r * r, Real(0), sq), name, "<r>^2 > <r^2>");
    check(in_range(Real(1), Real(0), r * inv), name, "<r><1/r> < 1");
  }
  const std::size_t n = 1 + in.choice(3);
  for (std::size_t i = 0; i < n; ++i) {
    const Real eps = in.real<Real>();
    const std::size_t mark = context().size();
    describe("eps", eps);
    const validity v = !(eps >= 0) ? validity::invalid
                       : uncertain ? validity::ambiguous
                                   : validity::valid;
    expect(v, name, [&] {
      const auto ft = p.force_torque(eps);
      check_finite(ft.force, name, "F");
      check_finite(ft.torque, name, "T");
      if (uncertain) return;  // a pressure quadrature may not resolve: finite is all
      check(in_range(ft.force, Real(0), Real(1)), name, "F outside [0, 1]");
      check(in_range(ft.torque, Real(0), r), name, "T outside [0, <r>]");
      check(p.force(eps) == ft.force && p.torque(eps) == ft.torque, name,
            "force()/torque() differ from force_torque()");
    });
    context().resize(mark);
  }
}

// Builds a profile inside expect(): a constructor may throw std::domain_error.
template <class Make>
void build(validity v, const char* name, fuzz_input& in, Make make, bool physical = true) {
  expect(v, name, [&] { exercise(make(), in, name, physical, v == validity::ambiguous); });
}

template <class Real>
bool in_unit(Real b) {
  return b >= 0 && b < 1;
}

// The custom pressure: c0 + c1 r + c2 r² + c3/√(1 − r), given as p(r, 1 − r).
struct custom_pressure {
  std::array<double, 4> c;
  double operator()(double r, double one_minus_r) const {
    const double rim = c[3] == 0 ? 0.0 : c[3] / std::sqrt(one_minus_r);
    return c[0] + c[1] * r + c[2] * r * r + rim;
  }
};

void custom(fuzz_input& in) {
  custom_pressure p{};
  bool finite = true, nonnegative = true, moderate = true, positive = false;
  for (std::size_t i = 0; i < p.c.size(); ++i) {
    const double c = p.c[i] = in.real<double>();
    describe("c", c);
    finite = finite && std::isfinite(c);
    nonnegative = nonnegative && c >= 0;
    // 1/√(1 − r) reaches ~1e162 at the quadrature nodes nearest the rim.
    moderate = moderate && c <= (i == 3 ? 1e140 : 1e290);
    positive = positive || c >= 1e-290;
  }
  const double inner = in.byte() % 2 ? 0.0 : in.unit<double>();
  describe("inner", inner);
  // Negative coefficients may still give p >= 0 at every quadrature node, and
  // extreme ones may overflow or underflow the load: either outcome is allowed.
  validity v = validity::ambiguous;
  // Subnormal coefficients make p a staircase (its arithmetic rounds to
  // multiples of 5e-324), which quadrature does not resolve: ambiguous too.
  bool subnormal = false;
  for (const double c : p.c) subnormal = subnormal || (c != 0 && std::fabs(c) < 1e-290);
  if (!finite || !in_unit(inner) || (nonnegative && !positive && p.c == std::array<double, 4>{}))
    v = validity::invalid;
  else if (nonnegative && moderate && positive && !subnormal)
    v = validity::valid;
  build(v, "radial_profile", in,
        [&] { return spinslide::radial_profile<double, custom_pressure>(p, inner); });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spinslide;
  fuzz_input in(data, size);
  context().clear();
  switch (in.choice(14)) {
    case 0:
      build(validity::valid, "uniform_disk", in, [] { return uniform_disk<double>(); });
      break;
    case 1: {
      const double b = in.unit<double>();
      describe("b", b);
      build(valid_if(in_unit(b)), "annulus", in, [b] { return annulus<double>(b); });
      break;
    }
    case 2:
      build(validity::valid, "hertz", in, [] { return hertz<double>(); });
      break;
    case 3:
      build(validity::valid, "boussinesq", in, [] { return boussinesq<double>(); });
      break;
    case 4:
      build(validity::valid, "ring", in, [] { return ring<double>(); });
      break;
    case 5: {
      const double a = in.unit<double>();
      describe("a", a);
      const validity v = valid_if(a > 0 && a <= 1 && a * a >= std::numeric_limits<double>::min());
      if (in.byte() % 2)
        build(v, "scaled(hertz)", in, [a] { return scaled<hertz<double>>(hertz<double>(), a); });
      else
        build(v, "scaled(uniform_disk)", in,
              [a] { return scaled<uniform_disk<double>>(uniform_disk<double>(), a); });
      break;
    }
    case 6: {
      std::array<double, 3> w{};
      bool ok = true;
      for (double& x : w) {
        x = in.real<double>();
        describe("w", x);
        ok = ok && x >= 0 && std::isfinite(x);
      }
      ok = ok && (w[0] > 0 || w[1] > 0 || w[2] > 0);
      const double b = in.unit<double>();
      describe("b", b);
      build(valid_if(ok && in_unit(b)), "weighted_sum", in, [&] {
        return weighted_sum(w, uniform_disk<double>(), annulus<double>(b), ring<double>());
      });
      break;
    }
    case 7:
      custom(in);
      break;
    case 8:
      build(validity::valid, "tabulated_profile(hertz)", in,
            []() -> const tabulated_profile<double>& { return tabulated_hertz(); });
      break;
    case 9: {
      const double cap = in.real<double>();
      describe("torque_cap", cap);
      // Documented: finite and > 0; the code takes the smallest normal as the least.
      build(
          valid_if(cap >= std::numeric_limits<double>::min() && std::isfinite(cap)),
          "uncoupled_caps", in, [cap] { return uncoupled_caps<double>(cap); }, false);
      break;
    }
    case 10: {
      const double tau = in.real<double>();
      describe("torque_axis", tau);
      build(
          valid_if(tau >= std::numeric_limits<double>::min() && std::isfinite(tau)),
          "elliptic_limit_surface", in, [tau] { return elliptic_limit_surface<double>(tau); },
          false);
      break;
    }
    case 11: {
      std::array<double, 3> m{};
      bool ok = true;
      for (double& x : m) {
        x = in.real<double>();
        describe("moment", x);
        ok = ok && x >= std::numeric_limits<double>::min() && std::isfinite(x);
      }
      build(
          valid_if(ok), "pade_approximation", in,
          [&] { return pade_approximation<double>(m[0], m[1], m[2]); }, false);
      break;
    }
    case 12: {
      const float b = in.unit<float>();
      describe("b", b);
      build(valid_if(in_unit(b)), "annulus<float>", in, [b] { return annulus<float>(b); });
      break;
    }
    default: {
      const long double b = in.unit<long double>();
      describe("b", b);
      build(valid_if(in_unit(b)), "annulus<long double>", in,
            [b] { return annulus<long double>(b); });
      break;
    }
  }
  return 0;
}
