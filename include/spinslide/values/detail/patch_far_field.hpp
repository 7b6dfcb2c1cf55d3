//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file patch_far_field.hpp
/// The friction integrals of a patch whose instantaneous centre is far from
/// it (docs/patches.md, "Far centres").  About a point z₀ of the patch, in
/// the frame scaled by ρ₀, with z = (x − z₀)/ρ₀, q = ω z₀ − i v (the centre
/// is c = z₀ − q/ω), W = ωρ₀/q and ζ = W z (|ζ| ≤ 1/R, R = |q|/(|ω|ρ₀)):
///   r̂ = sign(ω) q̂ v/u,   v = (1 + ζ)^{1/2},   u = (1 + ζ̄)^{1/2} = v̄,
/// so that F = −i q̂ S and the torque about z₀ is −ρ₀ Re(q̂ T), with
///   S = ∬ p v/u,   T = ∬ p z̄ v/u,   S_D = ∬ p v u (the dissipation D = |q| S_D).
/// Over a polygon by Green's theorem ∬ f dA = (1/2i)∮ F dz with ∂F/∂z̄ = f:
/// v and p's holomorphic part a + b̄z/2 are constants for ∂/∂z̄, and the
/// antiderivatives in z̄ from 0 are closed forms (s = 1 + W̄t, (u − 1)/W̄ = z̄/(u + 1)):
///   A₀ = ∫ u⁻¹ = 2z̄/(u+1),            A₁ = ∫ t u⁻¹ = ⅔ z̄² (u+2)/(u+1)²,
///   A₂ = ∫ t² u⁻¹ = (2/15) z̄³ (3u² + 9u + 8)/(u+1)³,
///   B₀ = ∫ u = ⅔ z̄ (u² + u + 1)/(u+1),  B₁ = ∫ t u = (2/15) z̄² (3u³ + 6u² + 4u + 2)/(u+1)²,
/// none of them divided by W (ω → 0 is continuous) and none cancelling: F is
/// O(|z|²) (S) or O(|z|³) (T) on each edge, the result O(area).  F is analytic along each edge
/// but at the branch points z = −1/W (the centre) and its image; on the
/// edge z = m + x d, x ∈ [−1, 1], the centre sits at x_c = (−1/W − m)/d, so
/// F is analytic inside the Bernstein ellipse through x_c, of parameter
/// ϱ = a + √(a² − 1), 2a = |x_c − 1| + |x_c + 1|, and n-point Gauss–Legendre
/// errs by O(ϱ^{−2n}) (Trefethen, Approximation Theory and Approximation
/// Practice, Thm. 19.3), times the size of F on the ellipse relative to the
/// result, ~R³ (F is a polynomial of degree 3 in z, z̄ times a series in ζ,
/// so its terms of degree j in x are ~R³(|d|/R)^j; without it the
/// reference rows at 10³ sizes lost 5e-14): each edge takes the fewest of
/// far_rule_sizes with ϱ^{2n} ≥ 2^(digits + 8) R³ (8 bits for the bound's
/// constant; with 0 or 16 no reference row, 4.001 ρ₀ to 2·10⁷ sizes, moves
/// beyond 2e-16).
/// A segment is the same along itself, with v/u = (1 + ζ)/|1 + ζ| and v u = |1 + ζ|.

#ifndef SPINSLIDE_VALUES_DETAIL_PATCH_FAR_FIELD_HPP
#define SPINSLIDE_VALUES_DETAIL_PATCH_FAR_FIELD_HPP

#include <spinslide/values/detail/patch_geometry.hpp>

