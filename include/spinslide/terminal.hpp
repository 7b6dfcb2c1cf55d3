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

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

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

// The pull h γ = γ𝓕/(ε𝓣) at ε ∈ [0, ∞], so that g = f/ε = 1 − pull.  Finite
// at both ends: γ⟨1/r⟩/(2⟨r⟩) at 0 and 2γ/⟨r²⟩ at ∞.
template <class Profile, class Real>
Real flow_pull(const Profile& p, Real eps, Real gamma) {
  const auto t = flow_terms_at(p, eps);
  return t.torque >= boost::math::tools::min_value<Real>()
             ? Real(gamma * t.force_over_ratio / t.torque)
             : Real(gamma * t.force / t.ratio_torque);
}

// g(ε) = f(ε)/ε = 1 − γ𝓕/(ε𝓣): f's sign without f's factor ε, and finite
// at both ends: g(0) = 1 − γ⟨1/r⟩/(2⟨r⟩), g(∞) = 1 − 2γ/⟨r²⟩.  A pull
// γ𝓕/(ε𝓣) beyond the type's range gives −max_value, not −∞.
template <class Profile, class Real>
Real flow_over_ratio(const Profile& p, Real eps, Real gamma) {
  const Real g = 1 - flow_pull(p, eps, gamma);
  return g >= -boost::math::tools::max_value<Real>() ? g : -boost::math::tools::max_value<Real>();
}

