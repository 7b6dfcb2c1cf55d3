//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file contact_patch.hpp
/// The flat patch of an engine's contact (docs/engines.md, "A pair's own
/// patch"): from the engine's contact points of one pair in one step, their
/// positions in the tangent plane (about the point where the engine
/// evaluates the pair's relative motion) and the normal loads on them, the
/// convex hull of the points under the linear (no-tension) pressure whose
/// resultant and centre are those loads' (polygon_patch.hpp).  Engines give
/// what they give: Bullet builds its up to 4 manifold points over several
/// frames (a landing box is a point, then a line, for a few steps), points
/// repeat, and a box on its edge has collinear points.  So this never
/// throws: points closer than a tolerance merge, points on a line make a
/// line patch, one point (or all points merged) a point patch, and the
/// centre of pressure is kept inside the hull, before any constructor that
/// would refuse them is called.  Up to 8 points nothing is allocated.

#ifndef SPINSLIDE_CONTACT_CONTACT_PATCH_HPP
#define SPINSLIDE_CONTACT_CONTACT_PATCH_HPP

#include <spinslide/base/named_inputs.hpp>
#include <spinslide/values/detail/patch_geometry.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <boost/math/tools/precision.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <type_traits>

namespace spinslide {

/// One contact point of an engine: contact_point<double>{{x, y}, load}.
template <class Real>
struct contact_point {
  using value_type = Real;       ///< the floating type
  std::array<Real, 2> position;  ///< in the tangent plane's axes, about the patch origin
  /// The normal force (or impulse) on the point: ≥ 0; only the ratios of the
  /// points' loads matter.  A negative or non-finite load counts as 0.
  Real load;
};

/// The distance below which contact points merge and below which a point
/// counts as on the line of others, relative to the points' spread (their
/// largest distance from their mean; never below 64 ε of the coordinates'
/// size, the rounding of the positions): merge_tolerance<double>{1e-6}.
template <class Real>
struct merge_tolerance : named_input<merge_tolerance<Real>, Real> {
  using named_input<merge_tolerance<Real>, Real>::named_input;
};
/// merge_tolerance{x} is a merge_tolerance<double> for a double x.
template <class Real>
merge_tolerance(Real) -> merge_tolerance<Real>;

namespace detail {

/// The points of a contact after their checks: the distinct positions, the
/// load-weighted centre, the spread, and the merge distance.
template <class Real>
struct gathered_points {
  vertex_list<Real> unique;
  point2<Real> centre{};
  Real spread = 0;
  Real merge = 0;
  bool loaded = false;  // some point carries a load
};

/// |a − b|², compared squared where only the order matters (no square
/// root; beyond √(max) it is +∞, and such points merge into one).
template <class Real>
Real squared_distance(const point2<Real>& a, const point2<Real>& b) {
  const Real dx = a[0] - b[0], dy = a[1] - b[1];
  return dx * dx + dy * dy;
}

template <class Real>
Real distance(const point2<Real>& a, const point2<Real>& b) {
  using std::sqrt;
  return sqrt(squared_distance(a, b));
}

/// The relative tolerance as used: at least 1024 ε (below, the polygon's own
/// checks would see a sliver as flat), at most 1/16; NaN counts as the least.
template <class Real>
Real usable_tolerance(Real relative) {
  const Real least = 1024 * boost::math::tools::epsilon<Real>();
  if (!(relative >= least)) return least;
  return relative < Real(1) / 16 ? relative : Real(1) / 16;
}

/// The largest coordinate's size among `points` and e: what rounding a
/// point's coordinates is relative to.
template <class Real>
Real coordinate_size(const vertex_list<Real>& points, const point2<Real>& e) {
  using std::fabs;
  Real size = std::max(fabs(e[0]), fabs(e[1]));
  for (const auto& x : points) size = std::max(size, std::max(fabs(x[0]), fabs(x[1])));
  return size;
}

/// The finite points, their load-weighted centre (the plain mean if no
/// point is loaded) and spread, the distinct positions (a point within the
/// merge distance of an earlier one is that one).
template <class Real, class Range>
gathered_points<Real> gather_points(const Range& points, Real relative) {
  using std::isfinite;
  gathered_points<Real> g;
  vertex_list<Real> finite;
  point2<Real> mean{}, moment{};
  Real total = 0;
  for (const auto& p : points) {
    if (!isfinite(p.position[0]) || !isfinite(p.position[1])) continue;
    finite.push_back(p.position);
    const Real w = isfinite(p.load) && p.load > 0 ? p.load : Real(0);
    total += w;
    for (std::size_t k = 0; k < 2; ++k) {
      mean[k] += p.position[k];
      moment[k] += w * p.position[k];
    }
  }
  const std::size_t n = finite.size();
  if (n == 0) return g;
  for (std::size_t k = 0; k < 2; ++k) mean[k] /= Real(n);
  g.loaded = total > 0 && isfinite(total);
  g.centre = g.loaded ? point2<Real>{moment[0] / total, moment[1] / total} : mean;
  Real spread2 = 0;
  for (const auto& x : finite) spread2 = std::max(spread2, squared_distance(x, mean));
  using std::sqrt;
  g.spread = sqrt(spread2);
  // Not below the rounding of the coordinates: points that differ by
  // rounding only are one point, however small their spread.
  g.merge = std::max(usable_tolerance(relative) * g.spread,
                     64 * boost::math::tools::epsilon<Real>() * coordinate_size(finite, g.centre));
  const Real merge2 = g.merge * g.merge;
  for (const auto& x : finite) {
    bool repeated = false;
    for (const auto& u : g.unique) repeated = repeated || squared_distance(x, u) <= merge2;
    if (!repeated) g.unique.push_back(x);
  }
  return g;
}

/// (b − a) × (c − a): > 0 for a left turn.
template <class Real>
Real turn(const point2<Real>& a, const point2<Real>& b, const point2<Real>& c) {
  return cross(minus(b, a), minus(c, a));
}

/// A stack of points over vertex_list's storage (no allocation up to 18).
template <class Real>
struct point_stack {
  vertex_list<Real, 18> store;
  std::size_t size = 0;
  void push(const point2<Real>& p) {
    if (size < store.size()) {
      store[size] = p;
    } else {
      store.push_back(p);
    }
    ++size;
  }
  const point2<Real>& from_top(std::size_t k) const { return store[size - 1 - k]; }
};

/// The convex hull of `points` (distinct; sorted here), counter-clockwise,
/// by Andrew's monotone chain; then every vertex nearer than `merge` to the
/// chord of its neighbours is dropped (rounding cannot then make the
/// outline turn the wrong way).
template <class Real>
vertex_list<Real> convex_hull(vertex_list<Real>& points, Real merge) {
  std::sort(points.data(), points.data() + points.size());
  const std::size_t n = points.size();
  point_stack<Real> h;
  for (int pass = 0; pass < 2; ++pass) {  // the lower chain, then the upper
    const std::size_t floor = h.size;
    for (std::size_t k = 0; k < n; ++k) {
      const point2<Real>& p = points[pass == 0 ? k : n - 1 - k];
      while (h.size >= floor + 2 && !(turn(h.from_top(1), h.from_top(0), p) > 0)) --h.size;
      h.push(p);
    }
    --h.size;  // the chain's last point starts the other chain
  }
  vertex_list<Real> hull;
  for (std::size_t k = 0; k < h.size; ++k) hull.push_back(h.store[k]);
  for (bool dropped = true; dropped && hull.size() > 2;) {
    dropped = false;
    vertex_list<Real> kept;
    const std::size_t m = hull.size();
    for (std::size_t k = 0; k < m; ++k) {
      const point2<Real>& before = hull[k == 0 ? m - 1 : k - 1];
      const point2<Real>& after = hull.next(k);
      const Real chord = distance(before, after);
      const bool flat = !dropped && turn(before, hull[k], after) <= merge * chord;
      if (flat) {
        dropped = true;
      } else {
        kept.push_back(hull[k]);
      }
    }
    hull = kept;
  }
  return hull;
}

/// The two points of `points` farthest apart.
template <class Real>
std::array<point2<Real>, 2> farthest_pair(const vertex_list<Real>& points) {
  std::array<point2<Real>, 2> best{points[0], points[0]};
  Real longest = -1;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      const Real d = squared_distance(points[i], points[j]);
      if (d > longest) {
        longest = d;
        best = {points[i], points[j]};
      }
    }
  return best;
}

/// Twice the area of the counter-clockwise `hull`, about its first vertex.
template <class Real>
Real twice_area(const vertex_list<Real>& hull) {
  Real a = 0;
  for (std::size_t k = 1; k + 1 < hull.size(); ++k) a += turn(hull[0], hull[k], hull[k + 1]);
  return a;
}

/// The point of segment a→b nearest to e, as the fraction along it.
template <class Real>
Real fraction_along(const point2<Real>& a, const point2<Real>& b, const point2<Real>& e) {
  const point2<Real> d = minus(b, a);
  const Real t = dot(minus(e, a), d) / dot(d, d);
  return t < 0 ? Real(0) : (t > 1 ? Real(1) : t);
}

/// e, if it is inside the counter-clockwise `hull` by at least `margin`;
/// otherwise its nearest point on the outline moved `margin` towards the
/// vertices' mean (inside the hull, since the hull is convex).  The centre
/// of a convex combination of the points is inside the hull but for
/// rounding and for the points the hull dropped as flat (at most the merge
/// distance out).
template <class Real>
point2<Real> clamped_centre(const vertex_list<Real>& hull, const point2<Real>& e, Real margin) {
  Real inside = 0;
  point2<Real> nearest = e, mean{};
  Real nearest_distance = -1;
  const std::size_t m = hull.size();
  for (std::size_t k = 0; k < m; ++k) {
    const point2<Real>& a = hull[k];
    const point2<Real>& b = hull.next(k);
    const Real signed_distance = turn(a, b, e) / distance(a, b);
    inside = k == 0 ? signed_distance : std::min(inside, signed_distance);
    const Real t = fraction_along(a, b, e);
    const point2<Real> p{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
    const Real d = squared_distance(p, e);
    if (nearest_distance < 0 || d < nearest_distance) {
      nearest_distance = d;
      nearest = p;
    }
    mean[0] += a[0] / Real(m);
    mean[1] += a[1] / Real(m);
  }
  if (inside >= margin) return e;
  const Real to_mean = distance(mean, nearest);
  if (!(to_mean > 0)) return mean;
  return {nearest[0] + margin * (mean[0] - nearest[0]) / to_mean,
          nearest[1] + margin * (mean[1] - nearest[1]) / to_mean};
}

/// The line patch on a→b with its centre at e's nearest point on it, or a
/// point patch at e where the segment is shorter than 1/8 of its distance
/// from the origin (the origin's rounding would then put the centre off the
/// segment by more than polygon_patch::segment accepts).
template <class Real>
polygon_patch<Real> line_patch(const point2<Real>& a, const point2<Real>& b,
                               const point2<Real>& e) {
  const Real length = distance(a, b);
  const point2<Real> zero{};
  if (!(8 * length >= std::max(distance(a, zero), distance(b, zero))))
    return polygon_patch<Real>::point(e);
  const Real t = fraction_along(a, b, e);
  const point2<Real> c{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
  return polygon_patch<Real>::segment(a, b, centre_of_pressure<Real>{c});
}

}  // namespace detail

/// The patch of one contact from the engine's `points` (a range of
/// contact_point<Real>; positions in the tangent plane about the patch
/// origin, which should be near the points: the engine's contact centre):
///  - the convex hull of the distinct points (points nearer than the merge
///    distance, `tolerance` times the points' spread, are one; the hull's
///    vertices nearer than it to the chord of their neighbours are dropped),
///    under the linear (or no-tension) pressure whose centre is the points'
///    load-weighted mean, clamped into the hull (uniform if no point is
///    loaded);
///  - the line patch between the two points farthest apart where the hull's
///    area is below tolerance × its diameter² (collinear points: a box on its
///    edge), its centre the load-weighted mean's nearest point on it;
///  - a point patch at the load-weighted mean where all points merge into
///    one, or there is one point; at the origin where no point is finite.
/// Points with a non-finite coordinate are left out.  Never throws; no heap
/// allocation for up to 8 points.  `tolerance` below 1024 ε (or NaN) is
/// raised to it, above 1/16 lowered to it.
template <class Range, class Real = typename std::decay_t<
                           decltype(*std::begin(std::declval<const Range&>()))>::value_type>
polygon_patch<Real> contact_patch(const Range& points,
                                  merge_tolerance<Real> tolerance = merge_tolerance<Real>{
                                      Real(1e-6)}) {
  using point = detail::point2<Real>;
  detail::gathered_points<Real> g = detail::gather_points<Real>(points, tolerance.value);
  if (g.unique.size() == 0) return polygon_patch<Real>::point(point{});
  if (g.unique.size() == 1) return polygon_patch<Real>::point(g.centre);
  const detail::vertex_list<Real> hull = detail::convex_hull(g.unique, g.merge);
  const std::array<point, 2> ends = detail::farthest_pair(g.unique);
  const Real diameter = detail::distance(ends[0], ends[1]);
  const Real relative = detail::usable_tolerance(tolerance.value);
  const Real area2 = hull.size() >= 3 ? detail::twice_area(hull) : Real(0);
  if (!(area2 > relative * diameter * diameter))
    return detail::line_patch(ends[0], ends[1], g.centre);
  if (!g.loaded) return polygon_patch<Real>(hull);
  // The clamp's margin: a few roundings of the largest coordinate (the
  // polygon's check allows 16 ε of its size outside).  A hull thinner than
  // that (an origin ~10⁷ sizes away) is a point at the centre.
  const Real margin =
      8 * boost::math::tools::epsilon<Real>() * detail::coordinate_size(hull, g.centre);
  if (!(margin * diameter < area2 / 8)) return polygon_patch<Real>::point(g.centre);
  return polygon_patch<Real>(
      hull, centre_of_pressure<Real>{detail::clamped_centre(hull, g.centre, margin)});
}

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_CONTACT_PATCH_HPP