#include <boost/math/quadrature/gauss.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace spinslide {
namespace detail {

/// A complex number over any Real (std::complex is specified for the
/// built-in types only).
template <class Real>
struct cplx {
  Real re, im;
};
template <class Real>
cplx<Real> operator+(const cplx<Real>& a, const cplx<Real>& b) {
  return {a.re + b.re, a.im + b.im};
}
template <class Real>
cplx<Real> operator*(const cplx<Real>& a, const cplx<Real>& b) {
  return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}
template <class Real>
cplx<Real> operator*(const Real& a, const cplx<Real>& b) {
  return {a * b.re, a * b.im};
}
template <class Real>
cplx<Real> conj(const cplx<Real>& a) {
  return {a.re, -a.im};
}

/// Below this distance ratio R = |c − z₀|/ρ₀ the edge sums are used, above
/// it the far field: the edge sums lose up to ~R² ulp in the torque.
template <class Real>
Real far_crossover() {
  return Real(4);
}

/// Calls f(x, w) for the K-point Gauss–Legendre rule on [−1, 1].
template <class Real, unsigned K, class F>
void gauss_nodes(F& f) {
  using rule = boost::math::quadrature::gauss<Real, K>;
  const auto& x = rule::abscissa();
  const auto& w = rule::weights();
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (K % 2 == 1 && i == 0) {
      f(x[0], w[0]);
    } else {
      f(x[i], w[i]);
      f(Real(-x[i]), w[i]);
    }
  }
}

/// The rule sizes used (Boost tabulates 7, 10, 15, 20, 25 and 30 points for
/// the built-in types; the others are computed once, on first use): dense up
/// to 16, where most edges land, so that few nodes are spent beyond the need.
constexpr std::array<unsigned, 20> far_rule_sizes{3,  4,  5,  6,  7,  8,  9,  10, 11, 12,
                                                  13, 14, 15, 16, 20, 25, 30, 40, 60, 90};

/// Calls f on the rule far_rule_sizes[k].
template <class Real, class F>
void with_far_rule(std::size_t k, F& f) {
  switch (k) {
    case 0:
      return gauss_nodes<Real, 3>(f);
    case 1:
      return gauss_nodes<Real, 4>(f);
    case 2:
      return gauss_nodes<Real, 5>(f);
    case 3:
      return gauss_nodes<Real, 6>(f);
    case 4:
      return gauss_nodes<Real, 7>(f);
    case 5:
      return gauss_nodes<Real, 8>(f);
    case 6:
      return gauss_nodes<Real, 9>(f);
    case 7:
      return gauss_nodes<Real, 10>(f);
    case 8:
      return gauss_nodes<Real, 11>(f);
    case 9:
      return gauss_nodes<Real, 12>(f);
    case 10:
      return gauss_nodes<Real, 13>(f);
    case 11:
      return gauss_nodes<Real, 14>(f);
    case 12:
      return gauss_nodes<Real, 15>(f);
    case 13:
      return gauss_nodes<Real, 16>(f);
    case 14:
      return gauss_nodes<Real, 20>(f);
    case 15:
      return gauss_nodes<Real, 25>(f);
    case 16:
      return gauss_nodes<Real, 30>(f);
    case 17:
      return gauss_nodes<Real, 40>(f);
    case 18:
      return gauss_nodes<Real, 60>(f);
    default:
      return gauss_nodes<Real, 90>(f);
  }
}

/// How many extra bits the rule must resolve (below).
constexpr double far_rule_margin_bits = 8;

/// ln(2^(digits + margin) R³), R = 1/|W|: what ϱ^{2n} must reach (far_rule).
template <class Real>
double far_rule_target(const cplx<Real>& W) {
  const double w = static_cast<double>(W.re * W.re + W.im * W.im);
  return (std::numeric_limits<Real>::digits + far_rule_margin_bits) * 0.6931471805599453 -
         1.5 * std::log(w);
}

