//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file patch_limit_set.hpp
/// The limit set of a flat patch (polygon_patch.hpp) and the projection onto
/// it: exact stick and slip for any flat patch (docs/patches.md, "The limit
/// set and its projection").
///
/// A patch under the load μN can sustain the friction wrenches
///   L = {(F, τ) per unit μN : (F, τ)·w ≤ D(w) for every twist w},
/// D its dissipation (patch_dissipation.hpp), a convex set whose boundary
/// point with outward normal w is minus the friction wrench of w, the wrench
/// of the twist −w.  The projection works in the limit set's units, in which
/// the torque is divided by the patch's length ℓ (its largest vertex
/// distance from the origin, polygon_patch::radius(); 1 for a point patch at
/// the origin), so that a metric weighs force and torque alike.

#ifndef SPINSLIDE_CONTACT_PATCH_LIMIT_SET_HPP
#define SPINSLIDE_CONTACT_PATCH_LIMIT_SET_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/contact/detail/patch_projector.hpp>
#include <spinslide/contact/patch_result.hpp>
#include <spinslide/contact/planar_metric.hpp>
#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/hypot.hpp>

#include <array>
#include <cmath>
#include <limits>

namespace spinslide {

namespace detail {

// The checks of a wrench in the limit set's units and of a start twist; NaN in `bad` once reported.
template <class Real, class Policy>
bool check_wrench(const char* function, const planar_wrench<Real>& w, Real& bad,
                  const Policy& pol) {
  return check(function, "point.force[0]", w.force[0], argument_rule::finite, &bad, pol) &&
         check(function, "point.force[1]", w.force[1], argument_rule::finite, &bad, pol) &&
         check(function, "point.torque", w.torque, argument_rule::finite, &bad, pol);
}

template <class Real, class Policy>
bool check_start(const char* function, const planar_twist<Real>& w, Real& bad, const Policy& pol) {
  return check(function, "start.velocity[0]", w.velocity[0], argument_rule::finite, &bad, pol) &&
         check(function, "start.velocity[1]", w.velocity[1], argument_rule::finite, &bad, pol) &&
         check(function, "start.omega", w.omega, argument_rule::finite, &bad, pol);
}

// The slip in the limit set's units from a twist whose wrench is a slip's
// point (the result's slip): s = −(v, ℓω).
template <class Real>
vector3<Real> slip_of(const planar_twist<Real>& w, Real length) {
  return {-w.velocity[0], -w.velocity[1], -length * w.omega};
}
// The twist of a slip s: −(s_x, s_y, s_t/ℓ).
template <class Real>
planar_twist<Real> twist_of(const vector3<Real>& s, Real length) {
  return {{-s[0], -s[1]}, -s[2] / length};
}

// The projection of z (checked) in the metric m (inverse `inverse`), from the twist `start`.
template <class Real>
patch_projection<Real> project_patch(const polygon_patch<Real>& patch, const vector3<Real>& z,
                                     const matrix3<Real>& m, const matrix3<Real>& inverse,
                                     const planar_twist<Real>& start) {
  const patch_slip_model<Real> d(patch);
  const vector3<Real> s = slip_of(start, d.length());
  const bool warm = s[0] != 0 || s[1] != 0 || s[2] != 0;
  return patch_projector<Real>(d, z, m, inverse)(warm ? &s : nullptr);
}

}  // namespace detail

/// The point of `patch`'s limit set nearest to `point` in the metric M =
/// `metric`, (p − point)ᵀM(p − point), for a point in the limit set's units
/// (the force per unit μN, the torque about the patch origin per unit μNℓ:
/// see the file's comment).  Inside the set (the boundary included, to
/// rounding): `sticking`, the point unchanged, the slip zero, `ratio` NaN.  Outside: the
/// force and torque of the nearest point p (same units) and the slip, the
/// twist whose friction wrench is p (friction_wrench(patch, slip) is
/// (p.force, ℓ·p.torque)), with M(point − p) along the set's outward normal
/// there (maximum dissipation), and `ratio` the slip's |v|/(ℓ|ω|).  A
/// point patch's set is the flat disk {(f, x × f/ℓ) : |f| ≤ 1}: a point off
/// its plane slips, and where its nearest point lies inside the disk (|f| <
/// 1) the slip is a pure rotation about x, which does not move x: then the
/// force is not that slip's friction wrench (which is 0), but the disk's
/// point, held by the stuck contact point.  `start`: the
/// contact's last slip (the last result's `slip`; zero: none), which only
/// speeds the search.  Every component finite, else a domain error through
/// `pol` (NaN components unless it throws).  Nothing else fails: no
/// allocation, no exception; a few evaluations of the patch's wrench and
/// Hessian.
template <class Real, class Policy = boost::math::policies::policy<>>
patch_friction_result<std::array<Real, 2>, Real> project_to_limit_set(
    const polygon_patch<Real>& patch, const planar_wrench<Real>& point,
    const planar_metric<Real>& metric,
    const planar_twist<Real>& start = planar_twist<Real>{{Real(0), Real(0)}, Real(0)},
    const Policy& pol = Policy()) {
  static const char* function =
      "spinslide::project_to_limit_set<%1%>(polygon_patch, planar_wrench, planar_metric)";
  Real bad = 0;
  using result = patch_friction_result<std::array<Real, 2>, Real>;
  if (!detail::check_wrench(function, point, bad, pol) ||
      !detail::check_start(function, start, bad, pol))
    return detail::patch_result<std::array<Real, 2>, Real, force_quantity>({bad, bad}, bad, false,
                                                                           {{bad, bad}, bad}, bad);
  const detail::vector3<Real> z{point.force[0], point.force[1], point.torque};
  const detail::patch_projection<Real> r =
      detail::project_patch(patch, z, metric.entries(), metric.inverse(), start);
  const Real length = detail::patch_length(patch);
  const result out = detail::patch_result<std::array<Real, 2>, Real, force_quantity>(
      {r.point[0], r.point[1]}, r.point[2], r.sticking,
      r.sticking ? planar_twist<Real>{{Real(0), Real(0)}, Real(0)}
                 : detail::twist_of(r.slip, length),
      length);
  return out;
}

/// Where the wrench `wrench`'s ray leaves the limit set, and the twist
/// there (limit_surface_twist).
template <class Real>
struct limit_surface_point {
  using value_type = Real;  ///< the floating type
  /// The twist whose friction wrench is wrench/gauge, with |v|² + (ℓω)² = 1.
  planar_twist<Real> twist;
  /// γ with wrench = γ·(the boundary point on its ray): 1 on the limit
  /// surface, below 1 inside the set, above outside.
  Real gauge;
};

/// The inverse of friction_wrench on the limit surface: for a wrench
/// (per unit μN, the torque about the patch origin, physical units), the
/// twist whose friction wrench is the limit surface's point on the
/// wrench's ray from 0, and the wrench's gauge γ (limit_surface_point).  A
/// wrench that is not finite or zero is a domain error through `pol`; so is
/// one off a point patch's plane {(f, x × f)}, whose ray never meets its
/// flat set.  No allocation; a few evaluations of the wrench and its Hessian.
template <class Real, class Policy = boost::math::policies::policy<>>
limit_surface_point<Real> limit_surface_twist(const polygon_patch<Real>& patch,
                                              const planar_wrench<Real>& wrench,
                                              const Policy& pol = Policy()) {
  using std::fabs;
  using std::sqrt;
  static const char* function = "spinslide::limit_surface_twist<%1%>(polygon_patch, planar_wrench)";
  Real bad = 0;
  if (!detail::check_wrench(function, wrench, bad, pol)) return {{{bad, bad}, bad}, bad};
  const Real length = detail::patch_length(patch);
  const detail::vector3<Real> b{wrench.force[0], wrench.force[1], wrench.torque / length};
  if (b[0] == 0 && b[1] == 0 && b[2] == 0) {
    bad = detail::raise_argument_error(function, "wrench", "non-zero (a zero wrench has no ray)",
                                       Real(0), pol);
    return {{{bad, bad}, bad}, bad};
  }
  if (patch.shape() == patch_shape::point) {
    const auto& x = patch.pressure_origin();
    const Real f = boost::math::hypot(b[0], b[1]);
    const Real off = b[2] - (x[0] * b[1] - x[1] * b[0]) / length;
    if (!(f > 0) || fabs(off) > 8 * std::numeric_limits<Real>::epsilon() * (f + fabs(b[2]))) {
      bad = detail::raise_argument_error(
          function, "wrench.torque",
          "x × force for a point patch at x (its limit set is the flat disk {(f, x × f)})",
          wrench.torque, pol);
      return {{{bad, bad}, bad}, bad};
    }
    // The friction of a point at x is −û(x): the twist that moves x along −f.
    return {{{-b[0] / f, -b[1] / f}, Real(0)}, f};
  }
  const detail::patch_slip_model<Real> d(patch);
  const auto n = detail::gauge_search<detail::patch_slip_model<Real>>(d, b)(b);
  const Real size = sqrt(detail::dot(n.s, n.s));
  const detail::vector3<Real> unit{n.s[0] / size, n.s[1] / size, n.s[2] / size};
  return {detail::twist_of(unit, length), 1 / n.value};
}

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_PATCH_LIMIT_SET_HPP
