//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The dissipation function of a flat patch (values/patch_dissipation.hpp) as
// the projections' Newton iterations read it (slip_newton.hpp,
// slip_descent.hpp): in the limit set's units, where the torque is divided
// by the patch's length ℓ and the spin multiplied by it, s = (v_x, v_y, ℓω),
//   D̃(s) = D(v_x, v_y, s_t/ℓ),  ∇D̃ = (∂_v D, ∂_ω D/ℓ),  ∇²D̃ = S ∇²D S,
// S = diag(1, 1, 1/ℓ).  ∇D̃(s) is the point of the limit set with outward
// normal s: minus the friction wrench of the twist (v, ω), in those units.
// A round profile is the other model of the same interface
// (round_dissipation.hpp); the iterations do not know which they minimize.
#ifndef SPINSLIDE_CONTACT_DETAIL_PATCH_SLIP_MODEL_HPP
#define SPINSLIDE_CONTACT_DETAIL_PATCH_SLIP_MODEL_HPP

#include <spinslide/contact/detail/matrix3.hpp>
#include <spinslide/contact/detail/vector3.hpp>
#include <spinslide/values/patch_dissipation.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <boost/math/tools/precision.hpp>

#include <cmath>
#include <limits>

namespace spinslide {
namespace detail {

// The patch's length in the limit set's units: its largest vertex
// distance from the origin, or 1 for a point patch at the origin (whose
// torque is 0 in any unit).
template <class Real>
Real patch_length(const polygon_patch<Real>& patch) {
  return patch.radius() > 0 ? patch.radius() : Real(1);
}

template <class Real>
class patch_slip_model {
 public:
  using value_type = Real;
  using vec = vector3<Real>;

  // D̃ and its derivatives at a slip.
  struct point {
    vec s;
    vec grad;                  // ∇D̃(s): the limit set's point with normal s
    symmetric3<Real> hessian;  // ∇²D̃(s)
    Real value;                // D̃(s)
    Real size;                 // |s|
  };

  // Its Hessian costs up to several wrenches (far from the patch, central
  // differences): slip_newton keeps it across a step with r = |δ|/|s| ≤
  // ε^{1/3} (6e-6 in double, 5e-3 in float).  The Hessian is then off by
  // about r relatively, and a converged last step (r ≤ ε^{2/3}) puts the
  // answer's point ∇D + ∇²Dδ off by r·ε^{2/3} ≤ ε.
  static constexpr bool reuses_hessian = true;
  static Real hessian_reuse_limit() {
    using std::cbrt;
    static const Real limit = cbrt(std::numeric_limits<Real>::epsilon());
    return limit * limit;
  }

  explicit patch_slip_model(const polygon_patch<Real>& patch)
      : p_(patch), length_(patch_length(patch)) {}

  Real length() const { return length_; }
  const polygon_patch<Real>& patch() const { return p_; }

  // The physical twist of the slip s.
  planar_twist<Real> twist(const vec& s) const { return {{s[0], s[1]}, s[2] / length_}; }

  // D̃ and ∇D̃ at s ≠ 0 (no Hessian: the line search's trials).
  void values(const vec& s, Real& value, vec& grad) const {
    const planar_wrench<Real> f = wrench_of(p_, twist(s), &value);
    grad = {-f.force[0], -f.force[1], -f.torque / length_};
  }

  // The point at s, with the Hessian; false where s is 0, not finite, or
  // the Hessian is not finite (a line patch pivoting about one of its own
  // points, a point patch): the caller then steps without it.
  bool at(const vec& s, point& x) const { return moved(s, x) && curve(x); }

  // The Hessian at x.s (x.size set); false where it is not finite.
  bool curve(point& x) const {
    const patch_matrix<Real> h = patch_dissipation_hessian(p_, twist(x.s));
    const Real r = 1 / length_;
    x.hessian = {h[0][0], h[0][1], h[0][2] * r, h[1][1], h[1][2] * r, h[2][2] * r * r};
    return finite(x.hessian);
  }

  // x moved to s, its Hessian kept; false where s is 0 or not finite (its
  // square out of the normal numbers' range).
  bool moved(const vec& s, point& x) const {
    static const Real low = boost::math::tools::min_value<Real>(),
                      high = boost::math::tools::max_value<Real>();
    const Real s2 = s[0] * s[0] + s[1] * s[1] + s[2] * s[2];
    if (!(s2 >= low && s2 <= high)) return false;
    plain(s, x);
    return true;
  }

  // A point without its Hessian at s ≠ 0.
  void plain(const vec& s, point& x) const {
    using std::sqrt;
    x.s = s;
    x.size = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    values(s, x.value, x.grad);
  }

  // The step's size relative to s: |δ|²/|s|².
  static Real step_ratio(const point& x, const vec& step) {
    return (step[0] * step[0] + step[1] * step[1] + step[2] * step[2]) / (x.size * x.size);
  }

 private:
  static bool finite(const symmetric3<Real>& h) {
    const Real inf = std::numeric_limits<Real>::infinity();
    const Real sum = h.xx + h.xy + h.xz + h.yy + h.yz + h.zz;
    return sum < inf && sum > -inf;
  }

  const polygon_patch<Real>& p_;
  Real length_;
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_PATCH_SLIP_MODEL_HPP