/// The rule for the edge z = m + x d when the centre is at −1/W: x_c =
/// −(1 + W m)/(W d), ϱ its Bernstein ellipse (above); the fewest of
/// far_rule_sizes with ϱ^{2n} ≥ 2^(digits + margin) R³ = e^target (the terms
/// of F of degree j in x are ~ R³ (|d|/R)^j).
template <class Real>
std::size_t far_rule(const cplx<Real>& W, const cplx<Real>& m, const cplx<Real>& d, double target) {
  BOOST_MATH_STD_USING
  const cplx<Real> num{-(1 + W.re * m.re - W.im * m.im), -(W.re * m.im + W.im * m.re)};
  const cplx<Real> den = W * d;
  // |x_c ∓ 1| = |num ∓ den|/|den|.
  const Real minus1 = sqrt((num.re - den.re) * (num.re - den.re) +
                           (num.im - den.im) * (num.im - den.im)),
             plus1 = sqrt((num.re + den.re) * (num.re + den.re) +
                          (num.im + den.im) * (num.im + den.im));
  const double a = static_cast<double>((minus1 + plus1) / 2),
               b = static_cast<double>(sqrt(den.re * den.re + den.im * den.im));
  // ϱ = (a + √(a² − b²))/b (a/b the semi-axis).
  const double log_rho = std::log((a + std::sqrt(std::fmax(0.0, (a - b) * (a + b)))) / b);
  const double needed = target / (2 * log_rho);
  // W d underflowing (the centre at infinity: ϱ = ∞, needed NaN or 0) takes the smallest rule.
  if (!(needed > far_rule_sizes[0])) return 0;
  std::size_t k = 0;
  while (k + 1 < far_rule_sizes.size() && !(double(far_rule_sizes[k]) >= needed)) ++k;
  return k;
}

/// S, T and S_D (above), in the patch's scaled frame.
template <class Real>
struct far_sums {
  cplx<Real> S, T, SD;
};

/// The pressure and the expansion variable in the frame scaled by ρ₀ about
/// z₀: p = a + Re(b̄ z), ζ = W z.
template <class Real>
struct far_frame {
  Real a;
  cplx<Real> b, W;
};

/// v = (1 + ζ)^{1/2} (principal; Re(1 + ζ) ≥ 3/4 here, so no cancellation).
template <class Real>
cplx<Real> far_root(const cplx<Real>& zeta) {
  BOOST_MATH_STD_USING
  const Real re = 1 + zeta.re;
  const Real m = sqrt(re * re + zeta.im * zeta.im);
  const Real r = sqrt((m + re) / 2);
  return {r, zeta.im / (2 * r)};
}

/// The Gauss nodes of one edge as arrays: z, the weight w·dz/dx and v =
/// (1 + ζ)^{1/2}, so that the arithmetic after the square roots vectorizes
/// (a loop with std::sqrt does not: it may set errno).
template <class Real>
struct far_batch {
  static constexpr std::size_t capacity = 90;  ///< the largest rule
  std::size_t size = 0;
  std::array<Real, capacity> zr, zi, wr, wi, vr, vi;

  /// Adds the node z with weight wd.
  void push(const cplx<Real>& z, const cplx<Real>& wd) {
    zr[size] = z.re;
    zi[size] = z.im;
    wr[size] = wd.re;
    wi[size] = wd.im;
    ++size;
  }
  /// v at every node.
  void roots(const cplx<Real>& W) {
    for (std::size_t i = 0; i < size; ++i) {
      const cplx<Real> v = far_root(W * cplx<Real>{zr[i], zi[i]});
      vr[i] = v.re;
      vi[i] = v.im;
    }
  }
};

/// The contributions of the Gauss nodes of a polygon's edges to ∮F dz.
template <class Real>
struct far_node {
  const far_frame<Real>& f;
  cplx<Real> half_b, half_bbar;
  bool uniform, with_dissipation;
  cplx<Real> S{Real(0), Real(0)}, T{Real(0), Real(0)}, SD{Real(0), Real(0)};

