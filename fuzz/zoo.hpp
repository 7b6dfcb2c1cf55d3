//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The profiles that the coupling, terminal, stop-time and contact harnesses
// run on: one of them, with fuzzed but valid parameters (fuzz_profiles
// fuzzes the constructors themselves).  Hertz comes tabulated (built once
// per process), as a simulator would use it; the quadrature profiles are
// represented by the Boussinesq profile and a weighted sum with a scaled part.

#ifndef SPINSLIDE_FUZZ_ZOO_HPP
#define SPINSLIDE_FUZZ_ZOO_HPP

#include "fuzz.hpp"

#include <spinslide/values/approximations.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include <array>
#include <string>
#include <type_traits>

namespace spinslide_fuzz {

inline const spinslide::tabulated_profile<double>& tabulated_hertz() {
  static const spinslide::tabulated_profile<double> table{spinslide::hertz<double>()};
  return table;
}

/// A positive number spread log-uniformly over 1e-k…1e+k.
inline double positive(fuzz_input& in, double k) {
  return std::pow(10.0, k * (2 * in.uniform01<double>() - 1));
}

/// Calls visit(profile, name, physical) with one profile chosen by the input;
/// physical is false for the engine models (uncoupled caps, elliptic cone,
/// Padé), which need not obey every property of a pressure distribution.
/// `models`: whether the engine models are among the choices.
template <class Visit>
void with_profile(fuzz_input& in, Visit visit, bool models = true) {
  using namespace spinslide;
  switch (in.choice(models ? 9 : 6)) {
    case 0:
      visit(uniform_disk<double>(), "uniform_disk", true);
      break;
    case 1: {
      const double b = in.uniform01<double>() * (1 - 1e-9);
      describe("annulus_b", b);
      visit(annulus<double>(b), "annulus", true);
      break;
    }
    case 2:
      visit(tabulated_hertz(), "tabulated_profile(hertz)", true);
      break;
    case 3:
      visit(boussinesq<double>(), "boussinesq", true);
      break;
    case 4:
      visit(ring<double>(), "ring", true);
      break;
    case 5: {
      // Load concentrated near the centre plus a ring: for some γ both ends
      // of the ratio flow attract.
      const double a = std::fmax(in.uniform01<double>(), 1e-6);
      const std::array<double, 2> w{positive(in, 6), positive(in, 6)};
      describe("scaled_a", a);
      describe("w0", w[0]);
      describe("w1", w[1]);
      visit(
          weighted_sum(w, scaled<uniform_disk<double>>(uniform_disk<double>(), a), ring<double>()),
          "weighted_sum(scaled disk, ring)", true);
      break;
    }
    case 6: {
      const double cap = positive(in, 10);
      describe("torque_cap", cap);
      visit(uncoupled_caps<double>(cap), "uncoupled_caps", false);
      break;
    }
    case 7: {
      const double tau = positive(in, 10);
      describe("torque_axis", tau);
      visit(elliptic_limit_surface<double>(tau), "elliptic_limit_surface", false);
      break;
    }
    default: {
      const double r = positive(in, 10), inv = positive(in, 10), sq = positive(in, 10);
      describe("pade_r", r);
      describe("pade_inv", inv);
      describe("pade_sq", sq);
      visit(pade_approximation<double>(r, inv, sq), "pade_approximation", false);
      break;
    }
  }
}

// The profiles the limit-set projections take: all but the Padé
// approximants, whose curve's normal is not (ε, 1) (they do not compile there).
template <class P>
struct projectable : std::true_type {};
template <class Policy>
struct projectable<spinslide::pade_approximation<double, Policy>> : std::false_type {};

/// with_profile over the projectable profiles only, the profile's name added
/// to the context; visit(p, name).
template <class Visit>
void with_projectable_profile(fuzz_input& in, Visit visit) {
  with_profile(in, [&](const auto& p, const char* name, bool) {
    if constexpr (projectable<std::decay_t<decltype(p)>>::value) {
      context() += std::string(" profile=") + name;
      visit(p, name);
    }
  });
}

}  // namespace spinslide_fuzz

#endif  // SPINSLIDE_FUZZ_ZOO_HPP
