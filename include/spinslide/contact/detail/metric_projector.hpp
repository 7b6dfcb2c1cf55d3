//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The point of the 3-D limit set L₃ = {(f, t) ∈ ℝ²×ℝ : (|f|, |t|) ∈ L} nearest
// to z in a metric M, (p − z)ᵀM(p − z) (docs/theory.md §11, "Any metric").
//
// Outside L₃ the nearest point p and the slip s = M(z − p) satisfy p = ∇D(s), with D(s) =
// |s_f|𝓕(ε) + |s_t|𝓣(ε), ε = |s_f|/|s_t|, the dissipation function of the contact (1-homogeneous
// and convex; ∇D is the friction law, (𝓕 s_f/|s_f|, 𝓣 sign s_t)).  So s is the minimum of the
// strictly convex
//   Ψ(s) = ½ sᵀM⁻¹s + D(s) − zᵀs,
// found by Newton's method with a line search on the sign of Ψ's slope (which keeps its digits
// where Ψ's differences round away: newton()). Whatever the iteration's error, ∇D(s) lies on the
// curve (to the profile's rounding) with s along its normal (ε d, sign s_t): only nearness is
// iterated, and it never fails: every step lowers Ψ, and the iteration ends when Newton's
// decrement is within the rounding of ∇Ψ's terms, which leaves the nearest point to a few ulp
// times the metric's condition number (tests/test_metric_projection.cpp, in float, double, long
// double and cpp_bin_float_50).  Every bound is the type's own (epsilon, the normal numbers'
// range).  Inside L₃ (decided on the magnitudes by the 2-D projection) s = 0: sticking.
#ifndef SPINSLIDE_CONTACT_DETAIL_METRIC_PROJECTOR_HPP
#define SPINSLIDE_CONTACT_DETAIL_METRIC_PROJECTOR_HPP

#include <spinslide/base/friction_result.hpp>
#include <spinslide/contact/detail/dissipation_hessian.hpp>
#include <spinslide/contact/detail/limit_projector.hpp>
#include <spinslide/contact/detail/matrix3.hpp>
#include <spinslide/contact/detail/round_dissipation.hpp>
#include <spinslide/contact/detail/slip_newton.hpp>
#include <spinslide/contact/planar_metric.hpp>
#include <spinslide/values/detail/force_slope.hpp>

#include <boost/config.hpp>
#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/tools/precision.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace spinslide {

namespace detail {

template <class Profile>
class metric_projector {
  using Real = typename Profile::value_type;
  using vec = vector3<Real>;
  using point_data = slip_point<Real>;
  using projection = friction_result<std::array<Real, 2>, Real>;  // the family's 2-D shape

 public:
  // z finite (checked by the caller); `metric` M and `inverse` M⁻¹, symmetric
  // positive definite (a planar_metric's, or derived from one).
  metric_projector(const Profile& profile, const vec& z, const matrix3<Real>& metric,
                   const matrix3<Real>& inverse)
      : p_(profile), hessian_of_d_(profile), z_(z), m_(&metric), inverse_(&inverse) {
    // The nearest point does not change if M is scaled: M/d and d·M⁻¹, d the
    // largest diagonal entry, keep s and Ψ away from over- and underflow
    // for metrics of any size.  (The impulse law's frame comes so scaled, d
    // = 1, and is read where it is.)
    const Real d = (std::max)({metric[0][0], metric[1][1], metric[2][2]});
    if (d == 1) return;
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) {
        scaled_m_[i][j] = metric[i][j] / d;
        scaled_inverse_[i][j] = inverse[i][j] * d;
      }
    m_ = &scaled_m_;
    inverse_ = &scaled_inverse_;
  }
  // (It points into itself: not to be copied.)
  metric_projector(const metric_projector&) = delete;
  metric_projector& operator=(const metric_projector&) = delete;

  // The projection; `start`: a ratio to search from (0 or ∞: none), or the
  // curve point `from` (at the ratio `start`, its 𝓕 and 𝓣 finite) that the
  // contact's last projection left, whose values save an evaluation.
  projection operator()(Real start, const curve_point<Real>* from = nullptr) {
    if (largest(z_) > far()) return support_point();
    if constexpr (fused_value_slope<Profile>::value) {
      projection quick;
      if (fast(start, from, quick)) return quick;
    }
    return careful(start, from);
  }

