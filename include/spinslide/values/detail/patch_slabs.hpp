//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file patch_slabs.hpp
/// A thin loaded region cut into fat slabs (docs/patches.md, "Thin patches"):
/// both the edge sums and the far field's contour integrals lose about the
/// region's aspect ratio (their terms scale with its perimeter times its
/// length, the result with its area) and as much again to the steep
/// pressure gradient a thin no-tension region carries across itself.  Cut
/// across its long axis into slabs of aspect at most 2, each is evaluated
/// on its own (edge sums or far field, each about its own centre) and the
/// wrenches add up.

#ifndef SPINSLIDE_VALUES_DETAIL_PATCH_SLABS_HPP
#define SPINSLIDE_VALUES_DETAIL_PATCH_SLABS_HPP

#include <spinslide/values/detail/patch_geometry.hpp>

#include <boost/math/tools/config.hpp>

#include <cmath>
#include <cstddef>

namespace spinslide {
namespace detail {

/// How a convex polygon is cut: along `axis` (its longest vertex-to-vertex
/// direction) from `start` in `count` slabs of width `step`.
template <class Real>
struct slab_plan {
  point2<Real> axis{};
  Real start = 0, step = 0;
  std::size_t count = 1;
};

/// The plan for `poly`: one slab unless its length exceeds 4 times its
/// width across the axis; at most `max_slabs`.
template <class Real, std::size_t N>
slab_plan<Real> plan_slabs(const vertex_list<Real, N>& poly, std::size_t max_slabs = 256) {
  BOOST_MATH_STD_USING
  slab_plan<Real> plan;
  const std::size_t n = poly.size();
  Real longest = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const point2<Real> d = minus(poly[j], poly[i]);
      const Real l2 = dot(d, d);
      if (l2 > longest) {
        longest = l2;
        plan.axis = d;
      }
    }
  }
  const Real length = sqrt(longest);
  if (!(length > 0)) return plan;
  plan.axis = {plan.axis[0] / length, plan.axis[1] / length};
  Real lo = dot(plan.axis, poly[0]), hi = lo, across_lo = cross(plan.axis, poly[0]),
       across_hi = across_lo;
  for (const auto& v : poly) {
    lo = fmin(lo, dot(plan.axis, v));
    hi = fmax(hi, dot(plan.axis, v));
    across_lo = fmin(across_lo, cross(plan.axis, v));
    across_hi = fmax(across_hi, cross(plan.axis, v));
  }
  const Real width = across_hi - across_lo;
  if (!(hi - lo > 4 * width)) return plan;
  const Real slabs = ceil((hi - lo) / (2 * width));
  plan.count = slabs < Real(max_slabs) ? static_cast<std::size_t>(slabs) : max_slabs;
  plan.start = lo;
  plan.step = (hi - lo) / Real(plan.count);
  return plan;
}

/// Slab k of `poly` under `plan`, into `out` (`scratch` holds the first cut):
/// axis·x ≥ start + k·step (not for the first) and ≤ start + (k + 1)·step
/// (not for the last).
template <class Real, std::size_t N, std::size_t M>
void slab(const vertex_list<Real, N>& poly, const slab_plan<Real>& plan, std::size_t k,
          vertex_list<Real, M>& scratch, vertex_list<Real, M>& out) {
  const Real from = plan.start + Real(k) * plan.step, to = from + plan.step;
  const point2<Real> back{-plan.axis[0], -plan.axis[1]};
  scratch.clear();
  if (k == 0) {
    for (const auto& v : poly) scratch.push_back(v);
  } else {
    clip_polygon(poly, point2<Real>{}, Real(-from), plan.axis, scratch);
  }
  if (k + 1 == plan.count) {
    out.clear();
    for (const auto& v : scratch) out.push_back(v);
  } else {
    clip_polygon(scratch, point2<Real>{}, to, back, out);
  }
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DETAIL_PATCH_SLABS_HPP
