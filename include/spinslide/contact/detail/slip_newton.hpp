//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The fast path of the metric projection (metric_projector.hpp; issue 41):
// Newton's method on Ψ(s) = ½ sᵀM⁻¹s + D(s) − zᵀs with full steps, no line
// search and no test beyond the step's size, over any dissipation function
// D that gives its gradient and its (full, symmetric) Hessian at a slip:
// the round patches' now (round_dissipation.hpp), a flat patch's next.
//
// It ends in one of two ways.  Converged: a step δ within first order of s
// (r² ≤ ε_mach^(4/3), r the dissipation's relative step size: the rule of
// the careful iteration's last_step, which it shares), taken from a point
// whose values are the profile's own; the answer is then s + δ and the
// point ∇D(s) + ∇²D(s)δ, as there.  Or declined: a point out of the
// dissipation's range, a Hessian that is not positive definite and finite,
// a step that is not finite, or max_steps without converging (a start far
// from the answer, or z near the set, where the slip tends to 0).  Then the
// caller's careful iteration answers from its own start: the fast path
// changes no answer beyond the rounding of its last step, only its cost.
// Steps larger than half of s (r > 1/2) are shortened to that: a full step
// there can reverse the slip's force or the sign of its spin.
#ifndef SPINSLIDE_CONTACT_DETAIL_SLIP_NEWTON_HPP
#define SPINSLIDE_CONTACT_DETAIL_SLIP_NEWTON_HPP

#include <spinslide/contact/detail/matrix3.hpp>

#include <cmath>
#include <limits>

namespace spinslide {
namespace detail {

// x moved to s: evaluated there, with its Hessian, or, for a model whose
// Hessian costs several evaluations (a flat patch's), keeping the Hessian
// across a step within its reuse limit (r² ≤ hessian_reuse_limit()): the
// next step then errs by about that step's size times its own, and the
// answer's point ∇D + ∇²Dδ by as little (below rounding at the limit).
template <class Dissipation>
bool advance(const Dissipation& d, const vector3<typename Dissipation::value_type>& s,
             typename Dissipation::value_type r2, typename Dissipation::point& x) {
  if constexpr (Dissipation::reuses_hessian) {
    if (r2 <= Dissipation::hessian_reuse_limit()) return d.moved(s, x);
  }
  static_cast<void>(r2);
  return d.at(s, x);
}

// Newton's steps from x (`evaluated`: whether x's values are the profile's
// own, not a stored start's; `ms` = M⁻¹s at x) on Ψ for z and M⁻¹ =
// `inverse`; true when converged, with x the last point and `step` the
// last step.  The step's size r² is the sum of the dissipation's two
// (step_ratio): NaN or ∞ where δ is not finite, which then leaves the
// dissipation's range (at() declines) or fails the test.
template <class Dissipation>
bool slip_newton(const Dissipation& d, const vector3<typename Dissipation::value_type>& z,
                 const matrix3<typename Dissipation::value_type>& inverse,
                 typename Dissipation::point& x, vector3<typename Dissipation::value_type> ms,
                 bool evaluated, vector3<typename Dissipation::value_type>& step) {
  using Real = typename Dissipation::value_type;
  using std::cbrt;
  using std::sqrt;
  constexpr int max_steps = 8;
  static const Real limit =
      std::numeric_limits<Real>::epsilon() * cbrt(std::numeric_limits<Real>::epsilon());
  for (int k = 0; k < max_steps; ++k) {
    // δ solves (M⁻¹ + ∇²D)δ = −∇Ψ = z − M⁻¹s − ∇D.
    const vector3<Real> descent{z[0] - ms[0] - x.grad[0], z[1] - ms[1] - x.grad[1],
                                z[2] - ms[2] - x.grad[2]};
    if (!solve_symmetric(upper_plus(inverse, x.hessian), descent, step)) return false;
    const Real r2 = Dissipation::step_ratio(x, step);
    if (r2 <= limit && evaluated) return true;
    const Real t = r2 > Real(0.25) ? Real(1 / (2 * sqrt(r2))) : Real(1);
    if (!advance(d, shifted(x.s, step, t), r2, x)) return false;
    ms = multiply(inverse, x.s);
    evaluated = true;
  }
  return false;
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_SLIP_NEWTON_HPP