 private:
  // Out of line: the fast path runs in a small frame (tools/path_instructions).
  BOOST_NOINLINE projection careful(Real start, const curve_point<Real>* from) {
    using std::fabs;
    // With a start: if z lies beyond the support plane of L₃ with the normal
    // n at the start's curve point (zᵀn > D(n) = max over L₃ of pᵀn), z is
    // outside and n a descent direction: Newton from there, one evaluation
    // (none from a curve point).  Nothing is decided on the point's values:
    // Newton starts only where Ψ, from the profile's own values, is < 0
    // (which proves z outside: Ψ(0) = 0 is the minimum inside).
    if (start > 0 && start < std::numeric_limits<Real>::infinity()) {
      const bool known =
          from && (boost::math::isfinite)(from->force) && (boost::math::isfinite)(from->torque);
      // From a ratio alone, the profile's values there serve the ray and its
      // start (whose ratio is the same): one evaluation.
      const own_values own =
          known ? own_values{{from->force, from->torque}, from->slope} : values_at(start);
      // Along the slip M(z − p) that the curve point p at the start, in z's
      // direction, would leave (the metric turns the slip away from z).
      const ray first = normal_ray(start, own.ft);
      const vec p0 = {own.ft.force * first.dx, own.ft.force * first.dy,
                      z_[2] < 0 ? Real(-own.ft.torque) : own.ft.torque};
      const vec slip = multiply(*m_, vec{z_[0] - p0[0], z_[1] - p0[1], z_[2] - p0[2]});
      const ray turned = normal_ray(start, own.ft, slip);
      const ray& r = turned.resolved ? turned : first;
      if (r.resolved) {
        const point_data x = ray_start(r, known ? nullptr : &own);
        if (x.psi < 0) return newton(x);
      }
    }
    // Otherwise the 2-D projection decides sticking on the magnitudes and
    // gives the curve point, along z's direction, to start from.
    const friction_result<Real, Real> flat =
        limit_projector<Profile>(p_, {length(z_[0], z_[1]), fabs(z_[2])}, torque_weight())(start);
    if (flat.sticking) return {{z_[0], z_[1]}, z_[2], true};
    const ray r = normal_ray(flat.ratio, {flat.force, flat.torque});
    if (r.resolved) {
      const point_data x = ray_start(r);
      if (x.psi < 0) return newton(x);
    }
    // No gain beyond rounding (z outside L₃ only by rounding): the 2-D answer
    // itself, on the curve and within rounding of z.
    return result_on_ray(r, {flat.force, flat.torque}, flat.ratio);
  }

  // Beyond this distance from L₃ (whose points are O(1)) Ψ's quadratic term
  // could overflow (|z|² of the largest value over 256), and the nearest
  // point is the support point below to rounding: its direction is off by
  // about κ|p|/|z|, within rounding once |z| > κ/ε_mach, which is below
  // this bound in every type for the condition numbers planar_metric
  // accepts (3e23 against 8e152 in double, 7e10 against 1e18 in float).
  static Real far() {
    using std::sqrt;
    static const Real bound = sqrt(boost::math::tools::max_value<Real>()) / 16;
    return bound;
  }
  static Real epsilon() { return std::numeric_limits<Real>::epsilon(); }

  // The fast path (slip_newton.hpp) from the start's values (the stored
  // curve point's where it has 𝓕′ too, else the profile's at its ratio) or,
  // without a start, from the ratio of the support point's normal Mz (the
  // answer's, for a z far from the set); false where it declines.  The
  // answer's curve point carries the 𝓕′ of the last iterate, within that
  // step's first order of its ratio: a start for the next projection.
  bool fast(Real start, const curve_point<Real>* from, projection& out) const {
    using round = round_dissipation<Profile>;
    using std::fabs;
    const round d(p_);
    typename round::values v;
    bool evaluated = true;
    if (start > 0 && start < std::numeric_limits<Real>::infinity()) {
      if (from && (boost::math::isfinite)(from->force + from->torque + from->slope)) {
        v = {start, {from->force, from->torque}, from->slope};
        evaluated = false;
      } else {
        v = d.at_ratio(start);
      }
    } else {
      const vec u = multiply(*m_, z_);
      const Real guess = length(u[0], u[1]) / fabs(u[2]);
      if (!(guess > 0 && guess < std::numeric_limits<Real>::infinity())) return false;
      v = d.at_ratio(guess);
    }
    typename round::point x;
    vec ms, step;
    if (!d.start(z_, *m_, *inverse_, v, x, ms) ||
        !slip_newton(d, z_, *inverse_, x, ms, evaluated, step))
      return false;
    const vec dp = multiply(x.hessian, step);
    out = slip({x.grad[0] + dp[0], x.grad[1] + dp[1], x.grad[2] + dp[2]},
               round::ratio_of(shifted(x.s, step, Real(1))), x.slope);
    return true;
  }

