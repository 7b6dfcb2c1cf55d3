//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file impulse_friction.hpp
/// Velocity-level (impulse) friction for one contact over one time step:
/// exact stick, and slip on the coupled limit set by maximum dissipation
/// (docs/contact.md, "The impulse law"; docs/theory.md §11).
///
/// Given the contact's relative sliding velocity v and spin ω before
/// friction, and its effective inverse mass W over (v_x, v_y, ω) (the
/// velocity change per unit impulse: the Delassus operator restricted to
/// those directions), the friction impulse P = (P_x, P_y, L) is the one that
/// leaves the least kinetic energy of the relative motion,
///   P = argmin ½ (s + WP)ᵀ W⁻¹ (s + WP) over μΛ·{(f, a t) : (f, t) ∈ L₃},
/// Λ the normal impulse.  If the impulse that stops the contact,
/// −W⁻¹(v, ω), lies in that set, it is the answer (exact stick: no creep, no
/// velocity scale).  Otherwise P lies on the set's boundary with the
/// velocity after it, (v⁺, ω⁺) = (v, ω) + WP, along the outward normal:
/// P = −μΛ(𝓕(ε) v⁺/|v⁺|, a𝓣(ε) sign ω⁺) with ε = |v⁺|/(a|ω⁺|), the exact
/// Contensou law at the end of the step (an implicit step, which tends to
/// the exact motion as the step shrinks; tests/test_impulse_friction.cpp).

#ifndef SPINSLIDE_CONTACT_IMPULSE_FRICTION_HPP
#define SPINSLIDE_CONTACT_IMPULSE_FRICTION_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/base/detail/product.hpp>
#include <spinslide/base/detail/vector_access.hpp>
#include <spinslide/contact/contact_inputs.hpp>
#include <spinslide/contact/detail/impulse_frame.hpp>
#include <spinslide/contact/detail/impulse_in_frame.hpp>
#include <spinslide/contact/detail/sticking_triangle.hpp>
#include <spinslide/contact/limit_set.hpp>
#include <spinslide/contact/planar_metric.hpp>

#include <boost/config.hpp>
#include <boost/math/tools/precision.hpp>

#include <array>
#include <cmath>
#include <limits>

