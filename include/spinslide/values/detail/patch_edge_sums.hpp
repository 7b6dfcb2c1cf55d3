//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file patch_edge_sums.hpp
/// The exact friction integrals of a polygon (or a segment) under a linear
/// pressure about an instantaneous centre c near the patch, as sums over the
/// edges of elementary functions (docs/patches.md, "The closed form"):
///   G = ∬ p r̂ dA,   H = ∬ p |r| dA,   r = x − c.
/// Along an edge r = h n + s t (n the outward normal, h = r·n constant,
/// ρ = √(s² + h²)); every term is a polynomial in s times ρ plus h² times
///   Λ = ∫ ds/ρ = asinh(s₁/|h|) − asinh(s₀/|h|).
/// The sums cancel as |c| grows (the force loses ~|c|/ℓ, the torque
/// ~(|c|/ℓ)²); the caller uses them only for |c − z₀| < 4ρ₀
/// (patch_far_field.hpp beyond).

#ifndef SPINSLIDE_VALUES_DETAIL_PATCH_EDGE_SUMS_HPP
#define SPINSLIDE_VALUES_DETAIL_PATCH_EDGE_SUMS_HPP

#include <spinslide/values/detail/patch_geometry.hpp>

#include <boost/math/special_functions/hypot.hpp>
#include <boost/math/special_functions/log1p.hpp>

#include <cmath>
#include <cstddef>