  // The antiderivatives halved (A₀/2 = g, A₁/2 = g²(u + 2)/3, ...; g = z̄/(u + 1)):
  // the 2 goes into the 1/2i of Green's theorem.  Each node's terms into
  // out (S, T, S_D as re, im pairs), in a loop of its own.
  template <bool Linear, bool Dissipation>
  void terms(const far_batch<Real>& b,
             std::array<std::array<Real, far_batch<Real>::capacity>, 6>& out) const {
    for (std::size_t i = 0; i < b.size; ++i) {
      const cplx<Real> z{b.zr[i], b.zi[i]}, v{b.vr[i], b.vi[i]}, u = conj(v);
      const Real ur = u.re + 1, inverse = 1 / (ur * ur + u.im * u.im);
      const cplx<Real> g = conj(z) * cplx<Real>{ur * inverse, -u.im * inverse};
      const cplx<Real> g2 = g * g;
      const cplx<Real> A1 = (Real(1) / 3) * (g2 * cplx<Real>{u.re + 2, u.im});
      const cplx<Real> lin = cplx<Real>{f.a, Real(0)} + half_bbar * z;
      const cplx<Real> vwd = v * cplx<Real>{b.wr[i], b.wi[i]};
      cplx<Real> s = lin * g, t = lin * A1;
      if (Linear) {
        const cplx<Real> u2 = u * u;
        const cplx<Real> A2 =
            (Real(1) / 15) * (g2 * g * cplx<Real>{3 * u2.re + 9 * u.re + 8, 3 * u2.im + 9 * u.im});
        s = s + half_b * A1;
        t = t + half_b * A2;
      }
      s = s * vwd;
      t = t * vwd;
      out[0][i] = s.re;
      out[1][i] = s.im;
      out[2][i] = t.re;
      out[3][i] = t.im;
      if (Dissipation) {
        const cplx<Real> u2 = u * u, u3 = u2 * u;
        const cplx<Real> B0 = (Real(1) / 3) * (g * cplx<Real>{u2.re + u.re + 1, u2.im + u.im});
        const cplx<Real> B1 =
            (Real(1) / 15) * (g2 * cplx<Real>{3 * u3.re + 6 * u2.re + 4 * u.re + 2,
                                              3 * u3.im + 6 * u2.im + 4 * u.im});
        const cplx<Real> sd = (lin * B0 + half_b * B1) * vwd;
        out[4][i] = sd.re;
        out[5][i] = sd.im;
      }
    }
  }

  /// Adds the nodes of one edge (their roots taken).
  void operator()(const far_batch<Real>& b) {
    std::array<std::array<Real, far_batch<Real>::capacity>, 6> out;
    if (with_dissipation) {
      terms<true, true>(b, out);
    } else if (uniform) {
      terms<false, false>(b, out);
    } else {
      terms<true, false>(b, out);
    }
    for (std::size_t i = 0; i < b.size; ++i) {
      S = S + cplx<Real>{out[0][i], out[1][i]};
      T = T + cplx<Real>{out[2][i], out[3][i]};
      if (with_dissipation) SD = SD + cplx<Real>{out[4][i], out[5][i]};
    }
  }
};

/// Calls f(m, d) for each edge z = m + x d, x ∈ [−1, 1], of the polygon
/// `poly` in the scaled frame z = (x − z0)/rho0.
template <class Real, std::size_t N, class F>
void for_each_far_edge(const vertex_list<Real, N>& poly, const point2<Real>& z0, Real rho0, F&& f) {
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const point2<Real>& next = poly.next(i);
    const cplx<Real> A{(poly[i][0] - z0[0]) / rho0, (poly[i][1] - z0[1]) / rho0};
    const cplx<Real> B{(next[0] - z0[0]) / rho0, (next[1] - z0[1]) / rho0};
    const cplx<Real> d{(B.re - A.re) / 2, (B.im - A.im) / 2};  // dz/dx on [−1, 1]
    f(cplx<Real>{A.re + d.re, A.im + d.im}, d);
  }
}

