//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file patch_multipole.hpp
/// The friction integrals of a patch whose instantaneous centre is far from
/// it, by the complex multipole expansion about a point z₀ of the patch
/// (docs/patches.md, "Far centres").  With z = x − z₀, q = ω z₀ − i v (so
/// that the centre is c = z₀ − q/ω) and ζ = ωz/q (|ζ| ≤ ρ₀|ω|/|q| = 1/R):
///   r̂ = sign(ω) q̂ (1 + ζ)^{1/2} (1 + ζ̄)^{−1/2},
/// so that F = −i q̂ S and the torque about z₀ is −Re(q̂ T), with
///   S = ∬ p P(ζ) Q(ζ̄),   T = ∬ p z̄ P(ζ) Q(ζ̄),
/// P and Q the binomial series of (1 + ζ)^{1/2} and (1 + ζ̄)^{−1/2} to order N
/// (the binomial series, DLMF §4.6), both integrals of polynomials: over a polygon exactly by
/// Green's theorem ∬ f dA = (1/2i)∮ F dz, ∂F/∂z̄ = f, and Gauss–Legendre on
/// each edge; over a segment by Gauss–Legendre along it.  sign(ω) cancels:
/// ω = 0 (ζ = 0) is pure sliding, F = −v̂.  The truncation error is below
/// 4R^{−(N+1)}; N is chosen from R and the type's digits.

#ifndef SPINSLIDE_VALUES_DETAIL_PATCH_MULTIPOLE_HPP
#define SPINSLIDE_VALUES_DETAIL_PATCH_MULTIPOLE_HPP

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
cplx<Real> conj(const cplx<Real>& a) {
  return {a.re, -a.im};
}

/// Below this distance ratio R = |c − z₀|/ρ₀ the edge sums are used, above
/// it the expansion: the edge sums lose up to ~R² ulp in the torque.
template <class Real>
Real multipole_crossover() {
  return Real(4);
}

/// The largest order the expansion uses (at R = 4) for Real.
template <class Real>
constexpr std::size_t max_multipole_order() {
  return static_cast<std::size_t>(std::numeric_limits<Real>::digits + 3) / 2 + 1;
}

