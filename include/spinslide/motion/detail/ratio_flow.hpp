//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file ratio_flow.hpp
/// The flow of the ratio, g(ε) = f(ε)/ε = 1 − γ𝓕/(ε𝓣), analysed for
/// terminal.hpp (docs/theory.md §8): its terms at any ε ∈ [0, ∞], its sign
/// where resolved, which ends of (0, ∞) attract, the walk and the march in
/// ln ε to its sign changes, and their refinement.  Not API.
#ifndef SPINSLIDE_MOTION_DETAIL_RATIO_FLOW_HPP
#define SPINSLIDE_MOTION_DETAIL_RATIO_FLOW_HPP

#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/tools/precision.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace spinslide {
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
}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_DETAIL_RATIO_FLOW_HPP
