//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file terminal.hpp
/// How a sliding, spinning body stops: the flow of the ratio ε = v/(Rω)
/// towards the end of the motion, for any profile and inertia ratio
/// γ = I/(mR²) (docs/theory.md §8).
///
/// With x = −ln ω* the equations of motion dv*/dt* = −𝓕, dω*/dt* = −𝓣/γ give
/// the autonomous flow dε/dx = f(ε) = ε − γ𝓕(ε)/𝓣(ε) (the paper's Eq. (5) for
/// γ = 1/2).  As the motion stops, x → ∞ and ε tends to an attractor of f:
/// ∞ (pure sliding), a zero ε₀ (sliding and spinning) or 0 (pure spinning).

#ifndef SPINSLIDE_TERMINAL_HPP
#define SPINSLIDE_TERMINAL_HPP

#include <spinslide/detail/checks.hpp>
#include <spinslide/profile.hpp>
#include <spinslide/profile_concept.hpp>

#include <boost/math/tools/toms748_solve.hpp>

#include <limits>
#include <utility>

namespace spinslide {

/// How the ratio ε behaves as the motion stops.  Sliding and spinning always
/// end at the same instant; the regime says which of them dominates on the way.
enum class terminal_regime {
  pure_sliding,          ///< ε → ∞: the spin dies relatively faster
  sliding_and_spinning,  ///< ε → ε₀, a finite attracting zero of f
  pure_spinning          ///< ε → 0: the sliding dies relatively faster
};

/// The terminal regime and the limit of ε: ε₀, +∞ or 0.
template <class Real>
struct terminal_state {
  terminal_regime regime;  ///< how ε behaves as the motion stops
  Real ratio;              ///< the limit of ε: ε₀, +∞ (pure sliding) or 0 (pure spinning)
};

/// The inertia ratios γ for which both ends of the flow repel, so that every
/// motion that starts sliding and spinning ends with a finite ratio ε₀:
/// lower = ⟨r²⟩/2 < γ < upper = 2⟨r⟩/⟨1/r⟩ (docs/theory.md §8).  For the
/// uniform disk: 1/4 < γ < 2/3.  The window is empty if lower ≥ upper.
template <class Real>
struct inertia_window {
  Real lower;  ///< ⟨r²⟩/2: below it, ε → ∞
  Real upper;  ///< 2⟨r⟩/⟨1/r⟩: above it, ε → 0
};

/// The window (W) of `p` from its moments: ⟨r²⟩/2 < γ < 2⟨r⟩/⟨1/r⟩.  No
/// errors of its own (a profile's moments are finite and > 0).
template <class Profile>
inertia_window<typename Profile::value_type> terminal_window(const Profile& p) {
  static_assert(detail::requires_profile<Profile>());
  return {p.mean_square_radius() / 2, 2 * p.mean_radius() / p.mean_inverse_radius()};
}

namespace detail {

// The terms of the flow at ε ∈ [0, ∞]: 𝓕/ε, 𝓣, 𝓕 and ε𝓣, with the limits
// 𝓕/ε → ⟨1/r⟩/2 (ε → 0) and ε𝓣 → ⟨r²⟩/2 (ε → ∞) wherever 𝓕 or 𝓣 is not a
// normal number: they under- or overflow only there, and the limits are
// then exact to the type's precision (found by fuzz_terminal: a Padé form's
// 𝓣 underflowed to 0 at ε = 1e300, giving g = −∞).
template <class Real>
struct flow_terms {
  Real force_over_ratio;  ///< 𝓕/ε
  Real torque;            ///< 𝓣
  Real force;             ///< 𝓕
  Real ratio_torque;      ///< ε𝓣
};

template <class Profile, class Real>
flow_terms<Real> flow_terms_at(const Profile& p, Real eps) {
  const Real small = boost::math::tools::min_value<Real>();
  const Real inv_half = p.mean_inverse_radius() / 2, sq_half = p.mean_square_radius() / 2;
  if (eps == 0) return {inv_half, p.mean_radius(), Real(0), Real(0)};
  if ((boost::math::isinf)(eps)) return {Real(0), Real(0), Real(1), sq_half};
  const auto ft = p.force_torque(eps);
  return {ft.force >= small ? Real(ft.force / eps) : inv_half, ft.torque, ft.force,
          ft.torque >= small ? Real(eps * ft.torque) : sq_half};
}

// g(ε) = f(ε)/ε = 1 − γ𝓕/(ε𝓣): f's sign without f's factor ε, and finite
// at both ends: g(0) = 1 − γ⟨1/r⟩/(2⟨r⟩), g(∞) = 1 − 2γ/⟨r²⟩.  A pull
// γ𝓕/(ε𝓣) beyond the type's range gives −max_value, not −∞.
template <class Profile, class Real>
Real flow_over_ratio(const Profile& p, Real eps, Real gamma) {
  const auto t = flow_terms_at(p, eps);
  const Real pull = t.torque >= boost::math::tools::min_value<Real>()
                        ? Real(gamma * t.force_over_ratio / t.torque)
                        : Real(gamma * t.force / t.ratio_torque);
  const Real g = 1 - pull;
  return g >= -boost::math::tools::max_value<Real>() ? g : -boost::math::tools::max_value<Real>();
}

// Which ends of (0, ∞) attract the flow.  At an exact edge of the window
// (g(0) = 0 or g(∞) = 0) the next-order term decides: the sign of g at a
// ratio where its O(ε²) (resp. O(1/ε²)) departure from the limit is resolved.
template <class Profile, class Real>
std::pair<bool, bool> attracting_ends(const Profile& p, Real gamma) {
  const Real g0 = 1 - gamma * p.mean_inverse_radius() / (2 * p.mean_radius());
  const Real ginf = 1 - 2 * gamma / p.mean_square_radius();
  const Real probe = Real(1e-4);
  const bool zero_attracts = g0 < 0 || (g0 == 0 && flow_over_ratio(p, probe, gamma) < 0);
  const bool infinity_attracts =
      ginf > 0 || (ginf == 0 && flow_over_ratio(p, 1 / probe, gamma) > 0);
  return {zero_attracts, infinity_attracts};
}

// The zero of g between lo (g > 0) and hi (g < 0), to full precision.
template <class Profile, class Real, class Policy>
Real flow_zero(const Profile& p, Real gamma, Real lo, Real hi, const Policy& pol) {
  auto g = [&](Real e) { return flow_over_ratio(p, e, gamma); };
  boost::uintmax_t max_iter = boost::math::policies::get_max_root_iterations<Policy>();
  const auto r = boost::math::tools::toms748_solve(
      g, lo, hi, g(lo), g(hi), boost::math::tools::eps_tolerance<Real>(), max_iter, pol);
  return (r.first + r.second) / 2;
}

// Follows the flow from ε (g(ε) ≠ 0) to the next sign change of g in the
// direction of motion, by steps of a factor 4 (bounded by the exponent range).
// Returns false if the flow runs to 0 or ∞ instead.
template <class Profile, class Real>
bool bracket_next_zero(const Profile& p, Real gamma, Real eps, Real& lo, Real& hi) {
  const Real big = boost::math::tools::max_value<Real>() / 8;
  const Real tiny = boost::math::tools::min_value<Real>() * 8;
  if (flow_over_ratio(p, eps, gamma) > 0) {  // ε grows
    lo = eps;
    for (hi = 4 * eps; hi < big; lo = hi, hi *= 4)
      if (flow_over_ratio(p, hi, gamma) < 0) return true;
  } else {  // ε shrinks
    hi = eps;
    for (lo = eps / 4; lo > tiny; hi = lo, lo /= 4)
      if (flow_over_ratio(p, lo, gamma) > 0) return true;
  }
  return false;
}

}  // namespace detail

/// f(ε) = ε − γ𝓕(ε)/𝓣(ε) = dε/dx with x = −ln ω*: the flow of the ratio.
/// f(0) = 0; f(ε) ≈ ε(1 − γ⟨1/r⟩/(2⟨r⟩)) as ε → 0 and ≈ ε(1 − 2γ/⟨r²⟩) as
/// ε → ∞ (for the paper's disk, γ = 1/2: ε/4 and −ε).  ε must be finite and
/// ≥ 0, γ finite and > 0; otherwise a domain error.
template <class Profile, class Real>
Real ratio_flow(const Profile& profile, Real eps, Real inertia_ratio) {
  static_assert(detail::requires_profile<Profile>());
  using Policy = typename Profile::policy_type;
  using detail::argument_rule;
  static const char* function = "spinslide::ratio_flow<%1%>(profile, %1%, %1%)";
  Real invalid = 0;
  if (!detail::check(function, "inertia_ratio", inertia_ratio, argument_rule::finite_positive,
                     &invalid, Policy()) ||
      !detail::check(function, "eps", eps, argument_rule::finite_non_negative, &invalid, Policy()))
    return invalid;
  const Real& gamma = inertia_ratio;  // checked above
  if (eps == 0) return 0;
  const auto ft = profile.force_torque(eps);
  return eps - gamma * ft.force / ft.torque;
}

/// The terminal regime for a motion that starts sliding and spinning
/// (0 < ε < ∞), and the limit of ε.  If both ends of the flow attract (possible
/// only when the load is concentrated near the centre), the outcome depends
/// on the initial ratio: that is a domain error here; use the overload below.
/// γ not finite and > 0 is a domain error.
template <class Profile, class Real>
terminal_state<Real> terminal_motion(const Profile& profile, Real inertia_ratio) {
  static_assert(detail::requires_profile<Profile>());
  using Policy = typename Profile::policy_type;
  static const char* function = "spinslide::terminal_motion<%1%>(profile, %1%)";
  Real invalid = 0;
  if (!detail::check(function, "inertia_ratio", inertia_ratio,
                     detail::argument_rule::finite_positive, &invalid, Policy()))
    return {terminal_regime::sliding_and_spinning, invalid};
  const Real& gamma = inertia_ratio;  // checked above
  const auto ends = detail::attracting_ends(profile, gamma);
  const Real inf = std::numeric_limits<Real>::infinity();
  if (ends.first && ends.second) {
    const Real bad = detail::raise_argument_error(
        function, "inertia_ratio",
        "one for which not both eps -> 0 and eps -> infinity attract (for this one the outcome "
        "depends on the initial ratio: use the overload that takes it)",
        gamma, Policy());
    return {terminal_regime::sliding_and_spinning, bad};
  }
  if (ends.first) return {terminal_regime::pure_spinning, Real(0)};
  if (ends.second) return {terminal_regime::pure_sliding, inf};
  if (detail::flow_over_ratio(profile, Real(1), gamma) == 0)
    return {terminal_regime::sliding_and_spinning, Real(1)};
  Real lo, hi;
  if (!detail::bracket_next_zero(profile, gamma, Real(1), lo, hi)) {
    const Real bad = boost::math::policies::raise_evaluation_error<Real>(
        function, "No zero of the ratio flow found for inertia_ratio = %1%.", gamma, Policy());
    return {terminal_regime::sliding_and_spinning, bad};
  }
  if (!(lo < hi)) std::swap(lo, hi);
  return {terminal_regime::sliding_and_spinning,
          detail::flow_zero(profile, gamma, lo, hi, Policy())};
}

/// The terminal regime reached from a given initial ratio ε_i = v0/(Rω0) ∈ [0, ∞]:
/// 0 and ∞ stay where they are (pure spinning and pure sliding are invariant),
/// a zero of f stays there, and otherwise ε follows the flow to the next zero
/// of f in its direction of motion, or to 0 or ∞.  (Steps of a factor 4 find
/// the next zero; two zeros closer than that would be missed.)
template <class Profile, class Real>
terminal_state<Real> terminal_motion(const Profile& profile, Real inertia_ratio,
                                     Real initial_ratio) {
  static_assert(detail::requires_profile<Profile>());
  using Policy = typename Profile::policy_type;
  using detail::argument_rule;
  static const char* function = "spinslide::terminal_motion<%1%>(profile, %1%, %1%)";
  Real invalid = 0;
  if (!detail::check(function, "inertia_ratio", inertia_ratio, argument_rule::finite_positive,
                     &invalid, Policy()) ||
      !detail::check(function, "initial_ratio", initial_ratio, argument_rule::non_negative,
                     &invalid, Policy()))
    return {terminal_regime::sliding_and_spinning, invalid};
  const Real& gamma = inertia_ratio;  // checked above
  const Real inf = std::numeric_limits<Real>::infinity();
  if (initial_ratio == 0) return {terminal_regime::pure_spinning, Real(0)};
  if ((boost::math::isinf)(initial_ratio)) return {terminal_regime::pure_sliding, inf};
  const Real g = detail::flow_over_ratio(profile, initial_ratio, gamma);
  if (g == 0) return {terminal_regime::sliding_and_spinning, initial_ratio};
  Real lo, hi;
  if (detail::bracket_next_zero(profile, gamma, initial_ratio, lo, hi)) {
    if (!(lo < hi)) std::swap(lo, hi);
    return {terminal_regime::sliding_and_spinning,
            detail::flow_zero(profile, gamma, lo, hi, Policy())};
  }
  return g > 0 ? terminal_state<Real>{terminal_regime::pure_sliding, inf}
               : terminal_state<Real>{terminal_regime::pure_spinning, Real(0)};
}

/// ε₀ of the paper: the uniform disk with γ = 1/2, ε₀ = 0.65300178920559763898…
/// Computed in the policy's evaluation type (long double for double) and
/// rounded, so that double is within 1 ulp.
template <class Real = double>
Real terminal_ratio() {
  using value_type =
      typename boost::math::policies::evaluation<Real, boost::math::policies::policy<>>::type;
  return static_cast<Real>(terminal_motion(uniform_disk<value_type>(), value_type(0.5)).ratio);
}

}  // namespace spinslide

#endif  // SPINSLIDE_TERMINAL_HPP
