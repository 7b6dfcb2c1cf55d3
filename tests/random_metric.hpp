//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Random symmetric positive-definite 3×3 matrices for the tests of the
// metric projection and the impulse law: L Lᵀ with L lower triangular,
// entries uniform in [−1, 1], plus a diagonal shift (which bounds the
// condition number).
#ifndef SPINSLIDE_TESTS_RANDOM_METRIC_HPP
#define SPINSLIDE_TESTS_RANDOM_METRIC_HPP

#include <spinslide/contact/planar_metric.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <random>

namespace spinslide_test {

using matrix3 = spinslide::planar_metric<double>::matrix;

// L Lᵀ + diag(shift + extra·|u|), u uniform in [−1, 1].
inline matrix3 random_spd(std::mt19937_64& rng, double shift, double extra) {
  std::uniform_real_distribution<double> u(-1, 1);
  matrix3 l{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j <= i; ++j) l[i][j] = u(rng);
  matrix3 m{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t k = 0; k < 3; ++k) m[i][j] += l[i][k] * l[j][k];
  for (std::size_t i = 0; i < 3; ++i) m[i][i] += shift + extra * std::fabs(u(rng));
  return m;
}

// Q diag(1, κ^u, κ) Qᵀ times 10^(6v − 3), with Q a random rotation (Gram–
// Schmidt of normal samples) and u, v uniform in [0, 1]: a condition number
// of exactly κ (to rounding) at a random orientation and scale.
inline matrix3 random_spd_with_condition(std::mt19937_64& rng, double kappa) {
  std::normal_distribution<double> normal(0, 1);
  std::uniform_real_distribution<double> u(0, 1);
  matrix3 q{};
  for (auto& row : q)
    for (double& x : row) x = normal(rng);
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t k = 0; k < i; ++k) {
      const double d = q[i][0] * q[k][0] + q[i][1] * q[k][1] + q[i][2] * q[k][2];
      for (std::size_t j = 0; j < 3; ++j) q[i][j] -= d * q[k][j];
    }
    const double n = std::sqrt(q[i][0] * q[i][0] + q[i][1] * q[i][1] + q[i][2] * q[i][2]);
    for (double& x : q[i]) x /= n;
  }
  const double eigenvalues[3] = {1, std::pow(kappa, u(rng)), kappa};
  const double scale = std::pow(10.0, 6 * u(rng) - 3);
  matrix3 m{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j <= i; ++j) {
      double s = 0;
      for (std::size_t k = 0; k < 3; ++k) s += q[k][i] * eigenvalues[k] * q[k][j];
      m[i][j] = m[j][i] = s * scale;
    }
  return m;
}

// m x.
inline std::array<double, 3> times(const matrix3& m, const std::array<double, 3>& x) {
  std::array<double, 3> y{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) y[i] += m[i][j] * x[j];
  return y;
}

}  // namespace spinslide_test

#endif  // SPINSLIDE_TESTS_RANDOM_METRIC_HPP
