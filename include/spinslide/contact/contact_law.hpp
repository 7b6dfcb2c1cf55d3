//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file contact_law.hpp
/// The coupled friction law for simulators: one call per contact per step,
/// vectors in, friction force and torque out (docs/contact.md).
///
/// For a contact of radius a, normal force N and friction coefficient μ, with
/// relative sliding velocity v (in the contact plane) and relative spin ω
/// about the normal, ε = |v|/(a|ω|) and
///   F = −μN 𝓕(ε) v/|v|,     T = −μN a 𝓣(ε) sign(ω) n,
/// the friction acting on the body whose motion relative to the other is
/// (v, ω).  It does negative work: F·v + T·ω = −μN(𝓕|v| + a𝓣|ω|) ≤ 0.

#ifndef SPINSLIDE_CONTACT_CONTACT_LAW_HPP
#define SPINSLIDE_CONTACT_CONTACT_LAW_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/base/detail/product.hpp>
#include <spinslide/base/detail/vector_access.hpp>
#include <spinslide/base/friction_result.hpp>
#include <spinslide/contact/contact_inputs.hpp>
#include <spinslide/contact/detail/vector3.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/profile_concept.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

namespace spinslide {

/// The 3-D friction `friction` (the contact law's, acting at the patch
/// centre: a friction_result of a force vector in the tangent plane and a
/// torque vector along the normal; applied at the centre of mass without
/// its moment, the force's moment (c − x)×F is lost) as a wrench about
/// `point`: the force unchanged, the torque T + (c − point) × F with c =
/// `patch_centre` (any frame, the same for all three).  For a body's centre
/// of mass x this is the force and torque to apply there.
template <class Vec3>
friction_result<Vec3, Vec3> wrench_about(const friction_result<Vec3, Vec3>& friction,
                                         const Vec3& patch_centre, const Vec3& point) {
  static_assert(detail::is_vector<Vec3, 3>(),
                "spinslide::wrench_about: the points and the friction must be 3-component "
                "vector classes (operator[] or members x, y, z), not pointers or C arrays");
  using R = std::decay_t<decltype(detail::get<0>(friction.force))>;
  const detail::vector3<R> c = detail::read<3, R>(patch_centre), x = detail::read<3, R>(point);
  const detail::vector3<R> moment =
      detail::cross(detail::vector3<R>{c[0] - x[0], c[1] - x[1], c[2] - x[2]},
                    detail::read<3, R>(friction.force));
  friction_result<Vec3, Vec3> out = friction;
  detail::set<0>(out.torque, detail::get<0>(friction.torque) + moment[0]);
  detail::set<1>(out.torque, detail::get<1>(friction.torque) + moment[1]);
  detail::set<2>(out.torque, detail::get<2>(friction.torque) + moment[2]);
  return out;
}

/// The contact law for one profile, with a regularization near rest.
///
/// Near rest ε is undefined.  With ρ = √(|v|² + (aω)²) and the velocity scale
/// v_s (a required argument, in the caller's velocity unit: about 2μgΔt for
/// an explicit integrator with step Δt, so that the step resolves it; there
/// is no default, as 1e-6 made the spin chatter at engine time steps), the
/// exact law is scaled
/// by min(1, ρ/v_s): continuous everywhere (F, T → 0 as ρ → 0 whatever the
/// direction), still dissipative (the factor is ≥ 0), and exactly the
/// unregularized law for ρ ≥ v_s.  It keeps the coupling: the direction of
/// (v, aω) still sets ε.  Finite input never gives NaN, and gives ∞ only where the
/// true result overflows; a speed |v| that overflows is a domain error.
template <class Profile = uniform_disk<double>>
class contact_law {
  static_assert(detail::requires_profile<Profile>());
  using Real = typename Profile::value_type;
  using Policy = typename Profile::policy_type;

 public:
  /// The profile's floating-point type.
  using value_type = Real;

