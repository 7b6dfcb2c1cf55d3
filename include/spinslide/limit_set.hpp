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

#ifndef SPINSLIDE_LIMIT_SET_HPP
#define SPINSLIDE_LIMIT_SET_HPP

#include <spinslide/approximations.hpp>
#include <spinslide/detail/checks.hpp>
#include <spinslide/detail/limit_projector.hpp>
#include <spinslide/profile_concept.hpp>

#include <limits>
#include <type_traits>

namespace spinslide {

/// A ratio ε to start the projection's search from, typically the last
/// step's (from the contact's history).  Its own type, so that it cannot be
/// passed where a force, a torque or a weight is meant.
template <class Real>
struct starting_ratio {
  Real value;  ///< ε ≥ 0 (0 or +∞: no guess)
};

namespace detail {

template <class P>
struct is_pade_approximation : std::false_type {};
template <class Real, class Policy>
struct is_pade_approximation<pade_approximation<Real, Policy>> : std::true_type {};

template <class Profile, class Real>
limit_projection<Real> project_checked(const Profile& profile, Real force, Real torque,
                                       Real torque_weight, Real start, const char* function) {
  static_assert(requires_profile<Profile>());
  static_assert(std::is_same<Real, typename Profile::value_type>::value,
                "project_to_limit_set: force, torque and torque_weight must have the profile's "
                "value_type");
  static_assert(!is_pade_approximation<Profile>::value,
                "project_to_limit_set: the Pade approximants do not obey T' = -eps F' (no pressure "
                "gives them), so the curve's normal is not (eps, 1) and the projection does not "
                "apply");
  using Policy = typename Profile::policy_type;
  const Policy pol;
  const Real f = checked(function, "force", force, argument_rule::finite_non_negative, pol);
  const Real t = checked(function, "torque", torque, argument_rule::finite_non_negative, pol);
  const Real w =
      checked(function, "torque_weight", torque_weight, argument_rule::finite_positive, pol);
  const Real s = checked(function, "starting_ratio", start, argument_rule::non_negative, pol);
  if (any_reported(f, t, w, s)) {
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    return {nan, nan, false, nan};
  }
  return limit_projector<Profile>(profile, f, t, w)(s, function);
}

}  // namespace detail

/// The point of `profile`'s limit set L nearest to (force, torque) in
/// (f − force)² + torque_weight·(t − torque)², with f = |F|/(μN) and
/// t = |T|/(μNa).  Inside L (the boundary included): `sticking`, (force,
/// torque) unchanged, `ratio` NaN.  Outside: on the curve at `ratio` ε
/// (+∞ at (1, 0), 0 at (0, ⟨r⟩)), where the displacement is normal to the
/// curve in this metric: force − 𝓕 = torque_weight·ε·(torque − 𝓣).
/// force and torque finite and ≥ 0, torque_weight finite and > 0, all of the
/// profile's value_type; otherwise a domain error (by default
/// std::domain_error).  No allocation; a few evaluations of the profile.
/// The profile must obey 𝓣′ = −ε𝓕′, as every pressure distribution does
/// (docs/theory.md §1), and so do the elliptic limit surface and the
/// uncoupled caps; the Padé approximants do not, and do not compile here.
template <class Profile, class Real>
limit_projection<Real> project_to_limit_set(const Profile& profile, Real force, Real torque,
                                            Real torque_weight) {
  return detail::project_checked(profile, force, torque, torque_weight, Real(0),
                                 "spinslide::project_to_limit_set<%1%>(profile, %1%, %1%, %1%)");
}

/// As above, searching from `start` (the last step's ratio, say): where the
/// ratio moved little, one or two evaluations of the profile.  The result
/// does not depend on `start` (to rounding).  start.value ≥ 0, else a
/// domain error.
template <class Profile, class Real>
limit_projection<Real> project_to_limit_set(const Profile& profile, Real force, Real torque,
                                            Real torque_weight, starting_ratio<Real> start) {
  return detail::project_checked(
      profile, force, torque, torque_weight, start.value,
      "spinslide::project_to_limit_set<%1%>(profile, %1%, %1%, %1%, starting_ratio)");
}

}  // namespace spinslide

#endif  // SPINSLIDE_LIMIT_SET_HPP
