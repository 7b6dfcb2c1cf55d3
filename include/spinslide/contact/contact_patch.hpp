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
#include <spinslide/values/detail/patch_outline.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <boost/math/tools/precision.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
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
  bool far = false;     // coordinates beyond √max/16 or all below 16√min: a point
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

/// The relative tolerance as used: at least 1024 ε and √ε of the working
/// type (below, the polygon's own checks, and its pressure solve on a
/// sliver whose short edge is 1e-7 of its size, fail), at most 1/16; NaN
/// counts as the least.
template <class Real>
Real usable_tolerance(Real relative) {
  using std::sqrt;
  const Real least = std::max(Real(1024 * boost::math::tools::epsilon<Real>()),
                              Real(boost::math::tools::root_epsilon<working_type<Real>>()));
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

/// A load as it counts: 0 if negative or not finite.
template <class Real>
Real counted_load(Real load) {
  using std::isfinite;
  return isfinite(load) && load > 0 ? load : Real(0);
}

/// The finite points (a coordinate below 64 ε of the largest, its rounding,
/// as 0: a subnormal distance from a vertex is where the wrench's edge sums
/// lose it) and their loads, the largest coordinate and the largest load.
template <class Real>
struct finite_points {
  vertex_list<Real> positions;
  vertex_list<Real> loads;  // (load, 0)
  Real size = 0, heaviest = 0;
};

template <class Real, class Range>
finite_points<Real> finite_points_of(const Range& points) {
  using std::fabs;
  using std::isfinite;
  finite_points<Real> f;
  for (const auto& p : points) {
    if (!isfinite(p.position[0]) || !isfinite(p.position[1])) continue;
    f.size = std::max(f.size, std::max(fabs(p.position[0]), fabs(p.position[1])));
    f.heaviest = std::max(f.heaviest, counted_load(p.load));
  }
  const Real noise = 64 * boost::math::tools::epsilon<Real>() * f.size;
  const auto snapped = [noise](Real x) { return fabs(x) <= noise ? Real(0) : x; };
  for (const auto& p : points) {
    if (!isfinite(p.position[0]) || !isfinite(p.position[1])) continue;
    f.positions.push_back({snapped(p.position[0]), snapped(p.position[1])});
    f.loads.push_back({counted_load(p.load), Real(0)});
  }
  return f;
}

/// The plain mean of the points and their load-weighted mean (the plain one
/// if no point is loaded; `loaded` says which), the sums scaled by the
/// largest coordinate and the largest load, so that neither overflows.
template <class Real>
std::array<point2<Real>, 2> means(const finite_points<Real>& f, bool& loaded) {
  const std::size_t n = f.positions.size();
  const Real unit = f.size > 0 ? f.size : Real(1);
  point2<Real> mean{}, moment{};
  Real total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Real w = f.heaviest > 0 ? f.loads[i][0] / f.heaviest : Real(0);
    total += w;
    for (std::size_t k = 0; k < 2; ++k) {
      mean[k] += f.positions[i][k] / unit / Real(n);
      moment[k] += w * (f.positions[i][k] / unit);
    }
  }
  loaded = total > 0;
  const point2<Real> plain{mean[0] * unit, mean[1] * unit};
  return {plain, loaded ? point2<Real>{moment[0] / total * unit, moment[1] / total * unit} : plain};
}

