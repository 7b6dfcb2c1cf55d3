//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file trial_cap.hpp
/// The trial-state cap of a discrete-element (DEM) contact: its springs'
/// trial friction, with damping, capped together on the coupled limit set
/// (docs/contact.md, "The spring-history law"; docs/theory.md §11).
///
/// A DEM contact carries a tangential spring ξ and a twisting spring φ,
/// stretched each step by the step's relative motion; with the damping the
/// trial friction is F = −k_t ξ + F_d and T = −k_θ φ + T_d.  If (F, T) lies
/// in μN·L it is kept (stick) and so are the springs.  Otherwise it is
/// replaced by the nearest point of μN·L in the springs' energy metric
/// |ΔF|²/k_t + |ΔT|²/k_θ (slip), and the springs are rewritten so that with
/// the damping they give it: ξ = −(F − F_d)/k_t, φ = −(T − T_d)/k_θ.  The
/// metric is isotropic in the tangent plane, so the cap keeps the trial
/// force's direction and the torque's sign: it projects the magnitudes
/// (project_to_limit_set) with the torque weighted by a²k_t/k_θ.
///
/// cap_trial_state is that cap for any DEM code: spring_history_friction
/// (spring_friction.hpp) and the LAMMPS plugin (engines/lammps) both call it.

#ifndef SPINSLIDE_CONTACT_TRIAL_CAP_HPP
#define SPINSLIDE_CONTACT_TRIAL_CAP_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/base/detail/product.hpp>
#include <spinslide/base/detail/vector_access.hpp>
#include <spinslide/base/friction_result.hpp>
#include <spinslide/contact/contact_inputs.hpp>
#include <spinslide/contact/detail/matrix3.hpp>
#include <spinslide/contact/detail/vector3.hpp>
#include <spinslide/contact/limit_set.hpp>

#include <boost/config.hpp>
#include <boost/math/special_functions/fpclassify.hpp>

#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>

