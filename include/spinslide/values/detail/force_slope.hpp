//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// 𝓕′(ε) of a profile that has it as a member force_derivative (Hertz and
// Boussinesq, whose closed forms give it at about the cost of 𝓕 and 𝓣).  The
// profile concept does not ask for a derivative, so a generic caller asks
// has_force_slope first and estimates the slope itself otherwise (the
// limit-set projection takes secants).  The uniform disk's force_derivative
// (disk.hpp) is not used there: through the Carlson forms it costs about 15
// evaluations of the fast path's 𝓕 and 𝓣 (bench_disk); in float and double
// the disk's slope comes with its values from its fast table instead
// (fused_value_slope).
#ifndef SPINSLIDE_VALUES_DETAIL_FORCE_SLOPE_HPP
#define SPINSLIDE_VALUES_DETAIL_FORCE_SLOPE_HPP

#include <spinslide/values/force_torque_result.hpp>

#include <type_traits>
#include <utility>

namespace spinslide {
namespace detail {

// 𝓕, 𝓣, 𝓕′ and 𝓕″ at one ratio, for the limit-set projections, which need
// them at each step (fused_value_slope below).
template <class Real>
struct value_slope {
  force_torque_result<Real> value;  // 𝓕, 𝓣
  Real slope;                       // 𝓕′
  Real curvature;                   // 𝓕″ (NaN where the profile gives none to trust)
};

template <class P, class = void>
struct has_member_force_derivative : std::false_type {};
template <class P>
struct has_member_force_derivative<P,
                                   std::void_t<decltype(std::declval<const P&>().force_derivative(
                                       std::declval<typename P::value_type>()))>> : std::true_type {
};

/// True if force_slope(p, ε) is the closed-form 𝓕′(ε) of P.
template <class P>
constexpr bool has_force_slope() {
  return has_member_force_derivative<P>::value;
}

/// Specialized (true, with static at<Curvature = true>(p, ε) giving 𝓕, 𝓣, 𝓕′
/// and, if Curvature, 𝓕″ together for 0 < ε < ∞, a value_slope) by profiles
/// whose closed forms or tables share work between the values and the
/// derivatives (Hertz and Boussinesq, and the uniform disk in float and
/// double: profile.hpp; a tabulated profile, without 𝓕″: tabulated.hpp);
/// the limit-set projections then take them from one call.  𝓕 and 𝓣 are
/// force_torque's bit for bit, with or without 𝓕″; 𝓕′ is force_slope's
/// where the profile has one (Hertz, Boussinesq, a table), and the
/// derivative of the fast table's polynomial for the disk (disk_fast.hpp).
/// bounded_curvature says whether at() gives an 𝓕″ for Halley's steps:
/// Hertz's is bounded; the disk's is NaN near ε = 1, where it diverges
/// (Newton's step there); Boussinesq's is unbounded at ε = 1 and not given.
template <class P>
struct fused_value_slope : std::false_type {
  static constexpr bool bounded_curvature = false;
};

/// 𝓕′(ε) for 0 < ε < ∞, for a profile with has_force_slope<P>().
template <class P>
typename P::value_type force_slope(const P& p, typename P::value_type eps) {
  static_assert(has_force_slope<P>(), "force_slope: this profile has no closed-form derivative");
  return p.force_derivative(eps);
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DETAIL_FORCE_SLOPE_HPP
