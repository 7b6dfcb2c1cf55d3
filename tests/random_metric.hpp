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

#include <spinslide/planar_metric.hpp>

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

}  // namespace spinslide_test

#endif  // SPINSLIDE_TESTS_RANDOM_METRIC_HPP
