//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file patch_trial_cap.hpp
/// The trial-state cap of a DEM contact on a flat patch's limit set
/// (trial_cap.hpp for round profiles; docs/patches.md, "The limit set and
/// its projection").  The springs' trial friction F = −k_t ξ + F_d, T = −k_θ φ
/// + T_d (in the patch's axes, the torque about its origin) is kept where it
/// lies in μN·L, L the patch's limit set, and is otherwise replaced by the
/// nearest point of μN·L in the springs' energy metric |ΔF|²/k_t + |ΔT|²/k_θ,
/// the springs rewritten to give it with the damping.  A patch's set is not
/// round, so the cap does not keep the force's direction: it is the 3-D
/// projection (patch_limit_set.hpp) in the metric diag(1, 1, ℓ²k_t/k_θ) of
/// the limit set's units.

#ifndef SPINSLIDE_CONTACT_PATCH_TRIAL_CAP_HPP
#define SPINSLIDE_CONTACT_PATCH_TRIAL_CAP_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/base/detail/vector_access.hpp>
#include <spinslide/contact/contact_inputs.hpp>
#include <spinslide/contact/patch_limit_set.hpp>
#include <spinslide/contact/patch_result.hpp>
#include <spinslide/contact/trial_cap.hpp>

#include <boost/math/policies/policy.hpp>

#include <array>
#include <cmath>

namespace spinslide {

/// A patch's capped friction (a patch_friction_result: force, torque,
/// sticking, ratio, slip), and the springs the contact keeps.
template <class Vec, class Real>
struct capped_patch_friction : patch_friction_result<Vec, Real> {
  Vec displacement;  ///< the tangential spring to keep: −(F − F_d)/k_t (ξ if sticking)
  Real twist;        ///< the twisting spring to keep: −(T − T_d)/k_θ (φ if sticking)
};

/// The trial state `trial` of a DEM contact (2-component vectors in the
/// patch's axes) capped on `patch`'s limit set under the load μN (see the
/// file's comment), searching from `start`, the contact's last slip (the
/// last result's `slip`; zero: none).  Every component finite, the
/// stiffnesses > 0, N and μ ≥ 0; otherwise a domain error through `pol`
/// (NaN components unless it throws).  Nothing else fails; no allocation.
template <class Vec, class Real, class Policy = boost::math::policies::policy<>>
capped_patch_friction<Vec, Real> cap_trial_state(
    const polygon_patch<Real>& patch, const spring_trial<Vec, Real>& trial,
    const spring_stiffness<Real>& springs, const patch_force_contact<Real>& contact,
    const planar_twist<Real>& start = planar_twist<Real>{{Real(0), Real(0)}, Real(0)},
    const Policy& pol = Policy()) {
  static_assert(detail::is_vector<Vec, 2>() && detail::components<Vec>() == 2,
                "spinslide::cap_trial_state(polygon_patch, ...): the spring and the damping force "
                "must be 2-component vector classes in the patch's axes");
  static const char* function =
      "spinslide::cap_trial_state<%1%>(polygon_patch, trial, springs, patch_force_contact)";
  using detail::argument_rule;
  const Real kt = springs.tangential.value, kw = springs.twisting.value;
  const Real n = contact.normal.value, mu = contact.friction.value;
  const Real xi[2] = {Real(detail::get<0>(trial.displacement)),
                      Real(detail::get<1>(trial.displacement))};
  const Real fd[2] = {Real(detail::get<0>(trial.damping_force)),
                      Real(detail::get<1>(trial.damping_force))};
  Real bad = 0;
  capped_patch_friction<Vec, Real> out{};
  const auto reported = [&] {
    out.force = Vec{bad, bad};
    out.displacement = Vec{bad, bad};
    out.torque = out.twist = out.ratio = bad;
    out.slip = {{bad, bad}, bad};
    return out;
  };
  if (!detail::check(function, "trial.displacement", xi[0], argument_rule::finite, &bad, pol) ||
      !detail::check(function, "trial.displacement", xi[1], argument_rule::finite, &bad, pol) ||
      !detail::check(function, "trial.damping_force", fd[0], argument_rule::finite, &bad, pol) ||
      !detail::check(function, "trial.damping_force", fd[1], argument_rule::finite, &bad, pol) ||
      !detail::check(function, "trial.twist", trial.twist, argument_rule::finite, &bad, pol) ||
      !detail::check(function, "trial.damping_torque", trial.damping_torque, argument_rule::finite,
                     &bad, pol) ||
      !detail::check(function, "springs.tangential", kt, argument_rule::finite_positive, &bad,
                     pol) ||
      !detail::check(function, "springs.twisting", kw, argument_rule::finite_positive, &bad, pol) ||
      !detail::check(function, "contact.normal", n, argument_rule::finite_non_negative, &bad,
                     pol) ||
      !detail::check(function, "contact.friction", mu, argument_rule::finite_non_negative, &bad,
                     pol) ||
      !detail::check_start(function, start, bad, pol))
    return reported();
  const Real f[3] = {-kt * xi[0] + fd[0], -kt * xi[1] + fd[1],
                     -kw * trial.twist + trial.damping_torque};
  const Real length = detail::patch_length(patch), load = mu * n;
  const auto keep = [&] {
    out.force = Vec{f[0], f[1]};
    out.torque = f[2];
    out.displacement = trial.displacement;
    out.twist = trial.twist;
    return out;
  };
  if (f[0] == 0 && f[1] == 0 && f[2] == 0) {
    out.sticking = true;
    return keep();
  }
  // In the limit set's units the trial, and the metric diag(1, 1, ℓ²k_t/k_θ).
  const Real weight = length * length * kt / kw;
  const detail::vector3<Real> z{f[0] / load, f[1] / load, f[2] / (length * load)};
  if (!(load > 0) || !detail::all_finite(z[0], z[1], z[2], weight) || !(weight > 0)) {
    // No load (or one below the trial's precision): nothing is held.
    static_cast<patch_friction_result<Vec, Real>&>(out) =
        detail::patch_result<Vec, Real, force_quantity>(Vec{Real(0), Real(0)}, Real(0), false,
                                                        {{-f[0], -f[1]}, -f[2] / length}, length);
    out.displacement = Vec{fd[0] / kt, fd[1] / kt};
    out.twist = trial.damping_torque / kw;
    return out;
  }
  const detail::matrix3<Real> m{{{1, 0, 0}, {0, 1, 0}, {0, 0, weight}}};
  const detail::matrix3<Real> inverse{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1 / weight}}};
  const detail::patch_projection<Real> r = detail::project_patch(patch, z, m, inverse, start);
  if (r.sticking) {
    out.sticking = true;
    return keep();
  }
  const Real force[3] = {load * r.point[0], load * r.point[1], load * length * r.point[2]};
  static_cast<patch_friction_result<Vec, Real>&>(out) =
      detail::patch_result<Vec, Real, force_quantity>(Vec{force[0], force[1]}, force[2], false,
                                                      detail::twist_of(r.slip, length), length);
  out.displacement = Vec{-(force[0] - fd[0]) / kt, -(force[1] - fd[1]) / kt};
  out.twist = -(force[2] - trial.damping_torque) / kw;
  return out;
}

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_PATCH_TRIAL_CAP_HPP
