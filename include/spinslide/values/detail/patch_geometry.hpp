//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file patch_geometry.hpp
/// The plane geometry of a flat patch (docs/patches.md, "The patch"): a list
/// of vertices with inline storage (no heap allocation up to its inline
/// capacity: an engine builds a patch per contact per step), the area
/// moments of a convex polygon under a linear pressure, and the clip of a
/// convex polygon by a half-plane.

#ifndef SPINSLIDE_VALUES_DETAIL_PATCH_GEOMETRY_HPP
#define SPINSLIDE_VALUES_DETAIL_PATCH_GEOMETRY_HPP

#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace spinslide {
namespace detail {

template <class Real>
using point2 = std::array<Real, 2>;

/// The type a patch is solved and evaluated in: double for float (the
/// no-tension solve and the edge sums lose up to the patch's aspect ratio
/// times (distance/size)² ulps; in float that is too much, in double free),
/// Real otherwise.
template <class Real>
using working_type = std::conditional_t<std::is_same<Real, float>::value, double, Real>;

template <class Real>
point2<Real> minus(const point2<Real>& a, const point2<Real>& b) {
  return {a[0] - b[0], a[1] - b[1]};
}

template <class Real>
Real dot(const point2<Real>& a, const point2<Real>& b) {
  return a[0] * b[0] + a[1] * b[1];
}

/// The z-component of a × b.
template <class Real>
Real cross(const point2<Real>& a, const point2<Real>& b) {
  return a[0] * b[1] - a[1] * b[0];
}

/// Vertices, the first `Inline` of them stored in the object; more go to
/// the heap (all of them then).
template <class Real, std::size_t Inline = 9>
class vertex_list {
 public:
  void push_back(const point2<Real>& p) {
    if (heap_.empty() && size_ < Inline) {
      inline_[size_++] = p;
      return;
    }
    if (heap_.empty()) heap_.assign(inline_.begin(), inline_.begin() + size_);
    heap_.push_back(p);
    ++size_;
  }
  void clear() {
    heap_.clear();
    size_ = 0;
  }
  std::size_t size() const { return size_; }
  const point2<Real>* data() const { return heap_.empty() ? inline_.data() : heap_.data(); }
  point2<Real>* data() { return heap_.empty() ? inline_.data() : heap_.data(); }
  const point2<Real>& operator[](std::size_t i) const { return data()[i]; }
  point2<Real>& operator[](std::size_t i) { return data()[i]; }
  /// The vertex after i, cyclically.
  const point2<Real>& next(std::size_t i) const { return data()[i + 1 == size_ ? 0 : i + 1]; }
  const point2<Real>* begin() const { return data(); }
  const point2<Real>* end() const { return data() + size_; }

 private:
  std::array<point2<Real>, Inline> inline_{};
  std::vector<point2<Real>> heap_;
  std::size_t size_ = 0;
};

/// The area moments of a polygon about a reference point g (y = x − g):
/// `area` = ∬ 1, `first` = ∬ y, `second` = ∬ y yᵀ as (xx, xy, yy).  A linear
/// pressure p = α + β·y has ∬ p = αA + β·S, ∬ p y = αS + Jβ and ∬ p² =
/// α²A + 2αβ·S + βᵀJβ from these alone.
template <class Real>
struct area_moments {
  Real area = 0;
  point2<Real> first{};
  std::array<Real, 3> second{};
};

/// The area moments of a polygon whose vertices (about the reference point)
/// arrive one at a time, fanned into triangles (y₀, yᵢ, yᵢ₊₁) (docs/patches.md,
/// "Moments": a triangle of area A has ∬ y = A s/3 and
/// ∬ y yᵀ = (A/12)(Σ yₐyₐᵀ + s sᵀ), s = Σ yₐ).
template <class Real>
class moment_fan {
 public:
  /// The next vertex y.
  void operator()(const point2<Real>& y) {
    if (count_ >= 2) add_triangle(y);
    if (count_ == 0) y0_ = y;
    previous_ = y;
    ++count_;
  }
  /// The moments of the vertices so far (zero for fewer than 3).
  const area_moments<Real>& moments() const { return m_; }

 private:
  void add_triangle(const point2<Real>& y2) {
    const point2<Real>&y0 = y0_, &y1 = previous_;
    const Real area = cross(minus(y1, y0), minus(y2, y0)) / 2;
    const point2<Real> s{y0[0] + y1[0] + y2[0], y0[1] + y1[1] + y2[1]};
    m_.area += area;
    m_.first[0] += area * s[0] / 3;
    m_.first[1] += area * s[1] / 3;
    const Real a12 = area / 12;
    m_.second[0] += a12 * (y0[0] * y0[0] + y1[0] * y1[0] + y2[0] * y2[0] + s[0] * s[0]);
    m_.second[1] += a12 * (y0[0] * y0[1] + y1[0] * y1[1] + y2[0] * y2[1] + s[0] * s[1]);
    m_.second[2] += a12 * (y0[1] * y0[1] + y1[1] * y1[1] + y2[1] * y2[1] + s[1] * s[1]);
  }

  area_moments<Real> m_;
  point2<Real> y0_{}, previous_{};
  std::size_t count_ = 0;
};

/// The area moments of the polygon `poly` about g (moment_fan).
template <class Real, std::size_t N>
area_moments<Real> polygon_moments(const vertex_list<Real, N>& poly, const point2<Real>& g) {
  moment_fan<Real> fan;
  for (const auto& v : poly) fan(minus(v, g));
  return fan.moments();
}

/// The vertices of the part of the convex polygon `poly` where
/// α + β·(x − g) ≥ 0 (Sutherland–Hodgman for one half-plane), in order, to `sink`.
template <class Real, std::size_t N, class Sink>
void clip_polygon_to(const vertex_list<Real, N>& poly, const point2<Real>& g, Real alpha,
                     const point2<Real>& beta, Sink& sink) {
  const std::size_t n = poly.size();
  auto f = [&](std::size_t i) { return alpha + dot(beta, minus(poly[i], g)); };
  Real fi = f(0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = i + 1 == n ? 0 : i + 1;
    const Real fj = f(j);
    if (fi >= 0) sink(poly[i]);
    if ((fi > 0 && fj < 0) || (fi < 0 && fj > 0)) {
      const Real t = fi / (fi - fj);
      sink(point2<Real>{poly[i][0] + t * (poly[j][0] - poly[i][0]),
                        poly[i][1] + t * (poly[j][1] - poly[i][1])});
    }
    fi = fj;
  }
}

/// The same into `out`.
template <class Real, std::size_t N, std::size_t M>
void clip_polygon(const vertex_list<Real, N>& poly, const point2<Real>& g, Real alpha,
                  const point2<Real>& beta, vertex_list<Real, M>& out) {
  out.clear();
  auto sink = [&](const point2<Real>& v) { out.push_back(v); };
  clip_polygon_to(poly, g, alpha, beta, sink);
}

/// The area moments about the origin of the part of `poly` where α + β·x ≥ 0,
/// without building it.
template <class Real, std::size_t N>
area_moments<Real> clipped_moments(const vertex_list<Real, N>& poly, Real alpha,
                                   const point2<Real>& beta) {
  moment_fan<Real> fan;
  clip_polygon_to(poly, point2<Real>{}, alpha, beta, fan);
  return fan.moments();
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DETAIL_PATCH_GEOMETRY_HPP
