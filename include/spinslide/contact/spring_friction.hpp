//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file spring_friction.hpp
/// Spring-history friction for discrete-element (DEM) contacts: a
/// tangential spring and a twisting spring, capped together on the coupled
/// limit set (docs/contact.md, "The spring-history law"; docs/theory.md §11).
///
/// Each step the springs take the step's tangential displacement and twist
/// increments; their trial force F = −k_t ξ and torque T = −k_θ φ are kept if
/// they lie in μN·L (stick), and otherwise replaced by the nearest point of
/// μN·L in the springs' energy metric |ΔF|²/k_t + |ΔT|²/k_θ, with the springs
/// rewritten to match (slip).  Under steady slip (constant increments) this
/// gives exactly the Contensou law, F = −μN𝓕(ε)v̂ and T = −μNa𝓣(ε) sign ω with
/// ε = |v|/(a|ω|): the increment is then the metric's normal at the capped
/// point, which is the curve's normal (ε, 1) at the ratio of the slip
/// (tests/test_spring_friction.cpp).

#ifndef SPINSLIDE_CONTACT_SPRING_FRICTION_HPP
#define SPINSLIDE_CONTACT_SPRING_FRICTION_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/base/detail/product.hpp>
#include <spinslide/base/detail/vector_access.hpp>
#include <spinslide/contact/contact_inputs.hpp>
#include <spinslide/contact/limit_set.hpp>
#include <spinslide/contact/trial_cap.hpp>

#include <cmath>
#include <limits>

namespace spinslide {

/// What a spring-history contact keeps from step to step.
template <class Vec2, class Real>
struct spring_history {
  using value_type = Real;  ///< the floating type
  Vec2 displacement;        ///< the tangential spring's stretch ξ (the force is −k_t ξ)
  Real twist;               ///< the twisting spring's angle φ (the torque is −k_θ φ)
  /// Where the last slip left the limit curve (its ratio ε, 0: none yet):
  /// the next search takes its first step from there, without evaluating
  /// the profile where the point has its values (a slip writes them), from
  /// the ratio alone where it has only that (`curve_point<Real>{ε}`).
  curve_point<Real> curve{};
};

/// The springs of a Hertz–Mindlin contact of radius a: the tangential
/// stiffness k_t (Mindlin: 8G*a for the effective shear modulus G*), and
/// Marshall's twisting stiffness k_t a²/2 (as LAMMPS' `twisting marshall`).
/// In the limit set's units their energy metric weighs the torque by
/// a²k_t/k_θ = 2.
template <class Real>
spring_stiffness<Real> mindlin_springs(tangential_stiffness<Real> kt, patch_radius<Real> a) {
  return {kt, twisting_stiffness<Real>{kt.value * a.value * a.value / 2}};
}

/// One step of a spring-history contact (see the file's comment):
/// `history` is updated in place; `displacement_increment` (a 2-component
/// vector class in the tangent plane's axes) and `twist_increment` are the
/// step's relative tangential displacement and rotation about the normal.
/// Every input finite, the stiffnesses and a > 0, N and μ ≥ 0, all of the
/// profile's value_type; otherwise a domain error (and the history is left
/// as it was).  No allocation; when it slips, a few evaluations of the
/// profile (fewer from the history's curve point, and one fewer again where
/// the point has its values).  The result's curve() is the history's new
/// point.
template <class Profile, class Vec2>
friction_result<Vec2, typename Profile::value_type> spring_history_friction(
    const Profile& profile, spring_history<Vec2, typename Profile::value_type>& history,
    const Vec2& displacement_increment, typename Profile::value_type twist_increment,
    const spring_stiffness<typename Profile::value_type>& springs,
    const force_contact<typename Profile::value_type>& contact) {
  using Real = typename Profile::value_type;
  detail::require_projectable<Profile, Real>();
  static_assert(detail::is_vector<Vec2, 2>(),
                "spinslide::spring_history_friction: the displacement must be a 2-component "
                "vector class (operator[] or members x, y), not a pointer or a C array");
  static const char* function =
      "spinslide::spring_history_friction<%1%>(profile, history, increment, %1%, springs, "
      "contact)";
  using detail::argument_rule;
  using detail::checked;
  const typename Profile::policy_type pol;
  // The springs after the increments: each increment, and each sum, finite.
  auto stretched = [&](const char* name, Real held, Real increment) {
    return checked(
        function, name,
        Real(held + checked(function, "an increment", increment, argument_rule::finite, pol)),
        argument_rule::finite, pol);
  };
  const Real x = stretched("history.displacement[0] + increment[0]",
                           static_cast<Real>(detail::get<0>(history.displacement)),
                           static_cast<Real>(detail::get<0>(displacement_increment)));
  const Real y = stretched("history.displacement[1] + increment[1]",
                           static_cast<Real>(detail::get<1>(history.displacement)),
                           static_cast<Real>(detail::get<1>(displacement_increment)));
  const Real phi = stretched("history.twist + twist_increment", history.twist, twist_increment);
  const Real kt = checked(function, "springs.tangential", springs.tangential.value,
                          argument_rule::finite_positive, pol);
  const Real kw = checked(function, "springs.twisting", springs.twisting.value,
                          argument_rule::finite_positive, pol);
  const auto patch = detail::checked_patch(function, contact, pol);
  const Real start = checked(function, "history.curve.ratio", history.curve.ratio,
                             argument_rule::non_negative, pol);
  friction_result<Vec2, Real> out{Vec2{}, Real(0), false, std::numeric_limits<Real>::quiet_NaN(),
                                  history.curve};
  // Every output NaN (and the history as it was) where a check reported an
  // error through a policy that does not throw.
  auto reported = [&out](Real bad) {
    detail::set<0>(out.force, bad);
    detail::set<1>(out.force, bad);
    out.torque = out.ratio = bad;
    return out;
  };
  if (detail::any_reported(x, y, phi, kt, kw, patch.radius, patch.normal, patch.friction, start))
    return reported(out.ratio);
  const detail::checked_trial<Real> trial{{x, y, Real(0)}, {}, phi, Real(0)};
  const spring_stiffness<Real> k{tangential_stiffness<Real>{kt}, twisting_stiffness<Real>{kw}};
  const capped_friction<Vec2, Real> cap = detail::cap_checked<2, Vec2>(
      profile, trial, detail::trial_friction_of<2>(trial, k), k, patch, history.curve, function);
  if ((boost::math::isnan)(cap.twist)) return reported(cap.twist);
  out = {cap.force, cap.torque, cap.sticking, cap.ratio, cap.point};
  history.displacement = cap.displacement;
  history.twist = cap.twist;
  if (!cap.sticking && !(boost::math::isnan)(cap.ratio)) history.curve = cap.point;
  return out;
}

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_SPRING_FRICTION_HPP
