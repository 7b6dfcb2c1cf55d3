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

#ifndef SPINSLIDE_MOTION_TERMINAL_HPP
#define SPINSLIDE_MOTION_TERMINAL_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/motion/detail/ratio_flow.hpp>
#include <spinslide/motion/terminal_state.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/profile_concept.hpp>

#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace spinslide {

/// The inertia ratios γ for which both ends of the flow repel, so that every
/// motion that starts sliding and spinning ends with a finite ratio ε₀:
/// lower = ⟨r²⟩/2 < γ < upper = 2⟨r⟩/⟨1/r⟩ (docs/theory.md §8).  For the
/// uniform disk: 1/4 < γ < 2/3.  The window is empty if lower ≥ upper.
template <class Real>
struct inertia_window {
  using value_type = Real;  ///< the floating type
  Real lower;               ///< ⟨r²⟩/2: below it, ε → ∞
  Real upper;               ///< 2⟨r⟩/⟨1/r⟩: above it, ε → 0
};

/// The window (W) of `p` from its moments: ⟨r²⟩/2 < γ < 2⟨r⟩/⟨1/r⟩.  No
/// errors of its own (a profile's moments are finite and > 0).
template <class Profile>
inertia_window<typename Profile::value_type> terminal_window(const Profile& p) {
  static_assert(detail::requires_profile<Profile>());
  return {p.mean_square_radius() / 2, 2 * p.mean_radius() / p.mean_inverse_radius()};
}

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

namespace detail {

// The one attractor of a flow whose ends repel: its one zero.  The bracket
// grown from ε = 1 is refined where the march found that zero alone (as
// before the march existed, so that these results kept their last bit) or
// none (a zero where |g| stays below flow_sign's noise level, just inside an
// edge of the window), else the march's; where there is none at all, the end
// the flow points to.
template <class Profile, class Real, class Policy>
terminal_state<Real> only_zero(const Profile& p, Real gamma,
                               const std::vector<flow_bracket<Real>>& zeros, const Policy& pol) {
  if (flow_over_ratio(p, Real(1), gamma) == 0) return {terminal_regime::sliding_and_spinning, 1};
  Real lo, hi;
  if (zeros.size() <= 1 && bracket_next_zero(p, gamma, Real(1), lo, hi))
    return {terminal_regime::sliding_and_spinning, flow_zero(p, gamma, lo, hi, pol)};
  if (zeros.size() == 1)
    return {terminal_regime::sliding_and_spinning, refine_zero(p, gamma, zeros.front(), pol)};
  // No sign change of g anywhere: g keeps the sign it has at ε = 1, and every
  // start runs to the end it points to.  This is an end that attracts too
  // weakly for attracting_ends to resolve: γ at an edge of the window, within
  // the rounding of the moments (float's Hertz at γ = 1/2, its ring at 2).
  if (zeros.empty())
    return flow_over_ratio(p, Real(1), gamma) < 0
               ? terminal_state<Real>{terminal_regime::pure_spinning, Real(0)}
               : terminal_state<Real>{terminal_regime::pure_sliding,
                                      std::numeric_limits<Real>::infinity()};
  const Real bad = boost::math::policies::raise_evaluation_error<Real>(
      "spinslide::terminal_motion<%1%>(profile, %1%)",
      "No zero of the ratio flow found for inertia_ratio = %1%.", gamma, pol);
  return {terminal_regime::sliding_and_spinning, bad};
}

// The flow's one attractor (0, ∞ or its one attracting zero), as
// terminal_motion(profile, γ) reports it; false where it has several (the
// outcome then depends on the start).
template <class Profile, class Real, class Policy>
bool unique_attractor(const Profile& p, Real gamma, const Policy& pol, terminal_state<Real>& out) {
  const auto ends = attracting_ends(p, gamma);
  const auto zeros = flow_sign_changes(p, gamma);
  const auto attractors =
      std::count_if(zeros.begin(), zeros.end(), [](const auto& z) { return z.attracting; }) +
      int(ends.first) + int(ends.second);
  if (attractors > 1) return false;
  if (ends.first)
    out = {terminal_regime::pure_spinning, Real(0)};
  else if (ends.second)
    out = {terminal_regime::pure_sliding, std::numeric_limits<Real>::infinity()};
  else
    out = only_zero(p, gamma, zeros, pol);
  return true;
}

// The attractor the flow reaches from ε (g(ε) ≠ 0): the first sign change of
// g in the direction of motion, else 0 or ∞.  The march runs from ε to the far
// end of the factor-4 bracket that the walk finds (or to the window's end
// where it finds none) and stops at the first sign change, whose bracket
// (1/64 wide in ln ε, or less) is refined; the march does not run past that
// zero, which halves its work (bench_dynamics).  Where the walk's sign
// change lies within flow_sign's noise level, the march sees none: that is
// either a zero too shallow for g to resolve or rounding noise where g
// tends to 0 at an edge of the window (Hertz at γ = 1/5 from ε = 1e7: a
// "zero" at 4e7 where the flow runs to ∞).  Where the flow has one
// attractor, that attractor is the answer, as terminal_motion(profile, γ)
// gives it; otherwise the walk's bracket is refined.
template <class Profile, class Real, class Policy>
terminal_state<Real> reached_from(const Profile& p, Real gamma, Real eps, const Policy& pol) {
  const bool up = flow_over_ratio(p, eps, gamma) > 0;
  Real lo, hi;
  const bool walked = bracket_next_zero(p, gamma, eps, lo, hi);
  const auto w = flow_window(p);
  const Real end = walked ? (up ? hi : lo)
                   : up   ? (std::max)(eps, w.second)
                          : (std::min)(eps, w.first);
  std::vector<flow_bracket<Real>> found;
  march_flow(p, gamma, eps, end, true, found);
  if (!found.empty())
    return {terminal_regime::sliding_and_spinning, refine_zero(p, gamma, found.front(), pol)};
  if (walked) {
    terminal_state<Real> unique{};
    if (unique_attractor(p, gamma, pol, unique)) return unique;
    return {terminal_regime::sliding_and_spinning, flow_zero(p, gamma, lo, hi, pol)};
  }
  return up ? terminal_state<Real>{terminal_regime::pure_sliding,
                                   std::numeric_limits<Real>::infinity()}
            : terminal_state<Real>{terminal_regime::pure_spinning, Real(0)};
}

}  // namespace detail

