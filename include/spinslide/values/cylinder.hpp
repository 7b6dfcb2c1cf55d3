//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file cylinder.hpp
/// The paper's cylinder standing on one face (docs/theory.md §10): friction
/// at the contact makes a tipping moment about the centre of mass, at height
/// h, which tilts the pressure — higher at the front — and the tilted
/// pressure turns part of the friction sideways, along v × ω: the path curves.
/// Past a centre of pressure of R/4 the rear of the face lifts off (the
/// pressure stays linear where it is positive); the cylinder tips only when no
/// pressure on the face balances the moment, an outcome of
/// tilted_cylinder_friction, not an error.

#ifndef SPINSLIDE_VALUES_CYLINDER_HPP
#define SPINSLIDE_VALUES_CYLINDER_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/base/friction_result.hpp>
#include <spinslide/values/disk.hpp>

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/asinh.hpp>
#include <boost/math/special_functions/hypot.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace spinslide {

/// The three area integrals of a linearly tilted pressure (theory §10), in
/// the frame e_v = x̂, e_ω = ẑ of the unit disk, ρ = √(x² + (y − ε)²):
///   A(ε) = (1/π) ∬ y (ε − y)/ρ,   B(ε) = (1/π) ∬ x²/ρ,   C(ε) = (1/π) ∬ y (x² + y² − εy)/ρ.
/// 𝓣 = B − A is an identity the tests check.
template <class Real>
struct tilt_integrals {
  using value_type = Real;  ///< the floating type
  Real A;                   ///< (1/π) ∬ y (ε − y)/ρ
  Real B;                   ///< (1/π) ∬ x²/ρ
  Real C;                   ///< (1/π) ∬ y (x² + y² − εy)/ρ
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

/// Friction, per unit μN, of the truncated linear pressure on a segment of
/// the unit face (theory §10): p ∝ max(0, n·r − cos θ), n = (cos φ, sin φ)
/// in the frame x along v, y to the left of the motion for a counter-clockwise
/// spin; the contact is the segment n·r ≥ cos θ, of half-angle θ.  θ = π is
/// the whole face under p ∝ 1 + n·r, the last full contact.  A
/// friction_result: `force` = (along the velocity, along y) per μN, `torque`
/// about the normal per μNR (negative: opposes the spin), `ratio` ε; and the
/// centre of pressure.
template <class Real>
struct segment_friction : friction_result<std::array<Real, 2>, Real> {
  Real centre;  ///< distance of the centre of pressure from the axis, per R (along n)
};

namespace detail {

/// The chord u = cos ψ of the unit disk (rotated frame u along n, w along
/// ẑ × n; the instantaneous centre at (u0, w0)), integrated in closed form
/// over w: with a = u − u0, s = w − w0, ρ = √(a² + s²),
///   J0 = ∫ds/ρ,  J1 = ∫s/ρ ds,  J2 = ∫s²/ρ ds = [sρ − a²J0]/2 (endpoints).
/// Returns the chord's force along n and along ẑ × n and its torque, per
/// unit pressure: −v̂ = (s n − a m)/ρ and −r·(r − r0)/ρ.
template <class Real>
std::array<Real, 3> chord_friction(Real psi, Real u0, Real w0) {
  BOOST_MATH_STD_USING
  const Real u = cos(psi), W = sin(psi);
  const Real a = u - u0, hi = W - w0, lo = -W - w0;
  const Real rho_hi = boost::math::hypot(a, hi), rho_lo = boost::math::hypot(a, lo);
  const Real J0 =
      a == 0 ? Real(0) : Real(boost::math::asinh(hi / fabs(a)) - boost::math::asinh(lo / fabs(a)));
  const Real J1 = rho_hi + rho_lo > 0 ? Real(-4 * W * w0 / (rho_hi + rho_lo)) : Real(0);
  const Real J2 = (hi * rho_hi - lo * rho_lo - a * a * J0) / 2;
  return {J1, -a * J0, -(u * a * J0 + J2 + w0 * J1)};
}

/// ∫₀^θ f(ψ) dψ by tanh_sinh, split at ψ0 (where the chord meets the
/// instantaneous centre) when 0 < ψ0 < θ.  Each piece starts at 0: Boost
/// 1.74's tanh_sinh loses the endpoint complement for a left end |a| ≥ 1/2.
template <class Real, class F>
Real integrate_segment(F f, Real theta, Real psi0) {
  static thread_local boost::math::quadrature::tanh_sinh<Real> q;
  const Real tol = boost::math::tools::root_epsilon<Real>();
  if (!(psi0 > 0 && psi0 < theta)) return q.integrate(f, Real(0), theta, tol);
  return q.integrate(f, Real(0), psi0, tol) +
         q.integrate([&](Real t) { return f(psi0 + t); }, Real(0), theta - psi0, tol);
}

/// The pressure weight on the segment of half-angle θ at u = cos ψ:
/// cos ψ − cos θ = 2 sin((θ + ψ)/2) sin((θ − ψ)/2) (no cancellation on thin
/// segments).
template <class Real>
Real segment_weight(Real theta, Real psi) {
  BOOST_MATH_STD_USING
  return 2 * sin((theta + psi) / 2) * sin((theta - psi) / 2);
}

/// The load ∫ p dA and the lever ∫ p (1 − u) dA of the segment (1 − ζ =
/// lever/load without cancellation), independent of ε and φ.
template <class Real>
std::array<Real, 2> segment_load(Real theta) {
  BOOST_MATH_STD_USING
  const Real load = integrate_segment(
      [&](Real psi) {
        const Real s = sin(psi);
        return Real(2 * segment_weight(theta, psi) * s * s);
      },
      theta, Real(-1));
  const Real lever = integrate_segment(
      [&](Real psi) {
        const Real h = sin(psi / 2), s = sin(psi);
        return Real(4 * h * h * segment_weight(theta, psi) * s * s);
      },
      theta, Real(-1));
  return {load, lever};
}

/// The friction of the segment of half-angle θ and direction φ, given its
/// `load` (segment_load); the torque only if `with_torque` (else 0).  ε finite
/// and ≥ 0.
template <class Real>
segment_friction<Real> segment_friction_integrals(Real eps, Real theta, Real phi,
                                                  const std::array<Real, 2>& load,
                                                  bool with_torque = true) {
  BOOST_MATH_STD_USING
  const Real u0 = eps * sin(phi), w0 = eps * cos(phi);
  const Real psi0 = fabs(u0) <= 1 ? Real(acos(u0)) : Real(-1);
  // du = sin ψ dψ; the chord's length element is already in J0, J1, J2.
  auto part = [&](std::size_t k) {
    return integrate_segment(
               [&](Real psi) {
                 return Real(segment_weight(theta, psi) * sin(psi) *
                             chord_friction(psi, u0, w0)[k]);
               },
               theta, psi0) /
           load[0];
  };
  const Real fn = part(0), fm = part(1), t = with_torque ? part(2) : Real(0);
  return {{{fn * cos(phi) - fm * sin(phi), fn * sin(phi) + fm * cos(phi)}, t, false, eps},
          1 - load[1] / load[0]};
}

template <class Real>
segment_friction<Real> segment_friction_integrals(Real eps, Real theta, Real phi) {
  return segment_friction_integrals(eps, theta, phi, segment_load(theta));
}

}  // namespace detail

/// The friction of the truncated linear pressure on the segment of
/// half-angle `contact_angle` θ ∈ (0, π] in the direction `direction` φ
/// (radians, from the velocity towards the left), at ε = v/(Rω) (finite
/// and ≥ 0): the three area integrals, each over the segment,
///   F = −∬ p v̂ / ∬ p,   T = −∬ p r × v̂ / ∬ p,   v̂ = (ε − y, x)/ρ,
/// by one closed-form integral along each chord perpendicular to n and
/// tanh_sinh across the chords.  Bad arguments: a domain error through `pol`.
template <class Real, class Policy = boost::math::policies::policy<>>
segment_friction<Real> truncated_pressure_friction(Real eps, Real contact_angle, Real direction,
                                                   const Policy& pol = Policy()) {
  static const char* function = "spinslide::truncated_pressure_friction<%1%>(%1%, %1%, %1%)";
  using detail::argument_rule;
  Real bad = 0;
  if (!detail::check(function, "eps", eps, argument_rule::finite_non_negative, &bad, pol) ||
      !detail::check(function, "contact_angle", contact_angle, argument_rule::contact_half_angle,
                     &bad, pol) ||
      !detail::check(function, "direction", direction, argument_rule::finite, &bad, pol))
    return {{{bad, bad}, bad, false, bad}, bad};
  return detail::segment_friction_integrals(eps, contact_angle, direction);
}

/// How the cylinder stands: on its whole face, on a segment of it (the rear
/// lifts off), or not at all (no pressure on the face balances the moment:
/// it tips over).
enum class cylinder_contact { full, partial, tipped };

/// Friction on a cylinder (radius R, centre of mass at height h, uniform
/// face) sliding along e_v and spinning with sign s = ±1, per unit μN: a
/// friction_result whose `force` is (along the velocity, sideways along
/// v × ω), whose `torque` is about the normal per μNR (opposing the spin)
/// and whose `ratio` is ε; the centre of pressure (x forward, y' to the left
/// of the motion for s = +1, per R) and the contact.  When `contact` is
/// `tipped` every number is NaN.
template <class Real>
struct cylinder_friction : friction_result<std::array<Real, 2>, Real> {
  std::array<Real, 2> centre;  ///< centre of pressure (forward, along y'), per R
  Real contact_angle;          ///< half-angle θ of the contact segment (π: the whole face)
  cylinder_contact contact;    ///< full, partial (the rear lifts off) or tipped
};

namespace detail {

/// A point of the branch of equilibria at contact half-angle θ: the
/// direction φ with the centre of pressure along −F, and the λ = μh/R it
/// needs, λ = ζ/|F|.  `ok` is false where no direction balances (ε < 1,
/// beyond the end of the branch).
template <class Real>
struct branch_point {
  Real theta, phi, lambda;
  segment_friction<Real> f;
  bool ok;
};

template <class Real, class Policy>
branch_point<Real> branch_at(Real eps, Real theta, const Policy& /*pol: digits*/) {
  BOOST_MATH_STD_USING
  const Real pi = boost::math::constants::pi<Real>();
  const auto load = segment_load(theta);
  auto cross = [&](Real phi) {
    const auto f = segment_friction_integrals(eps, theta, phi, load, false);
    return Real(sin(phi) * f.force[0] - cos(phi) * f.force[1]);  // n × (−F)
  };
  branch_point<Real> b{theta, 0, 0, {}, false};
  Real hi = 0, f_hi = cross(Real(0));
  if (!(f_hi > 0)) return b;
  for (Real step : {pi / 2, 3 * pi / 4, pi}) {
    const Real lo = hi, f_lo = f_hi;
    hi = step;
    f_hi = cross(hi);
    if (f_hi > 0) continue;
    boost::uintmax_t iterations = 100;
    const auto r = boost::math::tools::toms748_solve(
        cross, lo, hi, f_lo, f_hi,
        boost::math::tools::eps_tolerance<Real>(boost::math::policies::digits<Real, Policy>() - 3),
        iterations);
    b.phi = (r.first + r.second) / 2;
    b.f = segment_friction_integrals(eps, theta, b.phi, load);
    b.ok = cos(b.phi) * b.f.force[0] + sin(b.phi) * b.f.force[1] < 0;  // n · F < 0
    b.lambda = b.f.centre / boost::math::hypot(b.f.force[0], b.f.force[1]);
    return b;
  }
  return b;
}

/// Below this contact half-angle the centre of pressure is at the rim to
/// about 3θ²/14 (1e-11 R for double): the cylinder counts as tipped.
template <class Real>
Real tipping_angle() {
  return boost::math::tools::cbrt_epsilon<Real>();
}

/// Narrows [lo, hi] (branch ends at lo, branch point at hi with λ < target)
/// to a point of the branch with λ ≥ target; ε < 1, where λ grows without
/// bound towards the end of the branch.
template <class Real, class Policy>
bool bracket_before_end(Real eps, Real target, Real& lo, Real& hi, const Policy& pol) {
  for (int i = 0; i < 200 && hi - lo > tipping_angle<Real>(); ++i) {
    const Real mid = (lo + hi) / 2;
    const auto b = branch_at(eps, mid, pol);
    if (!b.ok) {
      lo = mid;
    } else if (b.lambda >= target) {
      lo = mid;
      return true;
    } else {
      hi = mid;
    }
  }
  return false;
}

/// A bracket [lo, hi] of contact half-angles with λ(lo) ≥ target > λ(hi),
/// the first met walking the branch from the whole face (θ = π) to the rim;
/// false if the branch reaches the rim first (the cylinder tips).
template <class Real, class Policy>
bool bracket_branch(Real eps, Real target, Real& lo, Real& hi, const Policy& pol) {
  BOOST_MATH_STD_USING
  hi = boost::math::constants::pi<Real>();
  Real best = hi, best_lambda = -1;
  for (Real theta = hi * Real(0.7); theta > tipping_angle<Real>(); theta *= Real(0.7)) {
    const auto b = branch_at(eps, theta, pol);
    lo = theta;
    if (!b.ok) return bracket_before_end(eps, target, lo, hi, pol);
    if (b.lambda >= target) return true;
    if (b.lambda > best_lambda) {
      best_lambda = b.lambda;
      best = theta;
    }
    hi = theta;
  }
  // Near ε = 1 the branch folds: λ rises above its rim value and falls back.
  // The walk's steps may step over the top; find it.
  const Real upper = fmin(best / Real(0.7), boost::math::constants::pi<Real>());
  auto minus_lambda = [&](Real theta) { return -branch_at(eps, theta, pol).lambda; };
  const auto top = boost::math::tools::brent_find_minima(
      minus_lambda, best * Real(0.7), upper, boost::math::policies::digits<Real, Policy>() / 2);
  if (-top.second < target) return false;
  lo = top.first;
  hi = upper;
  return true;
}

// The cylinder's result from its numbers, at ratio ε.
template <class Real>
cylinder_friction<Real> cylinder_result(Real eps, const std::array<Real, 2>& force, Real torque,
                                        const std::array<Real, 2>& centre, Real contact_angle,
                                        cylinder_contact contact) {
  return {{force, torque, false, eps}, centre, contact_angle, contact};
}

template <class Real>
cylinder_friction<Real> tipped_cylinder(Real eps) {
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  return cylinder_result(eps, {nan, nan}, nan, {nan, nan}, nan, cylinder_contact::tipped);
}

/// The root of `excess` in [lo, hi] by TOMS 748, where it falls from at_lo > 0 to
/// at_hi < 0.
template <class Real, class Excess, class Policy>
Real root_between(Excess excess, Real lo, Real hi, Real at_lo, Real at_hi,
                  const Policy& /*digits*/) {
  boost::uintmax_t iterations = 100;
  const auto r = boost::math::tools::toms748_solve(
      excess, lo, hi, at_lo, at_hi,
      boost::math::tools::eps_tolerance<Real>(boost::math::policies::digits<Real, Policy>() - 3),
      iterations);
  return (r.first + r.second) / 2;
}

/// The equilibrium on a segment (λ beyond the full-contact range).
template <class Real, class Policy>
cylinder_friction<Real> partial_contact(Real eps, Real lambda, const Policy& pol) {
  BOOST_MATH_STD_USING
  Real lo = 0, hi = 0;
  if (!bracket_branch(eps, lambda, lo, hi, pol)) return tipped_cylinder(eps);
  auto excess = [&](Real theta) { return branch_at(eps, theta, pol).lambda - lambda; };
  const Real at_lo = excess(lo), at_hi = excess(hi);
  // Just past lift-off the closed form's full-contact test and the branch's
  // λ at the whole face (θ = π) differ by rounding (1.6e-12 at ε = 1.002):
  // the branch may then already carry λ at θ = π, where the closed form did
  // not.  The face is in full contact to that rounding; its answer is the
  // branch's point there (an uncaught toms748 "do not bracket" before).
  const Real theta = !(at_hi < 0)   ? hi
                     : !(at_lo > 0) ? lo
                                    : root_between(excess, lo, hi, at_lo, at_hi, pol);
  const auto b = branch_at(eps, theta, pol);
  return cylinder_result(eps, {b.f.force[0], -b.f.force[1]}, b.f.torque,
                         {b.f.centre * cos(b.phi), b.f.centre * sin(b.phi)}, b.theta,
                         theta == boost::math::constants::pi<Real>() ? cylinder_contact::full
                                                                     : cylinder_contact::partial);
}

/// Pure sliding (ε = ∞): F = −e_v whatever the pressure, so the centre of
/// pressure is λ e_v; the segment with ζ(θ) = λ.
template <class Real, class Policy>
cylinder_friction<Real> sliding_cylinder(Real eps, Real lambda, const Policy& /*pol: digits*/) {
  const Real pi = boost::math::constants::pi<Real>();
  if (lambda <= Real(0.25))
    return cylinder_result(eps, {Real(-1), Real(0)}, Real(0), {lambda, Real(0)}, pi,
                           cylinder_contact::full);
  if (lambda >= 1) return tipped_cylinder(eps);
  auto excess = [&](Real theta) {
    const auto load = segment_load(theta);
    return 1 - load[1] / load[0] - lambda;
  };
  boost::uintmax_t iterations = 100;
  const auto r = boost::math::tools::toms748_solve(
      excess, tipping_angle<Real>(), pi,
      boost::math::tools::eps_tolerance<Real>(boost::math::policies::digits<Real, Policy>() - 3),
      iterations);
  return cylinder_result(eps, {Real(-1), Real(0)}, Real(0), {lambda, Real(0)},
                         Real((r.first + r.second) / 2), cylinder_contact::partial);
}

}  // namespace detail

/// The cylinder's friction with the moment balance solved (theory §10).  The
/// pressure is linear where positive and zero where the face lifts off,
/// p ∝ max(0, 1 + αx + βy'); the centre of pressure must sit at −(μh/R)F
/// (per R, F per μN).  With λ = μh/R:
///  - full contact (`contact == full`, centre of pressure within R/4): the
///    closed form of the linear tilt, κ = 4λ,
///    α = κ𝓕/(1 − κ²AB), β = κBα, F_along = −(𝓕 + βA), F_sideways = αB,
///    T = −(𝓣 + βC), centre of pressure (α, β)/4;
///  - the rear lifted off (`partial`): the contact segment and the direction
///    of the pressure's gradient solved with the friction of that pressure,
///    following the branch of equilibria from full contact as λ grows;
///  - `tipped`: the branch reaches the rim (for ε > 1 at λ = 1; near ε = 1 it
///    folds at a larger λ, 1.0377 at ε = 1) before λ: no pressure on the face
///    balances the moment, and every number is NaN.  For ε < 1 the branch
///    never reaches the rim in this model.
/// Bad arguments (ε < 0 or NaN, h or μ negative, not finite or NaN, R not
/// finite and > 0) are a domain error through `pol`: every number is the
/// policy's NaN.
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
    return detail::cylinder_result(bad, {bad, bad}, bad, {bad, bad}, bad, cylinder_contact::full);
  const Real pi = boost::math::constants::pi<Real>();
  const auto ft = force_torque(eps, pol);
  const Real lambda = friction_coefficient * height / radius, kappa = 4 * lambda;
  if (kappa == 0)
    return detail::cylinder_result(eps, {Real(-ft.force), Real(0)}, Real(-ft.torque),
                                   {Real(0), Real(0)}, pi, cylinder_contact::full);
  if (eps > 1 / boost::math::tools::epsilon<Real>())
    return detail::sliding_cylinder(eps, lambda, pol);
  const auto I = tilted_pressure_integrals(eps, pol);
  const Real det = 1 - kappa * kappa * I.A * I.B;
  const Real alpha = kappa * ft.force / det, beta = kappa * I.B * alpha;
  if (det > 0 && alpha * alpha + beta * beta <= 1)
    return detail::cylinder_result(eps, {Real(-(ft.force + beta * I.A)), Real(alpha * I.B)},
                                   Real(-(ft.torque + beta * I.C)),
                                   {Real(alpha / 4), Real(beta / 4)}, pi, cylinder_contact::full);
  return detail::partial_contact(eps, lambda, pol);
}

}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_CYLINDER_HPP
