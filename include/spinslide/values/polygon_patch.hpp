//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file polygon_patch.hpp
/// A flat contact patch (docs/patches.md): a convex polygon pressed
/// uniformly, or linearly with a given centre of pressure; beyond the kern
/// the no-tension pressure max(0, α + β·x) with the same resultant and
/// centre (a rigid face on a Winkler floor: the part that lifts off carries
/// nothing).  The same class holds the two degenerate patches: a line patch
/// (a segment with a linear line pressure: a box on its edge, or a polygon
/// whose centre of pressure is on an edge) and a point patch (point
/// friction: a centre of pressure on a vertex).  friction_wrench.hpp
/// computes its friction.

#ifndef SPINSLIDE_VALUES_POLYGON_PATCH_HPP
#define SPINSLIDE_VALUES_POLYGON_PATCH_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/values/detail/patch_geometry.hpp>
#include <spinslide/values/detail/patch_outline.hpp>
#include <spinslide/values/detail/patch_pressure.hpp>
#include <spinslide/values/detail/patch_slabs.hpp>

#include <boost/math/special_functions/hypot.hpp>
#include <boost/math/tools/precision.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <initializer_list>

namespace spinslide {

/// A centre of pressure, in the vertices' frame: centre_of_pressure<double>{{x, y}}.
template <class Real>
struct centre_of_pressure {
  using value_type = Real;    ///< the floating type
  std::array<Real, 2> point;  ///< (x, y)
};

/// What carries the load: an area (≥ 3 vertices), a segment, or a point.
enum class patch_shape { area, line, point };

/// A flat patch under a linear pressure p(x) = p₀ + β·(x − z₀) ≥ 0 on its
/// loaded region, with ∫ p = 1 (per unit area for an area, per unit length
/// for a segment; a point carries the whole load).
///  - polygon_patch(vertices[, centre]): a convex polygon, ≥ 3 vertices in
///    either orientation (kept counter-clockwise), any length unit; uniform
///    pressure, or linear with the given centre of pressure (no-tension
///    beyond the kern).  A centre on an edge makes a line patch, on a vertex
///    a point patch.
///  - polygon_patch::segment(a, b[, centre]): a line patch (uniform, or
///    linear with the centre on the segment; no-tension beyond its middle third).
///  - polygon_patch::point(x): point friction.
/// A bad outline or centre is std::domain_error naming the problem.  Up to 8
/// vertices nothing is allocated.
template <class Real>
class polygon_patch {
 public:
  using value_type = Real;                        ///< the floating type
  using vertex = std::array<Real, 2>;             ///< a point of the plane
  using vertex_list = detail::vertex_list<Real>;  ///< inline storage for 9 vertices
  /// The type the pressure is solved in (and the wrench computed in): double for float.
  using working = detail::working_type<Real>;

  /// A convex polygon under uniform pressure.
  template <class Range>
  explicit polygon_patch(const Range& vertices) {
    build(vertices, nullptr);
  }
  /// A convex polygon under the linear (or no-tension) pressure with centre `centre`.
  template <class Range>
  polygon_patch(const Range& vertices, const centre_of_pressure<Real>& centre) {
    build(vertices, &centre.point);
  }
  /// The same from a braced list of vertices, uniform.
  polygon_patch(std::initializer_list<vertex> vertices) { build(vertices, nullptr); }
  /// The same from a braced list of vertices, with the centre of pressure `centre`.
  polygon_patch(std::initializer_list<vertex> vertices, const centre_of_pressure<Real>& centre) {
    build(vertices, &centre.point);
  }

  /// The line patch from a to b, uniform.
  static polygon_patch segment(const vertex& a, const vertex& b) {
    return segment(a, b, centre_of_pressure<Real>{{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2}});
  }
  /// The line patch from a to b with its centre of pressure on it.
  static polygon_patch segment(const vertex& a, const vertex& b,
                               const centre_of_pressure<Real>& centre) {
    static const char* function = "spinslide::polygon_patch<%1%>::segment";
    polygon_patch p;
    check_finite(function, a);
    check_finite(function, b);
    check_finite(function, centre.point);
    const Real length = boost::math::hypot(b[0] - a[0], b[1] - a[1]);
    if (!(length > 0))
      detail::refuse_constructor_argument(function, "segment length", "> 0 (two distinct points)",
                                          length);
    const vertex d{b[0] - a[0], b[1] - a[1]}, e{centre.point[0] - a[0], centre.point[1] - a[1]};
    const Real off = detail::cross(d, e) / length, along = detail::dot(d, e) / (length * length);
    if (!(fabs_(off) <= tolerance() * length && along >= -tolerance() && along <= 1 + tolerance()))
      detail::refuse_constructor_argument(function,
                                          "centre of pressure's distance from the segment",
                                          "0 (the centre on the segment)", off);
    p.set_segment(a, b, along);
    p.radius_ = fmax_(norm(a), norm(b));
    return p;
  }
  /// Point friction at x.
  static polygon_patch point(const vertex& x) {
    polygon_patch p;
    check_finite("spinslide::polygon_patch<%1%>::point", x);
    p.set_point(x);
    p.radius_ = norm(x);
    return p;
  }

