//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file approximations.hpp
/// The friction models engines use today, written as profiles (force_torque
/// and the three moments), so that they plug into the coupling curve, the
/// terminal analysis, the dynamics and the contact law exactly like the
/// exact law, for comparison (docs/approximations.md).
///
/// Each is parametrised by the moments of the profile it imitates (the
/// uniform disk by default: ⟨r⟩ = 2/3, ⟨1/r⟩ = 2, ⟨r²⟩ = 1/2).  Their
/// "moments" are the ones their own limits imply through docs/theory.md (L),
/// +∞ where a limit does not exist, which is what the terminal analysis needs.

#ifndef SPINSLIDE_VALUES_APPROXIMATIONS_HPP
#define SPINSLIDE_VALUES_APPROXIMATIONS_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/base/detail/product.hpp>
#include <spinslide/values/profile_base.hpp>
#include <spinslide/values/profile_concept.hpp>

#include <cmath>
#include <limits>

namespace spinslide {

/// Uncoupled caps: |F| = μN whenever sliding, |T| = μN⟨r⟩a whenever spinning,
/// independently — Bullet's m_spinningFriction, the torsional rows of ODE and
/// Gazebo, Chrono's spinning friction, Box2D's b2FrictionJoint maxTorque,
/// PhysX's torsional patch, LAMMPS "marshall" twisting, YADE, MercuryDPM.
/// 𝓕(ε) = 1 and 𝓣(ε) = ⟨r⟩ for 0 < ε < ∞.
template <class Real = double, class Policy = boost::math::policies::policy<>>
class uncoupled_caps : public profile_base<uncoupled_caps<Real, Policy>, Real, Policy> {
 public:
  /// 𝓕 and 𝓣 are capped independently: the limit set is a box (has_box_limit_set).
  static constexpr bool box_limit_set = true;
  /// `torque_cap` = ⟨r⟩ of the imitated profile (the torque cap in units of
  /// μNa): finite and at least the smallest normal number, otherwise
  /// std::domain_error.
  explicit uncoupled_caps(Real torque_cap = Real(2) / 3)
      : cap_(detail::checked_constructor_argument<Policy>(
            "spinslide::uncoupled_caps<%1%>::uncoupled_caps(%1%)", "torque_cap", torque_cap,
            detail::argument_rule::normal_positive)) {}
  /// ⟨r⟩ = the cap.
  Real mean_radius() const { return cap_; }
  /// ∞: the force jumps to 1 at any ε > 0.
  Real mean_inverse_radius() const { return std::numeric_limits<Real>::infinity(); }
  /// ∞: the torque stays at the cap for every finite ε.
  Real mean_square_radius() const { return std::numeric_limits<Real>::infinity(); }

 private:
  friend class profile_base<uncoupled_caps, Real, Policy>;
  static constexpr const char* name = "spinslide::uncoupled_caps<%1%>";
  force_torque_result<Real> general(Real) const { return {Real(1), cap_}; }