namespace spinslide {
namespace detail {

/// G = ∬ p r̂ and H = ∬ p |r| of a patch about its instantaneous centre.
template <class Real>
struct centre_integrals {
  point2<Real> G{};
  Real H = 0;
};

/// One edge (or segment) from r = a to r = b: its frame and the elementary
/// integrals ∫ρ, ∫sρ, ∫ρ³, ∫s/ρ, ∫s²/ρ, ∫1/ρ (times h where h = 0 makes it 0).
template <class Real>
struct edge_terms {
  point2<Real> t, n;  ///< unit tangent, outward normal (for a counter-clockwise polygon)
  Real h;             ///< r·n along the edge
  Real K;             ///< ∫ρ ds = ½[sρ]₀¹ + ½h²Λ
  Real I1;            ///< ∫sρ ds = [ρ³]₀¹/3
  Real J3;            ///< ∫ρ³ ds = ([sρ³]₀¹ + 3h²K)/4
  Real D1;            ///< ∫s/ρ ds = ρ₁ − ρ₀
  Real D2;            ///< ∫s²/ρ ds = ½[sρ]₀¹ − ½h²Λ
  Real hL;            ///< hΛ (0 for h = 0: the segment passes through c)
  Real rho0, rho1;    ///< |r| at the ends
  Real s0, s1;        ///< s at the ends
};

/// Λ = asinh(s₁/|h|) − asinh(s₀/|h|) without cancellation, by one log1p
/// (asinh(s/|h|) = ln((s + ρ)/|h|); s₁ − s₀ = L, D₁ = ρ₁ − ρ₀ = L(s₀ + s₁)/(ρ₀ + ρ₁)):
///  - 0 < s₀ < s₁:  Λ = ln((s₁ + ρ₁)/(s₀ + ρ₀)) = log1p((L + D₁)/(s₀ + ρ₀)), D₁ > 0;
///  - s₀ < s₁ < 0:  Λ = ln((ρ₀ − s₀)/(ρ₁ − s₁)) = log1p((L − D₁)/(ρ₁ − s₁)), D₁ < 0;
///  - s₀ ≤ 0 ≤ s₁:  Λ = ln((1 + a)(1 + b)) = log1p(a + b + ab) with
///    a = (s₁ + ρ₁ − |h|)/|h| = (s₁ + s₁²/(ρ₁ + |h|))/|h| ≥ 0 and b the same of −s₀;
/// every argument a sum of non-negative terms.  (It replaced asinh, A&S
/// 4.5.24's difference form: one log1p costs half of asinh plus its log.)
template <class Real>
Real asinh_difference(Real s0, Real s1, Real rho0, Real rho1, Real h, Real length, Real d1) {
  BOOST_MATH_STD_USING
  // The standard library's log1p for the built-in types (Boost's, with its
  // policy checks, costs more); multiprecision types find theirs by ADL.
  using std::log1p;
  if (s0 > 0) return log1p((length + d1) / (s0 + rho0));
  if (s1 < 0) return log1p((length - d1) / (rho1 - s1));
  const Real ah = fabs(h);
  const Real a = (s1 + s1 * s1 / (rho1 + ah)) / ah, b = (s0 * s0 / (rho0 + ah) - s0) / ah;
  return log1p(a + b + a * b);
}

template <class Real>
edge_terms<Real> edge_integrals(const point2<Real>& a, const point2<Real>& b) {
  BOOST_MATH_STD_USING
  edge_terms<Real> e{};
  const point2<Real> d = minus(b, a);
  // sqrt(x² + y²), not hypot: the near sums see lengths of the patch's size.
  const Real L = sqrt(d[0] * d[0] + d[1] * d[1]);
  if (!(L > 0)) return e;  // a repeated vertex (a clip through a vertex): no edge
  e.t = {d[0] / L, d[1] / L};
  e.n = {e.t[1], -e.t[0]};
  e.h = dot(a, e.n);
  const Real s0 = dot(a, e.t), s1 = dot(b, e.t);
  const Real rho0 = sqrt(a[0] * a[0] + a[1] * a[1]), rho1 = sqrt(b[0] * b[0] + b[1] * b[1]);
  const Real h2 = e.h * e.h;
  // ρ₁² − ρ₀² = s₁² − s₀² = L(s₀ + s₁): the differences of powers of ρ without cancellation.
  const Real sum = rho0 + rho1;
  e.D1 = sum > 0 ? Real(L * (s0 + s1) / sum) : Real(0);
  const Real lambda = e.h == 0 ? Real(0) : asinh_difference(s0, s1, rho0, rho1, e.h, L, e.D1);
  const Real srho = s1 * rho1 - s0 * rho0;
  e.K = (srho + h2 * lambda) / 2;
  e.I1 = e.D1 * (rho1 * rho1 + rho1 * rho0 + rho0 * rho0) / 3;
  e.J3 = (s1 * rho1 * rho1 * rho1 - s0 * rho0 * rho0 * rho0 + 3 * h2 * e.K) / 4;
  e.D2 = (srho - h2 * lambda) / 2;
  e.hL = e.h * lambda;
  e.rho0 = rho0;
  e.rho1 = rho1;
  e.s0 = s0;
  e.s1 = s1;
  return e;
}

/// G and H of the polygon `poly` (counter-clockwise, about the origin) under
/// p = α + β·x, about c (docs/patches.md, "The closed form"):
///   ∬ r̂ = Σ K n,  ∬ |r| = ⅓ Σ h K,  ∬ r (β·r)/|r| = Σ (hK n + I₁ t)(β·n) − β ∬|r|,
///   ∬ (β·r)|r| = ⅓ Σ (β·n) J₃.
template <class Real, std::size_t N>
centre_integrals<Real> polygon_centre_integrals(const vertex_list<Real, N>& poly, Real alpha,
                                                const point2<Real>& beta, const point2<Real>& c) {
  point2<Real> uniform{}, linear{};
  Real H0 = 0, H1 = 0;
  const std::size_t n = poly.size();
  point2<Real> a = minus(poly[0], c);
  const point2<Real> first = a;
  for (std::size_t i = 0; i < n; ++i) {
    const point2<Real> b = i + 1 == n ? first : minus(poly[i + 1], c);
    const edge_terms<Real> e = edge_integrals(a, b);
    const Real bn = dot(beta, e.n);
    uniform[0] += e.K * e.n[0];
    uniform[1] += e.K * e.n[1];
    linear[0] += (e.h * e.K * e.n[0] + e.I1 * e.t[0]) * bn;
    linear[1] += (e.h * e.K * e.n[1] + e.I1 * e.t[1]) * bn;
    H0 += e.h * e.K;
    H1 += bn * e.J3;
    a = b;
  }
  H0 /= 3;
  H1 /= 3;
  const Real pc = alpha + dot(beta, c);
  return {{pc * uniform[0] + linear[0] - beta[0] * H0, pc * uniform[1] + linear[1] - beta[1] * H0},
          pc * H0 + H1};
}

/// G and H of the segment from x₀ to x₁ under the line density p = α + β·x
/// (β along the segment), about c: with q = a₀ + a₁s, a₀ = p(c) + h β·n,
/// a₁ = β·t (docs/patches.md, "The line patch"):
///   G = n (a₀hΛ + a₁h D₁) + t (a₀D₁ + a₁D₂),   H = a₀K + a₁I₁.
template <class Real>
centre_integrals<Real> segment_centre_integrals(const point2<Real>& x0, const point2<Real>& x1,
                                                Real alpha, const point2<Real>& beta,
                                                const point2<Real>& c) {
  const edge_terms<Real> e = edge_integrals(minus(x0, c), minus(x1, c));
  const Real a0 = alpha + dot(beta, c) + e.h * dot(beta, e.n), a1 = dot(beta, e.t);
  const Real gn = a0 * e.hL + a1 * e.h * e.D1, gt = a0 * e.D1 + a1 * e.D2;
  return {{gn * e.n[0] + gt * e.t[0], gn * e.n[1] + gt * e.t[1]}, a0 * e.K + a1 * e.I1};
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DETAIL_PATCH_EDGE_SUMS_HPP
