//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file patch_impulse.hpp
/// Velocity-level (impulse) friction of a flat patch (polygon_patch.hpp)
/// over one time step: exact stick, and slip on the patch's limit set by
/// maximum dissipation (docs/patches.md, "The impulse law").
///
/// As for a round patch (impulse_friction.hpp): given the relative sliding
/// velocity v of the patch origin and the spin ω before friction, and the
/// effective inverse mass W over (v_x, v_y, ω), the friction impulse
/// P = (P_x, P_y, L) is the one that leaves the least kinetic energy of the
/// relative motion, P = argmin ½ (s + WP)ᵀW⁻¹(s + WP) over μΛ·L, L the
/// patch's limit set (patch_limit_set.hpp).  If the impulse that stops the
/// contact, −W⁻¹(v, ω), lies in μΛ·L it is the answer (exact stick);
/// otherwise the velocity after the step, (v⁺, ω⁺) = (v, ω) + WP, is the
/// twist whose friction wrench is P/(μΛ): the patch's exact friction law at
/// the end of the step.

#ifndef SPINSLIDE_CONTACT_PATCH_IMPULSE_HPP
#define SPINSLIDE_CONTACT_PATCH_IMPULSE_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/base/detail/vector_access.hpp>
#include <spinslide/contact/contact_inputs.hpp>
#include <spinslide/contact/patch_limit_set.hpp>
#include <spinslide/contact/patch_result.hpp>
#include <spinslide/contact/planar_metric.hpp>

#include <boost/math/policies/policy.hpp>

#include <cmath>
#include <cstddef>
#include <limits>

namespace spinslide {

namespace detail {

// The stopping impulse in the limit set's units, ẑ = S⁻¹(−W⁻¹s)/(μΛ) with
// S = diag(1, 1, ℓ); where it overflows (a load far below the motion's),
// a finite point along it beyond the projector's far bound, whose answer
// is the same support point.
template <class Real>
vector3<Real> scaled_stop(const vector3<Real>& s, const matrix3<Real>& inverse_mass_inverse,
                          Real load, Real length) {
  const Real size = largest(s);
  const vector3<Real> unit{s[0] / size, s[1] / size, s[2] / size};
  const vector3<Real> stop = multiply(inverse_mass_inverse, unit);
  const Real factor = size / load;
  vector3<Real> z{-stop[0] * factor, -stop[1] * factor, -stop[2] / length * factor};
  if (all_finite(z[0], z[1], z[2])) return z;
  using std::sqrt;
  const vector3<Real> d{-stop[0], -stop[1], -stop[2] / length};
  const Real far = sqrt(std::numeric_limits<Real>::max()) / largest(d);
  return {d[0] * far, d[1] * far, d[2] * far};
}

}  // namespace detail

/// The friction impulse of a flat patch over one step (see the file's
/// comment).  `velocity`: the relative sliding velocity of the patch origin
/// before friction (a 2-component vector class, in the patch's axes);
/// `spin`: the relative angular velocity about the normal; `inverse_mass`:
/// W over (v_x, v_y, ω) in the same axes; `contact`: Λ ≥ 0 and μ ≥ 0.
/// Components finite, else a domain error through `pol`.  `start`: the
/// contact's last slip (the last result's `slip`; zero: none), which only
/// speeds the search.  The result's force and torque are the impulse
/// (P_x, P_y) and L (about the patch origin); its slip the velocity after
/// the step (v⁺, ω⁺) = (v, ω) + WP (to the projection's tolerance, and
/// exactly along the impulse's friction law), zero when sticking.  No allocation, no exception for
/// numerical reasons.
template <class Vec2, class Real, class Policy = boost::math::policies::policy<>>
patch_impulse_result<Vec2, Real> impulse_friction(
    const polygon_patch<Real>& patch, const Vec2& velocity,
    typename polygon_patch<Real>::value_type spin, const planar_metric<Real>& inverse_mass,
    const patch_impulse_contact<Real>& contact,
    const planar_twist<Real>& start = planar_twist<Real>{{Real(0), Real(0)}, Real(0)},
    const Policy& pol = Policy()) {
  static_assert(detail::is_vector<Vec2, 2>(),
                "spinslide::impulse_friction: the velocity must be a 2-component vector class "
                "(operator[] or members x, y), not a pointer or a C array: copy a raw array "
                "such as MuJoCo's mjtNum* into a std::array<double, 2>");
  static const char* function =
      "spinslide::impulse_friction<%1%>(polygon_patch, velocity, %1%, inverse_mass, "
      "patch_impulse_contact)";
  const detail::vector3<Real> s{static_cast<Real>(detail::get<0>(velocity)),
                                static_cast<Real>(detail::get<1>(velocity)), spin};
  Real bad = 0;
  const Real n = contact.normal.value, mu = contact.friction.value;
  if (!detail::check(function, "velocity[0]", s[0], detail::argument_rule::finite, &bad, pol) ||
      !detail::check(function, "velocity[1]", s[1], detail::argument_rule::finite, &bad, pol) ||
      !detail::check(function, "spin", s[2], detail::argument_rule::finite, &bad, pol) ||
      !detail::check(function, "contact.normal", n, detail::argument_rule::finite_non_negative,
                     &bad, pol) ||
      !detail::check(function, "contact.friction", mu, detail::argument_rule::finite_non_negative,
                     &bad, pol) ||
      !detail::check_start(function, start, bad, pol))
    return detail::patch_result<Vec2, Real, impulse_quantity>(Vec2{bad, bad}, bad, false,
                                                              {{bad, bad}, bad}, bad);
  const Real load = mu * n;
  const bool still = s[0] == 0 && s[1] == 0 && s[2] == 0;
  const Real length = detail::patch_length(patch);
  if (still || !(load > 0))
    return detail::patch_result<Vec2, Real, impulse_quantity>(
        Vec2{Real(0), Real(0)}, Real(0), still,
        still ? planar_twist<Real>{{Real(0), Real(0)}, Real(0)}
              : planar_twist<Real>{{s[0], s[1]}, s[2]},
        length);
  // In the limit set's units: ẑ, the metric SWS and its inverse S⁻¹W⁻¹S⁻¹.
  const Real scale[3] = {1, 1, length};
  const auto& w = inverse_mass.entries();
  const auto& winv = inverse_mass.inverse();
  detail::matrix3<Real> m{}, inverse{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      m[i][j] = w[i][j] * scale[i] * scale[j];
      inverse[i][j] = winv[i][j] / scale[i] / scale[j];
    }
  const detail::vector3<Real> z = detail::scaled_stop(s, winv, load, length);
  const detail::patch_projection<Real> r = detail::project_patch(patch, z, m, inverse, start);
  if (r.sticking) {
    const detail::vector3<Real> stop = detail::multiply(winv, s);
    return detail::patch_result<Vec2, Real, impulse_quantity>(
        Vec2{-stop[0], -stop[1]}, -stop[2], true, {{Real(0), Real(0)}, Real(0)}, length);
  }
  // The velocity after, from the slip s = −S v⁺/(μΛ) (in the metric SWS), not
  // as v + WP, which cancels where the contact nearly sticks: its friction
  // wrench is the impulse's direction to the projection's own rounding.
  const planar_twist<Real> after = detail::twist_of(r.slip, length);
  return detail::patch_result<Vec2, Real, impulse_quantity>(
      Vec2{load * r.point[0], load * r.point[1]}, load * length * r.point[2], false,
      {{load * after.velocity[0], load * after.velocity[1]}, load * after.omega}, length);
}

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_PATCH_IMPULSE_HPP