/// Feeds `node` each edge's Gauss nodes as one batch (their roots taken,
/// far_batch::roots), the rule per edge sized for `target`
/// (far_rule_target): the far field's sums and its Hessian's alike.
template <class Real, std::size_t N, class Node>
void for_each_far_batch(const vertex_list<Real, N>& poly, const point2<Real>& z0, Real rho0,
                        const cplx<Real>& W, double target, Node& node) {
  far_batch<Real> batch;
  for_each_far_edge(poly, z0, rho0, [&](const cplx<Real>& mid, const cplx<Real>& d) {
    batch.size = 0;
    auto at = [&](const Real& x, const Real& w) {
      batch.push({mid.re + x * d.re, mid.im + x * d.im}, {w * d.re, w * d.im});
    };
    with_far_rule<Real>(far_rule(W, mid, d, target), at);
    batch.roots(W);
    node(batch);
  });
}

/// S, T (and S_D if asked) of the polygon `poly` whose scaled vertices are
/// (x − z0)/rho0: Green's theorem with F = v[(a + b̄z/2)A₀ + (b/2)A₁] for S,
/// v[(a + b̄z/2)A₁ + (b/2)A₂] for T, v[(a + b̄z/2)B₀ + (b/2)B₁] for S_D (above).
template <class Real, std::size_t N>
far_sums<Real> polygon_far_integrals(const vertex_list<Real, N>& poly, const point2<Real>& z0,
                                     Real rho0, const far_frame<Real>& f,
                                     bool with_dissipation = false) {
  const cplx<Real> half_b{f.b.re / 2, f.b.im / 2};
  far_node<Real> node{f, half_b, conj(half_b), f.b.re == 0 && f.b.im == 0, with_dissipation};
  for_each_far_batch(poly, z0, rho0, f.W, far_rule_target(f.W), node);
  // ∬ f dA = (1/2i) ∮ F dz = (Im X, −Re X) for X = ∮ F/2 dz.
  return {{node.S.im, -node.S.re}, {node.T.im, -node.T.re}, {node.SD.im, -node.SD.re}};
}

/// S, T (and S_D) of the segment from x₀ to x₁ under the line density
/// p = a + Re(b̄z) (z = (x − z0)/rho0): Gauss–Legendre along it.
template <class Real>
far_sums<Real> segment_far_integrals(const point2<Real>& x0, const point2<Real>& x1,
                                     const point2<Real>& z0, Real rho0, const far_frame<Real>& f,
                                     bool with_dissipation = false) {
  BOOST_MATH_STD_USING
  cplx<Real> S{0, 0}, T{0, 0}, SD{0, 0};
  const cplx<Real> A{(x0[0] - z0[0]) / rho0, (x0[1] - z0[1]) / rho0};
  const cplx<Real> B{(x1[0] - z0[0]) / rho0, (x1[1] - z0[1]) / rho0};
  const cplx<Real> d{(B.re - A.re) / 2, (B.im - A.im) / 2};
  const cplx<Real> mid{A.re + d.re, A.im + d.im};
  const Real half_length = sqrt(d.re * d.re + d.im * d.im);
  auto node = [&](const Real& x, const Real& w) {
    const cplx<Real> z{mid.re + x * d.re, mid.im + x * d.im};
    const cplx<Real> one_zeta{1 + f.W.re * z.re - f.W.im * z.im, f.W.re * z.im + f.W.im * z.re};
    const Real m = sqrt(one_zeta.re * one_zeta.re + one_zeta.im * one_zeta.im);  // |1 + ζ|
    const Real p = f.a + f.b.re * z.re + f.b.im * z.im;
    const Real pw = w * half_length * p;
    const cplx<Real> pg{pw * one_zeta.re / m, pw * one_zeta.im / m};  // p v/u = p(1+ζ)/|1+ζ|
    S = S + pg;
    T = T + conj(z) * pg;
    if (with_dissipation) SD = SD + cplx<Real>{pw * m, Real(0)};
  };
  with_far_rule<Real>(far_rule(f.W, mid, d, far_rule_target(f.W)), node);
  return {S, T, SD};
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DETAIL_PATCH_FAR_FIELD_HPP
