//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The library's one small-vector vocabulary: vector3<Real> (std::array) and
// its operations, for the projections, the impulse law, the contact law,
// the joint solve and the engine adapters; the symmetric 3×3 matrices over
// it are in matrix3.hpp.  The overflow-safe helpers (the contact law's:
// every finite input) say so.
#ifndef SPINSLIDE_CONTACT_DETAIL_VECTOR3_HPP
#define SPINSLIDE_CONTACT_DETAIL_VECTOR3_HPP

#include <boost/config.hpp>
#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/tools/config.hpp>
#include <boost/math/tools/precision.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <initializer_list>

namespace spinslide {
namespace detail {

// The library's one small vector: a 3-vector over the tangent plane's
// (x, y) and the normal spin, or a 3-D vector (the adapters' normals and
// motions).
template <class Real>
using vector3 = std::array<Real, 3>;
template <class Real>
Real dot(const vector3<Real>& a, const vector3<Real>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// a × b.
template <class Real>
vector3<Real> cross(const vector3<Real>& a, const vector3<Real>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// √(x² + y²), by hypot only where the squares could over- or underflow
// (outside the square roots of the normal numbers, with a margin).
template <class Real>
Real length(Real x, Real y) {
  using std::fabs;
  using std::hypot;
  using std::sqrt;
  static const Real low = 16 * sqrt(boost::math::tools::min_value<Real>());
  static const Real high = sqrt(boost::math::tools::max_value<Real>()) / 16;
  const Real big = (std::max)(fabs(x), fabs(y));
  return big > low && big < high ? Real(sqrt(x * x + y * y)) : Real(hypot(x, y));
}

// max |vᵢ|.
template <class Real>
Real largest(const vector3<Real>& v) {
  using std::fabs;
  return (std::max)({Real(fabs(v[0])), Real(fabs(v[1])), Real(fabs(v[2]))});
}

// s + t·step.
template <class Real>
vector3<Real> shifted(const vector3<Real>& s, const vector3<Real>& step, Real t) {
  return {s[0] + t * step[0], s[1] + t * step[1], s[2] + t * step[2]};
}

// The largest |component|.
template <class Real>
Real largest_magnitude(Real x, Real y, Real z) {
  BOOST_MATH_STD_USING
  return (std::max)({fabs(x), fabs(y), fabs(z)});
}

// √(x² + y² + z²) in units of the largest |component| (vector_norm's
// rescaled path, out of line: the common path is a sum of squares).
template <class Real>
BOOST_NOINLINE Real rescaled_norm(Real x, Real y, Real z) {
  BOOST_MATH_STD_USING
  const Real m = largest_magnitude(x, y, z);
  if (m == 0 || !(boost::math::isfinite)(m)) return m;
  const Real a = x / m, b = y / m, c = z / m;
  return m * sqrt(a * a + b * b + c * c);
}

// √(x² + y² + z²) without overflow or underflow for any finite input.
// Always inlined, its rescaling apart: a call in the DEM trial cap kept its
// caller's vectors on the stack around it (about 40 instructions a call,
// tools/path_instructions.py).
template <class Real>
BOOST_FORCEINLINE Real vector_norm(Real x, Real y, Real z) {
  BOOST_MATH_STD_USING
  const Real s2 = x * x + y * y + z * z;
  // NaN only from a NaN component (std::max would drop it; found by fuzz_contact).
  if ((boost::math::isnan)(s2)) return s2;
  if (s2 > boost::math::tools::min_value<Real>() && s2 < boost::math::tools::max_value<Real>())
    return sqrt(s2);
  return rescaled_norm(x, y, z);
}

// a·n for a unit n, without overflow where the result is finite: if a
// partial sum overflows, the same in units of a's largest component.
template <class Real>
Real vector_dot(const vector3<Real>& a, const vector3<Real>& n) {
  BOOST_MATH_STD_USING
  const Real d = a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
  if ((boost::math::isfinite)(d) || !(boost::math::isfinite)(a[0]) ||
      !(boost::math::isfinite)(a[1]) || !(boost::math::isfinite)(a[2]))
    return d;
  const Real m = largest_magnitude(a[0], a[1], a[2]);
  return m * ((a[0] / m) * n[0] + (a[1] / m) * n[1] + (a[2] / m) * n[2]);
}

// The tangential part v − (v·n)n in place, and its length.  Where v·n
// overflows for finite v (components near the largest value; found by
// fuzz_contact), in units of v's largest component: then only a tangential
// part that itself exceeds the largest value is ∞.
template <class Real>
Real tangential_part(vector3<Real>& v, const vector3<Real>& n) {
  BOOST_MATH_STD_USING
  Real scale = 1;
  if (!(boost::math::isfinite)(v[0] * n[0] + v[1] * n[1] + v[2] * n[2]) &&
      (boost::math::isfinite)(v[0]) && (boost::math::isfinite)(v[1]) &&
      (boost::math::isfinite)(v[2])) {
    scale = largest_magnitude(v[0], v[1], v[2]);
    for (Real& vi : v) vi /= scale;
  }
  const Real vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
  for (std::size_t i = 0; i < 3; ++i) v[i] -= vn * n[i];
  const Real length = vector_norm(v[0], v[1], v[2]);
  if (scale == 1) return length;
  for (Real& vi : v) vi *= scale;
  return scale * length;
}

// v/|v| in place (0 for v = 0).  For a |v| near the subnormal range (below
// min/epsilon), in units of v's largest component, where the quotients of
// subnormals would make |v/|v|| exceed 1 by a percent (found by fuzz_contact).
template <class Real>
void unit_direction(vector3<Real>& v, Real speed) {
  BOOST_MATH_STD_USING
  if (!(speed > 0)) {
    v[0] = v[1] = v[2] = 0;
    return;
  }
  if (speed >= boost::math::tools::min_value<Real>() / boost::math::tools::epsilon<Real>()) {
    for (Real& vi : v) vi /= speed;
    return;
  }
  const Real m = largest_magnitude(v[0], v[1], v[2]);
  for (Real& vi : v) vi /= m;
  const Real length = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (Real& vi : v) vi /= length;
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_VECTOR3_HPP