/// A zero ε₀ of the flow f at which f changes sign, and whether it attracts
/// (f > 0 below it and f < 0 above it) or repels.
template <class Real>
struct ratio_flow_zero {
  using value_type = Real;  ///< the floating type
  Real ratio;               ///< ε₀
  bool attracting;          ///< true: the flow from either side ends at ε₀
};

/// Every zero of the flow f(ε) = ε − γ𝓕/𝓣 on (0, ∞) at which f changes sign,
/// ascending,
/// each to full precision and classified.  They alternate: between two
/// attracting zeros lies a repelling one, whose sides flow to different ends.
/// Found by a march in ln ε that cannot step over a pair of zeros
/// (docs/theory.md §8, "Every zero": what it proves and what it assumes).  A
/// double zero (f touches 0 without changing sign) is not reported.  γ not
/// finite and > 0 is a domain error (the result is then one NaN zero).
template <class Profile, class Real>
std::vector<ratio_flow_zero<Real>> ratio_flow_zeros(const Profile& profile, Real inertia_ratio) {
  static_assert(detail::requires_profile<Profile>());
  using Policy = typename Profile::policy_type;
  static const char* function = "spinslide::ratio_flow_zeros<%1%>(profile, %1%)";
  Real invalid = 0;
  if (!detail::check(function, "inertia_ratio", inertia_ratio,
                     detail::argument_rule::finite_positive, &invalid, Policy()))
    return {{invalid, false}};
  const Real& gamma = inertia_ratio;  // checked above
  std::vector<ratio_flow_zero<Real>> zeros;
  for (const auto& b : detail::flow_sign_changes(profile, gamma))
    zeros.push_back({detail::refine_zero(profile, gamma, b, Policy()), b.attracting});
  return zeros;
}

/// The terminal regime for a motion that starts sliding and spinning
/// (0 < ε < ∞), and the limit of ε, where that does not depend on the initial
/// ratio: the flow has one attractor (0, ∞ or one zero ε₀).  If it has more
/// (both ends attract, possible only when the load is concentrated near the
/// centre; or f has several attracting zeros, possible for a load on thin
/// rings: ratio_flow_zeros lists them), the outcome depends on the initial
/// ratio: that is a domain error here; use the overload below.  γ not
/// finite and > 0 is a domain error.
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
  terminal_state<Real> unique{};
  if (detail::unique_attractor(profile, gamma, Policy(), unique)) return unique;
  const Real bad = detail::raise_argument_error(
      function, "inertia_ratio",
      "one for which the flow of eps has one attractor (for this one it has several, among "
      "eps -> 0, eps -> infinity and the zeros listed by ratio_flow_zeros, and the outcome "
      "depends on the initial ratio: use the overload that takes it)",
      gamma, Policy());
  return {terminal_regime::sliding_and_spinning, bad};
}

/// The terminal regime reached from a given initial ratio ε_i = v0/(Rω0) ∈ [0, ∞]:
/// 0 and ∞ stay where they are (pure spinning and pure sliding are invariant),
/// a zero of f stays there, and otherwise ε follows the flow to the next zero
/// of f in its direction of motion (an attracting one), or to 0 or ∞.  The
/// zero is found by the march of ratio_flow_zeros, which cannot step over a
/// pair of zeros.
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
  if (initial_ratio == 0) return {terminal_regime::pure_spinning, Real(0)};
  if ((boost::math::isinf)(initial_ratio))
    return {terminal_regime::pure_sliding, std::numeric_limits<Real>::infinity()};
  if (detail::flow_over_ratio(profile, initial_ratio, gamma) == 0) {
    // The rounded flow vanishes: at a zero of f, or where f's departure from
    // 0 at an edge of the window is below rounding (Hertz at γ = 1/2 from
    // ε = 1e-9).  With one attractor the flow goes there (the same answer as
    // at the zero itself, if that is the attractor); otherwise the start is
    // taken as the zero it stays at.
    terminal_state<Real> unique{};
    if (detail::unique_attractor(profile, gamma, Policy(), unique)) return unique;
    return {terminal_regime::sliding_and_spinning, initial_ratio};
  }
  return detail::reached_from(profile, gamma, initial_ratio, Policy());
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

#endif  // SPINSLIDE_MOTION_TERMINAL_HPP