  // For z far from L₃: the point of L₃ whose outward normal is along
  // M(z − p) ≈ Mz, relatively within |p|/|z|: at the ratio
  // ε = |(Mz)_f|/|(Mz)_t| along (Mz)_f's direction and (Mz)_t's sign.
  projection support_point() const {
    const Real scale = largest(z_);
    const vec u = multiply(*m_, vec{z_[0] / scale, z_[1] / scale, z_[2] / scale});
    using std::fabs;
    const Real along = length(u[0], u[1]), across = fabs(u[2]);
    const Real eps = across > 0 ? Real(along / across) : std::numeric_limits<Real>::infinity();
    const force_torque_result<Real> c = p_.force_torque(along > 0 ? eps : Real(0));
    const Real fx = along > 0 ? Real(u[0] / along) : Real(0);
    const Real fy = along > 0 ? Real(u[1] / along) : Real(0);
    return slip({c.force * fx, c.force * fy, u[2] < 0 ? Real(-c.torque) : c.torque},
                along > 0 ? eps : Real(0));
  }

  // The outward normal n at the curve point of ratio ε along z's force
  // direction and torque sign (scaled to a largest component of 1), and the
  // gain zᵀn − D(n): positive when z lies beyond that point's support plane,
  // and resolved when that is more than rounding (8 ulp of the terms).
  struct ray {
    vec n;
    Real gain;
    Real dx, dy;    // z's force direction (1, 0 if z has no force)
    bool resolved;  // gain > 0 beyond rounding
  };
  ray normal_ray(Real eps, const force_torque_result<Real>& c) const {
    return normal_ray(eps, c, z_);
  }
  // The same along the force direction and torque sign of `toward`.
  ray normal_ray(Real eps, const force_torque_result<Real>& c, const vec& toward) const {
    const Real zf = length(toward[0], toward[1]);
    const bool wide = eps > 1;
    const Real nf = wide ? Real(1) : eps, nt = wide ? Real(1 / eps) : Real(1);
    ray r;
    r.dx = zf > 0 ? Real(toward[0] / zf) : Real(1);
    r.dy = zf > 0 ? Real(toward[1] / zf) : Real(0);
    r.n = {nf * r.dx, nf * r.dy, toward[2] < 0 ? Real(-nt) : nt};
    const Real along = dot(z_, r.n), support = nf * c.force + nt * c.torque;
    r.gain = along - support;
    using std::fabs;
    r.resolved = r.gain > 8 * epsilon() * (fabs(along) + support);
    return r;
  }

  projection result_on_ray(const ray& r, const force_torque_result<Real>& c, Real eps) const {
    return slip({c.force * r.dx, c.force * r.dy, z_[2] < 0 ? Real(-c.torque) : c.torque}, eps);
  }

  // The torque's weight relative to the force's for the 2-D start and test
  // (which one only changes the start: stick or slip does not depend on it).
  Real torque_weight() const {
    const auto& m = *m_;
    const Real w = 2 * m[2][2] / (m[0][0] + m[1][1]);
    return (boost::math::isfinite)(w) && w > 0 ? w : Real(1);
  }

  // The profile's own values at a ratio: 𝓕, 𝓣, and 𝓕′ where it comes with
  // them (fused_value_slope; else NaN, unused).
  struct own_values {
    force_torque_result<Real> ft;
    Real slope;
  };
  own_values values_at(Real eps) const {
    if constexpr (fused_value_slope<Profile>::value) {
      // 𝓕′ with the values, from the same call (Hertz, Boussinesq): the
      // Hessian needs it at every iterate.
      if (eps > 0 && eps < std::numeric_limits<Real>::infinity()) {
        const auto both = fused_value_slope<Profile>::template at<false>(p_, eps);
        return {both.value, both.slope};
      }
    }
    return {p_.force_torque(eps), std::numeric_limits<Real>::quiet_NaN()};
  }