/// The order N with 4R^{−(N+1)} below Real's epsilon; 0 for R = ∞ (ω = 0).
template <class Real>
std::size_t multipole_order(Real ratio) {
  const double lr = std::log(static_cast<double>(ratio));
  if (!(lr < std::numeric_limits<double>::max())) return 0;
  const double terms = (std::numeric_limits<Real>::digits + 2) * 0.6931471805599453 / lr;
  const auto n = static_cast<std::size_t>(std::ceil(terms));
  return n < 1 ? 0 : (n - 1 < max_multipole_order<Real>() ? n - 1 : max_multipole_order<Real>());
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

/// The smallest of Boost's rules (tabulated for 7 to 30 points; the others,
/// the 3 to 5 of far centres and the wide ones of types beyond long double,
/// computed once on first use) with at least `needed` points.
template <class Real, class F>
void with_gauss_rule(std::size_t needed, F& f) {
  if (needed <= 3) return gauss_nodes<Real, 3>(f);
  if (needed <= 4) return gauss_nodes<Real, 4>(f);
  if (needed <= 5) return gauss_nodes<Real, 5>(f);
  if (needed <= 7) return gauss_nodes<Real, 7>(f);
  if (needed <= 10) return gauss_nodes<Real, 10>(f);
  if (needed <= 15) return gauss_nodes<Real, 15>(f);
  if (needed <= 20) return gauss_nodes<Real, 20>(f);
  if (needed <= 25) return gauss_nodes<Real, 25>(f);
  if (needed <= 30) return gauss_nodes<Real, 30>(f);
  if (needed <= 40) return gauss_nodes<Real, 40>(f);
  if (needed <= 60) return gauss_nodes<Real, 60>(f);
  return gauss_nodes<Real, 90>(f);
}

/// Gauss points per edge for the expansion of order N.  Exact would be N + 3
/// (degree 2N + 4 in the edge parameter), but a term of degree j + k in
/// (ζ, ζ̄) is of size R^−(j+k): a rule exact to degree 2n − 1 misses only
/// terms below R^−(2n−5), under the truncation's R^−(N+1) for
/// n = (N + 6)/2 + 1 (the crossover rows of patch_reference.csv test it).
inline std::size_t polygon_nodes(std::size_t order) { return (order + 6) / 2 + 1; }
/// The same along a segment (degree 2N + 2 there).
inline std::size_t segment_nodes(std::size_t order) { return (order + 4) / 2 + 1; }

/// Σ c_k x^k by Horner for real c and complex x.
template <class Real, std::size_t M>
cplx<Real> horner(const std::array<Real, M>& c, std::size_t order, const cplx<Real>& x) {
  cplx<Real> s{c[order], Real(0)};
  for (std::size_t k = order; k-- > 0;) s = s * x + cplx<Real>{c[k], Real(0)};
  return s;
}

/// The series coefficients: binom(1/2, j) for P, binom(−1/2, k)/(k + m) for
/// the antiderivatives z̄^m Σ binom(−1/2, k) ζ̄^k/(k + m) (m = 1, 2, 3), and
/// binom(−1/2, k) itself (m = 0, for the segment); the binomial series, DLMF §4.6.
template <class Real>
struct multipole_series {
  static constexpr std::size_t size = max_multipole_order<Real>() + 1;
  std::size_t order;
  std::array<Real, size> p;
  std::array<std::array<Real, size>, 4> q;
  std::array<std::array<Real, size>, 2> d;  ///< binom(1/2, k)/(k + 1 + m): the dissipation's

  explicit multipole_series(std::size_t n) : order(n) {
    Real cp = 1, cq = 1;
    for (std::size_t k = 0; k <= n; ++k) {
      p[k] = cp;
      d[0][k] = cp / Real(k + 1);
      d[1][k] = cp / Real(k + 2);
      for (std::size_t m = 0; m < 4; ++m) q[m][k] = m == 0 ? cq : Real(cq / Real(k + m));
      cp *= (Real(0.5) - Real(k)) / Real(k + 1);
      cq *= (Real(-0.5) - Real(k)) / Real(k + 1);
    }
  }
};

/// S and T of the expansion (above), in the patch's scaled frame, and
/// S_D = ∬ p (1 + ζ)^{1/2}(1 + ζ̄)^{1/2} (the dissipation D = |q| S_D) if asked.
template <class Real>
struct multipole_sums {
  cplx<Real> S, T, SD;
};

/// The pressure and the expansion variable in the frame scaled by ρ₀ about
/// z₀: p = a + Re(b̄ z), ζ = W z.
template <class Real>
struct multipole_frame {
  Real a;
  cplx<Real> b, W;
};

/// S and T of the polygon `poly` (vertices already in the scaled frame):
/// Green's theorem with F = P(ζ)[(a + b̄z/2) Q₁ + (b/2) Q₂] for S and
/// P(ζ)[(a + b̄z/2) Q₂ + (b/2) Q₃] for T, Q_m = z̄^m Σ binom(−1/2,k) ζ̄^k/(k+m)
/// (docs/patches.md, "Far centres"); Gauss on each edge (polygon_nodes).
template <class Real, std::size_t N>
multipole_sums<Real> polygon_multipole(const vertex_list<Real, N>& poly,
                                       const multipole_frame<Real>& f,
                                       const multipole_series<Real>& s,
                                       bool with_dissipation = false) {
  cplx<Real> S{0, 0}, T{0, 0}, SD{0, 0};
  const cplx<Real> half_b{f.b.re / 2, f.b.im / 2}, half_bbar = conj(half_b);
  const std::size_t n = poly.size(), o = s.order;
  const bool uniform = f.b.re == 0 && f.b.im == 0;
  for (std::size_t i = 0; i < n; ++i) {
    const cplx<Real> A{poly[i][0], poly[i][1]};
    const point2<Real>& next = poly.next(i);
    const cplx<Real> d{(next[0] - A.re) / 2, (next[1] - A.im) / 2};  // dz/dx on [−1, 1]
    const cplx<Real> mid{A.re + d.re, A.im + d.im};
    auto node = [&](const Real& x, const Real& w) {
      const cplx<Real> z{mid.re + x * d.re, mid.im + x * d.im}, zb = conj(z);
      const cplx<Real> zeta = f.W * z, zeta_bar = conj(zeta);
      const cplx<Real> P = horner(s.p, o, zeta);
      const cplx<Real> zb2 = zb * zb;
      const cplx<Real> Q1 = zb * horner(s.q[1], o, zeta_bar);
      const cplx<Real> Q2 = zb2 * horner(s.q[2], o, zeta_bar);
      const cplx<Real> lin = cplx<Real>{f.a, Real(0)} + half_bbar * z;
      const cplx<Real> wd{w * d.re, w * d.im};
      S = S + P * (lin * Q1 + half_b * Q2) * wd;
      if (uniform) {
        T = T + P * lin * Q2 * wd;
      } else {  // Q₃ only for a pressure gradient
        const cplx<Real> Q3 = zb2 * zb * horner(s.q[3], o, zeta_bar);
        T = T + P * (lin * Q2 + half_b * Q3) * wd;
      }
      if (with_dissipation) {
        const cplx<Real> D1 = zb * horner(s.d[0], o, zeta_bar);
        const cplx<Real> D2 = zb2 * horner(s.d[1], o, zeta_bar);
        SD = SD + P * (lin * D1 + half_b * D2) * wd;
      }
    };
    with_gauss_rule<Real>(polygon_nodes(o), node);
  }
  // ∬ f dA = (1/2i) ∮ F dz: X/(2i) = (Im X, −Re X)/2.
  return {{S.im / 2, -S.re / 2}, {T.im / 2, -T.re / 2}, {SD.im / 2, -SD.re / 2}};
}

/// S and T of the segment from x₀ to x₁ (scaled frame) under the line
/// density p = a + Re(b̄z): Gauss–Legendre along it (segment_nodes).
template <class Real>
multipole_sums<Real> segment_multipole(const point2<Real>& x0, const point2<Real>& x1,
                                       const multipole_frame<Real>& f,
                                       const multipole_series<Real>& s,
                                       bool with_dissipation = false) {
  BOOST_MATH_STD_USING
  cplx<Real> S{0, 0}, T{0, 0}, SD{0, 0};
  const cplx<Real> d{(x1[0] - x0[0]) / 2, (x1[1] - x0[1]) / 2};
  const cplx<Real> mid{x0[0] + d.re, x0[1] + d.im};
  const Real half_length = sqrt(d.re * d.re + d.im * d.im);
  const std::size_t o = s.order;
  auto node = [&](const Real& x, const Real& w) {
    const cplx<Real> z{mid.re + x * d.re, mid.im + x * d.im};
    const cplx<Real> zeta = f.W * z;
    const Real p = f.a + f.b.re * z.re + f.b.im * z.im;
    const cplx<Real> g = horner(s.p, o, zeta) * horner(s.q[0], o, conj(zeta));
    const cplx<Real> pg{w * half_length * p * g.re, w * half_length * p * g.im};
    S = S + pg;
    T = T + conj(z) * pg;
    if (with_dissipation) {
      const cplx<Real> gd = horner(s.p, o, zeta) * horner(s.p, o, conj(zeta));
      SD = SD + cplx<Real>{w * half_length * p * gd.re, w * half_length * p * gd.im};
    }
  };
  with_gauss_rule<Real>(segment_nodes(o), node);
  return {S, T, SD};
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DETAIL_PATCH_MULTIPOLE_HPP
