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
#include <spinslide/contact/detail/sticking_triangle.hpp>
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

// The trial friction `f` in the limit set's units, x = |F|/(μN) and y =
// |T|/(μNa), with the load μN and the torque weight a²k_t/k_θ, and whether
// every one of them and of the springs and the contact is in range (k_t,
// k_θ, a, μN and the weight > 0, N ≥ 0, x, y, μN and the weight finite).
// Where that holds, every argument but the start is good (each is finite:
// a non-finite k_t, k_θ, a, N or μ makes the weight or the load ∞, 0 or
// NaN, a non-finite trial x or y), and nothing the cap computes before the
// projection can leave the range: cap_trial_state goes straight to it.
// Otherwise (an argument that cap_trial_state refuses, a trial that is not
// finite, a load of 0, a quotient that overflows) the flag is false,
// deciding nothing.
template <class Real>
struct scaled_trial {
  Real x, y;    // |F|/(μN), |T|/(μNa)
  Real load;    // μN
  Real weight;  // a²k_t/k_θ, cap_trial_state's torque weight
  bool in_range;
};
template <class Real>
BOOST_FORCEINLINE scaled_trial<Real> scaled_trial_of(const trial_friction<Real>& f,
                                                     const spring_stiffness<Real>& springs,
                                                     const force_contact<Real>& contact) {
  using std::fabs;
  const Real kt = springs.tangential.value, kw = springs.twisting.value;
  const Real a = contact.radius.value, normal = contact.normal.value;
  const Real load = contact.friction.value * normal;
  const Real x = f.magnitude / load, y = fabs(f.torque) / a / load;
  const Real weight = a * a * kt / kw;
  return {x, y, load, weight,
          kt > 0 && kw > 0 && a > 0 && normal >= 0 && load > 0 && weight > 0 &&
              all_finite(x, y, load, weight)};
}

// Whether the trial friction lies in the inner triangle |F|/(μN) +
// |T|/(μNa⟨r⟩) ≤ 1 (`top` = ⟨r⟩), by the cap's own arithmetic
// (limit_projector): false, deciding nothing, where scaled_trial_of's flag
// is (a trial that is not finite fails it).
template <class Real>
BOOST_FORCEINLINE bool trial_in_triangle(const scaled_trial<Real>& s, Real top) {
  return s.in_range && in_sticking_triangle(s.x, s.y, top);
}

// Every output `bad` (NaN: a reported error), the start kept.
template <int N, class Vec, class Real>
capped_friction<Vec, Real> reported_cap(const curve_point<Real>& start, Real bad) {
  capped_friction<Vec, Real> out{{Vec{}, bad, false, bad, start}, Vec{}, bad};
  for (Vec* v : {&out.force, &out.displacement}) write<N>(*v, vector3<Real>{bad, bad, bad});
  return out;
}

// The trial friction and the springs kept (a stick), with the ratio `ratio`.
template <int N, class Vec, class Real>
BOOST_FORCEINLINE capped_friction<Vec, Real> kept_trial(const trial_friction<Real>& trial,
                                                        const checked_trial<Real>& in, Real ratio,
                                                        const curve_point<Real>& start) {
  // Field by field: a braced initializer would zero the whole result first.
  capped_friction<Vec, Real> out;
  write<N>(out.force, trial.force);
  out.torque = trial.torque;
  out.sticking = true;
  out.ratio = ratio;
  out.point = start;
  write<N>(out.displacement, in.spring);
  out.twist = in.twist;
  return out;
}

// The first rewritten spring that is not finite, reported (report_not_finite).
// Out of line: its names are not built on a good contact's path.
template <class Real, class Policy>
BOOST_NOINLINE Real rewritten_not_finite(const char* function, const vector3<Real>& spring,
                                         Real twist, const Policy& pol) {
  return report_not_finite(
      function,
      {"a rewritten spring -(F - damping)/k_t", "a rewritten spring -(F - damping)/k_t",
       "a rewritten spring -(F - damping)/k_t", "the rewritten spring -(T - damping)/k_w"},
      {spring[0], spring[1], spring[2], twist}, pol);
}