  point_data point(const vec& s) const { return point(s, nullptr); }
  // At s, from the profile's own values `known` at s's ratio where the
  // caller has them (the ray's start: its ratio is the one they were
  // evaluated at, to rounding), else evaluating the profile.
  point_data point(const vec& s, const own_values* known) const {
    point_data d;
    d.s = s;
    d.along = length(s[0], s[1]);
    using std::fabs;
    d.across = fabs(s[2]);
    d.eps = d.across > 0 ? Real(d.along / d.across) : std::numeric_limits<Real>::infinity();
    if (d.along == 0) d.eps = 0;
    const own_values v = known ? *known : values_at(d.eps);
    d.ft = v.ft;
    d.slope = v.slope;
    const Real unit = d.along > 0 ? Real(d.ft.force / d.along) : Real(0);
    d.grad_d = {s[0] * unit, s[1] * unit,
                s[2] > 0   ? d.ft.torque
                : s[2] < 0 ? Real(-d.ft.torque)
                           : Real(0)};
    d.ms = multiply(*inverse_, s);
    const Real quadratic = dot(s, d.ms) / 2,
               dissipation = d.along * d.ft.force + d.across * d.ft.torque;
    const Real linear = dot(z_, s);
    d.psi = quadratic + dissipation - linear;
    d.psi_scale = fabs(quadratic) + dissipation + fabs(linear);
    return d;
  }

  // Newton's start, the best point of the ray: Ψ(τn) = ½τ²nᵀM⁻¹n − τ·gain
  // is least at τ = gain/(nᵀM⁻¹n) > 0, where Ψ < 0 if the gain is the
  // profile's own.  Every later iterate keeps Ψ below that, away from the
  // kink at s = 0, where a start in a poor direction (an ill-conditioned M)
  // would make the iteration collapse; so the caller starts there only if
  // Ψ < 0 (a curve point's values may not be the profile's).
  point_data ray_start(const ray& r, const own_values* known = nullptr) const {
    const Real tau = r.gain / dot(r.n, multiply(*inverse_, r.n));
    return point({tau * r.n[0], tau * r.n[1], tau * r.n[2]}, known);
  }

  // Newton's method on Ψ from s: the step δ solves (M⁻¹ + ∇²D)δ = −∇Ψ, and the line search moves
  // along it by the sign of Ψ's slope ∇Ψ·δ, which is known to the rounding of ∇Ψ's terms (a few
  // ulp of z's size), not by Ψ's values, whose differences round away first: with a metric
  // conditioned near its limit a decrease of Ψ of 1e-19 is all a step of ∇Ψ = 1e-7 can show, below
  // Ψ's rounding, and a line search on values stalls there. Converged when Newton's decrement
  // −∇Ψ·δ is within that rounding and every component of ∇Ψ within its own (along(): no direction
  // left in which Ψ falls that this type can show), when δ is no descent direction, or when the
  // step is negligible (below 4 ulp of s_f and of s_t).  Never fails: every iterate is on the
  // curve with s along its normal, each step lowers the strictly convex Ψ (line_search), and after
  // max_newton_iterations the last iterate is the answer.  A step within first_order() of s ends
  // the iteration without evaluating the profile again (last_step).
  projection newton(point_data x) const {
    point_data previous{};
    for (int iteration = 0; iteration < max_newton_iterations; ++iteration) {
      const vec g = gradient(x);
      const matrix3<Real> h = hessian_of_d_(x, iteration > 0 ? &previous : nullptr);
      const vec step = newton_step(h, g);
      const directional start = along(x, g, step);
      const bool at_rounding = !(start.slope < -start.rounding) && !start.resolved;
      if (at_rounding || !(start.slope < 0) || negligible(x, step, Real(1))) return result(x);
      if (first_order(x, step)) return last_step(x, h, step);
      previous = x;
      if (!line_search(previous, step, start, x)) return result(x);
    }
    return result(x);
  }
  static constexpr int max_newton_iterations = 100;
  // Each rejected t at least halves the next: the type's digits of halvings
  // take any step below the floor of s's rounding.
  static constexpr int max_line_steps = std::numeric_limits<Real>::digits + 8;

