//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file contact.hpp
/// The coupled friction law for simulators: one call per contact per step,
/// vectors in, friction force and torque out (docs/contact.md).
///
/// For a contact of radius a, normal force N and friction coefficient μ, with
/// relative sliding velocity v (in the contact plane) and relative spin ω
/// about the normal, ε = |v|/(a|ω|) and
///   F = −μN 𝓕(ε) v/|v|,     T = −μN a 𝓣(ε) sign(ω) n,
/// the friction acting on the body whose motion relative to the other is
/// (v, ω).  It does negative work: F·v + T·ω = −μN(𝓕|v| + a𝓣|ω|) ≤ 0.

#ifndef SPINSLIDE_CONTACT_HPP
#define SPINSLIDE_CONTACT_HPP

#include <spinslide/detail/product.hpp>
#include <spinslide/profile.hpp>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

namespace spinslide {

namespace detail {

// Component access for users' vector types: operator[] (std::array, Eigen,
// most math libraries) or public members x, y, z (Box2D, glm, plain structs).
template <class V, class = void>
struct has_subscript : std::false_type {};
template <class V>
struct has_subscript<V, std::void_t<decltype(std::declval<V&>()[0])>> : std::true_type {};

template <int I, class V>
decltype(auto) component(V& v) {
  if constexpr (has_subscript<V>::value) {
    return (v[I]);
  } else if constexpr (I == 0) {
    return (v.x);
  } else if constexpr (I == 1) {
    return (v.y);
  } else {
    return (v.z);
  }
}
template <int I, class V>
auto get(const V& v) {
  return component<I>(v);  // V deduced const: reads through the const accessors
}
template <int I, class V, class Real>
void set(V& v, Real value) {
  using C = std::remove_reference_t<decltype(component<I>(v))>;
  component<I>(v) = static_cast<C>(value);
}

}  // namespace detail

/// The friction on a contact in the contact plane: force vector and the
/// torque about the normal (signed, positive counter-clockwise).
template <class Vec2, class Real>
struct planar_friction {
  /// The force vector, against the sliding velocity (units of the normal force).
  Vec2 force;
  /// The torque about the normal, against the spin.
  Real torque;
};

/// The friction on a contact in 3-D: force vector (in the tangent plane) and
/// torque vector (along the normal).
template <class Vec3>
struct spatial_friction {
  /// The force vector, in the tangent plane, against the sliding velocity.
  Vec3 force;
  /// The torque vector, along the normal, against the spin.
  Vec3 torque;
};

/// The contact law for one profile, with a regularization near rest.
///
/// Near rest ε is undefined.  With ρ = √(|v|² + (aω)²) and the velocity scale
/// v_s (default 1e-6, in the caller's velocity unit), the exact law is scaled
/// by min(1, ρ/v_s): continuous everywhere (F, T → 0 as ρ → 0 whatever the
/// direction), still dissipative (the factor is ≥ 0), and exactly the
/// unregularized law for ρ ≥ v_s.  It keeps the coupling: the direction of
/// (v, aω) still sets ε.  Finite input never gives NaN, and gives ∞ only where the
/// true result overflows; a speed |v| that overflows is a domain error.
template <class Profile = uniform_disk<double>>
class contact_law {
 public:
  /// The profile's floating-point type.
  using Real = typename Profile::value_type;

  /// The law for `profile`, regularized below `velocity_scale` = v_s ≥ 0 (0:
  /// no regularization); v_s < 0 or NaN is a domain error.
  explicit contact_law(Profile profile = Profile(), Real velocity_scale = Real(1e-6))
      : profile_(std::move(profile)),
        vs_(detail::checked_parameter<Real>(velocity_scale, Real(0),
                                            std::numeric_limits<Real>::max(), false,
                                            "spinslide::contact_law<%1%>::contact_law",
                                            "Got velocity_scale = %1%, but it must be >= 0.")) {}

  /// The profile.
  const Profile& profile() const { return profile_; }
  /// v_s.
  Real velocity_scale() const { return vs_; }

