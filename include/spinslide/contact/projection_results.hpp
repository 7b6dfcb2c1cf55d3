//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file projection_results.hpp
/// What the projections onto a contact's limit set return (limit_set.hpp),
/// and the point of the limit curve a contact keeps from step to step to
/// start its next projection from: one vocabulary for the 2-D and the 3-D
/// projection and the laws built on them (force, torque, sticking, ratio,
/// curve()).

#ifndef SPINSLIDE_CONTACT_PROJECTION_RESULTS_HPP
#define SPINSLIDE_CONTACT_PROJECTION_RESULTS_HPP

#include <spinslide/contact/planar_metric.hpp>

#include <cmath>
#include <limits>

namespace spinslide {

/// A point of a profile's limit curve as a projection left it
/// (limit_projection::curve()): the ratio ε and 𝓕, 𝓣, 𝓕′ and 𝓕″ there.
/// Passed to the next projection of the same contact with the same profile
/// (project_to_limit_set, limit_set.hpp; impulse_friction; cap_trial_state),
/// it lets that search take its first step without evaluating the profile.
/// The one warm start of every projection and law: `curve_point<Real>{ε}`
/// (the values unknown) starts from a ratio alone, and `{}` from nothing.
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

/// The point of a profile's limit set nearest to a given (force, torque)
/// (project_to_limit_set, limit_set.hpp).
template <class Real>
struct limit_projection {
  using value_type = Real;  ///< the floating type
  Real force;               ///< f = |F|/(μN) of the nearest point of L
  Real torque;              ///< t = |T|/(μNa) of the nearest point of L
  bool sticking;            ///< true if the given point lies in L (then returned unchanged)
  Real ratio;  ///< the ratio ε of the curve point (NaN if sticking; +∞ at (1, 0), 0 at (0, ⟨r⟩))
  /// 𝓕′ at `ratio`, where the profile has it in closed form and the point is
  /// on the curve between the ends (else NaN).
  Real slope = std::numeric_limits<Real>::quiet_NaN();
  /// 𝓕″ at `ratio`, where the projection's last step was Halley's (else NaN).
  Real curvature = std::numeric_limits<Real>::quiet_NaN();
  /// Where this projection left the curve, to start the contact's next one
  /// from; `{}` (no start) if sticking, so that it can always be passed on.
  curve_point<Real> curve() const {
    if (sticking) return {};
    return {ratio, force, torque, slope, curvature};
  }
};

/// The point of a profile's limit set nearest to a tangent wrench in a
/// planar_metric (project_to_limit_set, limit_set.hpp).
template <class Real>
struct wrench_projection {
  using value_type = Real;     ///< the floating type
  tangent_wrench<Real> point;  ///< the nearest point of L₃ (in the limit set's units)
  bool sticking;               ///< true if the given wrench lies in L₃ (then returned unchanged)
  Real ratio;                  ///< ε of the curve point (NaN if sticking)
  /// Where this projection left the curve (𝓕 = |point's force|, 𝓣 = |its
  /// torque|; 𝓕′ and 𝓕″ unknown), to start the contact's next one from;
  /// `{}` (no start) if sticking, so that it can always be passed on.
  curve_point<Real> curve() const {
    using std::fabs;
    using std::hypot;
    if (sticking) return {};
    return {ratio, Real(hypot(point.force_x, point.force_y)), Real(fabs(point.torque))};
  }
};

/// The friction of one contact over one step, as every contact law returns
/// it (impulse_friction, spring_history_friction): the same names as the
/// projections' results.
template <class Vec2, class Real>
struct friction_result {
  using value_type = Real;  ///< the floating type
  /// F (impulse_friction: the linear impulse P), on the body whose relative
  /// motion was given, in the tangent plane's axes
  Vec2 force;
  Real torque;    ///< T about the normal (impulse_friction: the angular impulse L)
  bool sticking;  ///< true: the contact sticks exactly (the trial state is kept)
  Real ratio;     ///< ε of the slip (NaN if sticking)
  /// Where the slip left the limit curve (the given start if sticking).
  curve_point<Real> point;
  /// Where this step left the limit curve, to start the contact's next one from.
  curve_point<Real> curve() const { return point; }
};

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_PROJECTION_RESULTS_HPP