  // ∇Ψ·δ at a point, and the bound of its rounding: a few ulp of the sum of
  // the magnitudes of its terms (M⁻¹s, ∇D, whose profile values are good to
  // a few ulp, and z) along δ.
  // `resolved`: some component of ∇Ψ is above 64 ulp of its own terms'
  // magnitudes (as where z lies by 1e-14 beyond the corner (1, 0): the
  // torque's terms are 1e-11, the force's 1, and a sum over all the
  // components would call the torque's converged 1e5 times too early).
  struct directional {
    Real slope, rounding;
    bool resolved;
  };
  directional along(const point_data& x, const vec& g, const vec& step) const {
    using std::fabs;
    Real sum = 0, size = 0;
    bool resolved = false;
    for (std::size_t i = 0; i < 3; ++i) {
      Real row = 0;
      for (std::size_t j = 0; j < 3; ++j) row += fabs((*inverse_)[i][j] * x.s[j]);
      const Real terms = row + fabs(x.grad_d[i]) + fabs(z_[i]);
      sum += g[i] * step[i];
      size += terms * fabs(step[i]);
      resolved = resolved || fabs(g[i]) > 64 * epsilon() * terms;
    }
    return {sum, epsilon() * size, resolved};
  }

  // ∇Ψ = M⁻¹s + ∇D − z.
  vec gradient(const point_data& x) const {
    return {x.ms[0] + x.grad_d[0] - z_[0], x.ms[1] + x.grad_d[1] - z_[1],
            x.ms[2] + x.grad_d[2] - z_[2]};
  }

  // A point s + tδ where Ψ is lower, into `next`; false if there is none
  // beyond rounding.  Along the line φ(t) = Ψ(s + tδ) is convex with
  // φ′(0) < 0, so wherever φ′(t) ≤ 0, φ fell all the way from 0 to t: t is
  // taken.  So is a t that lowers Ψ by 10⁻⁴ of its promise tφ′(0) (Armijo's
  // test, where Ψ's differences are resolved: a step across a near-corner
  // of D, where φ′ jumps), and a t where φ′ rose to at most half |φ′(0)|
  // and Ψ is no higher to its rounding (near the line's minimum, as a
  // Newton step near the answer).  Otherwise t is halved.  (A secant of φ′
  // for the next t, tried, zig-zags across such a corner: an exact line
  // search with a poor Hessian.)  A t taken with φ′(t) ≤ 0 after 2t was
  // rejected lies in [t*/2, t*] for the line's minimum t*, and lowers Ψ by
  // at least half what the exact line search would (convexity); Armijo's
  // steps lower it by their promise: Newton's method stays globally
  // convergent.
  bool line_search(const point_data& x, const vec& step, const directional& start,
                   point_data& next) const {
    using std::fabs;
    Real t = first_trial(x, step);
    for (int k = 0; k < max_line_steps && !negligible(x, step, t); ++k) {
      point_data y = point(shifted(x.s, step, t));
      const directional d = along(y, gradient(y), step);
      const Real slack = 4 * epsilon() * (x.psi_scale + y.psi_scale);
      const bool armijo = y.psi < x.psi + Real(1e-4) * t * start.slope;
      if (d.slope <= 0 || armijo || (d.slope <= -start.slope / 2 && y.psi <= x.psi + slack)) {
        next = y;
        return true;
      }
      t /= 2;
    }
    return false;
  }

  // True if the step tδ from x is below 4 ulp of s in each of its blocks,
  // s_f and s_t, each against its own size (where s_f is 1e-9 of s_t, at a
  // concentrated load's answer ε = 5e-7, its own digits still move the
  // answer), or below ε_mach² of s in a block that is 0.
  static bool negligible(const point_data& x, const vec& step, Real t) {
    using std::fabs;
    const Real tiny = 4 * epsilon(), zero = epsilon() * epsilon() * largest(x.s);
    return t * length(step[0], step[1]) <= tiny * x.along + zero &&
           t * fabs(step[2]) <= tiny * x.across + zero;
  }

