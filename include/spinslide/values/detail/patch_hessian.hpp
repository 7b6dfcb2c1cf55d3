//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file patch_hessian.hpp
/// The Hessian of a patch's dissipation D(v, ω) = ∬ p |u| (docs/patches.md,
/// "Dissipation"): with g = (e_x, e_y, ẑ × x) the derivatives of u and
/// (I − ûûᵀ) = r̂r̂ᵀ, and (ẑ × x)·r̂ = k·r̂ for k = ẑ × c,
///   ∇²D = (1/|ω|) Bᵀ M B,   B = [I | k],   M = ∬ p r rᵀ/|r|³,
/// M by edge sums (from ∂ⱼ(rᵢ/|r|) = δᵢⱼ/|r| − rᵢrⱼ/|r|³ and ∬ 1/|r| = ∮ (r·n)/|r|):
///   ∬ rrᵀ/|r|³ = I Σ hΛ − Σ (hΛ n + D₁ t) nᵀ,
///   ∬ (β·r) rrᵀ/|r|³ = β Gᵤᵀ + Gᵤ βᵀ − Σ (β·n)(h²Λ nnᵀ + hD₁(ntᵀ + tnᵀ) + D₂ ttᵀ),
/// Gᵤ = ∬ r̂ = Σ K n.  ω = 0: ∇²D = (1/|v|) ∬ p (g·n̂)(g·n̂)ᵀ, n̂ ⊥ v̂, from the
/// pressure's moments ∬ p, ∬ p x, ∬ p x xᵀ.

#ifndef SPINSLIDE_VALUES_DETAIL_PATCH_HESSIAN_HPP
#define SPINSLIDE_VALUES_DETAIL_PATCH_HESSIAN_HPP

#include <spinslide/values/detail/patch_edge_sums.hpp>
#include <spinslide/values/detail/patch_geometry.hpp>

#include <boost/math/quadrature/gauss.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace spinslide {
namespace detail {

/// A symmetric 2×2 matrix (xx, xy, yy).
template <class Real>
using sym2 = std::array<Real, 3>;

/// M = ∬ p r rᵀ/|r|³ of the polygon `poly` under p = α + β·x about c.
template <class Real, std::size_t N>
sym2<Real> polygon_inverse_moment(const vertex_list<Real, N>& poly, Real alpha,
                                  const point2<Real>& beta, const point2<Real>& c) {
  Real trace_part = 0;
  sym2<Real> edge_part{}, linear{};
  point2<Real> Gu{};
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const edge_terms<Real> e = edge_integrals(minus(poly[i], c), minus(poly.next(i), c));
    trace_part += e.hL;
    const point2<Real> a{e.hL * e.n[0] + e.D1 * e.t[0], e.hL * e.n[1] + e.D1 * e.t[1]};
    // Σ a nᵀ is symmetric in the sum only: keep its symmetric part.
    edge_part[0] += a[0] * e.n[0];
    edge_part[1] += (a[0] * e.n[1] + a[1] * e.n[0]) / 2;
    edge_part[2] += a[1] * e.n[1];
    Gu[0] += e.K * e.n[0];
    Gu[1] += e.K * e.n[1];
    const Real bn = dot(beta, e.n), h2L = e.h * e.hL, hD = e.h * e.D1;
    linear[0] -= bn * (h2L * e.n[0] * e.n[0] + 2 * hD * e.n[0] * e.t[0] + e.D2 * e.t[0] * e.t[0]);
    linear[1] -= bn * (h2L * e.n[0] * e.n[1] + hD * (e.n[0] * e.t[1] + e.t[0] * e.n[1]) +
                       e.D2 * e.t[0] * e.t[1]);
    linear[2] -= bn * (h2L * e.n[1] * e.n[1] + 2 * hD * e.n[1] * e.t[1] + e.D2 * e.t[1] * e.t[1]);
  }
  linear[0] += 2 * beta[0] * Gu[0];
  linear[1] += beta[0] * Gu[1] + beta[1] * Gu[0];
  linear[2] += 2 * beta[1] * Gu[1];
  const Real pc = alpha + dot(beta, c);
  return {pc * (trace_part - edge_part[0]) + linear[0], pc * (-edge_part[1]) + linear[1],
          pc * (trace_part - edge_part[2]) + linear[2]};
}

