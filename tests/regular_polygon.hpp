//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// A regular n-gon inscribed in the circle of a radius about the origin, a
// vertex on the positive x axis: the flat-patch tests' stand-in for a disk.
#ifndef SPINSLIDE_TESTS_REGULAR_POLYGON_HPP
#define SPINSLIDE_TESTS_REGULAR_POLYGON_HPP

#include <boost/math/constants/constants.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace spinslide_test {

inline std::vector<std::array<double, 2>> regular_polygon(int n, double radius = 1) {
  std::vector<std::array<double, 2>> v;
  v.reserve(static_cast<std::size_t>(n));
  const double pi = boost::math::constants::pi<double>();
  for (int k = 0; k < n; ++k)
    v.push_back({radius * std::cos(2 * pi * k / n), radius * std::sin(2 * pi * k / n)});
  return v;
}

}  // namespace spinslide_test

#endif  // SPINSLIDE_TESTS_REGULAR_POLYGON_HPP
