//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file plate_terminal.hpp
/// How a thrown plate (plate_motion.hpp) ends (docs/plate_dynamics.md, "The
/// terminal flow"): as the twist shrinks, its direction n on the unit sphere
/// of (u, kω) follows dn/ds = −∇_S ln D (s = −ln r), so the possible endings
/// are the critical points of the dissipation D on the sphere, where
/// (F, τ/k) is antiparallel to the twist.  Near one, δn decays as
/// e^{−λs} = (r/r₀)^λ, i.e. as a power λ of the time left, where λ are the
/// eigenvalues of Eᵀ∇²D E/D − I (E a tangent basis, ∇²D in (u, kω)).  The
/// circle ω = 0 (pure sliding) is a family of fixed points (no torque about
/// the centroid); it is not listed.

#ifndef SPINSLIDE_MOTION_PLATE_TERMINAL_HPP
#define SPINSLIDE_MOTION_PLATE_TERMINAL_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/motion/throw_inputs.hpp>
#include <spinslide/values/patch_dissipation.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/policies/policy.hpp>
#include <boost/math/tools/config.hpp>
#include <boost/math/tools/precision.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace spinslide {

/// A fixed point of a plate's direction flow, with ω > 0 (its mirror with
/// ω < 0 is the same point with the slip reversed: direction + π).
template <class Real>
struct plate_fixed_point {
  using value_type = Real;        ///< the floating type
  Real ratio;                     ///< ε* = |u|/(ℓ ω), ℓ = patch.radius()
  Real direction;                 ///< φ*, the slip's angle in the body frame (0 at ε* = 0)
  std::array<Real, 2> exponents;  ///< λ₁ ≤ λ₂: δn ∝ (time left)^λ
  bool stable;                    ///< both exponents > 0: the throws that reach it end here
  std::array<Real, 3> twist;      ///< n = (u, kω)/|(u, kω)|
};