/// Λ = ∫ ds/ρ of an edge, also for h = 0: ln|s₁/s₀|·sign(s) beside c, +∞ through it.
template <class Real>
Real edge_lambda(const edge_terms<Real>& e) {
  BOOST_MATH_STD_USING
  if (e.h != 0) return e.hL / e.h;
  if (e.s0 * e.s1 <= 0) return std::numeric_limits<Real>::infinity();
  return e.s0 > 0 ? Real(log(e.s1 / e.s0)) : Real(log(e.s0 / e.s1));  // ∫ ds/|s|
}

/// M = ∫ q r rᵀ/|r|³ ds of the segment x₀→x₁ under q = α + β·x about c, with
/// q = a₀ + a₁s (docs/patches.md, "Dissipation"): ∫ ds/ρ³ = [s/(h²ρ)],
/// ∫ s/ρ³ = −[1/ρ], ∫ s²/ρ³ = Λ − [s/ρ], ∫ s³/ρ³ = D₁ + h²[1/ρ].  +∞ where the
/// segment passes through c (pivoting about a point of it).
template <class Real>
sym2<Real> segment_inverse_moment(const point2<Real>& x0, const point2<Real>& x1, Real alpha,
                                  const point2<Real>& beta, const point2<Real>& c) {
  const edge_terms<Real> e = edge_integrals(minus(x0, c), minus(x1, c));
  const Real lambda = edge_lambda(e);
  const Real a0 = alpha + dot(beta, c) + e.h * dot(beta, e.n), a1 = dot(beta, e.t);
  const Real inv = 1 / e.rho1 - 1 / e.rho0, sr = e.s1 / e.rho1 - e.s0 / e.rho0;
  const Real nn = a0 * sr - a1 * e.h * e.h * inv;
  const Real nt = e.h == 0 ? Real(0) : Real(e.h * (-a0 * inv + a1 * (lambda - sr)));
  const Real tt = a0 * (lambda - sr) + a1 * (e.D1 + e.h * e.h * inv);
  const point2<Real>& n = e.n;
  const point2<Real>& t = e.t;
  return {nn * n[0] * n[0] + 2 * nt * n[0] * t[0] + tt * t[0] * t[0],
          nn * n[0] * n[1] + nt * (n[0] * t[1] + t[0] * n[1]) + tt * t[0] * t[1],
          nn * n[1] * n[1] + 2 * nt * n[1] * t[1] + tt * t[1] * t[1]};
}

/// (1/|ω|) Bᵀ M B, B = [I | k], as a symmetric 3×3 (row-major).
template <class Real>
std::array<std::array<Real, 3>, 3> hessian_from(const sym2<Real>& M, const point2<Real>& k,
                                                Real scale) {
  const Real mk0 = M[0] * k[0] + M[1] * k[1], mk1 = M[1] * k[0] + M[2] * k[1];
  const Real kmk = k[0] * mk0 + k[1] * mk1;
  return {{{scale * M[0], scale * M[1], scale * mk0},
           {scale * M[1], scale * M[2], scale * mk1},
           {scale * mk0, scale * mk1, scale * kmk}}};
}

/// ∬ p x xᵀ of the polygon under p = α + β·x: the triangles fanned from the
/// first vertex, mapped from the square (Duffy), 3 × 3 Gauss points (exact
/// for the cubic p x xᵀ times the map's Jacobian).
template <class Real, std::size_t N>
sym2<Real> pressure_second_moment(const vertex_list<Real, N>& poly, Real alpha,
                                  const point2<Real>& beta) {
  using rule = boost::math::quadrature::gauss<Real, 3>;
  sym2<Real> m{};
  const auto& x = rule::abscissa();
  const auto& w = rule::weights();
  // The 3 nodes on [−1, 1]: 0 and ±x[1].
  const std::array<Real, 3> node{x[0], x[1], Real(-x[1])}, weight{w[0], w[1], w[1]};
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
    const point2<Real> e1 = minus(poly[i], poly[0]), e2 = minus(poly[i + 1], poly[0]);
    const Real jac = cross(e1, e2);
    for (std::size_t a = 0; a < 3; ++a) {
      for (std::size_t b = 0; b < 3; ++b) {
        const Real u = (node[a] + 1) / 2, t = (node[b] + 1) / 2;
        const point2<Real> y{poly[0][0] + u * (1 - t) * e1[0] + u * t * e2[0],
                             poly[0][1] + u * (1 - t) * e1[1] + u * t * e2[1]};
        const Real f = jac * weight[a] * weight[b] * u / 4 * (alpha + dot(beta, y));
        m[0] += f * y[0] * y[0];
        m[1] += f * y[0] * y[1];
        m[2] += f * y[1] * y[1];
      }
    }
  }
  return m;
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DETAIL_PATCH_HESSIAN_HPP
