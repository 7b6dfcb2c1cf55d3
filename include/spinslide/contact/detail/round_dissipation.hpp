//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The dissipation function of a round patch, D(s) = |s_f|𝓕(ε) + |s_t|𝓣(ε)
// with ε = |s_f|/|s_t|, as the fast Newton iteration of the metric
// projection reads it (slip_newton.hpp): at a slip s, the curve point ∇D(s)
// = (𝓕 d, 𝓣 sign s_t), d = s_f/|s_f|, and the Hessian
//   ∇²D = [ (α − q) ddᵀ + q I    −β sign(s_t) d ]
//         [ −β sign(s_t) dᵀ       γ             ],
// α = 𝓕′/|s_t|, q = 𝓕/|s_f|, β = αε, γ = βε (docs/theory.md §11: rank
// two, from 𝓣′ = −ε𝓕′), all from one fused evaluation of 𝓕, 𝓣, 𝓕′
// (fused_value_slope).  Only where the slip's two blocks are normal numbers
// with squares that are too (else at() declines, and the careful iteration
// of metric_projector.hpp takes over): so every quantity above keeps the
// type's precision.
#ifndef SPINSLIDE_CONTACT_DETAIL_ROUND_DISSIPATION_HPP
#define SPINSLIDE_CONTACT_DETAIL_ROUND_DISSIPATION_HPP

#include <spinslide/contact/detail/matrix3.hpp>
#include <spinslide/values/detail/force_slope.hpp>
#include <spinslide/values/force_torque_result.hpp>

#include <boost/math/tools/precision.hpp>

#include <cmath>
#include <limits>

namespace spinslide {
namespace detail {

template <class Profile>
class round_dissipation {
 public:
  using value_type = typename Profile::value_type;
  using Real = value_type;
  using vec = vector3<Real>;

  // D's derivatives at a slip, and the slope they came from.
  struct point {
    vec s;
    vec grad;                  // ∇D(s): the curve point
    symmetric3<Real> hessian;  // ∇²D(s)
    Real along, across;        // |s_f|, |s_t|
    Real slope;                // 𝓕′ at s's ratio: the answer's start for the next call
  };
  // 𝓕, 𝓣 and 𝓕′ at a ratio.
  struct values {
    Real ratio;
    force_torque_result<Real> ft;
    Real slope;
  };

  // Its Hessian comes with its evaluation: never kept across a step (slip_newton.hpp).
  static constexpr bool reuses_hessian = false;

  explicit round_dissipation(const Profile& profile) : p_(profile) {}

  values at_ratio(Real eps) const {
    const auto v = fused_value_slope<Profile>::template at<false>(p_, eps);
    return {eps, v.value, v.slope};
  }

  // The point at s, evaluating the profile at s's ratio; false where s is
  // out of the fast path's range (see the file's comment).
  bool at(const vec& s, point& x) const {
    if (!measure(s, x)) return false;
    const values v = at_ratio(Real(x.along / x.across));
    return finish(v, x);
  }
  // The same from the profile's values `v` at s's ratio (to rounding): the
  // start, on a ray of that ratio.
  bool at(const vec& s, const values& v, point& x) const { return measure(s, x) && finish(v, x); }

