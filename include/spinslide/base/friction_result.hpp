//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file friction_result.hpp
/// The one family of friction results (docs/architecture.md, "Three shared
/// decisions"): every law and projection returns a `friction_result`, with
/// `force` and `torque` as scalars, 2-vectors or 3-vectors as the law needs,
/// `sticking`, `ratio` and `curve()`; an impulse law's result is an
/// `impulse_result`, so that its type says it holds impulses.  Here too is
/// `curve_point`, the point of a limit curve a contact keeps from one solve
/// to the next.

#ifndef SPINSLIDE_BASE_FRICTION_RESULT_HPP
#define SPINSLIDE_BASE_FRICTION_RESULT_HPP

#include <spinslide/base/detail/vector_access.hpp>

#include <limits>
#include <type_traits>
#include <utility>

namespace spinslide {

/// A point of a profile's limit curve as a solve left it (a result's
/// curve()): the ratio ε and 𝓕, 𝓣, 𝓕′ and 𝓕″ there.  Passed to the next
/// solve of the same contact with the same profile (project_to_limit_set,
/// impulse_friction, cap_trial_state, spring_history_friction), it lets that
/// search take its first step without evaluating the profile.
/// `curve_point<Real>{ε}` (the values unknown) starts from a ratio alone, and
/// `{}` from nothing.
template <class Real>
struct curve_point {
  using value_type = Real;  ///< the floating type
  Real ratio = 0;           ///< ε (0 or +∞: no start)
  /// 𝓕(ε) (NaN: unknown, and the point serves as a ratio only)
  Real force = std::numeric_limits<Real>::quiet_NaN();
  /// 𝓣(ε) (NaN: unknown, and the point serves as a ratio only)
  Real torque = std::numeric_limits<Real>::quiet_NaN();
  /// 𝓕′(ε) (NaN: unknown, and the point serves as a ratio only)
  Real slope = std::numeric_limits<Real>::quiet_NaN();
  /// 𝓕″(ε) (NaN: unknown, and the first step is Newton's)
  Real curvature = std::numeric_limits<Real>::quiet_NaN();
};

/// The quantity of a friction_result: a force and a torque (the projections,
/// the contact law, the spring-history and trial-cap laws, the cylinder).
struct force_quantity {};
/// The quantity of an impulse_result: the linear and the angular impulse
/// over one time step (impulse_friction, pair_friction, the joint solve).
struct impulse_quantity {};

namespace detail {

// The floating type of a vector class's components (operator[] or members
// x, y), or the type itself for a scalar (also a class, as Boost's
// multiprecision numbers).
template <class T, bool = is_vector<T, 2>()>
struct component_type {
  using type = T;
};
template <class T>
struct component_type<T, true> {
  using type = std::decay_t<decltype(get<0>(std::declval<const T&>()))>;
};

}  // namespace detail

/// The friction of one contact, as every law and projection returns it.
///
/// `Force` is a scalar (a magnitude, f = |F|/(μN) in the limit set's
/// units), a 2-vector (in the tangent plane's axes) or a 3-vector (in the
/// world); `Torque` a scalar (about the normal) or a 3-vector (along it).
/// `Quantity` says what they hold: force_quantity, or impulse_quantity for
/// the impulses over a step (impulse_result).
///
/// `curve()` has one meaning: the curve point the next solve of the same
/// contact starts from.  After a slip it is where the slip left the curve;
/// when sticking it is the start the solve was given, so that a stick does
/// not lose the warm start.  A law that is not a solve (the regularized
/// contact law, the cylinder) returns the point at its ratio.
template <class Force, class Torque, class Quantity = force_quantity>
struct friction_result {
  /// The floating type.
  using value_type = typename detail::component_type<Torque>::type;
  /// force_quantity or impulse_quantity.
  using quantity = Quantity;
  /// F (an impulse_result: the linear impulse P), on the body whose relative
  /// motion was given, against its sliding.
  Force force;
  /// T (an impulse_result: the angular impulse L), against the spin.
  Torque torque;
  /// True: the contact sticks exactly (the given point or trial state is kept).
  bool sticking = false;
  /// ε of the slip (NaN if sticking; +∞ pure sliding, 0 pure spinning).
  value_type ratio = std::numeric_limits<value_type>::quiet_NaN();
  /// Where the slip left the limit curve; the given start if sticking.
  curve_point<value_type> point{};
  /// The curve point the contact's next solve starts from (see above).
  curve_point<value_type> curve() const { return point; }
};

/// The friction_result of an impulse law: force and torque hold the linear
/// and the angular impulse over one step.
template <class Force, class Torque>
using impulse_result = friction_result<Force, Torque, impulse_quantity>;

}  // namespace spinslide

#endif  // SPINSLIDE_BASE_FRICTION_RESULT_HPP