// A contact's capped friction from `cap`, the projection of its trial
// friction `trial` (trial_friction_of) in the limit set's units at the load
// μN = `load` and the radius a: the trial and the springs kept where it
// sticks; otherwise the force's direction and the torque's sign kept, and
// the springs rewritten to hold the result with the damping (a spring too
// soft for the capped force, F/k beyond the largest value, is a domain
// error).
template <int N, class Vec, class Real, class Policy>
BOOST_FORCEINLINE capped_friction<Vec, Real> capped_from(
    const friction_result<Real, Real>& cap, const checked_trial<Real>& in,
    const trial_friction<Real>& trial, const spring_stiffness<Real>& springs, Real load, Real a,
    const curve_point<Real>& start, const char* function, const Policy& pol) {
  if (cap.sticking) return kept_trial<N, Vec>(trial, in, cap.ratio, start);
  const Real kt = springs.tangential.value, kw = springs.twisting.value, f = trial.magnitude;
  const Real scale = f > 0 ? Real(cap.force * load / f) : Real(0);
  vector3<Real> force{}, spring{};
  for (std::size_t i = 0; i < std::size_t(N); ++i) {
    force[i] = trial.force[i] * scale;
    spring[i] = -(force[i] - in.damping[i]) / kt;
  }
  const Real torque = std::copysign(product(load, a, cap.torque), trial.torque);
  const Real twist = -(torque - in.damping_torque) / kw;
  if (!all_finite(spring[0], spring[1], spring[2], twist))
    return reported_cap<N, Vec>(start, rewritten_not_finite(function, spring, twist, pol));
  capped_friction<Vec, Real> out{
      {Vec{}, torque, false, cap.ratio, (boost::math::isnan)(cap.ratio) ? start : cap.curve()},
      Vec{},
      twist};
  write<N>(out.force, force);
  write<N>(out.displacement, spring);
  return out;
}

// The projection of the trial (x, y) = (|F|/(μN), |T|/(μNa)) in the torque
// weight a²k_t/k_θ, from the curve point `start` (ratio 0: none).
template <class Profile, class Real = typename Profile::value_type>
BOOST_FORCEINLINE friction_result<Real, Real> project_trial(const Profile& profile, Real x, Real y,
                                                            Real weight,
                                                            const curve_point<Real>& start) {
  const bool from_point = start.ratio > 0 && (boost::math::isfinite)(start.force);
  return limit_projector<Profile>(profile, {x, y}, weight)(start.ratio,
                                                           from_point ? &start : nullptr);
}

// The cap on checked inputs (spring_history_friction, and cap_trial_state
// where a number is out of scaled_trial_of's range), their trial friction
// `friction` given (trial_friction_of): the stiffnesses finite and > 0,
// `patch` checked, `start` a curve point (ratio 0: none).  What could
// overflow on the way (the trial, the torque weight, the rewritten springs)
// is checked here.  `Vec` has N = 2 or 3 components.
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
  // The trial friction (trial_friction_of(in, springs), the caller's), which
  // must not overflow (|F| finite: each component is).
  const Real t = friction.torque, f = friction.magnitude;
  if (!((isfinite)(f) && (isfinite)(t)))
    return reported_cap<N, Vec>(start, report_not_finite(function,
                                                         {"the trial force -k_t xi + damping",
                                                          "the trial torque -k_w phi + damping"},
                                                         {f, t}, pol));
  const Real a = patch.radius, load = patch.friction * patch.normal;
  // The magnitudes in the limit set's units.  Where they overflow, the load
  // is below 2^-1024 of the trial: the exact cap is as far below it, zero
  // to the trial's precision, and is taken as zero (a contact coming apart).
  const Real x = f / load, y = fabs(t) / a / load;
  friction_result<Real, Real> cap{0, 0, f == 0 && t == 0, std::numeric_limits<Real>::quiet_NaN()};
  if (load > 0 && (isfinite)(x) && (isfinite)(y)) {
    Real weight = a * a * kt / kw;
    if (!(weight > 0 && (isfinite)(weight))) {  // a² alone out of range, or the whole
      weight = checked(function, "the torque weight a^2 k_t/k_w", Real(product(a, a, kt) / kw),
                       argument_rule::finite_positive, pol);
      if (any_reported(weight)) return reported_cap<N, Vec>(start, weight);
    }
    cap = project_trial(profile, x, y, weight, start);
  }
  return capped_from<N, Vec>(cap, in, friction, springs, load, a, start, function, pol);
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
  if (bad) return reported_cap<N, Vec>(start, std::numeric_limits<Real>::quiet_NaN());
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
  return detail::trial_in_triangle(
      detail::scaled_trial_of(detail::trial_friction_of<n>(in, springs), springs, contact),
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
  const detail::trial_friction<Real> friction = detail::trial_friction_of<n>(in, springs);
  const detail::scaled_trial<Real> scaled = detail::scaled_trial_of(friction, springs, contact);
  // The common contact: every number in range and a good start.  First the
  // trial in the inner triangle, as surely_sticks decides it: the trial is
  // kept.
  if (scaled.in_range && start.ratio >= 0) {
    if (detail::in_sticking_triangle(scaled.x, scaled.y, profile.mean_radius()))
      return detail::kept_trial<n, Vec>(friction, in, std::numeric_limits<Real>::quiet_NaN(),
                                        start);
    const friction_result<Real, Real> cap =
        detail::project_trial(profile, scaled.x, scaled.y, scaled.weight, start);
    return detail::capped_from<n, Vec>(cap, in, friction, springs, scaled.load,
                                       contact.radius.value, start, function,
                                       typename Profile::policy_type());
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