  // Newton's start for the projection of z in the metric M = `metric`
  // (inverse M⁻¹ = `inverse`) from the profile's values `v` at a ratio: the
  // curve point p₀ there, along z's force and with z's spin sign, leaves
  // the slip w = M(z − p₀); the normal n = (ε e, sign w_t) (scaled to a
  // largest component of 1) of the curve point at that ratio along w's
  // force direction e; on the ray τn, Ψ is least at τ = gain/(nᵀM⁻¹n),
  // gain = zᵀn − D(n).  False unless the gain is positive beyond rounding
  // (z beyond that point's support plane) and the point in range; `ms`:
  // M⁻¹s there.
  bool start(const vec& z, const matrix3<Real>& metric, const matrix3<Real>& inverse,
             const values& v, point& x, vec& ms) const {
    // (Plain square roots: |z| is below √max/16 (metric_projector::far), and
    // a direction that loses digits to underflow only makes a poorer start.)
    using std::fabs;
    using std::sqrt;
    const Real zf = sqrt(z[0] * z[0] + z[1] * z[1]);
    const Real ex = zf > 0 ? Real(z[0] / zf) : Real(1), ey = zf > 0 ? Real(z[1] / zf) : Real(0);
    const Real f = v.ft.force, t = v.ft.torque;
    const vec w =
        multiply(metric, vec{z[0] - f * ex, z[1] - f * ey, z[2] < 0 ? z[2] + t : z[2] - t});
    const Real wf = sqrt(w[0] * w[0] + w[1] * w[1]);
    if (!(wf > 0)) return false;
    const bool wide = v.ratio > 1;
    const Real nf = wide ? Real(1) : v.ratio, nt = wide ? Real(1 / v.ratio) : Real(1);
    const Real scale = nf / wf;
    const vec n{scale * w[0], scale * w[1], w[2] < 0 ? Real(-nt) : nt};
    const Real along = dot(z, n), support = nf * f + nt * t, gain = along - support;
    if (!(gain > 8 * std::numeric_limits<Real>::epsilon() * (fabs(along) + support))) return false;
    const vec mn = multiply(inverse, n);
    const Real tau = gain / dot(n, mn);
    ms = {tau * mn[0], tau * mn[1], tau * mn[2]};
    return at(vec{tau * n[0], tau * n[1], tau * n[2]}, v, x);
  }

  // The step's size relative to s: r_f² + r_t², r_f = |δ_f|/|s_f| and r_t =
  // |δ_t|/|s_t| (by which the force's direction and ε change relatively).
  static Real step_ratio(const point& x, const vec& step) {
    return (step[0] * step[0] + step[1] * step[1]) / (x.along * x.along) +
           step[2] * step[2] / (x.across * x.across);
  }

  // The ratio of a slip whose blocks are normal (the answer s + δ).
  static Real ratio_of(const vec& s) {
    using std::fabs;
    using std::sqrt;
    return sqrt(s[0] * s[0] + s[1] * s[1]) / fabs(s[2]);
  }

 private:
  bool measure(const vec& s, point& x) const {
    using std::fabs;
    using std::sqrt;
    static const Real low = boost::math::tools::min_value<Real>(),
                      high = boost::math::tools::max_value<Real>();
    const Real f2 = s[0] * s[0] + s[1] * s[1], t2 = s[2] * s[2];
    if (!(f2 >= low && f2 <= high && t2 >= low && t2 <= high)) return false;
    x.s = s;
    x.along = sqrt(f2);
    x.across = fabs(s[2]);
    return true;
  }

  bool finish(const values& v, point& x) const {
    const Real to_t = 1 / x.across, to_f = 1 / x.along;
    const Real eps = x.along * to_t;
    const Real dx = x.s[0] * to_f, dy = x.s[1] * to_f;
    const Real sign = x.s[2] < 0 ? Real(-1) : Real(1);
    const Real q = v.ft.force * to_f, alpha = v.slope * to_t;
    const Real beta = alpha * eps, gamma = beta * eps, cross = (alpha - q);
    x.slope = v.slope;
    x.grad = {v.ft.force * dx, v.ft.force * dy, sign * v.ft.torque};
    const Real bx = -beta * sign * dx, by = -beta * sign * dy;
    x.hessian = {cross * dx * dx + q, cross * dx * dy, bx, cross * dy * dy + q, by, gamma};
    return gamma < std::numeric_limits<Real>::infinity() &&
           q < std::numeric_limits<Real>::infinity();
  }

  const Profile& p_;
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_ROUND_DISSIPATION_HPP
