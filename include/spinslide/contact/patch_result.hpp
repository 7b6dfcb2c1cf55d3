//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file patch_result.hpp
/// What a flat patch's projection and impulse law return
/// (patch_limit_set.hpp, patch_impulse.hpp): the result family of
/// friction_result.hpp for a patch, whose slip is a twist, not a ratio.

#ifndef SPINSLIDE_CONTACT_PATCH_RESULT_HPP
#define SPINSLIDE_CONTACT_PATCH_RESULT_HPP

#include <spinslide/base/friction_result.hpp>
#include <spinslide/values/friction_wrench.hpp>

#include <cmath>
#include <limits>

namespace spinslide {

/// A flat patch's friction: a friction_result (the force and torque, or,
/// an impulse result, the linear and angular impulse; `sticking`; `ratio`,
/// the slip's |v|/(ℓ|ω|) about the patch origin, NaN when sticking; no curve
/// point, which a patch has not) with the slip, a planar_twist whose
/// friction wrench (friction_wrench) points along the answer: zero when
/// sticking (and, for a point patch whose point holds while the body turns
/// about it, that turn: project_to_limit_set).  The slip is where the contact's next solve starts.
template <class Force, class Real, class Quantity = force_quantity>
struct patch_friction_result : friction_result<Force, Real, Quantity> {
  /// The slip: the twist along which the patch slides and spins.
  planar_twist<Real> slip{{Real(0), Real(0)}, Real(0)};
};

namespace detail {

/// The result of a slip (`sticking` false) or a stick (slip zero).
template <class Force, class Real, class Quantity>
patch_friction_result<Force, Real, Quantity> patch_result(const Force& force, Real torque,
                                                          bool sticking,
                                                          const planar_twist<Real>& slip,
                                                          Real length) {
  using std::fabs;
  using std::sqrt;
  patch_friction_result<Force, Real, Quantity> r;
  r.force = force;
  r.torque = torque;
  r.sticking = sticking;
  r.slip = slip;
  const Real v = sqrt(slip.velocity[0] * slip.velocity[0] + slip.velocity[1] * slip.velocity[1]);
  const Real w = length * fabs(slip.omega);
  r.ratio = sticking ? std::numeric_limits<Real>::quiet_NaN()
            : w > 0  ? Real(v / w)
                     : std::numeric_limits<Real>::infinity();
  return r;
}

}  // namespace detail

/// A flat patch's impulse law's result (patch_impulse.hpp).
template <class Force, class Real>
using patch_impulse_result = patch_friction_result<Force, Real, impulse_quantity>;

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_PATCH_RESULT_HPP