namespace spinslide {

namespace detail {

// Every output NaN: a check reported an error through a policy that does
// not throw.
template <class Vec2, class Real>
impulse_result<Vec2, Real> reported_impulse(const curve_point<Real>& start) {
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  impulse_result<Vec2, Real> out{Vec2{}, nan, false, nan, start};
  set<0>(out.force, nan);
  set<1>(out.force, nan);
  return out;
}

// The result of a contact that sticks: the impulse z = 0 − W⁻¹s that
// stops it (+0 where W⁻¹s is 0, as at rest), `out` carrying the rest.
template <class Vec2, class Real>
impulse_result<Vec2, Real> sticking_impulse(impulse_result<Vec2, Real> out,
                                            const vector3<Real>& stop) {
  out.sticking = true;
  set<0>(out.force, Real(0 - stop[0]));
  set<1>(out.force, Real(0 - stop[1]));
  out.torque = 0 - stop[2];
  return out;
}

// The law on a thin set (impulse_frame's `point`), exactly (thin_set.hpp),
// from point friction's answer; that answer itself at a = 0, where the
// spin after it is 0 (the root at ε = ∞), and where the search ends on a
// number that is not finite (an extreme input's overflow): the guaranteed
// answer of the limit.  `stop` = W⁻¹s: sticking where the root's disk and
// torque hold the stopping impulse.
template <class Profile, class Vec2, class Real = typename Profile::value_type>
impulse_result<Vec2, Real> thin_set_result(const Profile& profile, impulse_result<Vec2, Real> out,
                                           const law_inputs<Real>& law, Real a,
                                           const vector3<Real>& stop) {
  using std::fabs;
  const point_answer<Real> q = point_answer_for(law);
  const Real guess = point_ratio(profile, q, a, law.load);
  if (!(a > 0 && q.spin != 0 && guess < std::numeric_limits<Real>::infinity()))
    return point_limit_result(out, q, a);
  const thin_set<Profile> thin(profile, law, a, q.spin < 0 ? Real(-1) : Real(1));
  const thin_trial<Real> t = thin.solve(guess > 0 ? guess : Real(1));
  if (!all_finite(t.p.force[0], t.p.force[1], t.torque, t.miss))
    return point_limit_result(out, q, a);
  if (t.p.slip == 0 && length(stop[0], stop[1]) <= law.load * t.ft.force &&
      fabs(stop[2]) <= fabs(t.torque))
    return sticking_impulse(out, stop);
  set<0>(out.force, t.p.force[0]);
  set<1>(out.force, t.p.force[1]);
  out.torque = t.torque;
  out.ratio = t.ratio;
  out.point = {t.ratio, t.ft.force, t.ft.torque};
  return out;
}

// The impulse law's errors, where its one test of good arguments failed:
// the checks one by one report the first bad one, through the policy; the
// result NaN where the policy does not throw.
template <class Profile, class Vec2>
impulse_result<Vec2, typename Profile::value_type> impulse_argument_error(
    const char* function, const std::array<typename Profile::value_type, 3>& slip,
    const impulse_contact<typename Profile::value_type>& contact,
    const curve_point<typename Profile::value_type>& start) {
  const typename Profile::policy_type pol;
  checked(function, "velocity[0]", slip[0], argument_rule::finite, pol);
  checked(function, "velocity[1]", slip[1], argument_rule::finite, pol);
  checked(function, "spin", slip[2], argument_rule::finite, pol);
  checked_patch(function, contact, pol, argument_rule::finite_non_negative);
  checked(function, "start.ratio", start.ratio, argument_rule::non_negative, pol);
  return reported_impulse<Vec2>(start);
}

// The impulse law beyond the inner triangle (impulse_friction, which has
// tested its arguments and the triangle): `stop` = W⁻¹s, the negated
// impulse that stops the contact, which the triangle's test did not check
// (a W⁻¹s, μΛ or μΛa⟨r⟩ that overflowed is an error here).  Out of line,
// so that a caller inlines the entry and its test.
template <class Profile, class Vec2>
BOOST_NOINLINE impulse_result<Vec2, typename Profile::value_type> impulse_beyond_triangle(
    const Profile& profile, const char* function, const vector3<typename Profile::value_type>& slip,
    const vector3<typename Profile::value_type>& stop,
    const planar_metric<typename Profile::value_type>& inverse_mass,
    const impulse_contact<typename Profile::value_type>& contact,
    const curve_point<typename Profile::value_type>& start) {
  using Real = typename Profile::value_type;
  const typename Profile::policy_type pol;
  const Real a = contact.radius.value, load = contact.friction.value * contact.normal.value;
  const Real top = profile.mean_radius();
  impulse_result<Vec2, Real> out{Vec2{}, Real(0), false, std::numeric_limits<Real>::quiet_NaN(),
                                 start};
  // The largest angular impulse, μΛa⟨r⟩, must be a number too (its exact
  // product only where the plain one overflows: an intermediate may).
  if (!all_finite(stop[0], stop[1], stop[2], load, Real(load * (a * top)))) {
    vector3<Real> z = stop;
    for (Real& x : z)
      x = checked(function, "the stopping impulse -W^-1 (v, spin)", x, argument_rule::finite, pol);
    const Real good_load =
        checked(function, "contact.normal*contact.friction", load, argument_rule::finite, pol);
    const Real spin_load = checked(function, "contact.normal*contact.friction*contact.radius*<r>",
                                   product(load, a, top), argument_rule::finite, pol);
    if (any_reported(z[0], z[1], z[2], good_load, spin_load)) return reported_impulse<Vec2>(start);
  }
  const Real vx = slip[0], vy = slip[1], w = slip[2];
  if (load == 0 || (vx == 0 && vy == 0 && w == 0)) {
    out.sticking = vx == 0 && vy == 0 && w == 0;
    if (!out.sticking) out.ratio = slip_ratio(length(vx, vy), a, w);
    return out;
  }
  const impulse_frame<Real> frame =
      impulse_frame_for(inverse_mass, a, Real(2 / profile.mean_inverse_radius()));
  if (frame.too_large) {
    raise_argument_error(
        function, "contact.radius",
        "at most 1/(16 sqrt(kappa) epsilon) times the inverse mass's own length scale "
        "sqrt((W_xx + W_yy)/(2 W_ww)) (kappa its condition number; 1e13 times it in double "
        "for kappa = 1e3)",
        a, pol);
    return reported_impulse<Vec2>(start);
  }
  if (frame.point) return thin_set_result(profile, out, {inverse_mass, slip, load}, a, stop);
  // z = −W⁻¹s in the frame's units (L = cτ), likewise.
  const vector3<Real> target{-stop[0] / load, -stop[1] / load, -stop[2] / frame.c / load};
  const friction_result<std::array<Real, 2>, Real> r =
      frame.k == 1  // the profile's own curve: the one step of a coin's or a block's contact
          ? metric_projector<Profile>(profile, target, frame.metric, frame.inverse)(start.ratio,
                                                                                    &start)
          : project_in_frame(profile, frame, target, start, {inverse_mass, slip, load});
  if (r.sticking) return sticking_impulse(out, stop);
  out.ratio = r.ratio;
  out.point = r.curve();
  set<0>(out.force, Real(load * r.force[0]));
  set<1>(out.force, Real(load * r.force[1]));
  out.torque = product(load, a, r.torque);
  return out;
}

}  // namespace detail

/// The friction impulse for one contact over one step (see the file's
/// comment).  `velocity`: the relative sliding velocity before friction (a
/// 2-component vector class, in the tangent plane's axes); `spin`: the
/// relative angular velocity about the normal; `inverse_mass`: W over
/// (v_x, v_y, ω), in the same axes; `contact`: a, Λ and μ.  Components
/// finite, a ≥ 0, Λ ≥ 0 and μ ≥ 0, all of the profile's value_type;
/// otherwise a domain error, and so is a patch beyond 1/(16√κ ε_mach) times
/// W's own length scale √((W_xx + W_yy)/(2W_ωω)) (1e13 times it in double at
/// κ = 1e3): these are the only errors.  Every smaller patch is valid, down
/// to a = 0, where the law is point friction (no angular impulse; a patch
/// growing from nothing tends to it continuously: docs/theory.md §11, "A
/// patch that starts at zero").  `start`: where the
/// contact's last step left the limit curve (the last result's curve(), or
/// `curve_point<Real>{ε}` for a ratio alone; ratio ≥ 0, else a domain error;
/// `{}`: none); it only speeds the search.  The result is an
/// impulse_result: its `force` and `torque` are the impulse (P_x, P_y) and L.  No allocation: two
/// 3×3 factorizations and, when it slips, a few evaluations of the profile.
template <class Profile, class Vec2>
impulse_result<Vec2, typename Profile::value_type> impulse_friction(
    const Profile& profile, const Vec2& velocity, typename Profile::value_type spin,
    const planar_metric<typename Profile::value_type>& inverse_mass,
    const impulse_contact<typename Profile::value_type>& contact,
    const curve_point<typename Profile::value_type>& start = {}) {
  using Real = typename Profile::value_type;
  detail::require_smooth_curve<Profile, Real>();
  static_assert(detail::is_vector<Vec2, 2>(),
                "spinslide::impulse_friction: the velocity must be a 2-component vector class "
                "(operator[] or members x, y), not a pointer or a C array: copy a raw array "
                "such as MuJoCo's mjtNum* into a std::array<double, 2>");
  static const char* function =
      "spinslide::impulse_friction<%1%>(profile, velocity, %1%, inverse_mass, contact)";
  const detail::vector3<Real> slip{static_cast<Real>(detail::get<0>(velocity)),
                                   static_cast<Real>(detail::get<1>(velocity)), spin};
  const Real a = contact.radius.value, n = contact.normal.value, mu = contact.friction.value;
  // One test for good arguments; where it fails, the checks one by one.
  if (!(detail::all_finite(slip[0], slip[1], slip[2], a, n, mu) && a >= 0 && n >= 0 && mu >= 0 &&
        start.ratio >= 0))
    return detail::impulse_argument_error<Profile, Vec2>(function, slip, contact, start);
  // The impulse that stops the contact, z = −W⁻¹s, and the set μΛ·S·L₃ with
  // S = diag(1, 1, a): in the limit set's units ẑ = S⁻¹z/(μΛ), in the metric
  // SWS (inverse S⁻¹W⁻¹S⁻¹), both positive definite since W is.
  const detail::vector3<Real> stop = detail::multiply(inverse_mass.inverse(), slip);  // −z
  // Sticking is decided on z's magnitudes (L₃ = {(|f|, |t|) ∈ L}) where
  // they lie in L's inner triangle, in the limit set's units (divided by a,
  // then by the load: μΛa itself may be subnormal), before any evaluation
  // or metric, and before z's own tests: a z that overflowed and a load
  // beyond the largest value (with a > 0, μΛa⟨r⟩ is then too) fail the
  // triangle's comparisons, a load of 0 its own test (−0, from Λ = −0,
  // would turn the quotients' signs: fuzz_impulse found a z of ∞ taken as
  // sticking), and the rest tests them.
  using std::fabs;
  const Real load = mu * n, top = profile.mean_radius();
  if (a > 0 && load > 0 && Real(load * (a * top)) <= boost::math::tools::max_value<Real>() &&
      detail::in_sticking_triangle(Real(stop[0] / load), Real(stop[1] / load),
                                   Real(fabs(stop[2]) / a / load), top)) {
    impulse_result<Vec2, Real> out{Vec2{}, Real(0), false, std::numeric_limits<Real>::quiet_NaN(),
                                   start};
    return detail::sticking_impulse(out, stop);
  }
  return detail::impulse_beyond_triangle<Profile, Vec2>(profile, function, slip, stop, inverse_mass,
                                                        contact, start);
}

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_IMPULSE_FRICTION_HPP