  // The line search's first t: 1, but a step that takes the torque's slip
  // across 0 goes first as far as 0 (pure sliding, where D's curvature in
  // s_t is ⟨r²⟩/(2|s_f|)): beyond, D is a V in s_t (|s_t|⟨r⟩ at small ε)
  // that the model at this side does not see, and full steps across
  // zig-zag (fuzz_impulse: 100 iterations).  Likewise a step that takes the
  // force's slip past its nearest approach to 0 (reversing its direction)
  // goes first as far as that approach: where 𝓕 rises steeply from ε = 0 (a
  // load concentrated within radius 1e-6, 𝓕′(0) = ⟨1/r⟩/2 = 1e6), D is a
  // cone in s_f (about 𝓕|s_f|) beyond a core of |s_f| ≈ 1e-6|s_t|, and full
  // steps across it zig-zagged for 100 iterations and ended 150 times
  // farther than the nearest point (fuzz_impulse).  (Neither from where that
  // slip is already below √ε of s: there the model sees both sides, and the
  // answer may lie just across.)
  static Real first_trial(const point_data& x, const vec& step) {
    using std::fabs;
    using std::sqrt;
    static const Real near = sqrt(epsilon());
    const Real size = largest(x.s);
    Real t = 1;
    if (x.s[2] * step[2] < 0 && fabs(step[2]) > fabs(x.s[2]) && fabs(x.s[2]) > near * size)
      t = -x.s[2] / step[2];
    // s_f + tδ_f is nearest 0 at t = −s_f·δ_f/|δ_f|² (in units of s's
    // size); the step reverses s_f where s_f·(s_f + δ_f) < 0.
    const Real f0 = x.s[0] / size, f1 = x.s[1] / size, d0 = step[0] / size, d1 = step[1] / size;
    const Real along = f0 * d0 + f1 * d1, reach = d0 * d0 + d1 * d1;
    const bool reverses = f0 * f0 + f1 * f1 + along < 0;
    if (reverses && -along < t * reach && x.along > near * size) t = -along / reach;
    return t;
  }

  // δ = −(M⁻¹ + ∇²D)⁻¹∇Ψ, for ∇²D = `hd`.
  vec newton_step(matrix3<Real> h, const vec& g) const {
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) h[i][j] += (*inverse_)[i][j];
    vec step{};
    if (!solve_symmetric(h, g, step)) solve_symmetric(*inverse_, g, step);  // ∇²D not finite
    for (Real& v : step) v = -v;
    return step;
  }

  // True if the Newton step δ from x is small enough to take to first
  // order, by the 2-D search's rule (limit_projector::advance): r² ≤
  // epsilon^(4/3), r the larger of |δ_f|/|s_f| and |δ_t|/|s_t| (so that ε
  // and the force's direction change relatively by O(r)), where 𝓕′ is the
  // profile's closed form (elsewhere the Hessian's secant slope is not good
  // to r).  Then the error left after the step, O(r²) of s, and the terms of
  // ∇D(s + δ) left out of ∇D(s) + ∇²D(s)δ, O(r²) of ∇D, are below rounding.
  bool first_order(const point_data& x, const vec& step) const {
    if constexpr (fused_value_slope<Profile>::value || has_force_slope<Profile>()) {
      using std::cbrt;
      using std::fabs;
      static const Real limit = epsilon() * cbrt(epsilon());
      if (!(x.eps > 0 && x.eps < std::numeric_limits<Real>::infinity())) return false;
      const Real rf = length(step[0], step[1]) / x.along, rt = fabs(step[2]) / x.across;
      const Real r = (std::max)(rf, rt);
      return r * r <= limit;
    }
    static_cast<void>(x);
    static_cast<void>(step);
    return false;
  }
  // The answer after a step δ within first_order() of x: s + δ, and the
  // curve point ∇D(s + δ) as ∇D(s) + ∇²D(s)δ (`hd` = ∇²D(s)), which is
  // M(z − p) = s + δ exactly where the step solved Newton's equation.
  projection last_step(const point_data& x, const matrix3<Real>& hd, const vec& step) const {
    using std::fabs;
    const vec s = shifted(x.s, step, Real(1));
    const vec dp = multiply(hd, step);
    const Real along_s = length(s[0], s[1]), across_s = fabs(s[2]);
    return slip({x.grad_d[0] + dp[0], x.grad_d[1] + dp[1], x.grad_d[2] + dp[2]},
                Real(along_s / across_s));
  }

  static projection result(const point_data& d) { return slip(d.grad_d, d.eps); }

  // A slip to the curve point p = (force, torque) at ratio ε, with the curve
  // point the contact's next projection starts from (𝓕 = |p's force|, 𝓣 =
  // |p's torque|, 𝓕′ = `slope`, 𝓕″ unknown).
  static projection slip(const vec& p, Real eps,
                         Real slope = std::numeric_limits<Real>::quiet_NaN()) {
    using std::fabs;
    return {{p[0], p[1]}, p[2], false, eps, {eps, length(p[0], p[1]), Real(fabs(p[2])), slope}};
  }

  const Profile& p_;
  dissipation_hessian<Profile> hessian_of_d_;
  vec z_;
  const matrix3<Real>* m_;
  const matrix3<Real>* inverse_;
  matrix3<Real> scaled_m_, scaled_inverse_;  // M and M⁻¹ when scaled here
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_METRIC_PROJECTOR_HPP
