//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file motion/detail/stop_tail.hpp
/// The end of a leg (docs/theory.md §9; motion/detail/stop_integrator.hpp): the rest
/// of the motion after the last panel, in closed form where G tends to a
/// finite limit, or a bound that shows it negligible towards ε = ∞ in the
/// leg's variable.

#ifndef SPINSLIDE_MOTION_DETAIL_STOP_TAIL_HPP
#define SPINSLIDE_MOTION_DETAIL_STOP_TAIL_HPP

#include <spinslide/motion/detail/stop_leg.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace spinslide {
namespace detail {

/// The integrals from a point of a leg to its end.
struct leg_rest {
  double time = 0;          ///< ∫e^{−u}G
  double lead_travel = 0;   ///< ∫e^{−2u}G
  double other_travel = 0;  ///< ∫ρe^{−2u}G, in units of e^{rho_log}
};

/// λ of the approach q − q∞ ∝ e^{−λu} from `here`: −F/(q − q∞) at a finite
/// zero, else 1.
template <class Real>
double approach_rate(const leg_path& path, const flow_point<Real>& here) {
  if (!path.finite_target) return 1;
  const double lam = -here.rate / (here.q - path.q_target);
  return lam >= 0 && std::isfinite(lam) ? lam : 0;
}

/// The rest of the leg from `at` (where the flow is `here`) where G tends to
/// G∞ = leg.g_target() along the path, once it is known to the tolerance of
/// the totals; else nothing.  The rest lies between e^{−u}G and e^{−u}G∞ (and
/// alike for ∫e^{−2u}G), so once that interval is below the tolerance the
/// estimate for an exponential approach, e^{−u}(G∞ + (G − G∞)/(1 + λ)), is
/// taken.  For ∫ρe^{−2u}G: the same towards a finite zero, or, where it is
/// smaller (and towards ε = 0), the bound ρe^{−2u}max(G, G∞) (ρ grows at most
/// like e^u, since F ≤ 1) with the estimate at the present rate,
/// ρe^{−2u}G/(2 − F).  ρe^{−2u} is taken as one exponential (ρ alone may
/// overflow).
template <class Profile, class Real = typename Profile::value_type>
std::optional<leg_rest> closed_form_rest(const stop_leg<Profile>& leg, const leg_position& at,
                                         const flow_point<Real>& here, double tolerance) {
  const leg_path& path = leg.path();
  const double lam = approach_rate(path, here);
  const double decay = std::exp(-at.u), g = here.g, g_end = leg.g_target();
  leg_rest rest;
  rest.time = decay * (g_end + (g - g_end) / (1 + lam));
  // ∫e^{−2u}(G∞ + (G − G∞)e^{−λu}) = (G∞ + (G − G∞)·2/(2 + λ))/2, times e^{−2u}.
  const double half_decay2 = decay * decay / 2, approach_weight = 2 / (2 + lam);
  rest.lead_travel = half_decay2 * (g_end + (g - g_end) * approach_weight);
  const double other_here = leg.rho_integrand(here.q, at.u, g);
  rest.other_travel = leg.rest_at_rate(here, at.u);
  double other_bound = other_here * (std::max)(1.0, g_end / g);
  if (path.finite_target) {
    const double other_end = leg.rho_integrand(path.q_target, at.u, g_end);
    if (std::fabs(other_here - other_end) / 2 <= other_bound) {
      rest.other_travel = (other_end + (other_here - other_end) * approach_weight) / 2;
      other_bound = std::fabs(other_here - other_end) / 2;
    }
  }
  const bool known =
      decay * std::fabs(g - g_end) <= tolerance * (at.time + rest.time) &&
      half_decay2 * std::fabs(g - g_end) <= tolerance * (at.lead_travel + rest.lead_travel) &&
      other_bound <= tolerance * (at.other_travel + rest.other_travel);
  if (!known) return std::nullopt;
  return rest;
}

/// Whether the rest of the leg is negligible, towards ε = ∞ in its variable,
/// where the other motion stops first: a bound on the remaining time, from
/// `now` (the motion at `at`, where the flow is `here`).  ε moves
/// monotonically, so 𝓕 (growing ε) or 𝓣 (falling ε) only grows from here,
/// and both motions stop within v/𝓕 = ω/(𝓕/ε) or γω/𝓣 = γv/(ε𝓣)
/// respectively.  Negligible once that bound, and the distance and angle it
/// allows, are below 1e-18 of their totals (or below the smallest
/// subnormal).  (Where the flow only creeps towards ∞, at the edges of the
/// inertia window, the switch at 10⁸ may be astronomically far.)  The bound
/// is taken in logs, where neither motion under- or overflows; each bound is
/// the larger of its two forms (a NaN form is ignored); at a zero of the flow
/// ε stays, and both bounds hold.
template <class Profile, class Real = typename Profile::value_type>
bool rest_is_negligible(const stop_leg<Profile>& leg, const leg_position& at,
                        const flow_point<Real>& here, const motion_sample<Real>& now) {
  BOOST_MATH_STD_USING
  const bool by_speed = leg.by_speed();
  const Real ln_lead = log(leg.start().lead) - Real(at.u);
  const Real ln_other = log(leg.start().other) + Real(here.q - leg.path().q_start) - Real(at.u);
  const Real ln_v = by_speed ? ln_lead : ln_other, ln_w = by_speed ? ln_other : ln_lead;
  const flow_terms<Real>& ft = here.terms;
  auto larger = [](Real a, Real b) { return a >= b || b != b ? a : b; };
  const Real ln_by_force = larger(ln_v - log(ft.force), ln_w - log(ft.force_over_ratio));
  const Real ln_by_torque =
      log(leg.inertia_ratio()) + larger(ln_w - log(ft.torque), ln_v - log(ft.ratio_torque));
  const double rate = here.rate;
  const Real ln_left = rate == 0                          ? (std::min)(ln_by_force, ln_by_torque)
                       : (by_speed ? rate < 0 : rate > 0) ? ln_by_force
                                                          : ln_by_torque;
  const Real ln_tiny = log(Real(1e-18)), ln_floor = log(std::numeric_limits<Real>::denorm_min());
  auto negligible = [&](Real ln_part, Real total) {
    return ln_part <= ln_tiny + log(total) || ln_part < ln_floor;
  };
  return negligible(ln_left, now.time) && negligible(ln_v + ln_left, now.distance) &&
         negligible(ln_w + ln_left, now.angle);
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_DETAIL_STOP_TAIL_HPP
