//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file motion/detail/gauss_panel.hpp
/// One N-point Gauss–Legendre panel on [−1, 1] with what a panel integration
/// of nested integrals needs: the integral of a function given at the nodes,
/// its indefinite integral at every node (the spectral integration matrix),
/// the size of its highest Legendre coefficients (the error estimate) and its
/// indefinite integral anywhere (sampling inside a panel).  The nodes and
/// weights are Boost's; the rest is built from them once, in long double.

#ifndef SPINSLIDE_MOTION_DETAIL_GAUSS_PANEL_HPP
#define SPINSLIDE_MOTION_DETAIL_GAUSS_PANEL_HPP

#include <boost/math/quadrature/gauss.hpp>

#include <array>
#include <cmath>
#include <cstddef>

namespace spinslide {
namespace detail {

/// P_0(x) … P_{M−1}(x) by the three-term recurrence.
template <std::size_t M, class T>
std::array<T, M> legendre_values(T x) {
  std::array<T, M> p{};
  p[0] = 1;
  if (M > 1) p[1] = x;
  for (std::size_t m = 1; m + 1 < M; ++m)
    p[m + 1] = (T(2 * m + 1) * x * p[m] - T(m) * p[m - 1]) / T(m + 1);
  return p;
}

template <std::size_t N>
class gauss_panel {
 public:
  static constexpr std::size_t size = N;
  using values = std::array<double, N>;

  /// The rule, built on first use (thread-safe).
  static const gauss_panel& rule() {
    static const gauss_panel r;
    return r;
  }

  double node(std::size_t j) const { return x_[j]; }

  /// ∫_{−1}^{1} f, the Gauss sum.
  double integral(const values& f) const {
    double s = 0;
    for (std::size_t k = 0; k < N; ++k) s += w_[k] * f[k];
    return s;
  }

  /// ∫_{−1}^{x_j} p at every node, p the interpolant of f (exact for degree < N).
  values integrals_to_nodes(const values& f) const {
    values out{};
    for (std::size_t j = 0; j < N; ++j) {
      double s = 0;
      for (std::size_t k = 0; k < N; ++k) s += s_[j][k] * f[k];
      out[j] = s;
    }
    return out;
  }

  /// |c_{N−1}| + |c_{N−2}| + |c_{N−3}|, the highest Legendre coefficients of
  /// the interpolant of f: the size of its interpolation error.
  double tail(const values& f) const {
    double t = 0;
    for (std::size_t m = N - 3; m < N; ++m) t += std::fabs(coefficient(m, f));
    return t;
  }

  /// c_m = (2m + 1)/2 Σ w_k P_m(x_k) f_k (exact for the interpolant).
  double coefficient(std::size_t m, const values& f) const {
    double c = 0;
    for (std::size_t k = 0; k < N; ++k) c += c_[m][k] * f[k];
    return c;
  }

  /// ∫_{−1}^{x} p for any x in [−1, 1], from the Legendre coefficients c of p:
  /// ∫P_0 = x + 1, ∫P_m = (P_{m+1} − P_{m−1})/(2m + 1).
  double integral_to(double x, const values& c) const {
    const auto p = legendre_values<N + 1>(x);
    double s = c[0] * (x + 1);
    for (std::size_t m = 1; m < N; ++m) s += c[m] * (p[m + 1] - p[m - 1]) / double(2 * m + 1);
    return s;
  }

  /// All N Legendre coefficients of the interpolant of f.
  values coefficients(const values& f) const {
    values c{};
    for (std::size_t m = 0; m < N; ++m) c[m] = coefficient(m, f);
    return c;
  }

 private:
  gauss_panel() {
    using boost_rule = boost::math::quadrature::gauss<long double, N>;
    const auto& a = boost_rule::abscissa();  // the non-negative nodes, ascending
    const auto& wa = boost_rule::weights();
    std::array<long double, N> x{}, w{};
    std::size_t i = 0;
    for (std::size_t k = a.size(); k-- > 0;) {
      if (a[k] == 0) continue;
      x[i] = -a[k];
      w[i++] = wa[k];
    }
    for (std::size_t k = 0; k < a.size(); ++k) {
      x[i] = a[k];
      w[i++] = wa[k];
    }
    std::array<std::array<long double, N + 1>, N> p{};
    for (std::size_t k = 0; k < N; ++k) p[k] = legendre_values<N + 1>(x[k]);
    for (std::size_t j = 0; j < N; ++j) {
      x_[j] = static_cast<double>(x[j]);
      w_[j] = static_cast<double>(w[j]);
      for (std::size_t m = 0; m < N; ++m)
        c_[m][j] = static_cast<double>((2 * m + 1) * w[j] * p[j][m] / 2);
    }
    // S_jk = ∫_{−1}^{x_j} ℓ_k = (w_k/2)[(x_j + 1) + Σ_{m≥1} P_m(x_k)(P_{m+1}(x_j) − P_{m−1}(x_j))].
    for (std::size_t j = 0; j < N; ++j) {
      for (std::size_t k = 0; k < N; ++k) {
        long double s = x[j] + 1;
        for (std::size_t m = 1; m < N; ++m) s += p[k][m] * (p[j][m + 1] - p[j][m - 1]);
        s_[j][k] = static_cast<double>(w[k] * s / 2);
      }
    }
  }

  values x_{}, w_{};
  std::array<values, N> s_{}, c_{};
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_DETAIL_GAUSS_PANEL_HPP