  /// Area, line or point.
  patch_shape shape() const { return shape_; }
  /// The loaded region's vertices (counter-clockwise; 2 for a line patch, 1 for a point).
  const vertex_list& loaded_vertices() const { return loaded_; }
  /// The pressure's reference point z₀ (the loaded vertices' mean).
  const vertex& pressure_origin() const { return z0_; }
  /// p(z₀).
  Real pressure_at_origin() const { return p0_; }
  /// β = ∇p (along the segment for a line patch).
  const vertex& pressure_gradient() const { return beta_; }
  /// The pressure at x (0 where the patch lifts off; for a line patch along its line).
  Real pressure(const vertex& x) const {
    return p0_ + beta_[0] * (x[0] - z0_[0]) + beta_[1] * (x[1] - z0_[1]);
  }
  /// The largest distance ρ₀ of a loaded vertex from z₀.
  Real loaded_radius() const { return rho0_; }
  /// ℓ: the largest distance of a vertex of the outline from the origin.
  Real radius() const { return radius_; }
  /// The centre of pressure.
  const vertex& centre() const { return centre_; }
  /// True for a loaded area longer than 4 times its width: its wrench is
  /// summed over slabs (detail/patch_slabs.hpp).
  bool thin() const { return thin_; }

 private:
  polygon_patch() = default;

  static Real fabs_(Real x) { return x < 0 ? Real(-x) : x; }
  static Real fmax_(Real a, Real b) { return a < b ? b : a; }
  static Real norm(const vertex& x) { return boost::math::hypot(x[0], x[1]); }
  /// A relative tolerance: the centre within it of the boundary (times the
  /// patch size) is on the boundary.
  static Real tolerance() { return 16 * boost::math::tools::epsilon<Real>(); }
  /// A centre of pressure nearer the boundary than this (times the patch
  /// size) loads a line patch: closer in, the no-tension region is a sliver
  /// whose moments (and Newton's solve on them) lose ~ε·size/distance, and
  /// whose edge sums lose as much to the pressure's steep gradient.
  static Real boundary_band() { return 64 * boost::math::tools::root_epsilon<working>(); }

  static void check_finite(const char* function, const vertex& x) {
    detail::checked_constructor_argument(function, "vertex x", x[0], detail::argument_rule::finite);
    detail::checked_constructor_argument(function, "vertex y", x[1], detail::argument_rule::finite);
  }

  template <class Range>
  void build(const Range& vertices, const vertex* centre) {
    static const char* function = "spinslide::polygon_patch<%1%>::polygon_patch";
    const detail::patch_outline<Real> o = detail::checked_outline<Real>(function, vertices);
    for (const auto& v : o.poly) radius_ = fmax_(radius_, norm(v));
    if (!centre) return set_area(o, nullptr);
    check_finite(function, *centre);
    const auto near = detail::nearest_edge(o.poly, *centre);
    if (near.distance < -tolerance() * o.scale)
      detail::refuse_constructor_argument(
          function, "the centre of pressure's distance inside the outline",
          ">= 0 (the centre inside the polygon or on its boundary)", near.distance);
    if (near.distance > boundary_band() * o.scale) return set_area(o, centre);
    // On an edge: the load is on that edge (a line patch), or on a vertex.
    const vertex& a = o.poly[near.edge];
    const vertex& b = o.poly.next(near.edge);
    const vertex d = detail::minus(b, a);
    set_segment(a, b, detail::dot(d, detail::minus(*centre, a)) / detail::dot(d, d));
  }

