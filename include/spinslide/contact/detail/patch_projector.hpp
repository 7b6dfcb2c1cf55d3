//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The point of a flat patch's limit set L nearest to z in a metric M, in the
// limit set's units (patch_slip_model.hpp; docs/patches.md, "The limit set
// and its projection").  As for a round patch (metric_projector.hpp), the
// nearest point is p = ∇D(s) for the slip s = M(z − p) that minimizes the
// strictly convex Ψ(s) = ½ sᵀM⁻¹s + D(s) − zᵀs, and z sticks (p = z, s = 0)
// exactly when z ∈ L.  In order:
// 1. A point patch: its flat disk, in closed form (point_patch_projection.hpp).
// 2. Beyond a normal n with zᵀn > D(n) (n the contact's last slip, then Mz,
//    the answer's normal for a z far away), z is outside L, proved: Newton
//    starts from the best point τn of that ray (Ψ < 0 there), fast
//    (slip_newton.hpp) and, where that declines, careful (slip_descent.hpp).
// 3. Inside the double cone spanned by the pure translations' points and
//    the pure spins' (L contains it), z sticks: one evaluation.
// 4. Otherwise the gauge search (patch_gauge.hpp) decides: z's ray leaves L
//    at z/γ with normal n*; z sticks if γ ≤ 1, else Newton starts from n*'s ray.
// Nothing throws, and every answer's point is one of L's (the model's own).
#ifndef SPINSLIDE_CONTACT_DETAIL_PATCH_PROJECTOR_HPP
#define SPINSLIDE_CONTACT_DETAIL_PATCH_PROJECTOR_HPP

#include <spinslide/contact/detail/matrix3.hpp>
#include <spinslide/contact/detail/patch_gauge.hpp>
#include <spinslide/contact/detail/patch_slip_model.hpp>
#include <spinslide/contact/detail/point_patch_projection.hpp>
#include <spinslide/contact/detail/slip_descent.hpp>
#include <spinslide/contact/detail/slip_newton.hpp>
#include <spinslide/contact/detail/vector3.hpp>

#include <boost/math/tools/precision.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace spinslide {
namespace detail {

// A projection in the limit set's units: the point, and the slip (0 when sticking).
template <class Real>
struct patch_projection {
  vector3<Real> point;
  vector3<Real> slip;
  bool sticking;
};

template <class Real>
class patch_projector {
  using vec = vector3<Real>;
  using model = patch_slip_model<Real>;
  using point = typename model::point;

 public:
  // z finite; `metric` M and `inverse` M⁻¹ symmetric positive definite.
  patch_projector(const model& d, const vec& z, const matrix3<Real>& metric,
                  const matrix3<Real>& inverse)
      : d_(d), z_(z), m_(metric), inverse_(inverse) {
    // M/d and d·M⁻¹, d M's largest diagonal entry, have the same nearest
    // point, and keep s and Ψ away from over- and underflow.
    scale_ = (std::max)({metric[0][0], metric[1][1], metric[2][2]});
    const Real scale = scale_;
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) {
        m_[i][j] = metric[i][j] / scale;
        inverse_[i][j] = inverse[i][j] * scale;
      }
  }

  // The projection; `start`: a slip to search from (the last one), or null.
  // The slip is M(z − p) in the metric given, not the scaled one.
  patch_projection<Real> operator()(const vec* start) const {
    patch_projection<Real> r = solve(start);
    r.slip = {r.slip[0] * scale_, r.slip[1] * scale_, r.slip[2] * scale_};
    return r;
  }

 private:
  patch_projection<Real> solve(const vec* start) const {
    if (d_.patch().shape() == patch_shape::point) return point_contact();
    if (z_[0] == 0 && z_[1] == 0 && z_[2] == 0) return stuck();
    if (largest(z_) > far()) return support_point();
    patch_projection<Real> out;
    if (start && usable(*start) && from_ray(*start, out)) return out;
    if (in_inner_cone()) return stuck();
    if (from_ray(multiply(m_, z_), out)) return out;
    const point g =
        gauge_search<model>(d_, z_)(start && usable(*start) ? *start : multiply(m_, z_));
    if (!(g.value < 1 - 8 * epsilon()) || !from_ray(g.s, out)) return stuck();
    return out;
  }

