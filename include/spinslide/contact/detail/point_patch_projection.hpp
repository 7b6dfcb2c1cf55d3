//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The projection onto a point patch's limit set (patch_projector.hpp): a
// point contact at x can only push with a force f, |f| ≤ 1, and the torque
// x × f that it has about the origin, so its limit set is the flat disk
// {A f : |f| ≤ 1} with A = [I; aᵀ], a = (−x_y, x_x)/ℓ in the limit set's
// units.  The nearest point to z in the metric M is A f for the f that
// minimizes (Af − z)ᵀM(Af − z) over |f| ≤ 1: with Q = AᵀMA and c = AᵀMz,
// f = Q⁻¹c where that lies in the unit disk, else f = (Q + λI)⁻¹c on the
// circle, λ > 0 the root of 1/|f(λ)| = 1 (Newton's method on that nearly
// linear function, monotone from λ = 0: Moré and Sorensen's choice; it is
// the 2×2 trust-region problem).  Either way the slip s = M(z − Af) moves
// x along −f (Aᵀs = c − Qf = λf), or not at all: a pure rotation about x.
#ifndef SPINSLIDE_CONTACT_DETAIL_POINT_PATCH_PROJECTION_HPP
#define SPINSLIDE_CONTACT_DETAIL_POINT_PATCH_PROJECTION_HPP

#include <spinslide/contact/detail/matrix3.hpp>
#include <spinslide/contact/detail/vector3.hpp>

#include <boost/math/special_functions/hypot.hpp>

#include <array>
#include <cmath>

namespace spinslide {
namespace detail {

// The force f of the nearest point A f.
template <class Real>
std::array<Real, 2> point_patch_force(const std::array<Real, 2>& a, const vector3<Real>& z,
                                      const matrix3<Real>& m) {
  using std::fabs;
  // MA's columns, then Q and c.
  const vector3<Real> c0{m[0][0] + m[0][2] * a[0], m[1][0] + m[1][2] * a[0],
                         m[2][0] + m[2][2] * a[0]};
  const vector3<Real> c1{m[0][1] + m[0][2] * a[1], m[1][1] + m[1][2] * a[1],
                         m[2][1] + m[2][2] * a[1]};
  const Real q00 = c0[0] + a[0] * c0[2], q01 = c1[0] + a[0] * c1[2], q11 = c1[1] + a[1] * c1[2];
  const Real b0 = dot(c0, z), b1 = dot(c1, z);
  // f(λ) = (Q + λI)⁻¹c by the adjugate, with |f|'s derivative.
  const auto solve = [&](Real lambda, Real& norm, Real& slope) {
    const Real d00 = q00 + lambda, d11 = q11 + lambda, det = d00 * d11 - q01 * q01;
    const std::array<Real, 2> f{(d11 * b0 - q01 * b1) / det, (d00 * b1 - q01 * b0) / det};
    // d f/dλ = −(Q + λI)⁻¹ f.
    const std::array<Real, 2> df{-(d11 * f[0] - q01 * f[1]) / det,
                                 -(d00 * f[1] - q01 * f[0]) / det};
    norm = boost::math::hypot(f[0], f[1]);
    slope = norm > 0 ? Real((f[0] * df[0] + f[1] * df[1]) / norm) : Real(0);
    return f;
  };
  Real norm = 0, slope = 0;
  std::array<Real, 2> f = solve(Real(0), norm, slope);
  if (!(norm > 1)) return f;
  // φ(λ) = 1/|f| − 1 rises from < 0, concave: Newton's iterates rise to the root.
  Real lambda = 0;
  for (int k = 0; k < 60; ++k) {
    const Real phi = 1 / norm - 1, dphi = -slope / (norm * norm);
    if (!(dphi > 0)) break;
    const Real next = lambda - phi / dphi;
    if (!(next > lambda)) break;
    lambda = next;
    f = solve(lambda, norm, slope);
    if (fabs(norm - 1) <= 4 * std::numeric_limits<Real>::epsilon()) break;
  }
  // On the circle exactly (the root's last rounding).
  if (norm > 0) f = {f[0] / norm, f[1] / norm};
  return f;
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_POINT_PATCH_PROJECTION_HPP
