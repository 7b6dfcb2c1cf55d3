//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file product.hpp
/// detail::product: a product of a few factors without spurious over- or
/// underflow, for results that combine scales near the ends of the type
/// (the contact law's torque, the dynamics' scaled state).

#ifndef SPINSLIDE_BASE_DETAIL_PRODUCT_HPP
#define SPINSLIDE_BASE_DETAIL_PRODUCT_HPP

#include <boost/config.hpp>
#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/tools/config.hpp>
#include <boost/math/tools/precision.hpp>

#include <cmath>
#include <cstddef>

namespace spinslide {
namespace detail {

// The product of xs[0..n) with the binary exponents summed apart from the
// mantissas (product's rare path, apart so that the common one inlines).
template <class Real, std::size_t N>
BOOST_NOINLINE Real product_by_exponents(const Real (&xs)[N], Real plain) {
  BOOST_MATH_STD_USING
  Real mantissa = 1;
  int exponent = 0;
  for (const Real& xi : xs) {
    int e = 0;
    mantissa *= frexp(xi, &e);  // each in [1/2, 1): no underflow for a few factors
    exponent += e;
  }
  if (!(boost::math::isfinite)(mantissa)) return plain;  // an input is ∞ or NaN
  return mantissa == 0 ? Real(0) : Real(ldexp(mantissa, exponent));
}

// x₁x₂⋯xₙ without spurious over- or underflow: where a partial product
// leaves the normal range, the binary exponents are summed apart from the
// mantissas, so the result is finite and normal whenever the true product is
// (e.g. 1e300 · 1e300 · 1e-300).  Otherwise the plain product, in order.
// Always inlined: the common path is a few products and comparisons, which
// a call (one a slipping trial cap made) costs more than.
template <class Real, class... Rest>
BOOST_FORCEINLINE Real product(Real x, Rest... rest) {
  BOOST_MATH_STD_USING
  const Real xs[] = {x, rest...};
  const Real lo = boost::math::tools::min_value<Real>(), hi = boost::math::tools::max_value<Real>();
  Real plain = 1;
  bool normal = true;
  for (const Real& xi : xs) {
    plain *= xi;
    normal = normal && fabs(plain) >= lo && fabs(plain) <= hi;
  }
  if (normal) return plain;
  return product_by_exponents(xs, plain);
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_BASE_DETAIL_PRODUCT_HPP
