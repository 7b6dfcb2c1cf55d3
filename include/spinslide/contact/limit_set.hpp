//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file limit_set.hpp
/// The coupled limit set of a contact and the projection onto it: exact stick
/// and slip (docs/theory.md §11, docs/contact.md).
///
/// A contact with profile P can sustain the friction states
///   L = {(f, t) : f = |F|/(μN) ≥ 0, t = |T|/(μNa) ≥ 0, on or below the curve (𝓕(ε), 𝓣(ε))},
/// a convex set whose outward normal at the curve point ε is (ε, 1) (because
/// 𝓣′ = −ε𝓕′: maximum dissipation).  Every engine-facing friction law is a
/// projection onto L in some metric; project_to_limit_set is the one in
/// (f − force)² + w (t − torque)².  Inside L the contact sticks and the point
/// is returned unchanged; outside, the nearest point lies on the curve, at
/// the ratio ε where (force − 𝓕, w (torque − 𝓣)) is parallel to (ε, 1).

#ifndef SPINSLIDE_CONTACT_LIMIT_SET_HPP
#define SPINSLIDE_CONTACT_LIMIT_SET_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/base/friction_result.hpp>
#include <spinslide/contact/detail/limit_projector.hpp>
#include <spinslide/contact/detail/metric_projector.hpp>
#include <spinslide/contact/planar_metric.hpp>
#include <spinslide/values/profile_concept.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

#include <array>
#include <limits>
#include <type_traits>