  /// The law for `profile`, regularized below `scale` = v_s (finite and ≥ 0;
  /// 0: no regularization); otherwise std::domain_error.  The law has no
  /// static friction: a load below μN creeps at v_s·F/(μN) (docs/contact.md,
  /// "Near rest"); for exact stick use impulse_friction or
  /// spring_history_friction.
  contact_law(Profile profile, velocity_scale<Real> scale)
      : profile_(std::move(profile)),
        vs_(detail::checked_constructor_argument<Policy>(
            "spinslide::contact_law<%1%>::contact_law(profile, velocity_scale)", "velocity_scale",
            scale.value, detail::argument_rule::finite_non_negative)) {}

  /// The profile.
  const Profile& profile() const { return profile_; }
  /// v_s.
  Real velocity_scale() const { return vs_; }

  /// Planar contact.  `velocity`: the relative sliding velocity (x, y);
  /// `spin`: the relative angular velocity about the normal; `contact`: the
  /// radius a > 0, the normal force N ≥ 0 and μ ≥ 0, each named by its type.
  template <class Vec2>
  friction_result<Vec2, Real> operator()(const Vec2& velocity, Real spin,
                                         const force_contact<Real>& contact) const {
    static_assert(detail::is_vector<Vec2, 2>(),
                  "spinslide::contact_law: the velocity must be a 2-component vector class "
                  "(operator[] or members x, y), not a pointer or a C array: copy a raw array "
                  "such as MuJoCo's mjtNum* into a std::array<double, 2>");
    const Real vx = static_cast<Real>(detail::get<0>(velocity));
    const Real vy = static_cast<Real>(detail::get<1>(velocity));
    Real fx, fy, t;
    friction_result<Vec2, Real> out{Vec2{}, Real(0)};
    law(vx, vy, spin, contact, fx, fy, t, out.point);
    out.torque = t;
    out.ratio = out.point.ratio;
    detail::set<0>(out.force, fx);
    detail::set<1>(out.force, fy);
    return out;
  }

  /// 3-D contact.  `velocity` and `angular_velocity`: relative velocity of
  /// the body at the patch centre and its relative angular velocity;
  /// `normal`: the unit contact normal; `contact` as above.  Only the
  /// tangential part of the velocity and the normal part of the angular
  /// velocity enter (rolling is not friction here).  The result acts at the
  /// patch centre (wrench_about moves it to any point).
  template <class Vec3>
  friction_result<Vec3, Vec3> operator()(const Vec3& velocity, const Vec3& angular_velocity,
                                         const contact_normal<Vec3>& normal,
                                         const force_contact<Real>& contact) const {
    static_assert(
        detail::is_vector<Vec3, 3>(),
        "spinslide::contact_law: the velocity, angular velocity and normal must be "
        "3-component vector classes (operator[] or members x, y, z), not pointers or "
        "C arrays: copy a raw array such as MuJoCo's mjtNum* into a std::array<double, 3>");
    const detail::vector3<Real> n = detail::read<3, Real>(normal.value);
    const Real w = detail::vector_dot(detail::read<3, Real>(angular_velocity), n);
    detail::vector3<Real> v = detail::read<3, Real>(velocity);
    const Real speed = detail::tangential_part(v, n);  // the force is along −v_t
    Real f, t;
    friction_result<Vec3, Vec3> out{Vec3{}, Vec3{}};
    magnitudes(speed, w, contact, f, t, out.point);
    out.ratio = out.point.ratio;
    // NaN f: a domain error, through a policy that does not throw.
    // −f times the unit vector v/|v| (f/|v| alone overflows for a tiny |v|).
    detail::unit_direction(v, speed);
    for (Real& vi : v) vi = (boost::math::isnan)(f) ? f : Real(-f * vi);
    detail::set<0>(out.force, v[0]);
    detail::set<1>(out.force, v[1]);
    detail::set<2>(out.force, v[2]);
    // A zero component of n stays 0 where the torque overflows (∞ · 0).
    auto along = [t](Real ni) { return ni == 0 ? Real(0) : Real(t * ni); };
    detail::set<0>(out.torque, along(n[0]));
    detail::set<1>(out.torque, along(n[1]));
    detail::set<2>(out.torque, along(n[2]));
    return out;
  }