  /// Planar contact.  `velocity`: the relative sliding velocity (x, y);
  /// `spin`: the relative angular velocity about the normal; `radius` a > 0,
  /// `normal_force` N ≥ 0, `friction_coefficient` μ ≥ 0.
  template <class Vec2>
  planar_friction<Vec2, Real> operator()(const Vec2& velocity, Real spin, Real radius,
                                         Real normal_force, Real friction_coefficient) const {
    const Real vx = static_cast<Real>(detail::get<0>(velocity));
    const Real vy = static_cast<Real>(detail::get<1>(velocity));
    Real fx, fy, t;
    law(vx, vy, spin, radius, normal_force, friction_coefficient, fx, fy, t);
    planar_friction<Vec2, Real> out{Vec2{}, t};
    detail::set<0>(out.force, fx);
    detail::set<1>(out.force, fy);
    return out;
  }

  /// 3-D contact.  `velocity` and `angular_velocity`: relative velocity and
  /// angular velocity of the body at the contact point; `normal`: the unit
  /// contact normal.  Only the tangential part of the velocity and the normal
  /// part of the angular velocity enter (rolling is not friction here).
  template <class Vec3>
  spatial_friction<Vec3> operator()(const Vec3& velocity, const Vec3& angular_velocity,
                                    const Vec3& normal, Real radius, Real normal_force,
                                    Real friction_coefficient) const {
    const Real n[3] = {static_cast<Real>(detail::get<0>(normal)),
                       static_cast<Real>(detail::get<1>(normal)),
                       static_cast<Real>(detail::get<2>(normal))};
    const Real w = dot({static_cast<Real>(detail::get<0>(angular_velocity)),
                        static_cast<Real>(detail::get<1>(angular_velocity)),
                        static_cast<Real>(detail::get<2>(angular_velocity))},
                       n);
    Real v[3] = {static_cast<Real>(detail::get<0>(velocity)),
                 static_cast<Real>(detail::get<1>(velocity)),
                 static_cast<Real>(detail::get<2>(velocity))};
    const Real speed = tangential(v, n);  // the force is along −v_t
    Real f, t;
    magnitudes(speed, w, radius, normal_force, friction_coefficient, f, t);
    spatial_friction<Vec3> out{Vec3{}, Vec3{}};
    // NaN f: a domain error, through a policy that does not throw.
    // −f times the unit vector v/|v| (f/|v| alone overflows for a tiny |v|).
    direction(v, speed);
    for (int i = 0; i < 3; ++i) v[i] = (boost::math::isnan)(f) ? f : Real(-f * v[i]);
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
  // a·n for a unit n, without overflow where the result is finite: if a
  // partial sum overflows, the same in units of a's largest component.
  static Real dot(const Real (&a)[3], const Real (&n)[3]) {
    BOOST_MATH_STD_USING
    const Real d = a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
    if ((boost::math::isfinite)(d) || !(boost::math::isfinite)(a[0]) ||
        !(boost::math::isfinite)(a[1]) || !(boost::math::isfinite)(a[2]))
      return d;
    const Real m = largest(a[0], a[1], a[2]);
    return m * ((a[0] / m) * n[0] + (a[1] / m) * n[1] + (a[2] / m) * n[2]);
  }

  // v/|v| in place (0 for v = 0).  For a |v| near the subnormal range (below
  // min/epsilon), in units of v's largest component, where the quotients of
  // subnormals would make |v/|v|| exceed 1 by a percent (found by fuzz_contact).
  static void direction(Real (&v)[3], Real speed) {
    BOOST_MATH_STD_USING
    if (!(speed > 0)) {
      v[0] = v[1] = v[2] = 0;
      return;
    }
    if (speed >= boost::math::tools::min_value<Real>() / boost::math::tools::epsilon<Real>()) {
      for (Real& vi : v) vi /= speed;
      return;
    }
    const Real m = largest(v[0], v[1], v[2]);
    for (Real& vi : v) vi /= m;
    const Real length = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (Real& vi : v) vi /= length;
  }

  // The tangential part v − (v·n)n in place, and its length.  Where v·n
  // overflows for finite v (components near the largest value; found by
  // fuzz_contact), in units of v's largest component: then only a tangential
  // part that itself exceeds the largest value is ∞.
  static Real tangential(Real (&v)[3], const Real (&n)[3]) {
    BOOST_MATH_STD_USING
    Real scale = 1;
    if (!(boost::math::isfinite)(v[0] * n[0] + v[1] * n[1] + v[2] * n[2]) &&
        (boost::math::isfinite)(v[0]) && (boost::math::isfinite)(v[1]) &&
        (boost::math::isfinite)(v[2])) {
      scale = largest(v[0], v[1], v[2]);
      for (Real& vi : v) vi /= scale;
    }
    const Real vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
    for (int i = 0; i < 3; ++i) v[i] -= vn * n[i];
    const Real length = norm(v[0], v[1], v[2]);
    if (scale == 1) return length;
    for (Real& vi : v) vi *= scale;
    return scale * length;
  }

  // The largest |component|.
  static Real largest(Real x, Real y, Real z) {
    BOOST_MATH_STD_USING
    return (std::max)({fabs(x), fabs(y), fabs(z)});
  }

  // √(x² + y² + z²) without overflow or underflow for any finite input.
  static Real norm(Real x, Real y, Real z) {
    BOOST_MATH_STD_USING
    const Real s2 = x * x + y * y + z * z;
    // NaN only from a NaN component (std::max would drop it; found by fuzz_contact).
    if ((boost::math::isnan)(s2)) return s2;
    if (s2 > boost::math::tools::min_value<Real>() && s2 < boost::math::tools::max_value<Real>())
      return sqrt(s2);
    const Real m = largest(x, y, z);
    if (m == 0 || !(boost::math::isfinite)(m)) return m;
    const Real a = x / m, b = y / m, c = z / m;
    return m * sqrt(a * a + b * b + c * c);
  }

  // |F| (≥ 0, against v) and the signed torque about the normal.
  void magnitudes(Real speed, Real spin, Real a, Real N, Real mu, Real& f, Real& t) const {
    BOOST_MATH_STD_USING
    static const char* function = "spinslide::contact_law<%1%>::operator()";
    using Policy = typename Profile::policy_type;
    f = 0;
    t = 0;
    if (!(a > 0) || !(boost::math::isfinite)(a)) {
      f = t = boost::math::policies::raise_domain_error<Real>(
          function, "Got radius = %1%, but the contact radius must be finite and > 0.", a,
          Policy());
      return;
    }
    if (!(N >= 0) || !(mu >= 0) || !(boost::math::isfinite)(N * mu)) {
      f = t = boost::math::policies::raise_domain_error<Real>(
          function, "Got mu*N = %1%, but the normal force and mu must be finite and >= 0.", N * mu,
          Policy());
      return;
    }
    if (!(boost::math::isfinite)(speed) || !(boost::math::isfinite)(spin)) {
      f = t = boost::math::policies::raise_domain_error<Real>(
          function, "Got speed %1%: the velocities must be finite.", speed, Policy());
      return;
    }
    const Real muN = mu * N;
    const Real rim = a * fabs(spin);  // a|ω|
    if (!(muN > 0) || (speed == 0 && rim == 0)) return;
    Real F, T;
    if (rim == 0) {  // pure sliding (also when a|ω| underflows)
      F = 1;
      T = 0;
    } else if (speed == 0) {  // pure spinning
      F = 0;
      T = profile_.mean_radius();
    } else {
      const auto ft = profile_.force_torque(speed / rim);
      F = ft.force;
      T = ft.torque;
    }
    Real scale = 1;
    if (speed < vs_ && rim < vs_) {  // only then can ρ = |(v, aω)| be below v_s
      const Real rho = norm(speed, rim, Real(0));
      if (rho < vs_) scale = rho / vs_;
    }
    // Products without spurious over- or underflow (found by fuzz_contact):
    // μN a overflows where 𝓣 = 0 would make the torque 0, and μN s underflows
    // to 0 where a𝓣 overflows (∞ · 0).
    f = detail::product(muN, F, scale);
    t = -(spin > 0 ? Real(1) : Real(-1)) * detail::product(muN, scale, a, T);
  }

  void law(Real vx, Real vy, Real spin, Real a, Real N, Real mu, Real& fx, Real& fy,
           Real& t) const {
    const Real speed = norm(vx, vy, Real(0));
    Real f;
    magnitudes(speed, spin, a, N, mu, f, t);
    if ((boost::math::isnan)(f)) {  // a domain error, through a policy that does not throw
      fx = fy = f;
      return;
    }
    Real u[3] = {vx, vy, 0};
    direction(u, speed);
    fx = -f * u[0];
    fy = -f * u[1];
  }

  Profile profile_;
  Real vs_;
};

/// The uniform-disk contact law as one call (default regularization).
template <class Vec2, class Real>
planar_friction<Vec2, Real> contact_friction(const Vec2& velocity, Real spin, Real radius,
                                             Real normal_force, Real friction_coefficient) {
  static const contact_law<uniform_disk<Real>> law;
  return law(velocity, spin, radius, normal_force, friction_coefficient);
}

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_HPP