namespace spinslide {

namespace detail {

// What every projection requires of its profile and arguments, at compile time.
template <class Profile, class Real>
constexpr void require_projectable() {
  static_assert(requires_profile<Profile>());
  static_assert(std::is_same<Real, typename Profile::value_type>::value,
                "project_to_limit_set: the arguments (force, torque and torque_weight, or the "
                "wrench and the metric) must have the profile's value_type");
  static_assert(obeys_maximum_dissipation<Profile>::value,
                "project_to_limit_set: this profile's curve does not obey T' = -eps F' (the Pade "
                "approximants, also tabulated, scaled or in a weighted sum: no pressure gives "
                "them), so its normal is not (eps, 1) and the projection does not apply");
}

// The start a solve was given, as a sticking result's curve(): the point
// itself, or a ratio alone (`from` null).
template <class Real>
curve_point<Real> given_start(Real start, const curve_point<Real>* from) {
  return from ? *from : curve_point<Real>{start};
}

template <class Profile, class Real>
friction_result<Real, Real> project_checked(const Profile& profile,
                                            const force_torque_result<Real>& point,
                                            Real torque_weight, Real start, const char* function,
                                            const curve_point<Real>* from = nullptr) {
  require_projectable<Profile, Real>();
  const Real f = point.force, t = point.torque;
  // One test for good arguments; where it fails, the checks one by one
  // report the first bad one.
  if (!(all_finite(f, t, torque_weight) && f >= 0 && t >= 0 && torque_weight > 0 && start >= 0)) {
    using Policy = typename Profile::policy_type;
    const Policy pol;
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    // In this order (an argument list's is unspecified).
    const Real cf = checked(function, "force", f, argument_rule::finite_non_negative, pol);
    const Real ct = checked(function, "torque", t, argument_rule::finite_non_negative, pol);
    const Real cw =
        checked(function, "torque_weight", torque_weight, argument_rule::finite_positive, pol);
    const Real cs = checked(function, "start.ratio", start, argument_rule::non_negative, pol);
    if (any_reported(cf, ct, cw, cs)) return {nan, nan, false, nan};
  }
  friction_result<Real, Real> r =
      limit_projector<Profile>(profile, {f, t}, torque_weight)(start, from);
  if (r.sticking) r.point = given_start(start, from);
  return r;
}

// What the 3-D projection requires besides: a limit curve without corners
// (its Newton iteration minimizes a dissipation function that must be
// smooth away from rest).
template <class Profile, class Real>
constexpr void require_smooth_curve() {
  require_projectable<Profile, Real>();
  static_assert(!has_box_limit_set<Profile>::value,
                "project_to_limit_set(tangent_wrench, planar_metric) and impulse_friction: the "
                "uncoupled caps' limit set is a box, whose corners the 3-D projection's Newton "
                "iteration cannot resolve; project their magnitudes with the 2-D "
                "project_to_limit_set, which clamps");
}

template <class Profile, class Real>
friction_result<std::array<Real, 2>, Real> project_wrench_checked(
    const Profile& profile, const tangent_wrench<Real>& point, const planar_metric<Real>& metric,
    Real start, const char* function, const curve_point<Real>* from = nullptr) {
  require_smooth_curve<Profile, Real>();
  using Policy = typename Profile::policy_type;
  const Policy pol;
  const vector3<Real> z{
      checked(function, "point.force_x", point.force_x, argument_rule::finite, pol),
      checked(function, "point.force_y", point.force_y, argument_rule::finite, pol),
      checked(function, "point.torque", point.torque, argument_rule::finite, pol)};
  const Real s = checked(function, "start.ratio", start, argument_rule::non_negative, pol);
  if (any_reported(z[0], z[1], z[2], s)) {
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    return {{nan, nan}, nan, false, nan};
  }
  friction_result<std::array<Real, 2>, Real> r =
      metric_projector<Profile>(profile, z, metric.entries(), metric.inverse())(s, from);
  if (r.sticking) r.point = given_start(s, from);
  return r;
}

}  // namespace detail

/// The point of `profile`'s limit set L nearest to (force, torque) in
/// (f − force)² + torque_weight·(t − torque)², with f = |F|/(μN) and
/// t = |T|/(μNa).  Inside L (the boundary included): `sticking`, (force,
/// torque) unchanged, `ratio` NaN, curve() the start given (below; `{}`
/// without one).  Outside: on the curve at `ratio` ε
/// (+∞ at (1, 0), 0 at (0, ⟨r⟩)), where the displacement is normal to the
/// curve in this metric: force − 𝓕 = torque_weight·ε·(torque − 𝓣).
/// force and torque finite and ≥ 0, torque_weight finite and > 0, all of the
/// profile's value_type; otherwise a domain error (by default
/// std::domain_error).  No allocation; a few evaluations of the profile.
/// The profile must obey 𝓣′ = −ε𝓕′, as every pressure distribution does
/// (docs/theory.md §1), and so do the elliptic limit surface and the
/// uncoupled caps; the Padé approximants do not, and do not compile here.
template <class Profile, class Real>
friction_result<Real, Real> project_to_limit_set(const Profile& profile, Real force, Real torque,
                                                 Real torque_weight) {
  return detail::project_checked(profile, {force, torque}, torque_weight, Real(0),
                                 "spinslide::project_to_limit_set<%1%>(profile, %1%, %1%, %1%)");
}

/// As above, searching from where the contact's last projection left the
/// curve (its result's curve(): ratio ≥ 0, else a domain error): where the
/// ratio moved little, one or two evaluations of the profile.  From a point
/// with its values (a slip's curve()) the search takes its first step from
/// its 𝓕, 𝓣, 𝓕′ and 𝓕″ without evaluating the profile, one evaluation fewer
/// than from `curve_point<Real>{ε}`, a ratio alone (the last step's, say).
/// The values must be ones that a projection with the same profile
/// returned; the result does not depend on them (to rounding): no answer is
/// taken from them, only a step.
template <class Profile, class Real>
friction_result<Real, Real> project_to_limit_set(const Profile& profile, Real force, Real torque,
                                                 Real torque_weight,
                                                 const curve_point<Real>& start) {
  // (A point without values is a ratio alone: no first step from it.)
  return detail::project_checked(
      profile, {force, torque}, torque_weight, start.ratio,
      "spinslide::project_to_limit_set<%1%>(profile, %1%, %1%, %1%, curve_point)",
      (boost::math::isnan)(start.force) ? nullptr : &start);
}

/// The point of the 3-D limit set L₃ = {(f_x, f_y, t) : (|f|, |t|) ∈ L} nearest
/// to `point` in the metric M = `metric`, (p − point)ᵀM(p − point), for
/// forces and torques in the limit set's units (F/(μN), T/(μNa)).  Where M
/// couples the force's direction with the torque (an engine's effective mass
/// over a body with a lever arm), the answer is no longer a projection of
/// magnitudes: it is found by Newton's method on the dual, convex problem
/// (docs/theory.md §11, "Any metric").  The result's force is a 2-vector,
/// std::array<Real, 2>.  Inside L₃: `sticking`, the point unchanged, `ratio`
/// NaN, curve() the start given (below; `{}` without one).  Outside: p on the curve at `ratio` ε,
/// with M(point − p) along the normal (ε f̂, sign t) (maximum dissipation).  Each component of
/// `point` finite, else a domain error.  No allocation.
template <class Profile, class Real>
friction_result<std::array<Real, 2>, Real> project_to_limit_set(const Profile& profile,
                                                                const tangent_wrench<Real>& point,
                                                                const planar_metric<Real>& metric) {
  return detail::project_wrench_checked(
      profile, point, metric, Real(0),
      "spinslide::project_to_limit_set<%1%>(profile, tangent_wrench, planar_metric)");
}

/// As above, searching from where the contact's last projection left the
/// curve (its result's curve(): ratio ≥ 0, else a domain error); from a
/// slip's point with its values, one evaluation of the profile fewer than
/// from `curve_point<Real>{ε}`, a ratio alone.  The result does not depend
/// on the point (to rounding): only the start.
template <class Profile, class Real>
friction_result<std::array<Real, 2>, Real> project_to_limit_set(const Profile& profile,
                                                                const tangent_wrench<Real>& point,
                                                                const planar_metric<Real>& metric,
                                                                const curve_point<Real>& start) {
  return detail::project_wrench_checked(
      profile, point, metric, start.ratio,
      "spinslide::project_to_limit_set<%1%>(profile, tangent_wrench, planar_metric, curve_point)",
      &start);
}

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_LIMIT_SET_HPP
