//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file cylinder.hpp
/// The paper's cylinder standing on one face (docs/theory.md §10): friction
/// at the contact makes a tipping moment about the centre of mass, at height
/// h, which tilts the pressure — higher at the front — and the tilted
/// pressure turns part of the friction sideways, along v × ω: the path curves.

#ifndef SPINSLIDE_CYLINDER_HPP
#define SPINSLIDE_CYLINDER_HPP

#include <spinslide/detail/checks.hpp>
#include <spinslide/disk.hpp>

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/asinh.hpp>

#include <cmath>

namespace spinslide {

/// The three area integrals of a linearly tilted pressure (theory §10), in
/// the frame e_v = x̂, e_ω = ẑ of the unit disk, ρ = √(x² + (y − ε)²):
///   A(ε) = (1/π) ∬ y (ε − y)/ρ,   B(ε) = (1/π) ∬ x²/ρ,   C(ε) = (1/π) ∬ y (x² + y² − εy)/ρ.
/// 𝓣 = B − A is an identity the tests check.
template <class Real>
struct tilt_integrals {
  Real A;  ///< (1/π) ∬ y (ε − y)/ρ
  Real B;  ///< (1/π) ∬ x²/ρ
  Real C;  ///< (1/π) ∬ y (x² + y² − εy)/ρ
};

/// A, B, C by 2-D quadrature: the chord integral over x in closed form
/// (c = y − ε, X = √(1 − y²), S = √(X² + c²), L = asinh(X/|c|)):
///   ∫ y(ε − y)/ρ dx = −2ycL,  ∫ x²/ρ dx = XS − c²L,  ∫ y(x² + y² − εy)/ρ dx = y[XS + c(y + ε)L],
/// and the y integral by tanh_sinh, split at y = ε.  ε must be finite and
/// ≥ 0; otherwise a domain error through `pol` (NaN components).
template <class Real, class Policy = boost::math::policies::policy<>>
tilt_integrals<Real> tilted_pressure_integrals(Real eps, const Policy& pol = Policy()) {
  BOOST_MATH_STD_USING
  Real invalid = 0;
  if (!detail::check("spinslide::tilted_pressure_integrals<%1%>(%1%)", "eps", eps,
                     detail::argument_rule::finite_non_negative, &invalid, pol))
    return {invalid, invalid, invalid};
  static thread_local boost::math::quadrature::tanh_sinh<Real> q;
  const Real tol = boost::math::tools::root_epsilon<Real>();
  const Real pi = boost::math::constants::pi<Real>();
  auto parts = [eps](Real y, Real& X, Real& S, Real& c, Real& L) {
    X = sqrt((1 - y) * (1 + y));
    c = y - eps;
    S = sqrt(X * X + c * c);
    L = c == 0 ? Real(0) : Real(boost::math::asinh(X / fabs(c)));
  };
  auto fa = [&](Real y) {
    Real X, S, c, L;
    parts(y, X, S, c, L);
    return Real(-2 * y * c * L);
  };
  auto fb = [&](Real y) {
    Real X, S, c, L;
    parts(y, X, S, c, L);
    return Real(X * S - c * c * L);
  };
  auto fc = [&](Real y) {
    Real X, S, c, L;
    parts(y, X, S, c, L);
    return Real(y * (X * S + c * (y + eps) * L));
  };
  auto integrate = [&](auto f) {
    if (eps < 1)
      return Real(q.integrate(f, Real(-1), eps, tol) + q.integrate(f, eps, Real(1), tol));
    return Real(q.integrate(f, Real(-1), Real(1), tol));
  };
  return {integrate(fa) / pi, integrate(fb) / pi, integrate(fc) / pi};
}

/// Friction on a cylinder (radius R, centre of mass at height h, uniform
/// face) sliding along e_v and spinning with sign s = ±1, per unit μN:
/// along the velocity (`along`, ≤ 0), sideways along v × ω (`sideways`), and
/// the torque about the normal per μNR (`torque`, opposing the spin); and the
/// pressure tilt p ∝ 1 + αx/R + βy'/R it implies (x forward, y' to the left
/// of the motion for s = +1).
template <class Real>
struct cylinder_friction {
  Real along;          ///< force along the velocity, per μN (≤ 0)
  Real sideways;       ///< force along v × ω, per μN
  Real torque;         ///< torque about the normal, per μNR, opposing the spin
  Real tilt_forward;   ///< α in p ∝ 1 + αx/R + βy'/R
  Real tilt_sideways;  ///< β in p ∝ 1 + αx/R + βy'/R
};

/// The self-consistent tilt (theory §10): with κ = 4μh/R,
///   α = κ𝓕/(1 − κ²AB),  β = κBα,  F_along = −(𝓕 + βA),  F_sideways = αB,  T = −(𝓣 + βC).
/// h = 0 is the flat disk.  A tilt with α² + β² > 1 would need negative
/// pressure at the rear (the cylinder tips): a domain error through `pol`,
/// as are ε < 0 or NaN, `height` h or `friction_coefficient` μ negative, not
/// finite or NaN, and `radius` R not finite and > 0.  Every component of the
/// result is then the policy's NaN.
template <class Real, class Policy = boost::math::policies::policy<>>
cylinder_friction<Real> tilted_cylinder_friction(Real eps, Real height, Real radius,
                                                 Real friction_coefficient,
                                                 const Policy& pol = Policy()) {
  static const char* function = "spinslide::tilted_cylinder_friction<%1%>(%1%, %1%, %1%, %1%)";
  using detail::argument_rule;
  using detail::check;
  Real bad = 0;
  if (!check(function, "eps", eps, argument_rule::non_negative, &bad, pol) ||
      !check(function, "height", height, argument_rule::finite_non_negative, &bad, pol) ||
      !check(function, "radius", radius, argument_rule::finite_positive, &bad, pol) ||
      !check(function, "friction_coefficient", friction_coefficient,
             argument_rule::finite_non_negative, &bad, pol))
    return {bad, bad, bad, bad, bad};
  const auto ft = force_torque(eps, pol);
  const Real kappa = 4 * friction_coefficient * height / radius;
  if (kappa == 0 || (boost::math::isinf)(eps))
    return {-ft.force, 0, -ft.torque, kappa * ft.force, 0};
  const auto I = tilted_pressure_integrals(eps, pol);
  const Real alpha = kappa * ft.force / (1 - kappa * kappa * I.A * I.B);
  const Real beta = kappa * I.B * alpha;
  if (!(alpha * alpha + beta * beta <= 1) || !(1 - kappa * kappa * I.A * I.B > 0)) {
    bad = detail::raise_argument_error(
        function, "kappa = 4*friction_coefficient*height/radius",
        "small enough that the pressure tilt leaves the rear of the face loaded (else the "
        "cylinder tips over)",
        kappa, pol);
    return {bad, bad, bad, bad, bad};
  }
  return {-(ft.force + beta * I.A), alpha * I.B, -(ft.torque + beta * I.C), alpha, beta};
}

}  // namespace spinslide

#endif  // SPINSLIDE_CYLINDER_HPP
