//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Where the ray from the origin through a point b ≠ 0 leaves the limit set L
// of a dissipation model D (patch_slip_model.hpp), and the normal there:
// the least D(n) over the plane bᵀn = 1.  D is convex and 1-homogeneous, L =
// {p : pᵀn ≤ D(n) for every n}, so b/γ ∈ L exactly when γ ≥ max over n of
// bᵀn/D(n) = 1/min{D(n) : bᵀn = 1}: the gauge of b is γ = 1/D(n*), and at
// the minimum ∇D(n*) = D(n*)·b (Lagrange, with Euler's nᵀ∇D(n) = D(n)), the
// boundary point b/γ with outward normal n*.  So b lies in L when D(n*) ≥ 1,
// and beyond it, with b's support plane at n* cut, when D(n*) < 1: the
// projections' decision between stick and slip (patch_projector.hpp), and
// the inverse map from a wrench to its twist (patch_limit_set.hpp).
//
// The plane is D's domain less its kink at 0, where D is smooth and strictly
// convex for an area or a line patch: Newton's method in the plane's two
// coordinates, with the line search of slip_descent.hpp (the sign of the
// slope, or Armijo's test) and the plane's steepest descent where the
// Hessian is not finite or its step no descent.  It ends when no descent is
// left that the type can show, or after a fixed number of steps; it never fails.
#ifndef SPINSLIDE_CONTACT_DETAIL_PATCH_GAUGE_HPP
#define SPINSLIDE_CONTACT_DETAIL_PATCH_GAUGE_HPP

#include <spinslide/contact/detail/matrix3.hpp>
#include <spinslide/contact/detail/vector3.hpp>

#include <cmath>
#include <cstddef>
#include <limits>

namespace spinslide {
namespace detail {

template <class Model>
class gauge_search {
  using Real = typename Model::value_type;
  using vec = vector3<Real>;
  using point = typename Model::point;

 public:
  // b ≠ 0 and finite.
  gauge_search(const Model& d, const vec& b) : d_(d), b_(b) {
    using std::fabs;
    using std::sqrt;
    // An orthonormal basis u, w of the plane's directions, b's normal n0 =
    // b/|b|² the plane's point nearest 0.
    const Real bb = dot(b, b);
    n0_ = {b[0] / bb, b[1] / bb, b[2] / bb};
    const Real norm = sqrt(bb);
    const vec e{b[0] / norm, b[1] / norm, b[2] / norm};
    std::size_t k = 0;
    for (std::size_t i = 1; i < 3; ++i)
      if (fabs(e[i]) < fabs(e[k])) k = i;
    vec a{};
    a[k] = 1;
    const Real along = e[k];
    u_ = {a[0] - along * e[0], a[1] - along * e[1], a[2] - along * e[2]};
    const Real un = sqrt(dot(u_, u_));
    u_ = {u_[0] / un, u_[1] / un, u_[2] / un};
    w_ = cross(e, u_);
  }

  // The minimum from a start n with bᵀn > 0 (else from b's normal b/|b|²).
  point operator()(const vec& start) const {
    const Real on = dot(b_, start);
    const vec n = on > 0 && on < std::numeric_limits<Real>::infinity()
                      ? vec{start[0] / on, start[1] / on, start[2] / on}
                      : n0_;
    point x;
    d_.plain(n, x);
    bool curved = d_.curve(x);
    for (int iteration = 0; iteration < max_iterations; ++iteration) {
      const vec step = direction(x, curved);
      Real slope = 0, rounding = 0;
      measure(x, step, slope, rounding);
      if (!(slope < -rounding) || negligible(x.s, step, Real(1))) break;
      if (!line_search(step, slope, x)) break;
      curved = d_.curve(x);
    }
    return x;
  }

 private:
  static constexpr int max_iterations = 60;
  static constexpr int max_line_steps = std::numeric_limits<Real>::digits + 8;
  static Real epsilon() { return std::numeric_limits<Real>::epsilon(); }

  // Newton's step in the plane (u, w), else its steepest descent.
  vec direction(const point& x, bool curved) const {
    const Real gu = dot(x.grad, u_), gw = dot(x.grad, w_);
    if (curved) {
      const vec hu = multiply(x.hessian, u_), hw = multiply(x.hessian, w_);
      const Real a = dot(u_, hu), c = dot(u_, hw), e = dot(w_, hw);
      const Real det = a * e - c * c;
      if (det > 0 && det < std::numeric_limits<Real>::infinity() && a > 0) {
        const Real yu = -(e * gu - c * gw) / det, yw = -(a * gw - c * gu) / det;
        if (yu * gu + yw * gw < 0) return combine(yu, yw);
      }
    }
    return combine(-gu, -gw);
  }
  vec combine(Real a, Real c) const {
    return {a * u_[0] + c * w_[0], a * u_[1] + c * w_[1], a * u_[2] + c * w_[2]};
  }

  static void measure(const point& x, const vec& step, Real& slope, Real& rounding) {
    using std::fabs;
    slope = dot(x.grad, step);
    rounding = 4 * epsilon() *
               (fabs(x.grad[0] * step[0]) + fabs(x.grad[1] * step[1]) + fabs(x.grad[2] * step[2]));
  }

  static bool negligible(const vec& s, const vec& step, Real t) {
    using std::fabs;
    const Real tiny = 4 * epsilon() * (fabs(s[0]) + fabs(s[1]) + fabs(s[2]));
    return fabs(t * step[0]) + fabs(t * step[1]) + fabs(t * step[2]) <= tiny;
  }

  bool line_search(const vec& step, Real slope, point& x) const {
    using std::fabs;
    Real t = 1;
    for (int k = 0; k < max_line_steps && !negligible(x.s, step, t); ++k, t /= 2) {
      point next;
      d_.plain(shifted(x.s, step, t), next);
      const Real trial_slope = dot(next.grad, step);
      const Real slack = 4 * epsilon() * (x.value + next.value);
      const bool armijo = next.value < x.value + Real(1e-4) * t * slope;
      if (trial_slope <= 0 || armijo ||
          (trial_slope <= -slope / 2 && next.value <= x.value + slack)) {
        x = next;
        return true;
      }
    }
    return false;
  }

  const Model& d_;
  vec b_, n0_, u_, w_;
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_PATCH_GAUGE_HPP