  /// The polygon's linear or no-tension pressure, solved in the frame
  /// y = (x − g)/scale (detail/patch_pressure.hpp), and back.
  void set_area(const detail::patch_outline<Real>& o, const vertex* centre) {
    using W = working;
    using wvertex = detail::point2<W>;
    const W scale = W(o.scale);
    detail::vertex_list<W> y;
    for (const auto& v : o.poly)
      y.push_back({(W(v[0]) - W(o.mean[0])) / scale, (W(v[1]) - W(o.mean[1])) / scale});
    const auto m = detail::polygon_moments(y, wvertex{});
    const wvertex e = centre ? wvertex{(W((*centre)[0]) - W(o.mean[0])) / scale,
                                       (W((*centre)[1]) - W(o.mean[1])) / scale}
                             : wvertex{m.first[0] / m.area, m.first[1] / m.area};
    const auto lp = detail::patch_pressure(y, e);
    shape_ = patch_shape::area;
    loaded_.clear();
    if (lp.lifted) {
      for (const auto& v : lp.loaded)
        loaded_.push_back({Real(W(o.mean[0]) + scale * v[0]), Real(W(o.mean[1]) + scale * v[1])});
    } else {
      loaded_ = o.poly;
    }
    finish_loaded();
    const wvertex z{(W(z0_[0]) - W(o.mean[0])) / scale, (W(z0_[1]) - W(o.mean[1])) / scale};
    const W s2 = scale * scale;
    p0_ = Real((lp.alpha + detail::dot(lp.beta, z)) / s2);
    beta_ = {Real(lp.beta[0] / (s2 * scale)), Real(lp.beta[1] / (s2 * scale))};
    centre_ = centre ? *centre
                     : vertex{Real(W(o.mean[0]) + scale * e[0]), Real(W(o.mean[1]) + scale * e[1])};
  }

  /// The line patch on the segment a→b with its centre at a + along·(b − a):
  /// linear over the whole segment when along is in its middle third,
  /// triangular on the loaded part beyond (docs/patches.md, "The line patch").
  void set_segment(const vertex& a, const vertex& b, Real along) {
    if (along <= tolerance()) return set_point(a);
    if (along >= 1 - tolerance()) return set_point(b);
    const vertex d = detail::minus(b, a);
    const Real length = norm(d);
    vertex from = a, to = b;
    Real q0 = (4 - 6 * along) / length, q1 = (6 * along - 2) / length;
    if (along < Real(1) / 3) {
      to = {a[0] + 3 * along * d[0], a[1] + 3 * along * d[1]};
      q0 = 2 / (3 * along * length);
      q1 = 0;
    } else if (along > Real(2) / 3) {
      const Real rest = 1 - along;
      from = {b[0] - 3 * rest * d[0], b[1] - 3 * rest * d[1]};
      q0 = 0;
      q1 = 2 / (3 * rest * length);
    }
    shape_ = patch_shape::line;
    loaded_.clear();
    loaded_.push_back(from);
    loaded_.push_back(to);
    finish_loaded();
    const Real loaded_length = norm(detail::minus(to, from));
    p0_ = (q0 + q1) / 2;
    beta_ = {(q1 - q0) / loaded_length * d[0] / length, (q1 - q0) / loaded_length * d[1] / length};
    centre_ = {a[0] + along * d[0], a[1] + along * d[1]};
  }

  void set_point(const vertex& x) {
    shape_ = patch_shape::point;
    loaded_.clear();
    loaded_.push_back(x);
    z0_ = x;
    centre_ = x;
    p0_ = 1;
    beta_ = {0, 0};
    rho0_ = 0;
  }

  /// z₀ (the loaded vertices' mean) and ρ₀.
  void finish_loaded() {
    z0_ = {0, 0};
    const std::size_t n = loaded_.size();
    for (const auto& v : loaded_) {
      z0_[0] += v[0] / Real(n);
      z0_[1] += v[1] / Real(n);
    }
    rho0_ = 0;
    for (const auto& v : loaded_) rho0_ = fmax_(rho0_, norm(detail::minus(v, z0_)));
    thin_ = shape_ == patch_shape::area && detail::plan_slabs(loaded_).count > 1;
  }

  patch_shape shape_ = patch_shape::area;
  vertex_list loaded_;
  vertex z0_{}, beta_{}, centre_{};
  Real p0_ = 0, rho0_ = 0, radius_ = 0;
  bool thin_ = false;
};

}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_POLYGON_PATCH_HPP