namespace spinslide {

/// A DEM contact's springs after the step's increments, and the damping's
/// share of its trial friction.  `Vec` holds the tangent plane's vectors: a
/// 2-component vector class in the plane's axes, or a 3-component one in the
/// world's axes (tangential; a small normal part is capped with the rest):
/// 3 components where std::tuple_size says so (std::array<Real, 3>) or the
/// class has members x, y and z, else 2.
template <class Vec, class Real>
struct spring_trial {
  using value_type = Real;  ///< the floating type
  Vec displacement;         ///< ξ, the tangential spring (its force is −k_t ξ)
  Real twist;               ///< φ, the twisting spring (its torque is −k_θ φ)
  Vec damping_force;        ///< F_d, added to −k_t ξ in the trial force (zero: no damping)
  Real damping_torque;      ///< T_d, added to −k_θ φ in the trial torque
};

/// The capped friction of a DEM contact (a friction_result: force, torque,
/// sticking, ratio, curve()), and the springs the contact keeps.
template <class Vec, class Real>
struct capped_friction : friction_result<Vec, Real> {
  Vec displacement;  ///< the tangential spring to keep: −(F − F_d)/k_t (ξ if sticking)
  Real twist;        ///< the twisting spring to keep: −(T − T_d)/k_θ (φ if sticking)
};

namespace detail {

// A trial state's numbers (checked, in cap_trial_state): ξ and F_d with a
// z of 0 in 2-D.
template <class Real>
struct checked_trial {
  vector3<Real> spring;   // ξ
  vector3<Real> damping;  // F_d
  Real twist;             // φ
  Real damping_torque;    // T_d
};

// The first non-finite of `values`, reported through the policy under its
// name (by default a domain error; else NaN); 0 if all are finite.  The
// laws test finiteness in one expression and call this only when it fails.
template <class Real, class Policy>
Real report_not_finite(const char* function, std::initializer_list<const char*> names,
                       std::initializer_list<Real> values, const Policy& pol) {
  auto name = names.begin();
  for (const Real& v : values) {
    if (!(boost::math::isfinite)(v)) return checked(function, *name, v, argument_rule::finite, pol);
    ++name;
  }
  return 0;
}

// The trial friction of a trial state's numbers: −k_t ξ + F_d (N
// components, the rest 0), −k_θ φ + T_d and |F|.  The cap and
// surely_sticks share it, so that they decide sticking on the same numbers.
template <class Real>
struct trial_friction {
  vector3<Real> force;
  Real torque;
  Real magnitude;  // |force|
};
template <int N, class Real>
BOOST_FORCEINLINE trial_friction<Real> trial_friction_of(const checked_trial<Real>& in,
                                                         const spring_stiffness<Real>& springs) {
  const Real kt = springs.tangential.value, kw = springs.twisting.value;
  trial_friction<Real> out{{}, -kw * in.twist + in.damping_torque, Real(0)};
  for (std::size_t i = 0; i < std::size_t(N); ++i)
    out.force[i] = -kt * in.spring[i] + in.damping[i];
  out.magnitude = vector_norm(out.force[0], out.force[1], out.force[2]);
  return out;
}

// Whether the trial friction `f` lies in the inner triangle |F|/(μN) +
// |T|/(μNa⟨r⟩) ≤ 1 (`top` = ⟨r⟩), by the cap's own arithmetic (cap_checked,
// limit_projector): false, deciding nothing, for any springs or contact
// that cap_trial_state refuses, and for a trial that is not finite (its
// magnitudes then are not, or NaN: the comparisons fail).
template <class Real>
BOOST_FORCEINLINE bool trial_in_triangle(const trial_friction<Real>& f,
                                         const spring_stiffness<Real>& springs,
                                         const force_contact<Real>& contact, Real top) {
  using std::fabs;
  const Real kt = springs.tangential.value, kw = springs.twisting.value;
  const Real a = contact.radius.value, normal = contact.normal.value;
  const Real load = contact.friction.value * normal;
  const Real x = f.magnitude / load, y = fabs(f.torque) / a / load;
  const Real weight = a * a * kt / kw;  // cap_trial_state's torque weight, > 0 and finite
  return kt > 0 && kw > 0 && a > 0 && normal >= 0 && load > 0 && weight > 0 &&
         all_finite(x, y, load, weight) && in_sticking_triangle(x, y, top);
}

// The cap on checked inputs (cap_trial_state, spring_history_friction),
// their trial friction `friction` given (trial_friction_of): the
// stiffnesses finite and > 0, `patch` checked, `start` a curve point (ratio
// 0: none).  What could overflow on the way (the trial, the torque weight,
// the rewritten springs) is checked here.  `Vec` has N = 2 or 3 components.
template <int N, class Vec, class Profile>
BOOST_FORCEINLINE capped_friction<Vec, typename Profile::value_type> cap_checked(
    const Profile& profile, const checked_trial<typename Profile::value_type>& in,
    const trial_friction<typename Profile::value_type>& friction,
    const spring_stiffness<typename Profile::value_type>& springs,
    const patch_values<typename Profile::value_type>& patch,
    const curve_point<typename Profile::value_type>& start, const char* function) {
  using Real = typename Profile::value_type;
  using boost::math::isfinite;
  using std::fabs;
  const typename Profile::policy_type pol;
  const Real kt = springs.tangential.value, kw = springs.twisting.value;
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  capped_friction<Vec, Real> out{{Vec{}, Real(0), false, nan, start}, Vec{}, Real(0)};
  auto reported = [&out](Real bad) {
    for (Vec* v : {&out.force, &out.displacement}) write<N>(*v, vector3<Real>{bad, bad, bad});
    out.torque = out.twist = out.ratio = bad;
    return out;
  };
  // The trial friction (trial_friction_of(in, springs), the caller's), which
  // must not overflow (|F| finite: each component is).
  trial_friction<Real> trial = friction;
  vector3<Real>& force = trial.force;
  const Real t = trial.torque, f = trial.magnitude;
  if (!((isfinite)(f) && (isfinite)(t)))
    return reported(report_not_finite(
        function, {"the trial force -k_t xi + damping", "the trial torque -k_w phi + damping"},
        {f, t}, pol));
  const Real a = patch.radius, load = patch.friction * patch.normal;
  // The magnitudes in the limit set's units.  Where they overflow, the load
  // is below 2^-1024 of the trial: the exact cap is as far below it, zero
  // to the trial's precision, and is taken as zero (a contact coming apart).
  const Real x = f / load, y = fabs(t) / a / load;
  friction_result<Real, Real> cap{0, 0, f == 0 && t == 0, nan};
  if (load > 0 && (isfinite)(x) && (isfinite)(y)) {
    Real weight = a * a * kt / kw;
    if (!(weight > 0 && (isfinite)(weight))) {  // a² alone out of range, or the whole
      weight = checked(function, "the torque weight a^2 k_t/k_w", Real(product(a, a, kt) / kw),
                       argument_rule::finite_positive, pol);
      if (any_reported(weight)) return reported(weight);
    }
    const bool from_point = start.ratio > 0 && (isfinite)(start.force);
    cap = limit_projector<Profile>(profile, {x, y}, weight)(start.ratio,
                                                            from_point ? &start : nullptr);
  }
  out.sticking = cap.sticking;
  out.ratio = cap.ratio;
  if (cap.sticking) {
    out.torque = t;
    out.twist = in.twist;
    write<N>(out.force, force);
    write<N>(out.displacement, in.spring);
    return out;
  }
  if (!(boost::math::isnan)(cap.ratio)) out.point = cap.curve();
  // The force's direction and the torque's sign are kept; the springs
  // rewritten to hold the result with the damping (a spring too soft for
  // the capped force, F/k beyond the largest value, is a domain error).
  const Real scale = f > 0 ? Real(cap.force * load / f) : Real(0);
  vector3<Real> spring{};
  for (std::size_t i = 0; i < std::size_t(N); ++i) {
    force[i] *= scale;
    spring[i] = -(force[i] - in.damping[i]) / kt;
  }
  out.torque = std::copysign(product(load, a, cap.torque), t);
  out.twist = -(out.torque - in.damping_torque) / kw;
  if (!((isfinite)(spring[0]) && (isfinite)(spring[1]) && (isfinite)(spring[2]) &&
        (isfinite)(out.twist)))
    return reported(report_not_finite(
        function,
        {"a rewritten spring -(F - damping)/k_t", "a rewritten spring -(F - damping)/k_t",
         "a rewritten spring -(F - damping)/k_t", "the rewritten spring -(T - damping)/k_w"},
        {spring[0], spring[1], spring[2], out.twist}, pol));
  write<N>(out.force, force);
  write<N>(out.displacement, spring);
  return out;
}

// cap_trial_state where its one test of good arguments failed: the checks
// one by one report the first bad argument; where every one is good (a
// trial that overflowed), the cap reports that.  Out of line: never on a
// good contact's path.
template <int N, class Vec, class Profile>
BOOST_NOINLINE capped_friction<Vec, typename Profile::value_type> trial_cap_errors(
    const Profile& profile, const checked_trial<typename Profile::value_type>& in,
    const trial_friction<typename Profile::value_type>& friction,
    const spring_stiffness<typename Profile::value_type>& springs,
    const force_contact<typename Profile::value_type>& contact,
    const curve_point<typename Profile::value_type>& start, const char* function) {
  using Real = typename Profile::value_type;
  const typename Profile::policy_type pol;
  const Real kt = springs.tangential.value, kw = springs.twisting.value;
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  bool bad = false;
  auto check = [&](const char* name, Real x, argument_rule rule) {
    bad = any_reported(checked(function, name, x, rule, pol)) || bad;
  };
  for (const Real x : in.spring) check("trial.displacement", x, argument_rule::finite);
  for (const Real x : in.damping) check("trial.damping_force", x, argument_rule::finite);
  check("trial.twist", in.twist, argument_rule::finite);
  check("trial.damping_torque", in.damping_torque, argument_rule::finite);
  check("springs.tangential", kt, argument_rule::finite_positive);
  check("springs.twisting", kw, argument_rule::finite_positive);
  const patch_values<Real> patch = checked_patch(function, contact, pol);
  bad = any_reported(patch.radius, patch.normal, patch.friction) || bad;
  check("start.ratio", start.ratio, argument_rule::non_negative);
  if (bad) {
    capped_friction<Vec, Real> out{{Vec{}, nan, false, nan, start}, Vec{}, nan};
    for (Vec* v : {&out.force, &out.displacement}) write<N>(*v, vector3<Real>{nan, nan, nan});
    return out;
  }
  return cap_checked<N, Vec>(profile, in, friction, springs, patch, start, function);
}

}  // namespace detail

/// Whether a DEM contact's trial surely sticks: its trial force −k_t ξ + F_d
/// and torque −k_θ φ + T_d lie in the inner triangle |F|/(μN) + |T|/(μNa⟨r⟩)
/// ≤ 1, which every profile's limit set contains.  There cap_trial_state
/// decides the same by the same arithmetic, first, and keeps the trial: the
/// friction is the trial force and torque, and the springs stay as they
/// are.  A DEM loop whose contacts mostly stick (a pile, most of a pour)
/// can test this first and skip the call.  False, deciding nothing,
/// outside the triangle and for any trial, springs or contact that
/// cap_trial_state refuses (nothing is reported here: call it to hear
/// why).
/// `profile` is any profile or a contact_profile (its ⟨r⟩ only is read).
template <class Profile, class Vec>
bool surely_sticks(const Profile& profile,
                   const spring_trial<Vec, typename Profile::value_type>& trial,
                   const spring_stiffness<typename Profile::value_type>& springs,
                   const force_contact<typename Profile::value_type>& contact) {
  using Real = typename Profile::value_type;
  constexpr int n = detail::components<Vec>();
  static_assert(detail::is_vector<Vec, 2>() && (n == 2 || n == 3),
                "spinslide::surely_sticks: the spring and the damping force must be 2- or "
                "3-component vector classes (operator[] or members x, y[, z])");
  const detail::checked_trial<Real> in{detail::read<n, Real>(trial.displacement),
                                       detail::read<n, Real>(trial.damping_force), trial.twist,
                                       trial.damping_torque};
  return detail::trial_in_triangle(detail::trial_friction_of<n>(in, springs), springs, contact,
                                   profile.mean_radius());
}

/// The trial state `trial` of a DEM contact capped on `profile`'s limit set
/// (see the file's comment), searching from `start`, the contact's last
/// slip's curve_point (the last result's curve(); a point with ratio 0, as
/// `{}`, starts without one).  Every component finite, the stiffnesses and
/// a > 0, N and μ ≥ 0, start.ratio ≥ 0, all of the profile's value_type;
/// otherwise a domain error: these are the only errors, and none comes from
/// the search.  No allocation; when it slips, a few evaluations of the
/// profile (one fewer from a start).
template <class Profile, class Vec>
capped_friction<Vec, typename Profile::value_type> cap_trial_state(
    const Profile& profile, const spring_trial<Vec, typename Profile::value_type>& trial,
    const spring_stiffness<typename Profile::value_type>& springs,
    const force_contact<typename Profile::value_type>& contact,
    const curve_point<typename Profile::value_type>& start = {}) {
  using Real = typename Profile::value_type;
  detail::require_projectable<Profile, Real>();
  constexpr int n = detail::components<Vec>();
  static_assert(detail::is_vector<Vec, 2>() && (n == 2 || n == 3),
                "spinslide::cap_trial_state: the spring and the damping force must be 2- or "
                "3-component vector classes (operator[] or members x, y[, z]), not pointers or "
                "C arrays");
  static const char* function =
      "spinslide::cap_trial_state<%1%>(profile, trial, springs, contact, start)";
  detail::checked_trial<Real> in{detail::read<n, Real>(trial.displacement),
                                 detail::read<n, Real>(trial.damping_force), trial.twist,
                                 trial.damping_torque};
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  // First the trial in the inner triangle, as surely_sticks decides it (on
  // good arguments only; a bad one fails it): the trial is kept.
  const detail::trial_friction<Real> friction = detail::trial_friction_of<n>(in, springs);
  if (start.ratio >= 0 &&
      detail::trial_in_triangle(friction, springs, contact, profile.mean_radius())) {
    capped_friction<Vec, Real> out{{Vec{}, friction.torque, true, nan, start}, Vec{}, in.twist};
    detail::write<n>(out.force, friction.force);
    detail::write<n>(out.displacement, in.spring);
    return out;
  }
  const Real kt = springs.tangential.value, kw = springs.twisting.value;
  const Real a = contact.radius.value, normal = contact.normal.value;
  const Real mu = contact.friction.value;
  // One test for good arguments, on the trial's magnitudes (finite exactly
  // when every component of the trial is, for finite stiffnesses, unless
  // the trial overflowed) and the scalars; where it fails, the checks one
  // by one report the first bad one (trial_cap_errors).
  if (!(detail::all_finite(friction.magnitude, friction.torque, kt, kw, a, normal, mu) && kt > 0 &&
        kw > 0 && a > 0 && normal >= 0 && mu >= 0 && start.ratio >= 0))
    return detail::trial_cap_errors<n, Vec>(profile, in, friction, springs, contact, start,
                                            function);
  const spring_stiffness<Real> k{tangential_stiffness<Real>{kt}, twisting_stiffness<Real>{kw}};
  const detail::patch_values<Real> patch{a, normal, mu};
  return detail::cap_checked<n, Vec>(profile, in, friction, k, patch, start, function);
}

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_TRIAL_CAP_HPP
