//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Linear least squares min ‖A x − b‖ by Householder QR, for the fits of the
// table generator (in cpp_bin_float_50) and of bench_disk's rational bound
// (in long double).  Dense, unpivoted: the fits are small (≤ 25 columns) and
// full rank.  Not part of the library.
#ifndef SPINSLIDE_TOOLS_LEAST_SQUARES_HPP
#define SPINSLIDE_TOOLS_LEAST_SQUARES_HPP

#include <cmath>
#include <cstddef>
#include <vector>

namespace spinslide_tools {

template <class T>
std::vector<T> least_squares(std::vector<std::vector<T>> A, std::vector<T> b) {
  using std::sqrt;
  const std::size_t rows = A.size(), cols = A[0].size();
  for (std::size_t j = 0; j < cols; ++j) {
    T norm = 0;
    for (std::size_t i = j; i < rows; ++i) norm += A[i][j] * A[i][j];
    norm = sqrt(norm);
    if (A[j][j] > 0) norm = -norm;
    std::vector<T> v(rows, T(0));
    for (std::size_t i = j; i < rows; ++i) v[i] = A[i][j];
    v[j] -= norm;
    T vv = 0;
    for (std::size_t i = j; i < rows; ++i) vv += v[i] * v[i];
    if (vv == 0) continue;
    // Reflect every remaining column of A, and b, in v.
    for (std::size_t c = j; c <= cols; ++c) {
      T d = 0;
      for (std::size_t i = j; i < rows; ++i) d += v[i] * (c < cols ? A[i][c] : b[i]);
      d = 2 * d / vv;
      for (std::size_t i = j; i < rows; ++i) (c < cols ? A[i][c] : b[i]) -= d * v[i];
    }
  }
  std::vector<T> x(cols);
  for (std::size_t j = cols; j-- > 0;) {
    T d = b[j];
    for (std::size_t c = j + 1; c < cols; ++c) d -= A[j][c] * x[c];
    x[j] = d / A[j][j];
  }
  return x;
}

}  // namespace spinslide_tools

#endif  // SPINSLIDE_TOOLS_LEAST_SQUARES_HPP
