//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The careful, never-failing minimization of
//   Ψ(s) = ½ sᵀM⁻¹s + D(s) − zᵀs
// over any dissipation model (patch_slip_model.hpp; the interface of
// slip_newton.hpp plus `values`, D and ∇D without the Hessian): Newton's
// steps (M⁻¹ + ∇²D)δ = −∇Ψ where the Hessian is finite and the system
// positive definite, else the steepest descent in the metric, δ = −M∇Ψ
// (where D's Hessian diverges: a line patch pivoting about one of its own
// points).  The line search moves along δ by the sign of Ψ's slope, which
// is known to the rounding of ∇Ψ's terms, or by Armijo's test on Ψ's values
// (metric_projector.hpp explains why both): each accepted step lowers the
// strictly convex Ψ, so the iteration converges from any start with
// Ψ < 0 (which keeps it away from D's kink at 0), and it ends when no
// descent is left that the type can show.  Every iterate's point ∇D(s) is on
// the limit set; only its nearness is iterated.
#ifndef SPINSLIDE_CONTACT_DETAIL_SLIP_DESCENT_HPP
#define SPINSLIDE_CONTACT_DETAIL_SLIP_DESCENT_HPP

#include <spinslide/contact/detail/matrix3.hpp>
#include <spinslide/contact/detail/vector3.hpp>

#include <cmath>
#include <cstddef>
#include <limits>

namespace spinslide {
namespace detail {

// The state of the careful iteration at a slip: D's point, with or without
// its Hessian, and Ψ there.
template <class Model>
struct descent_point {
  typename Model::point x;
  bool curved;  // x.hessian is D's (finite)
  typename Model::value_type psi;
};

template <class Model>
class slip_descent {
  using Real = typename Model::value_type;
  using vec = vector3<Real>;
  using point = typename Model::point;

 public:
  slip_descent(const Model& d, const vec& z, const matrix3<Real>& metric,
               const matrix3<Real>& inverse)
      : d_(d), z_(z), m_(metric), inverse_(inverse) {}

  // The state at s ≠ 0 (finite): D's values, its Hessian where finite.
  descent_point<Model> at(const vec& s) const {
    descent_point<Model> y = plain(s);
    y.curved = d_.curve(y.x);
    return y;
  }
  // The same without the Hessian (a line search's trial).
  descent_point<Model> plain(const vec& s) const {
    descent_point<Model> y;
    d_.plain(s, y.x);
    y.curved = false;
    y.psi = psi(y.x);
    return y;
  }

  // From a start with Ψ < 0, the minimum: its slip and point.
  point operator()(descent_point<Model> y) const {
    for (int iteration = 0; iteration < max_iterations; ++iteration) {
      const vec g = gradient(y.x);
      const vec step = direction(y, g);
      Real slope = 0, rounding = 0;
      measure(y.x, g, step, slope, rounding);
      if (!(slope < -rounding) || negligible(y.x.s, step, Real(1))) break;
      if (!line_search(step, slope, y)) break;
    }
    return y.x;
  }

 private:
  static constexpr int max_iterations = 100;
  static constexpr int max_line_steps = std::numeric_limits<Real>::digits + 8;
  static Real epsilon() { return std::numeric_limits<Real>::epsilon(); }

  Real psi(const point& x) const {
    return dot(x.s, multiply(inverse_, x.s)) / 2 + x.value - dot(z_, x.s);
  }
  vec gradient(const point& x) const {
    const vec ms = multiply(inverse_, x.s);
    return {ms[0] + x.grad[0] - z_[0], ms[1] + x.grad[1] - z_[1], ms[2] + x.grad[2] - z_[2]};
  }

  // Newton's step where it is defined and a descent direction, else −M∇Ψ.
  vec direction(const descent_point<Model>& y, const vec& g) const {
    if (y.curved) {
      vec step;
      if (solve_symmetric(upper_plus(inverse_, y.x.hessian), vec{-g[0], -g[1], -g[2]}, step) &&
          dot(step, g) < 0)
        return step;
    }
    const vec mg = multiply(m_, g);
    return {-mg[0], -mg[1], -mg[2]};
  }

  // ∇Ψ·δ and the bound of its rounding (a few ulp of its terms along δ).
  void measure(const point& x, const vec& g, const vec& step, Real& slope, Real& rounding) const {
    using std::fabs;
    Real size = 0;
    slope = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      Real row = 0;
      for (std::size_t j = 0; j < 3; ++j) row += fabs(inverse_[i][j] * x.s[j]);
      size += (row + fabs(x.grad[i]) + fabs(z_[i])) * fabs(step[i]);
      slope += g[i] * step[i];
    }
    rounding = 4 * epsilon() * size;
  }

  static bool negligible(const vec& s, const vec& step, Real t) {
    using std::fabs;
    const Real tiny = 4 * epsilon();
    return fabs(t * step[0]) <= tiny * fabs(s[0]) && fabs(t * step[1]) <= tiny * fabs(s[1]) &&
           fabs(t * step[2]) <= tiny * fabs(s[2]);
  }

  // A lower point along the step into y; false if none beyond rounding.
  bool line_search(const vec& step, Real slope, descent_point<Model>& y) const {
    using std::fabs;
    Real t = 1;
    for (int k = 0; k < max_line_steps && !negligible(y.x.s, step, t); ++k, t /= 2) {
      const vec s = shifted(y.x.s, step, t);
      if (s[0] == 0 && s[1] == 0 && s[2] == 0) continue;
      descent_point<Model> next = plain(s);
      const Real trial_slope = dot(gradient(next.x), step);
      const Real slack = 4 * epsilon() * (fabs(y.psi) + fabs(next.psi) + fabs(next.x.value));
      const bool armijo = next.psi < y.psi + Real(1e-4) * t * slope;
      if (trial_slope <= 0 || armijo || (trial_slope <= -slope / 2 && next.psi <= y.psi + slack)) {
        next.curved = d_.curve(next.x);
        y = next;
        return true;
      }
    }
    return false;
  }

  const Model& d_;
  const vec& z_;
  const matrix3<Real>& m_;
  const matrix3<Real>& inverse_;
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_SLIP_DESCENT_HPP
