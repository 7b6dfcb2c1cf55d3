//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The impulse law's limit a → 0 (docs/theory.md §11, "A patch that starts at
// zero"): the limit set flattens to the disk |P| ≤ μΛ, L = 0, and the impulse
// nearest to the stopping one in the kinetic metric W is the point friction
// of the linear motion alone,
//   P = argmin (P − P*)ᵀ W_ff (P − P*) over |P| ≤ μΛ,  P* = −W_ff⁻¹ v,
// W_ff the force block of W (the spin keeps turning: nothing resists it).
// P* if it lies in the disk; else P = −(W_ff + λI)⁻¹ v on the circle, λ > 0
// the root of the secular equation 1/|P(λ)| = 1/(μΛ), which Newton's method
// from λ = 0 approaches from below, monotonically (1/|P(λ)| is concave:
// Moré and Sorensen, SIAM J. Sci. Stat. Comput. 4, 553 (1983)); the slip
// after the step is v⁺ = v + W_ff P = −λP.
#ifndef SPINSLIDE_CONTACT_DETAIL_POINT_FRICTION_HPP
#define SPINSLIDE_CONTACT_DETAIL_POINT_FRICTION_HPP

#include <spinslide/base/detail/product.hpp>
#include <spinslide/contact/detail/matrix3.hpp>

#include <boost/math/tools/precision.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace spinslide {
namespace detail {

template <class Real>
struct point_impulse {
  std::array<Real, 2> force;  // P
  Real slip;                  // |v⁺| after the step: λ|P| (0 if the slide stops)
};

// P for the force block of `w` (symmetric positive definite), the slip v
// (finite, not 0) and the bound μΛ (> 0, finite).  Never fails: λ is kept
// in its bracket [0, |v|/(μΛ)] (where |P(λ)| ≤ |v|/λ ≤ μΛ), a Newton step
// that leaves it is a bisection, and the iteration ends when λ moves by
// less than 4 ulp (or after the type's digits of steps); P is then put on
// the circle exactly.
template <class Real>
point_impulse<Real> point_friction(const matrix3<Real>& w, Real vx, Real vy, Real bound) {
  using std::fabs;
  // In units of W_ff's largest diagonal entry: λ and W of the same size.
  const Real d = (std::max)(w[0][0], w[1][1]);
  const Real a = w[0][0] / d, b = w[0][1] / d, c = w[1][1] / d;
  const Real big = (std::max)(fabs(vx), fabs(vy));
  if (big == 0) return {{Real(0), Real(0)}, Real(0)};                // no slide: nothing to resist
  auto back = [&](Real x) { return product(x, big, Real(1 / d)); };  // P from P', no overflow
  const Real ux = vx / big, uy = vy / big;  // v/|v|_∞, and μΛ in the same units
  // μΛ in those units, μΛ·d/|v|_∞, without overflow or underflow on the way.
  const Real ratio = bound / big;
  const Real limit = ratio >= boost::math::tools::min_value<Real>() &&
                             ratio <= boost::math::tools::max_value<Real>()
                         ? Real(ratio * d)
                         : product(bound, d, Real(1 / big));
  // P(λ) = −(W + λI)⁻¹u, |P| and P̂ᵀ(W + λI)⁻¹P̂ (P̂ = P/|P|); for λ > 1
  // from (W + λI)/λ, whose determinant does not overflow.
  struct at_lambda {
    Real px, py, norm, curvature;
  };
  auto solve = [&](Real lambda) {
    const Real f = lambda > 1 ? lambda : Real(1);
    const Real p = a / f + lambda / f, r = c / f + lambda / f, e = b / f, det = p * r - e * e;
    const Real px = -(r * ux - e * uy) / det / f, py = -(p * uy - e * ux) / det / f;
    const Real norm = length(px, py), hx = px / norm, hy = py / norm;
    const Real qx = (r * hx - e * hy) / det / f, qy = (p * hy - e * hx) / det / f;
    return at_lambda{px, py, norm, hx * qx + hy * qy};
  };
  at_lambda s = solve(Real(0));
  if (s.norm <= limit) return {{back(s.px), back(s.py)}, Real(0)};
  const Real hi_start = length(ux, uy) / limit;
  if (!(hi_start < boost::math::tools::max_value<Real>() / 4)) {
    // μΛ below rounding of W⁻¹v (λ beyond the largest value): P = −μΛ v/|v|,
    // Coulomb's against the slip, to rounding, and the slip v + W_ff P.
    const Real n = length(ux, uy), px = -bound * (ux / n), py = -bound * (uy / n);
    const Real sx = vx + w[0][0] * px + w[0][1] * py, sy = vy + w[1][0] * px + w[1][1] * py;
    return {{px, py}, length(sx, sy)};
  }
  Real lo = 0, hi = hi_start, lambda = 0;
  for (int k = 0; k < std::numeric_limits<Real>::digits + 8; ++k) {
    (s.norm > limit ? lo : hi) = lambda;
    // Newton on 1/|P(λ)| = 1/limit: d|P|/dλ = −|P| P̂ᵀ(W + λI)⁻¹P̂.
    Real next = lambda + (s.norm - limit) / (limit * s.curvature);
    if (!(next > lo && next < hi)) next = (lo + hi) / 2;
    const bool done = fabs(next - lambda) <= 4 * std::numeric_limits<Real>::epsilon() * next;
    lambda = next;
    s = solve(lambda);
    if (done) break;
  }
  // On the circle, |P| = μΛ: μΛ times P's direction.
  const Real px = bound * (s.px / s.norm), py = bound * (s.py / s.norm);
  return {{px, py}, Real(lambda * d * length(px, py))};
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_POINT_FRICTION_HPP