// The sign of g = 1 − pull where it is resolved: +1 where ε grows, −1 where
// it shrinks, and 0 where |g| ≤ √ε_mach (1.5e-8 for double): there g is not
// known to have a sign.  At an edge of the window, e.g. Hertz at γ = 1/2,
// g's departure from 0 near ε = 0 is below the accuracy of the profile's
// quadrature (measured: up to 5e-13 at ε ~ 1e-10), and the signs of those
// errors would make false zeros.
template <class Real>
int flow_sign(const Real& pull) {
  BOOST_MATH_STD_USING
  static const Real noise = sqrt(boost::math::tools::epsilon<Real>());
  return pull < 1 - noise ? 1 : (pull > 1 + noise ? -1 : 0);
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

// From ε (g(ε) ≠ 0), steps of a factor 4 up or down to the first ratio
// where g has the other sign (unlike flow_sign, any sign), within the
// exponent range: `near` and `far` are the last two ratios tried.  False if
// there is none.
template <class Profile, class Real>
bool walk_to_sign_change(const Profile& p, Real gamma, Real eps, bool up, Real& near, Real& far) {
  const Real big = boost::math::tools::max_value<Real>() / 8;
  const Real tiny = boost::math::tools::min_value<Real>() * 8;
  const bool grows = flow_pull(p, eps, gamma) < 1;
  for (near = eps, far = up ? Real(4 * eps) : Real(eps / 4); up ? far < big : far > tiny;
       near = far, far = up ? Real(4 * far) : Real(far / 4)) {
    const Real pull = flow_pull(p, far, gamma);
    if (grows ? pull > 1 : pull < 1) return true;
  }
  return false;
}

// Follows the flow from ε (g(ε) ≠ 0) to the next sign change of g in the
// direction of motion, by steps of a factor 4 (bounded by the exponent range):
// lo < hi.  Returns false if the flow runs to 0 or ∞ instead.  Steps of a
// factor 4 can jump over a pair of zeros: the march below checks them.
template <class Profile, class Real>
bool bracket_next_zero(const Profile& p, Real gamma, Real eps, Real& lo, Real& hi) {
  const bool up = flow_over_ratio(p, eps, gamma) > 0;
  Real near, far;
  if (!walk_to_sign_change(p, gamma, eps, up, near, far)) return false;
  lo = up ? near : far;
  hi = up ? far : near;
  return true;
}

// A sign change of g: a zero of the flow between lo and hi, attracting if g > 0 below it and < 0
// above it.
template <class Real>
struct flow_bracket {
  Real lo;
  Real hi;
  bool attracting;
};

// The ratios the march below covers with its proof (docs/theory.md §8, "Every
// zero"): [ε_mach/(4⟨1/r⟩), 4√(⟨r²⟩/ε_mach)].  A ring of mass m at radius a
// has m/a ≤ ⟨1/r⟩ and ma² ≤ ⟨r²⟩, so every ring heavier than ε_mach of the
// load lies inside; beyond, only the parity of the zeros is known.  A model
// with an infinite moment falls back on ⟨r⟩.
template <class Profile>
std::pair<typename Profile::value_type, typename Profile::value_type> flow_window(
    const Profile& p) {
  using Real = typename Profile::value_type;
  BOOST_MATH_STD_USING
  const Real e = boost::math::tools::epsilon<Real>();
  const Real inv = p.mean_inverse_radius(), sq = p.mean_square_radius();
  Real lo = (boost::math::isfinite)(inv) ? Real(e / (4 * inv)) : Real(e * p.mean_radius());
  Real hi = (boost::math::isfinite)(sq) ? Real(4 * sqrt(sq / e)) : Real(p.mean_radius() / e);
  lo = (std::max)(lo, Real(boost::math::tools::min_value<Real>() * 8));
  hi = (std::min)(hi, Real(boost::math::tools::max_value<Real>() / 8));
  return {lo, hi};
}

// Collects the sign changes of g met by a march, in the order met: each is
// bracketed by the last ratio with one resolved sign and the first with the
// other (ratios where the sign is not resolved lie between them).
template <class Real>
struct sign_changes {
  bool up;      // the march's direction
  int last;     // the last resolved sign of g met (0: none yet)
  Real before;  // where it was met
  std::vector<flow_bracket<Real>>& out;

  // Adds the sample (ε, sign of g there); true if it completes a sign change.
  bool add(const Real& eps, int sign) {
    if (sign == 0) return false;
    const bool change = last != 0 && sign != last;
    if (change) out.push_back({up ? before : eps, up ? eps : before, (up ? last : sign) > 0});
    last = sign;
    before = eps;
    return change;
  }
};

// Every sign change of g between `from` and `to` (either order), appended to
// `out` in the order met; with first_only, only the first.  The march works
// in s = ln ε with the certificate of docs/theory.md §8: since 𝓕 grows and 𝓣
// falls (I2), φ = ln(γ𝓕/(ε𝓣)) = ln(γ𝓕/𝓣) − s has slope ≥ −1, so a ratio
// with φ > 0 (g < 0) proves g < 0 on the next φ upwards, and one with φ < 0
// (g > 0) proves g > 0 on the next |φ| downwards.  Each step is one such
// proof (7/8 of it, for rounding), from either end; where |φ| is below
// 1/64 the march samples every 1/64 and sees only sign changes.
template <class Profile, class Real>
void march_flow(const Profile& p, Real gamma, Real from, Real to, bool first_only,
                std::vector<flow_bracket<Real>>& out) {
  BOOST_MATH_STD_USING
  const bool up = to > from;
  const Real resolution = Real(1) / 64, share = Real(7) / 8;
  // How far in s towards `to` (dir = 1) or back (dir = −1) the pull proves g's sign.
  auto reach = [&](const Real& pull, int dir) {
    const Real r = (up == (dir > 0) ? 1 : -1) * log(pull);
    return r > 0 ? Real(share * r) : Real(0);
  };
  // s = ln ε is the march's variable: ε itself would not move among subnormals.
  const Real s_to = log(to);
  Real s = log(from), eps = from, pull = flow_pull(p, from, gamma), trial = resolution;
  sign_changes<Real> found{up, flow_sign(pull), from, out};
  while (s != s_to) {
    const Real left = abs(s_to - s), ahead = reach(pull, 1);
    const Real step = (std::min)(ahead >= resolution ? ahead : trial, left);
    const Real next_s = step == left ? s_to : Real(up ? s + step : s - step);
    const Real next = step == left ? to : Real(exp(next_s));
    const Real next_pull = flow_pull(p, next, gamma);
    if (ahead < step && reach(next_pull, -1) < step && step > resolution) {
      trial = step / 2;  // neither end proves the step: halve it
      continue;
    }
    s = next_s;
    eps = next;
    pull = next_pull;
    // The next trial: 9/10 of what this ratio proves backwards (accepted if
    // |φ| does not fall by more than a tenth), else twice this step.
    const Real back = reach(pull, -1);
    trial = back >= resolution ? Real(back * 9 / 10) : Real(2 * step);
    if (found.add(eps, flow_sign(pull)) && first_only) return;
  }
}

// Below and above flow_window: one zero where g's sign at the window's end
// differs from its limit's (found by steps of a factor 4).  And if nothing
// was found though both ends repel (so that the number of zeros is odd), the
// zero bracketed from ε = 1, where |g| stayed below flow_sign's noise level.
template <class Profile, class Real>
void add_outer_zeros(const Profile& p, Real gamma, std::pair<Real, Real> window,
                     std::vector<flow_bracket<Real>>& out) {
  Real near, far;
  const int at_zero = flow_sign(flow_pull(p, Real(0), gamma));
  if (at_zero != 0 && flow_sign(flow_pull(p, window.first, gamma)) == -at_zero &&
      walk_to_sign_change(p, gamma, window.first, false, near, far))
    out.insert(out.begin(), flow_bracket<Real>{far, near, at_zero > 0});
  const int at_inf = flow_sign(flow_pull(p, std::numeric_limits<Real>::infinity(), gamma));
  const int at_hi = flow_sign(flow_pull(p, window.second, gamma));
  if (at_inf != 0 && at_hi == -at_inf &&
      walk_to_sign_change(p, gamma, window.second, true, near, far))
    out.push_back({near, far, at_hi > 0});
  const auto ends = attracting_ends(p, gamma);
  if (out.empty() && !ends.first && !ends.second && flow_over_ratio(p, Real(1), gamma) != 0 &&
      bracket_next_zero(p, gamma, Real(1), near, far))
    out.push_back({near, far, true});
}

// Every sign change of g on (0, ∞), ascending: the march over flow_window,
// then add_outer_zeros.
template <class Profile, class Real>
std::vector<flow_bracket<Real>> flow_sign_changes(const Profile& p, Real gamma) {
  const auto w = flow_window(p);
  std::vector<flow_bracket<Real>> out;
  march_flow(p, gamma, w.first, w.second, false, out);
  add_outer_zeros(p, gamma, w, out);
  return out;
}

// The zero of a sign change, to full precision.
template <class Profile, class Real, class Policy>
Real refine_zero(const Profile& p, Real gamma, const flow_bracket<Real>& b, const Policy& pol) {
  return flow_zero(p, gamma, b.lo, b.hi, pol);
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

namespace detail {

// The one attractor of a flow whose ends repel: its one zero.  The bracket
// grown from ε = 1 is refined where the march found that zero alone (as
// before the march existed, so that these results kept their last bit) or
// none (a zero where |g| stays below flow_sign's noise level, just inside an
// edge of the window), else the march's.
template <class Profile, class Real, class Policy>
terminal_state<Real> only_zero(const Profile& p, Real gamma,
                               const std::vector<flow_bracket<Real>>& zeros, const Policy& pol) {
  if (flow_over_ratio(p, Real(1), gamma) == 0) return {terminal_regime::sliding_and_spinning, 1};
  Real lo, hi;
  if (zeros.size() <= 1 && bracket_next_zero(p, gamma, Real(1), lo, hi))
    return {terminal_regime::sliding_and_spinning, flow_zero(p, gamma, lo, hi, pol)};
  if (zeros.size() == 1)
    return {terminal_regime::sliding_and_spinning, refine_zero(p, gamma, zeros.front(), pol)};
  const Real bad = boost::math::policies::raise_evaluation_error<Real>(
      "spinslide::terminal_motion<%1%>(profile, %1%)",
      "No zero of the ratio flow found for inertia_ratio = %1%.", gamma, pol);
  return {terminal_regime::sliding_and_spinning, bad};
}

// The attractor the flow reaches from ε (g(ε) ≠ 0): the first sign change of
// g in the direction of motion, else 0 or ∞.  The march runs from ε to the far
// end of the factor-4 bracket that the walk finds (or to the window's end
// where it finds none) and stops at the first sign change, whose bracket
// (1/64 wide in ln ε, or less) is refined; the march does not run past that
// zero, which halves its work (bench_dynamics).  Where the walk's sign
// change lies within flow_sign's noise level, the march sees none, and the
// walk's bracket is refined.
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
  if (walked) return {terminal_regime::sliding_and_spinning, flow_zero(p, gamma, lo, hi, pol)};
  return up ? terminal_state<Real>{terminal_regime::pure_sliding,
                                   std::numeric_limits<Real>::infinity()}
            : terminal_state<Real>{terminal_regime::pure_spinning, Real(0)};
}

}  // namespace detail

/// A zero ε₀ of the flow f at which f changes sign, and whether it attracts
/// (f > 0 below it and f < 0 above it) or repels.
template <class Real>
struct ratio_flow_zero {
  Real ratio;       ///< ε₀
  bool attracting;  ///< true: the flow from either side ends at ε₀
};

/// Every zero of f(ε) = ε − γ𝓕/𝓣 on (0, ∞) at which f changes sign, ascending,
/// each to full precision and classified.  They alternate: between two
/// attracting zeros lies a repelling one, whose sides flow to different ends.
/// Found by a march in ln ε that cannot step over a pair of zeros
/// (docs/theory.md §8, "Every zero": what it proves and what it assumes).  A
/// double zero (f touches 0 without changing sign) is not reported.  γ not
/// finite and > 0 is a domain error (the result is then one NaN zero).
template <class Profile, class Real>
std::vector<ratio_flow_zero<Real>> terminal_ratios(const Profile& profile, Real inertia_ratio) {
  static_assert(detail::requires_profile<Profile>());
  using Policy = typename Profile::policy_type;
  static const char* function = "spinslide::terminal_ratios<%1%>(profile, %1%)";
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
/// rings: terminal_ratios lists them), the outcome depends on the initial
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
  const auto ends = detail::attracting_ends(profile, gamma);
  const auto zeros = detail::flow_sign_changes(profile, gamma);
  const auto attractors =
      std::count_if(zeros.begin(), zeros.end(), [](const auto& z) { return z.attracting; }) +
      int(ends.first) + int(ends.second);
  if (attractors > 1) {
    const Real bad = detail::raise_argument_error(
        function, "inertia_ratio",
        "one for which the flow of eps has one attractor (for this one it has several, among "
        "eps -> 0, eps -> infinity and the zeros listed by terminal_ratios, and the outcome "
        "depends on the initial ratio: use the overload that takes it)",
        gamma, Policy());
    return {terminal_regime::sliding_and_spinning, bad};
  }
  if (ends.first) return {terminal_regime::pure_spinning, Real(0)};
  if (ends.second) return {terminal_regime::pure_sliding, std::numeric_limits<Real>::infinity()};
  return detail::only_zero(profile, gamma, zeros, Policy());
}

/// The terminal regime reached from a given initial ratio ε_i = v0/(Rω0) ∈ [0, ∞]:
/// 0 and ∞ stay where they are (pure spinning and pure sliding are invariant),
/// a zero of f stays there, and otherwise ε follows the flow to the next zero
/// of f in its direction of motion (an attracting one), or to 0 or ∞.  The
/// zero is found by the march of terminal_ratios, which cannot step over a
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
  if (detail::flow_over_ratio(profile, initial_ratio, gamma) == 0)
    return {terminal_regime::sliding_and_spinning, initial_ratio};
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

#endif  // SPINSLIDE_TERMINAL_HPP
