//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Symmetric 3×3 matrices over the library's 3-vectors (vector3.hpp), for the
// metric projection, the impulse law and the joint solve: products,
// Cholesky factorization and solves, conditioning.  Small and fixed-size: no
// allocation.
#ifndef SPINSLIDE_CONTACT_DETAIL_MATRIX3_HPP
#define SPINSLIDE_CONTACT_DETAIL_MATRIX3_HPP

#include <spinslide/contact/detail/vector3.hpp>

#include <boost/config.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace spinslide {
namespace detail {

template <class Real>
using matrix3 = std::array<std::array<Real, 3>, 3>;

// The products below are always inlined: g++ otherwise outlines them in
// the projections' Newton steps once they have callers elsewhere too (31
// instructions a call more, tools/path_instructions.py).
template <class Real>
BOOST_FORCEINLINE vector3<Real> multiply(const matrix3<Real>& a, const vector3<Real>& x) {
  vector3<Real> y{};
  for (std::size_t i = 0; i < 3; ++i) y[i] = a[i][0] * x[0] + a[i][1] * x[1] + a[i][2] * x[2];
  return y;
}

// ‖A‖_F, the Frobenius norm.
template <class Real>
Real frobenius(const matrix3<Real>& a) {
  using std::sqrt;
  Real s = 0;
  for (const auto& row : a)
    for (const Real& x : row) s += x * x;
  return sqrt(s);
}

// Whether ‖A‖_F‖A⁻¹‖_F, which bounds A's condition number from above (within
// a factor 3), is at most 1/√ε_mach (6.7e7 in double).  Beyond, the metric
// projection's Newton iteration was seen to stall (fuzz_impulse: a metric
// conditioned near 1e11 and the uniform disk).
template <class Real>
bool well_conditioned(const matrix3<Real>& a, const matrix3<Real>& inverse) {
  using std::sqrt;
  return frobenius(a) * frobenius(inverse) * sqrt(std::numeric_limits<Real>::epsilon()) <= 1;
}

// The lower Cholesky factor L (A = L Lᵀ) of the symmetric A (its lower
// triangle is read); false unless A is positive definite to rounding (every
// pivot > 0 and finite).
template <class Real>
bool cholesky(const matrix3<Real>& a, matrix3<Real>& l) {
  using std::sqrt;
  l = matrix3<Real>{};
  for (std::size_t j = 0; j < 3; ++j) {
    Real d = a[j][j];
    for (std::size_t k = 0; k < j; ++k) d -= l[j][k] * l[j][k];
    if (!(d > 0) || !(d < std::numeric_limits<Real>::infinity())) return false;
    l[j][j] = sqrt(d);
    for (std::size_t i = j + 1; i < 3; ++i) {
      Real s = a[i][j];
      for (std::size_t k = 0; k < j; ++k) s -= l[i][k] * l[j][k];
      l[i][j] = s / l[j][j];
    }
  }
  return true;
}

// x with L Lᵀ x = b.
template <class Real>
vector3<Real> cholesky_solve(const matrix3<Real>& l, const vector3<Real>& b) {
  vector3<Real> y{};
  for (std::size_t i = 0; i < 3; ++i) {
    Real s = b[i];
    for (std::size_t k = 0; k < i; ++k) s -= l[i][k] * y[k];
    y[i] = s / l[i][i];
  }
  vector3<Real> x{};
  for (std::size_t n = 3; n-- > 0;) {
    Real s = y[n];
    for (std::size_t k = n + 1; k < 3; ++k) s -= l[k][n] * x[k];
    x[n] = s / l[n][n];
  }
  return x;
}

// A symmetric 3×3 matrix by its upper triangle: the Newton steps' Hessians
// (slip_newton.hpp).
template <class Real>
struct symmetric3 {
  Real xx, xy, xz, yy, yz, zz;
};

// The upper triangle of a.
template <class Real>
symmetric3<Real> upper(const matrix3<Real>& a) {
  return {a[0][0], a[0][1], a[0][2], a[1][1], a[1][2], a[2][2]};
}

// The upper triangle of a, plus the symmetric h.
template <class Real>
symmetric3<Real> upper_plus(const matrix3<Real>& a, const symmetric3<Real>& h) {
  return {a[0][0] + h.xx, a[0][1] + h.xy, a[0][2] + h.xz,
          a[1][1] + h.yy, a[1][2] + h.yz, a[2][2] + h.zz};
}

template <class Real>
BOOST_FORCEINLINE vector3<Real> multiply(const symmetric3<Real>& a, const vector3<Real>& x) {
  return {a.xx * x[0] + a.xy * x[1] + a.xz * x[2], a.xy * x[0] + a.yy * x[1] + a.yz * x[2],
          a.xz * x[0] + a.yz * x[1] + a.zz * x[2]};
}

// x with A x = b for a symmetric A, by the adjugate: fewer dependent
// divisions than a factorization, for Newton's steps (which need no more
// than a few digits).  False if the determinant is not positive and finite.
template <class Real>
BOOST_FORCEINLINE bool solve_symmetric(const symmetric3<Real>& a, const vector3<Real>& b,
                                       vector3<Real>& x) {
  const Real c00 = a.yy * a.zz - a.yz * a.yz;
  const Real c01 = a.xz * a.yz - a.xy * a.zz;
  const Real c02 = a.xy * a.yz - a.xz * a.yy;
  const Real c11 = a.xx * a.zz - a.xz * a.xz;
  const Real c12 = a.xy * a.xz - a.xx * a.yz;
  const Real c22 = a.xx * a.yy - a.xy * a.xy;
  const Real det = a.xx * c00 + a.xy * c01 + a.xz * c02;
  if (!(det > 0) || !(det < std::numeric_limits<Real>::infinity())) return false;
  const Real r = 1 / det;
  x = {(c00 * b[0] + c01 * b[1] + c02 * b[2]) * r, (c01 * b[0] + c11 * b[1] + c12 * b[2]) * r,
       (c02 * b[0] + c12 * b[1] + c22 * b[2]) * r};
  return true;
}

// The same for a matrix3, of which the upper triangle is read.
template <class Real>
bool solve_symmetric(const matrix3<Real>& a, const vector3<Real>& b, vector3<Real>& x) {
  return solve_symmetric(upper(a), b, x);
}

// A⁻¹ from its Cholesky factor, column by column.
template <class Real>
matrix3<Real> cholesky_inverse(const matrix3<Real>& l) {
  matrix3<Real> inv{};
  for (std::size_t j = 0; j < 3; ++j) {
    vector3<Real> e{};
    e[j] = 1;
    const vector3<Real> c = cholesky_solve(l, e);
    for (std::size_t i = 0; i < 3; ++i) inv[i][j] = c[i];
  }
  return inv;
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_MATRIX3_HPP
