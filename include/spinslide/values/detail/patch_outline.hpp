//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file patch_outline.hpp
/// The set-up checks of a patch's outline (docs/patches.md, "The patch"):
/// at least 3 finite vertices, none repeated, a non-zero area, convex (every
/// turn to the same side, once around); kept counter-clockwise.  Each
/// failure is std::domain_error naming the problem (refuse_constructor_argument).

#ifndef SPINSLIDE_VALUES_DETAIL_PATCH_OUTLINE_HPP
#define SPINSLIDE_VALUES_DETAIL_PATCH_OUTLINE_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/values/detail/patch_geometry.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/hypot.hpp>
#include <boost/math/tools/precision.hpp>

#include <cmath>
#include <cstddef>

namespace spinslide {
namespace detail {

/// A checked outline: counter-clockwise, its vertex mean g and its size
/// (the largest distance of a vertex from g).
template <class Real>
struct patch_outline {
  vertex_list<Real> poly;
  point2<Real> mean{};
  Real scale = 0;
};

/// The checks that need no geometry: the count and finite coordinates.
template <class Real, class Range>
vertex_list<Real> read_vertices(const char* function, const Range& vertices) {
  vertex_list<Real> poly;
  for (const auto& v : vertices) {
    poly.push_back(
        {checked_constructor_argument(function, "vertex x", Real(v[0]), argument_rule::finite),
         checked_constructor_argument(function, "vertex y", Real(v[1]), argument_rule::finite)});
  }
  if (poly.size() < 3)
    refuse_constructor_argument(function, "the number of vertices",
                                "at least 3 (polygon_patch::segment and ::point make line and "
                                "point patches)",
                                Real(poly.size()));
  return poly;
}

/// The mean of the vertices and their largest distance from it.
template <class Real>
void outline_size(patch_outline<Real>& o) {
  BOOST_MATH_STD_USING
  const std::size_t n = o.poly.size();
  for (const auto& v : o.poly) {
    o.mean[0] += v[0] / Real(n);
    o.mean[1] += v[1] / Real(n);
  }
  for (const auto& v : o.poly)
    o.scale = fmax(o.scale, boost::math::hypot(v[0] - o.mean[0], v[1] - o.mean[1]));
}

/// Reverses a clockwise outline; refuses a zero area.
template <class Real>
void orient(const char* function, patch_outline<Real>& o) {
  BOOST_MATH_STD_USING
  Real twice_area = 0;
  const std::size_t n = o.poly.size();
  for (std::size_t i = 0; i < n; ++i)
    twice_area += cross(minus(o.poly[i], o.mean), minus(o.poly.next(i), o.mean));
  if (!(fabs(twice_area) > 64 * boost::math::tools::epsilon<Real>() * o.scale * o.scale))
    refuse_constructor_argument(function, "the area / size^2", "> 0 (not all on a line)",
                                Real(twice_area / (2 * o.scale * o.scale)));
  if (twice_area < 0)
    for (std::size_t i = 0, j = n - 1; i < j; ++i, --j) std::swap(o.poly[i], o.poly[j]);
}

/// Refuses a repeated vertex and a non-convex outline (a turn to the right,
/// or left turns that go round more than once: a star).
template <class Real>
void check_convex(const char* function, const patch_outline<Real>& o) {
  BOOST_MATH_STD_USING
  const std::size_t n = o.poly.size();
  const Real tol = 8 * boost::math::tools::epsilon<Real>();
  Real turning = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const point2<Real> a = minus(o.poly.next(i), o.poly[i]);
    const point2<Real> b = minus(o.poly.next(i + 1 == n ? 0 : i + 1), o.poly.next(i));
    const Real la = boost::math::hypot(a[0], a[1]), lb = boost::math::hypot(b[0], b[1]);
    if (!(la > tol * o.scale))
      refuse_constructor_argument(function, "the distance of a vertex from the next / size",
                                  "> 0 (no repeated vertex)", Real(la / o.scale));
    const Real turn = cross(a, b) / (la * lb);
    if (turn < -tol)
      refuse_constructor_argument(function, "the sine of a turn of the outline",
                                  ">= 0 (a convex outline)", turn);
    turning += atan2(cross(a, b), dot(a, b));
  }
  const Real two_pi = 2 * boost::math::constants::pi<Real>();
  if (!(fabs(turning - two_pi) < Real(1e-3)))
    refuse_constructor_argument(function, "the outline's total turning / (2 pi)",
                                "1 (a convex outline, once around)", Real(turning / two_pi));
}

/// The checked outline of `vertices`.
template <class Real, class Range>
patch_outline<Real> checked_outline(const char* function, const Range& vertices) {
  patch_outline<Real> o;
  o.poly = read_vertices<Real>(function, vertices);
  outline_size(o);
  orient(function, o);
  check_convex(function, o);
  return o;
}

/// The signed distance of e from the nearest edge of the counter-clockwise
/// `poly` (> 0 inside) and that edge's index.
template <class Real>
struct edge_distance {
  Real distance;
  std::size_t edge;
};

template <class Real>
edge_distance<Real> nearest_edge(const vertex_list<Real>& poly, const point2<Real>& e) {
  edge_distance<Real> best{0, 0};
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const point2<Real> t = minus(poly.next(i), poly[i]);
    const Real d = cross(t, minus(e, poly[i])) / boost::math::hypot(t[0], t[1]);
    if (i == 0 || d < best.distance) best = {d, i};
  }
  return best;
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DETAIL_PATCH_OUTLINE_HPP
