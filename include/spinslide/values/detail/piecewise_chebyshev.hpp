//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Adaptive piecewise polynomial approximation of a pair of functions on
// [0, 1]: the interval is bisected until, on every piece, the trailing
// Chebyshev coefficients of both functions are below a tolerance relative to
// the function's size.  Each piece's Chebyshev series is then converted to
// monomials in x ∈ [−1, 1] (harmless at these low degrees) and stored
// interleaved, so that one Horner loop evaluates both functions with two
// independent dependency chains; a bucket table finds the piece.  Used by
// tabulated_profile (docs/theory.md §7).
#ifndef SPINSLIDE_VALUES_DETAIL_PIECEWISE_CHEBYSHEV_HPP
#define SPINSLIDE_VALUES_DETAIL_PIECEWISE_CHEBYSHEV_HPP

#include <spinslide/values/detail/horner.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/chebyshev.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace spinslide {
namespace detail {

// The machinery shared by this runtime table and by the generator of the
// compile-time tables of the disk's fast path (tools/generate_disk_tables.cpp,
// which runs it in cpp_bin_float_50): Chebyshev interpolation and conversion
// to monomials.  Both evaluate with values/detail/horner.hpp.

// The j-th of n Chebyshev points of the first kind, cos(π(j + ½)/n): interior
// points, so the ends of a piece (singular points, or ε = 0 and ε = ∞) are
// never sampled.
template <class Real>
Real chebyshev_point(std::size_t j, std::size_t n) {
  using std::cos;
  return cos(boost::math::constants::pi<Real>() * (Real(j) + Real(0.5)) / Real(n));
}

// The coefficients c[0..n) of the interpolant Σ' c_k T_k (Boost's c₀/2
// convention) through values[j] at chebyshev_point(j, n): a DCT-II.
template <class Real>
void chebyshev_coefficients(const Real* values, std::size_t n, Real* c) {
  using std::cos;
  const Real pi = boost::math::constants::pi<Real>();
  for (std::size_t k = 0; k < n; ++k) {
    Real s = 0;
    for (std::size_t j = 0; j < n; ++j)
      s += values[j] * cos(pi * Real(k) * (Real(j) + Real(0.5)) / Real(n));
    c[k] = 2 * s / Real(n);
  }
}

// c[0]/2 + Σ_{k<n} c_k T_k(x) as Σ m_k x^k, by T_{k+1} = 2x T_k − T_{k−1}.
// Harmless at low degree on [−1, 1] when the c_k decay (no cancellation
// between the monomial terms).
template <class Real>
void chebyshev_to_monomial(const Real* c, std::size_t n, Real* m) {
  std::vector<Real> t_prev(n, Real(0)), t_cur(n, Real(0)), t_next(n);
  for (std::size_t j = 0; j < n; ++j) m[j] = 0;
  t_prev[0] = 1;            // T_0
  if (n > 1) t_cur[1] = 1;  // T_1
  m[0] = c[0] / 2;
  for (std::size_t k = 1; k < n; ++k) {
    for (std::size_t j = 0; j < n; ++j) m[j] += c[k] * t_cur[j];
    for (std::size_t j = 0; j < n; ++j) t_next[j] = 0;
    for (std::size_t j = 0; j + 1 < n; ++j) t_next[j + 1] = 2 * t_cur[j];
    for (std::size_t j = 0; j < n; ++j) t_next[j] -= t_prev[j];
    t_prev.swap(t_cur);
    t_cur.swap(t_next);
  }
}

template <class Real, std::size_t Degree>
class piecewise_chebyshev_pair {
 public:
  static constexpr std::size_t nodes = Degree + 1;

  struct piece {
    Real a, b;                       // the piece [a, b] of [0, 1]
    std::array<Real, nodes> c0, c1;  // Chebyshev coefficients, Boost's c[0]/2 convention
  };

  // What evaluation reads: x = (t − mid)·scale, then Σ m[k] x^k for both.
  struct evaluation_piece {
    Real mid, scale;
    std::array<Real, 2 * nodes> m;  // monomial coefficients, interleaved (f0, f1)
  };

  piecewise_chebyshev_pair() = default;

  /// f(t) returns a std::pair<Real, Real> for t in (0, 1); it is sampled only
  /// at interior Chebyshev points.  `tolerance` is relative to the largest
  /// |coefficient| of each function on the piece; `max_depth` bounds the
  /// bisection near singular points (a piece there is kept as is).
  template <class F>
  piecewise_chebyshev_pair(F f, Real tolerance, int max_depth) {
    build(f, Real(0), Real(1), tolerance, 0, max_depth);
    starts_.reserve(pieces_.size());
    fast_.reserve(pieces_.size());
    for (const auto& p : pieces_) {
      starts_.push_back(p.a);
      evaluation_piece e;
      e.mid = (p.a + p.b) / 2;
      e.scale = 2 / (p.b - p.a);
      const auto m0 = monomial(p.c0), m1 = monomial(p.c1);
      for (std::size_t k = 0; k < nodes; ++k) {
        e.m[2 * k] = m0[k];
        e.m[2 * k + 1] = m1[k];
      }
      fast_.push_back(e);
    }
    // bucket_[i] = the piece holding t = i / buckets.
    bucket_.resize(buckets + 1);
    std::size_t p = 0;
    for (std::size_t i = 0; i <= buckets; ++i) {
      const Real t = Real(i) / Real(buckets);
      while (p + 1 < pieces_.size() && pieces_[p].b <= t) ++p;
      bucket_[i] = static_cast<std::uint32_t>(p);
    }
  }