/// The finite points, their load-weighted centre and spread, the distinct
/// positions (a point within the merge distance of an earlier one is that
/// one).
template <class Real, class Range>
gathered_points<Real> gather_points(const Range& points, Real relative) {
  using std::sqrt;
  gathered_points<Real> g;
  const finite_points<Real> f = finite_points_of<Real>(points);
  if (f.positions.size() == 0) return g;
  const auto m = means(f, g.loaded);
  g.centre = m[1];
  // Beyond √max/16 the squares below (and the polygon's own) overflow, below
  // 16√min they underflow: a contact that far from its origin, or that
  // small about it, is a point at its centre.
  g.far = !(f.size <= sqrt(std::numeric_limits<Real>::max()) / 16) ||
          f.size < 16 * sqrt(std::numeric_limits<Real>::min());
  if (g.far) return g;
  Real spread2 = 0;
  for (const auto& x : f.positions) spread2 = std::max(spread2, squared_distance(x, m[0]));
  g.spread = sqrt(spread2);
  // Not below the rounding of the coordinates: points that differ by
  // rounding only are one point, however small their spread.
  g.merge =
      std::max(usable_tolerance(relative) * g.spread,
               64 * boost::math::tools::epsilon<Real>() * coordinate_size(f.positions, g.centre));
  const Real merge2 = g.merge * g.merge;
  for (const auto& x : f.positions) {
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

/// e if it is inside the counter-clockwise `hull`, otherwise its nearest
/// point on the outline.  The centre of a convex combination of the points
/// is inside the hull but for rounding and for the points the hull dropped
/// as flat (at most the merge distance out).
template <class Real>
point2<Real> clamped_centre(const vertex_list<Real>& hull, const point2<Real>& e) {
  if (nearest_edge(hull, e).distance >= 0) return e;
  point2<Real> nearest = e;
  Real nearest_distance = -1;
  for (std::size_t k = 0; k < hull.size(); ++k) {
    const point2<Real>& a = hull[k];
    const point2<Real>& b = hull.next(k);
    const Real t = fraction_along(a, b, e);
    const point2<Real> p{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
    const Real d = squared_distance(p, e);
    if (nearest_distance < 0 || d < nearest_distance) {
      nearest_distance = d;
      nearest = p;
    }
  }
  return nearest;
}

/// The polygon's largest distance of a vertex from the vertices' mean (its
/// size, as polygon_patch measures it).
template <class Real>
Real outline_scale(const vertex_list<Real>& hull) {
  point2<Real> mean{};
  for (const auto& v : hull)
    for (std::size_t k = 0; k < 2; ++k) mean[k] += v[k] / Real(hull.size());
  Real scale2 = 0;
  for (const auto& v : hull) scale2 = std::max(scale2, squared_distance(v, mean));
  using std::sqrt;
  return sqrt(scale2);
}

/// The line patch on a→b with its centre at e's nearest point on it, or a
/// point patch at e where the segment is shorter than 1/4 of its distance
/// from the origin (the origin's rounding would then put the centre off the
/// segment by more than polygon_patch::segment accepts).
template <class Real>
polygon_patch<Real> line_patch(const point2<Real>& a, const point2<Real>& b,
                               const point2<Real>& e) {
  const Real length = distance(a, b);
  const point2<Real> zero{};
  if (!(4 * length >= std::max(distance(a, zero), distance(b, zero))))
    return polygon_patch<Real>::point(e);
  const Real t = fraction_along(a, b, e);
  const point2<Real> c{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
  return polygon_patch<Real>::segment(a, b, centre_of_pressure<Real>{c});
}

/// The polygon `hull` under the linear (no-tension) pressure of centre e
/// (inside or on it).  polygon_patch puts the load of a centre within its
/// boundary band of an edge (64√ε_working of its size) on that edge; here
/// that band, widened to the rounding of the coordinates, is decided before
/// the constructor is called, so that a centre it would find a rounding
/// outside (a centre on a vertex of a sliver) never reaches it.
template <class Real>
polygon_patch<Real> area_patch(const vertex_list<Real>& hull, const point2<Real>& e) {
  using W = working_type<Real>;
  const Real band = std::max(Real(64 * boost::math::tools::root_epsilon<W>()) * outline_scale(hull),
                             64 * boost::math::tools::epsilon<Real>() * coordinate_size(hull, e));
  const edge_distance<Real> near = nearest_edge(hull, e);
  if (!(near.distance > band)) return line_patch(hull[near.edge], hull.next(near.edge), e);
  return polygon_patch<Real>(hull, centre_of_pressure<Real>{e});
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
/// Points with a non-finite coordinate are left out, a coordinate below 64 ε
/// of the largest counts as 0; a coordinate beyond
/// √(max)/16 (8e152 in double), or all of them below 16√(min) (2e-153),
/// make a point patch at the loads' centre.
/// Never throws; no heap
/// allocation for up to 8 points.  `tolerance` below 1024 ε and √ε of the
/// working type (1.5e-8 in double) or NaN is raised to that, above 1/16
/// lowered to it.
template <class Range, class Real = typename std::decay_t<
                           decltype(*std::begin(std::declval<const Range&>()))>::value_type>
polygon_patch<Real> contact_patch(const Range& points,
                                  merge_tolerance<Real> tolerance = merge_tolerance<Real>{
                                      Real(1e-6)}) {
  using point = detail::point2<Real>;
  detail::gathered_points<Real> g = detail::gather_points<Real>(points, tolerance.value);
  if (g.far) return polygon_patch<Real>::point(g.centre);
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
  return detail::area_patch(hull, detail::clamped_centre(hull, g.centre));
}

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_CONTACT_PATCH_HPP