  static Real epsilon() { return std::numeric_limits<Real>::epsilon(); }
  static Real far() {
    using std::sqrt;
    static const Real bound = sqrt(boost::math::tools::max_value<Real>()) / 16;
    return bound;
  }
  static bool usable(const vec& s) {
    const Real size = largest(s);
    return size > 0 && size < std::numeric_limits<Real>::infinity();
  }

  patch_projection<Real> stuck() const { return {z_, vec{}, true}; }

  patch_projection<Real> slipping(const point& x) const { return {x.grad, x.s, false}; }

  // For z far from L: the point with normal Mz (within |p|/|z| of the answer's).
  patch_projection<Real> support_point() const {
    const Real scale = largest(z_);
    const vec n = multiply(m_, vec{z_[0] / scale, z_[1] / scale, z_[2] / scale});
    point x;
    d_.plain(n, x);
    return {x.grad, n, false};
  }

  // Newton from the best point of the ray τn, if zᵀn > D(n) beyond rounding.
  bool from_ray(const vec& n, patch_projection<Real>& out) const {
    using std::fabs;
    if (!usable(n)) return false;
    const Real size = largest(n);
    const vec u{n[0] / size, n[1] / size, n[2] / size};
    point x;
    d_.plain(u, x);
    const Real along = dot(z_, u), gain = along - x.value;
    if (!(gain > 8 * epsilon() * (fabs(along) + x.value))) return false;
    // Ψ(τu) = ½τ²uᵀM⁻¹u − τ·gain is least at τ = gain/(uᵀM⁻¹u).
    const Real tau = gain / dot(u, multiply(inverse_, u));
    x.s = {tau * u[0], tau * u[1], tau * u[2]};
    x.value *= tau;
    x.size = std::sqrt(dot(x.s, x.s));
    const bool curved = d_.curve(x);
    if (curved) {
      point y = x;
      vec step;
      if (slip_newton(d_, z_, inverse_, y, multiply(inverse_, y.s), true, step)) {
        const vec dp = multiply(y.hessian, step);
        out = {{y.grad[0] + dp[0], y.grad[1] + dp[1], y.grad[2] + dp[2]},
               shifted(y.s, step, Real(1)),
               false};
        return true;
      }
    }
    const slip_descent<model> careful(d_, z_, m_, inverse_);
    descent_point<model> start = careful.at(x.s);
    out = slipping(careful(start));
    return true;
  }

  // z in the double cone over the pure translations' points (v̂, e × v̂/ℓ)
  // (e the centre of pressure), with the pure spins' points ±P as apexes: L
  // contains it (its points are L's, and L is convex).
  bool in_inner_cone() const {
    using std::fabs;
    using std::sqrt;
    point spin;
    d_.plain(vec{0, 0, 1}, spin);
    const auto& e = d_.patch().centre();
    const Real l = d_.length();
    const auto height = [&](Real fx, Real fy, Real t) { return t - (e[0] * fy - e[1] * fx) / l; };
    const Real top = height(spin.grad[0], spin.grad[1], spin.grad[2]);
    if (!(top > 0)) return false;
    const Real h = height(z_[0], z_[1], z_[2]);
    const Real alpha = fabs(h) / top, sign = h < 0 ? Real(-1) : Real(1);
    if (!(alpha < 1)) return false;
    const Real qx = z_[0] - alpha * sign * spin.grad[0], qy = z_[1] - alpha * sign * spin.grad[1];
    const Real margin = 1 - 16 * epsilon();
    return sqrt(qx * qx + qy * qy) <= (1 - alpha) * margin;
  }

  // A point patch's flat disk (point_patch_projection.hpp).
  patch_projection<Real> point_contact() const {
    using std::fabs;
    const auto& x = d_.patch().pressure_origin();
    const Real l = d_.length();
    const std::array<Real, 2> a{-x[1] / l, x[0] / l};
    const std::array<Real, 2> f = point_patch_force(a, z_, m_);
    const vec p{f[0], f[1], a[0] * f[0] + a[1] * f[1]};
    const vec r{z_[0] - p[0], z_[1] - p[1], z_[2] - p[2]};
    if (largest(r) <= 8 * epsilon() * (largest(z_) + 1)) return stuck();
    return {p, multiply(m_, r), false};
  }

  const model& d_;
  const vec& z_;
  matrix3<Real> m_, inverse_;
  Real scale_;
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_PATCH_PROJECTOR_HPP