  std::size_t size() const { return pieces_.size(); }
  const std::vector<piece>& pieces() const { return pieces_; }
  int deepest() const { return deepest_; }

  /// Both approximations at t ∈ [0, 1]; no allocation.
  std::pair<Real, Real> operator()(Real t) const {
    const evaluation_piece& p = piece_at(t);
    const Real x = (t - p.mid) * p.scale;
    Real s0, s1;
    horner_pair<Degree>(p.m.data(), 0, 1, 2, x, s0, s1);
    return {s0, s1};
  }

  /// Both approximations and their derivatives in t at t ∈ [0, 1] from one
  /// piece (Horner's scheme carrying the derivatives along): the values bit
  /// for bit operator()'s; no allocation.
  struct values_and_slopes {
    Real value0, value1, slope0, slope1;
  };
  values_and_slopes with_slopes(Real t) const {
    const evaluation_piece& p = piece_at(t);
    const Real x = (t - p.mid) * p.scale;
    Real v0 = p.m[2 * Degree], v1 = p.m[2 * Degree + 1], d0 = 0, d1 = 0;
    for (std::size_t k = Degree; k-- > 0;) {
      d0 = d0 * x + v0;
      v0 = v0 * x + p.m[2 * k];
      d1 = d1 * x + v1;
      v1 = v1 * x + p.m[2 * k + 1];
    }
    return {v0, v1, d0 * p.scale, d1 * p.scale};
  }

  /// The Chebyshev form of both approximations at t (for tests of the
  /// monomial conversion).
  std::pair<Real, Real> chebyshev_value(Real t) const {
    auto it = std::upper_bound(starts_.begin(), starts_.end(), t);
    const std::size_t i = it == starts_.begin() ? 0 : std::size_t(it - starts_.begin()) - 1;
    const piece& p = pieces_[i];
    const Real x = (2 * t - (p.a + p.b)) / (p.b - p.a);
    return {boost::math::chebyshev_clenshaw_recurrence(p.c0.data(), nodes, x),
            boost::math::chebyshev_clenshaw_recurrence(p.c1.data(), nodes, x)};
  }

 private:
  const evaluation_piece& piece_at(Real t) const {
    std::size_t b = static_cast<std::size_t>(t * Real(buckets));
    if (b >= buckets) b = buckets - 1;
    std::size_t i = bucket_[b];
    const std::size_t last = bucket_[b + 1];
    if (i != last) {  // several pieces in this bucket: bisect among them
      const auto it = std::upper_bound(starts_.begin() + std::ptrdiff_t(i) + 1,
                                       starts_.begin() + std::ptrdiff_t(last) + 1, t);
      i = std::size_t(it - starts_.begin()) - 1;
    }
    return fast_[i];
  }

  template <class F>
  void build(F& f, Real a, Real b, Real tolerance, int depth, int max_depth) {
    using std::fabs;
    piece p{a, b, {}, {}};
    std::array<Real, nodes> v0, v1;
    for (std::size_t j = 0; j < nodes; ++j) {
      const auto v = f((a + b) / 2 + (b - a) / 2 * chebyshev_point<Real>(j, nodes));
      v0[j] = v.first;
      v1[j] = v.second;
    }
    chebyshev_coefficients(v0.data(), nodes, p.c0.data());
    chebyshev_coefficients(v1.data(), nodes, p.c1.data());
    auto converged = [&](const std::array<Real, nodes>& c) {
      Real scale = 0;
      for (const Real& x : c) scale = std::max(scale, Real(fabs(x)));
      const Real tail = fabs(c[nodes - 1]) + fabs(c[nodes - 2]) + fabs(c[nodes - 3]);
      return tail <= tolerance * scale;
    };
    if (depth >= max_depth || (converged(p.c0) && converged(p.c1))) {
      pieces_.push_back(p);
      deepest_ = std::max(deepest_, depth);
      return;
    }
    const Real m = (a + b) / 2;
    build(f, a, m, tolerance, depth + 1, max_depth);
    build(f, m, b, tolerance, depth + 1, max_depth);
  }

  static std::array<Real, nodes> monomial(const std::array<Real, nodes>& c) {
    std::array<Real, nodes> m;
    chebyshev_to_monomial(c.data(), nodes, m.data());
    return m;
  }

  static constexpr std::size_t buckets = 1024;
  std::vector<piece> pieces_;
  std::vector<Real> starts_;
  std::vector<evaluation_piece> fast_;
  std::vector<std::uint32_t> bucket_;
  int deepest_ = 0;
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DETAIL_PIECEWISE_CHEBYSHEV_HPP