namespace detail {

/// D's value, its gradient and Hessian in (u, kω) at the unit vector n, and
/// a tangent basis e1, e2 of the sphere at n.
template <class Real>
struct sphere_point {
  std::array<Real, 3> n, e1, e2;
  Real value;
  std::array<Real, 2> gradient;             // Eᵀ∇D
  std::array<std::array<Real, 2>, 2> hess;  // Eᵀ∇²D E
};

template <class Real>
std::array<Real, 3> cross3(const std::array<Real, 3>& a, const std::array<Real, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

template <class Real>
Real dot3(const std::array<Real, 3>& a, const std::array<Real, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class Real>
std::array<Real, 3> unit3(const std::array<Real, 3>& a) {
  BOOST_MATH_STD_USING
  const Real norm = sqrt(dot3(a, a));
  return {a[0] / norm, a[1] / norm, a[2] / norm};
}

template <class Real>
sphere_point<Real> sphere_point_at(const polygon_patch<Real>& patch, Real k,
                                   const std::array<Real, 3>& x) {
  BOOST_MATH_STD_USING
  sphere_point<Real> p{};
  p.n = unit3(x);
  const std::array<Real, 3> a =
      fabs(p.n[0]) < Real(0.9) ? std::array<Real, 3>{1, 0, 0} : std::array<Real, 3>{0, 1, 0};
  const Real an = dot3(a, p.n);
  p.e1 = unit3(std::array<Real, 3>{a[0] - an * p.n[0], a[1] - an * p.n[1], a[2] - an * p.n[2]});
  p.e2 = cross3(p.n, p.e1);
  const patch_dissipation<Real> d =
      friction_dissipation(patch, planar_twist<Real>{{p.n[0], p.n[1]}, p.n[2] / k});
  // To (u, kω): ∂/∂(kω) = (1/k) ∂/∂ω.
  const std::array<Real, 3> scale{1, 1, 1 / k};
  std::array<Real, 3> g{};
  std::array<std::array<Real, 3>, 3> h{};
  for (std::size_t i = 0; i < 3; ++i) {
    g[i] = d.gradient[i] * scale[i];
    for (std::size_t j = 0; j < 3; ++j) h[i][j] = d.hessian[i][j] * scale[i] * scale[j];
  }
  p.value = d.value;
  const std::array<const std::array<Real, 3>*, 2> e{&p.e1, &p.e2};
  for (std::size_t i = 0; i < 2; ++i) {
    p.gradient[i] = dot3(*e[i], g);
    for (std::size_t j = 0; j < 2; ++j) {
      const std::array<Real, 3> he{dot3(h[0], *e[j]), dot3(h[1], *e[j]), dot3(h[2], *e[j])};
      p.hess[i][j] = dot3(*e[i], he);
    }
  }
  return p;
}

/// The eigenvalues (ascending) of a symmetric 2×2 matrix.
template <class Real>
std::array<Real, 2> eigenvalues2(const std::array<std::array<Real, 2>, 2>& m) {
  BOOST_MATH_STD_USING
  const Real mean = (m[0][0] + m[1][1]) / 2, half = (m[0][0] - m[1][1]) / 2;
  const Real off = (m[0][1] + m[1][0]) / 2, radius = sqrt(half * half + off * off);
  return {mean - radius, mean + radius};
}

/// Newton's method on the tangent gradient of D (the Riemannian Hessian
/// Eᵀ∇²DE − D·I), steps capped at 0.1 rad, at most 60; true if it converged
/// to a point off the pure-sliding circle.
template <class Real>
bool newton_on_sphere(const polygon_patch<Real>& patch, Real k, std::array<Real, 3>& n) {
  BOOST_MATH_STD_USING
  for (int it = 0; it < 60; ++it) {
    const sphere_point<Real> p = sphere_point_at(patch, k, n);
    const Real a = p.hess[0][0] - p.value, b = (p.hess[0][1] + p.hess[1][0]) / 2,
               c = p.hess[1][1] - p.value, det = a * c - b * b;
    if (!(fabs(det) > 0)) return false;
    Real d1 = -(c * p.gradient[0] - b * p.gradient[1]) / det;
    Real d2 = -(a * p.gradient[1] - b * p.gradient[0]) / det;
    const Real step = sqrt(d1 * d1 + d2 * d2);
    if (step > Real(0.1)) {
      d1 *= Real(0.1) / step;
      d2 *= Real(0.1) / step;
    }
    n = unit3(std::array<Real, 3>{p.n[0] + d1 * p.e1[0] + d2 * p.e2[0],
                                  p.n[1] + d1 * p.e1[1] + d2 * p.e2[1],
                                  p.n[2] + d1 * p.e1[2] + d2 * p.e2[2]});
    if (!(n[2] > Real(1e-6))) return false;
    if (step < 64 * boost::math::tools::epsilon<Real>()) return true;
  }
  const sphere_point<Real> p = sphere_point_at(patch, k, n);
  return fabs(p.gradient[0]) + fabs(p.gradient[1]) < 1024 * boost::math::tools::epsilon<Real>();
}

template <class Real>
plate_fixed_point<Real> fixed_point_at(const polygon_patch<Real>& patch, Real k,
                                       const std::array<Real, 3>& n) {
  BOOST_MATH_STD_USING
  const sphere_point<Real> p = sphere_point_at(patch, k, n);
  std::array<std::array<Real, 2>, 2> m = p.hess;
  for (auto& row : m)
    for (auto& x : row) x /= p.value;
  m[0][0] -= 1;
  m[1][1] -= 1;
  const std::array<Real, 2> ex = eigenvalues2(m);
  // A slip at rounding level is pure spinning (its angle is noise).
  const Real slip = sqrt(n[0] * n[0] + n[1] * n[1]);
  if (!(slip > 64 * boost::math::tools::epsilon<Real>())) return {0, 0, ex, ex[0] > 0, {0, 0, 1}};
  return {slip * k / (patch.radius() * n[2]), Real(atan2(n[1], n[0])), ex, ex[0] > 0, n};
}

}  // namespace detail

/// The fixed points with ω > 0 of the direction flow of a plate with face
/// `patch` (an area patch) and radius of gyration k: Newton's method from a
/// grid of starts (ε from 0.1 to 1.5 every 15° of the slip, and pure
/// spinning), the points closer than 1e-7 merged.  k not finite and > 0 is
/// a domain error through `pol` (an empty list unless it throws).
template <class Real, class Policy = boost::math::policies::policy<>>
std::vector<plate_fixed_point<Real>> plate_terminal_points(const polygon_patch<Real>& patch,
                                                           gyration_radius<Real> radius,
                                                           const Policy& pol = Policy()) {
  BOOST_MATH_STD_USING
  static const char* function = "spinslide::plate_terminal_points<%1%>(polygon_patch, %1%)";
  Real bad = 0;
  std::vector<plate_fixed_point<Real>> points;
  if (!detail::check(function, "gyration_radius", radius.value,
                     detail::argument_rule::finite_positive, &bad, pol))
    return points;
  const Real k = radius.value, ell = patch.radius();
  std::vector<std::array<Real, 3>> starts{{0, 0, 1}};
  for (Real eps : {Real(0.1), Real(0.25), Real(0.4), Real(0.6), Real(0.9), Real(1.5)})
    for (int j = 0; j < 24; ++j) {
      const Real phi = Real(j) * boost::math::constants::pi<Real>() / 12;
      starts.push_back({eps * ell / k * cos(phi), eps * ell / k * sin(phi), 1});
    }
  for (auto n : starts) {
    if (!detail::newton_on_sphere(patch, k, n)) continue;
    bool seen = false;
    for (const auto& p : points) {
      const std::array<Real, 3> d{p.twist[0] - n[0], p.twist[1] - n[1], p.twist[2] - n[2]};
      seen = seen || detail::dot3(d, d) < Real(1e-14);
    }
    if (!seen) points.push_back(detail::fixed_point_at(patch, k, n));
  }
  return points;
}

}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_PLATE_TERMINAL_HPP