 private:
  // |F| (≥ 0, against v) and the signed torque about the normal.
  // The checks of operator(): false, with f = t = the policy's NaN, on bad input.
  static bool valid(Real speed, Real spin, const force_contact<Real>& contact, Real& f, Real& t) {
    static const char* function = "spinslide::contact_law<%1%>::operator()";
    using detail::argument_rule;
    using detail::check;
    f = t = 0;
    Real invalid = 0;
    const Real a = contact.radius.value, N = contact.normal.value, mu = contact.friction.value;
    const bool ok =
        check(function, "contact.radius", a, argument_rule::finite_positive, &invalid, Policy()) &&
        check(function, "contact.normal", N, argument_rule::non_negative, &invalid, Policy()) &&
        check(function, "contact.friction", mu, argument_rule::non_negative, &invalid, Policy()) &&
        check(function, "contact.normal*contact.friction", Real(N * mu),
              argument_rule::finite_non_negative, &invalid, Policy()) &&
        check(function, "the sliding speed |v|", speed, argument_rule::finite_non_negative,
              &invalid, Policy()) &&
        check(function, "the spin", spin, argument_rule::finite, &invalid, Policy());
    if (!ok) f = t = invalid;
    return ok;
  }

  // |F| = f and the signed torque t, and `at`, the curve point (ε, 𝓕, 𝓣)
  // of the motion (ratio NaN at rest or on bad input).
  void magnitudes(Real speed, Real spin, const force_contact<Real>& contact, Real& f, Real& t,
                  curve_point<Real>& at) const {
    BOOST_MATH_STD_USING
    at.ratio = std::numeric_limits<Real>::quiet_NaN();
    if (!valid(speed, spin, contact, f, t)) return;
    const Real a = contact.radius.value;
    const Real muN = contact.friction.value * contact.normal.value;
    const Real rim = a * fabs(spin);  // a|ω|
    if (speed == 0 && rim == 0) return;
    Real F, T;
    if (rim == 0) {  // pure sliding (also when a|ω| underflows)
      F = 1;
      T = 0;
      at.ratio = std::numeric_limits<Real>::infinity();
    } else if (speed == 0) {  // pure spinning
      F = 0;
      T = profile_.mean_radius();
      at.ratio = 0;
    } else {
      at.ratio = speed / rim;
      const auto ft = profile_.force_torque(at.ratio);
      F = ft.force;
      T = ft.torque;
    }
    at.force = F;
    at.torque = T;
    if (!(muN > 0)) return;
    Real scale = 1;
    if (speed < vs_ && rim < vs_) {  // only then can ρ = |(v, aω)| be below v_s
      const Real rho = detail::vector_norm(speed, rim, Real(0));
      if (rho < vs_) scale = rho / vs_;
    }
    // Products without spurious over- or underflow (found by fuzz_contact):
    // μN a overflows where 𝓣 = 0 would make the torque 0, and μN s underflows
    // to 0 where a𝓣 overflows (∞ · 0).
    f = detail::product(muN, F, scale);
    t = -(spin > 0 ? Real(1) : Real(-1)) * detail::product(muN, scale, a, T);
  }

  void law(Real vx, Real vy, Real spin, const force_contact<Real>& contact, Real& fx, Real& fy,
           Real& t, curve_point<Real>& at) const {
    const Real speed = detail::vector_norm(vx, vy, Real(0));
    Real f;
    magnitudes(speed, spin, contact, f, t, at);
    if ((boost::math::isnan)(f)) {  // a domain error, through a policy that does not throw
      fx = fy = f;
      return;
    }
    detail::vector3<Real> u{vx, vy, Real(0)};
    detail::unit_direction(u, speed);
    fx = -f * u[0];
    fy = -f * u[1];
  }

  Profile profile_;
  Real vs_;
};

/// The uniform-disk contact law as one call, regularized below `scale`.
template <class Vec2, class Real>
friction_result<Vec2, Real> contact_friction(const Vec2& velocity, Real spin,
                                             const force_contact<Real>& contact,
                                             velocity_scale<Real> scale) {
  return contact_law<uniform_disk<Real>>(uniform_disk<Real>(), scale)(velocity, spin, contact);
}

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_CONTACT_LAW_HPP
