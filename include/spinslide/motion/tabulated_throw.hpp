//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file tabulated_throw.hpp
/// Every throw of one (profile, γ), precomputed: stop time and distance in
/// one table lookup, built from simulate_throw (dynamics.hpp) with the
/// machinery of tabulated_profile; and the paper's stop_time(v0, ω0).

#ifndef SPINSLIDE_MOTION_TABULATED_THROW_HPP
#define SPINSLIDE_MOTION_TABULATED_THROW_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/motion/dynamics.hpp>
#include <spinslide/values/detail/piecewise_chebyshev.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/profile_concept.hpp>

#include <algorithm>
#include <type_traits>
#include <utility>

namespace spinslide {

/// Stop times and distances of every throw of one (profile, γ), precomputed.
/// The flow depends on ε only, so t*(v0, ω0) = ω0 P(ε) and s*(v0, ω0) = ω0² S(ε)
/// with ε = v0/ω0 (docs/theory.md §9).  With t = ε/(1+ε) the bounded functions
///   P(ε)/(1+ε)   (→ γ/⟨r⟩ at ε = 0, → 1 at ε = ∞) and
///   S(ε)/(1+ε)²  (→ 0 at ε = 0,     → 1/2 at ε = ∞)
/// are tabulated with the machinery of tabulated_profile (sampled by
/// simulate_throw, ~1e-14), so a throw then costs one table lookup.  Measured:
/// stop times within 4e-14 of the integration; distances within ~1e-9 (their
/// table resolves the ε = 1 kink of ring-like profiles less well).
/// Construction takes a few thousand throws (about a second); calls are
/// allocation-free and thread-safe.
template <class Profile>
class tabulated_throw {
  static_assert(detail::requires_profile<Profile>());
  using Real = typename Profile::value_type;
  using Policy = typename Profile::policy_type;

 public:
  /// The profile's floating-point type.
  using value_type = Real;

  /// Tabulates the throws of `profile` with γ = `inertia_ratio` (in
  /// [min_value, max_value·epsilon], as for simulate_throw; otherwise
  /// std::domain_error); about a second, allocates.
  tabulated_throw(const Profile& profile, Real inertia_ratio)
      : gamma_(detail::checked_constructor_argument<Policy>(
            "spinslide::tabulated_throw<%1%>::tabulated_throw(profile, %1%)", "inertia_ratio",
            inertia_ratio, detail::argument_rule::throw_inertia_ratio)),
        spin_rate_(profile.mean_radius() / gamma_) {
    auto g = [&](double t) {
      const double eps = t / (1 - t);
      const auto r = simulate_throw(profile, gamma_, Real(eps), Real(1));
      const double s = 1 + eps;
      return std::make_pair(static_cast<double>(r.time) / s,
                            static_cast<double>(r.distance) / (s * s));
    };
    table_ = detail::piecewise_chebyshev_pair<double, 8>(g, 1e-13, 16);
  }

  /// t*(v0, ω0); bad input is a domain error, ω0 = 0 is exact (t* = v0).
  Real stop_time(Real v0, Real omega0) const {
    return evaluate(v0, omega0, "spinslide::tabulated_throw<%1%>::stop_time(%1%, %1%)").first;
  }
  /// s*(v0, ω0): the distance slid.
  Real distance(Real v0, Real omega0) const {
    return evaluate(v0, omega0, "spinslide::tabulated_throw<%1%>::distance(%1%, %1%)").second;
  }
  /// The number of Chebyshev pieces of the table.
  std::size_t pieces() const { return table_.size(); }

 private:
  std::pair<Real, Real> evaluate(Real v0, Real w0, const char* function) const {
    // γ was checked once, by the constructor: only the speeds here.
    using detail::argument_rule;
    Real invalid = 0;
    if (!detail::check(function, "v0", v0, argument_rule::finite_non_negative, &invalid,
                       Policy()) ||
        !detail::check(function, "omega0", w0, argument_rule::finite_non_negative, &invalid,
                       Policy()))
      return {invalid, invalid};
    if (w0 == 0) return {v0, v0 * v0 / 2};           // pure sliding, exact
    if (v0 == 0) return {w0 / spin_rate_, Real(0)};  // pure spinning, exact
    const Real s = v0 + w0;                          // ω0 (1 + ε)
    const auto g = table_(static_cast<double>(v0 / s));
    // The table's error near ε = 0 is ~1e-18 absolute, so g can come out just
    // below 0 where the distance is tiny: clamp it (the exact g is > 0).  And
    // s (s g) rather than s² g, with g = 0 giving 0: s² overflows first, and
    // ∞ · 0 would be NaN (both found by fuzz_stop_time).
    const Real gd = (std::max)(Real(g.second), Real(0));
    const Real d = gd == 0 ? Real(0) : Real(s * (s * gd));
    return {s * Real(g.first), d};
  }
  Real gamma_, spin_rate_;
  detail::piecewise_chebyshev_pair<double, 8> table_;
};

/// Dimensionless stop time t* of the paper's disk (uniform, γ = 1/2).  In
/// double it uses a tabulated_throw built on first use (thread-safe static);
/// other types integrate.
template <class Real>
Real stop_time(Real v0, Real omega0) {
  if constexpr (std::is_same<Real, double>::value) {
    // Check before the one-time build, so that bad input fails fast.
    detail::check_throw("spinslide::stop_time<%1%>(%1%, %1%)", 0.5, v0, omega0,
                        boost::math::policies::policy<>());
    static const tabulated_throw<uniform_disk<double>> table(uniform_disk<double>(), 0.5);
    return table.stop_time(v0, omega0);
  } else {
    return stop_time(uniform_disk<Real>(), Real(0.5), v0, omega0);
  }
}

}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_TABULATED_THROW_HPP