  Real cap_;
};

/// The ellipsoidal limit surface (robotics) and MuJoCo's elliptic cone:
/// (𝓕/1)² + (𝓣/τ)² = 1, with the direction given by maximum dissipation
/// (the normal of the curve along (v, aω)):
///   𝓕 = ε/√(ε² + τ²),   𝓣 = τ²/√(ε² + τ²).
/// τ is the torque semi-axis in units of μNa: ⟨r⟩ matches the imitated
/// profile's pure-spinning torque; MuJoCo's torsional coefficient μ_t (a
/// length) corresponds to τ = μ_t/(μa).
template <class Real = double, class Policy = boost::math::policies::policy<>>
class elliptic_limit_surface
    : public profile_base<elliptic_limit_surface<Real, Policy>, Real, Policy> {
 public:
  /// `torque_axis` = τ: finite and at least the smallest normal number,
  /// otherwise std::domain_error.
  explicit elliptic_limit_surface(Real torque_axis = Real(2) / 3)
      : tau_(detail::checked_constructor_argument<Policy>(
            "spinslide::elliptic_limit_surface<%1%>::elliptic_limit_surface(%1%)", "torque_axis",
            torque_axis, detail::argument_rule::normal_positive)) {}
  /// τ = 𝓣(0).
  Real mean_radius() const { return tau_; }
  /// 2/τ, so that 𝓕′(0) = 1/τ = ⟨1/r⟩/2.
  Real mean_inverse_radius() const { return 2 / tau_; }  // 𝓕′(0) = 1/τ
  /// 2τ², so that ε𝓣 → τ² = ⟨r²⟩/2.
  Real mean_square_radius() const { return 2 * tau_ * tau_; }  // ε𝓣 → τ²

 private:
  friend class profile_base<elliptic_limit_surface, Real, Policy>;
  static constexpr const char* name = "spinslide::elliptic_limit_surface<%1%>";
  force_torque_result<Real> general(Real eps) const {
    BOOST_MATH_STD_USING
    const Real h = hypot(eps, tau_);
    return {eps / h, tau_ * (tau_ / h)};  // τ/h ≤ 1: no overflow for any τ
  }

  Real tau_;
};

/// First-order two-point Padé approximants, matched to the exact limits
/// (docs/theory.md (L)) at ε → 0 and ε → ∞:
///   𝓕 = ε/(ε + 2/⟨1/r⟩),   𝓣 = ⟨r⟩⟨r²⟩/(⟨r²⟩ + 2⟨r⟩ε),
/// so 𝓕′(0) = ⟨1/r⟩/2, 𝓕(∞) = 1, 𝓣(0) = ⟨r⟩, ε𝓣 → ⟨r²⟩/2.
template <class Real = double, class Policy = boost::math::policies::policy<>>
class pade_approximation : public profile_base<pade_approximation<Real, Policy>, Real, Policy> {
 public:
  /// 𝓣′ ≠ −ε𝓕′: no pressure gives these curves (obeys_maximum_dissipation).
  static constexpr bool maximum_dissipation = false;
  /// The approximants for the moments ⟨r⟩, ⟨1/r⟩, ⟨r²⟩ (each finite and at
  /// least the smallest normal number, otherwise std::domain_error); the
  /// defaults are the uniform disk's.
  pade_approximation(Real mean_radius = Real(2) / 3, Real mean_inverse_radius = 2,
                     Real mean_square_radius = Real(1) / 2)
      : r_(moment("mean_radius", mean_radius)),
        inv_(moment("mean_inverse_radius", mean_inverse_radius)),
        sq_(moment("mean_square_radius", mean_square_radius)) {}
  /// Matched to a profile's moments.
  template <class Profile>
  static pade_approximation matching(const Profile& p) {
    static_assert(detail::requires_profile<Profile>());
    return pade_approximation(p.mean_radius(), p.mean_inverse_radius(), p.mean_square_radius());
  }
  /// ⟨r⟩ as given.
  Real mean_radius() const { return r_; }
  /// ⟨1/r⟩ as given.
  Real mean_inverse_radius() const { return inv_; }
  /// ⟨r²⟩ as given.
  Real mean_square_radius() const { return sq_; }

 private:
  friend class profile_base<pade_approximation, Real, Policy>;
  static constexpr const char* name = "spinslide::pade_approximation<%1%>";
  force_torque_result<Real> general(Real eps) const {
    // Written so that no intermediate over- or underflows for any moments in
    // [min, max] and any ε (fuzz_profiles and fuzz_coupling found four ways):
    // with x = ε⟨r⟩/⟨r²⟩ and y = ε⟨1/r⟩/2, each a three-factor product that
    // may be ∞ only where it truly overflows,
    //   𝓣 = ⟨r⟩/(1 + 2x), or for x > 1 the same as (⟨r²⟩/ε)/2/(1 + 1/(2x)),
    //   𝓕 = y/(1 + y),    or for y > 1 the same as 1/(1 + 1/y),
    // where ⟨r²⟩/ε < ⟨r⟩ when x > 1, so 𝓣 ≈ ⟨r²⟩/(2ε) stays finite and exact.
    BOOST_MATH_STD_USING
    int e = 0;
    const Real m = frexp(sq_, &e);  // 1/⟨r²⟩ = (1/m)·2^−e, each factor exact or normal
    const Real x = detail::product(eps, r_, 1 / m, Real(ldexp(Real(1), -e)));
    const Real y = detail::product(eps, inv_, Real(0.5));
    const Real torque = x > 1 ? Real(sq_ / eps / 2 / (1 + 1 / (2 * x))) : Real(r_ / (1 + 2 * x));
    const Real force = y > 1 ? Real(1 / (1 + 1 / y)) : Real(y / (1 + y));
    return {force, torque};
  }

  static Real moment(const char* which, Real x) {
    return detail::checked_constructor_argument<Policy>(
        "spinslide::pade_approximation<%1%>::pade_approximation(%1%, %1%, %1%)", which, x,
        detail::argument_rule::normal_positive);
  }
  Real r_, inv_, sq_;
};

}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_APPROXIMATIONS_HPP
