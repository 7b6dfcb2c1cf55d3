//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The projection of a point (x, y) onto a profile's limit set L in the
// metric (f − x)² + w (t − y)² (limit_set.hpp; docs/theory.md §11).
//
// The nearest point of the curve C(ε) = (𝓕(ε), 𝓣(ε)) satisfies
//   h(ε) = (x − 𝓕) − wε(y − 𝓣) = 0,
// because the curve's normal at ε is (ε, 1) (𝓣′ = −ε𝓕′).  For x, y > 0, h(0) = x > 0 and h(∞) =
// −∞, and h changes sign once where P lies outside L (§11), so the root is bracketed.  It is found
// by Newton's method in ε, safeguarded by the bracket (bisection in ln ε, or a growing factor
// towards an open side), with 𝓕′ where the profile gives it (force_slope.hpp: Hertz, Boussinesq,
// the disk's table), else the secant of 𝓕 through the last two samples (a difference quotient for
// the first).  Sticking is decided on the way: L contains the quadrilateral (0, 0), (1, 0), C(ε),
// (0, ⟨r⟩) of every sample (convexity), and so the inward normal of C(ε) (in [0, 𝓕] × [0, 𝓣]).
//
// Where 𝓕 jumps (the uncoupled caps jump from 0 to 1 at ε = 0⁺), L has a straight edge and the
// bracket closes on the jump without h reaching 0: the point is then projected onto the chord
// between the two sides (the edge). The ends ε = 0 and ε = ∞ are the bracket's initial sides, C(0)
// = (0, ⟨r⟩) and C(∞) = (1, 0); the search goes no further than the smallest and the largest
// normal number before it projects onto the chord to the end.
#ifndef SPINSLIDE_CONTACT_DETAIL_LIMIT_PROJECTOR_HPP
#define SPINSLIDE_CONTACT_DETAIL_LIMIT_PROJECTOR_HPP

#include <spinslide/base/detail/product.hpp>
#include <spinslide/base/friction_result.hpp>
#include <spinslide/contact/detail/sticking_triangle.hpp>
#include <spinslide/values/detail/force_slope.hpp>
#include <spinslide/values/force_torque_result.hpp>

#include <boost/config.hpp>
#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/tools/precision.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace spinslide {

namespace detail {

template <class Profile>
class limit_projector {
  using Real = typename Profile::value_type;
  using projection = friction_result<Real, Real>;  // the family's scalar shape

 public:
  // The point (x, y) = (point.force, point.torque) ≥ 0 and the weight w =
  // torque_weight > 0, finite (checked by the caller).
  limit_projector(const Profile& profile, force_torque_result<Real> point, Real torque_weight)
      : profile_(profile),
        x_(point.force),
        y_(point.torque),
        w_(torque_weight),
        top_(profile.mean_radius()) {}

  // The projection, searching from `start` (a ratio; 0 or ∞: no guess), or
  // from the curve point `from` (at the ratio `start`) if given.
  projection operator()(Real start, const curve_point<Real>* from = nullptr) {
    if (in_sticking_triangle(x_, y_, top_)) return sticking();
    if (y_ == 0) return on_curve(inf(), {Real(1), Real(0)});  // x > 1: the corner (1, 0)
    if (x_ == 0) return on_curve(Real(0), {Real(0), top_});  // y > ⟨r⟩: the corner (0, ⟨r⟩)
    return project(start, from);
  }

 private:
  // Apart from the tests above (a caller inlines those: a stick costs the
  // triangle's test), and the search apart again, so that the warm steps run
  // in a small frame (5 to 45 instructions less: tools/path_instructions).
  BOOST_NOINLINE projection project(Real start, const curve_point<Real>* from) {
    projection warm{};
    if (!(start > 0 && start < inf())) start = first_ratio(start);
    if (warm_steps(start, from, warm)) return warm;
    return search(start);
  }
  BOOST_NOINLINE projection search(Real start) {
    lo_ = {Real(0), {Real(0), top_}, x_, Real(0)};
    hi_ = {inf(), {Real(1), Real(0)}, -inf(), Real(0)};
    previous_ = {};
    reach_ = 8;
    curvature_ = 0;
    sample a = evaluate(first_ratio(start));
    for (int i = 0; i < max_iterations; ++i) {
      if (inside_quadrilateral(a.ft)) return sticking();
      if (a.h == 0) return on_sample(a, fused_value_slope<Profile>::value ? a.slope : nan(), nan());
      narrow(a);
      const step next = next_ratio(a);
      if (next.kind == step_kind::edge) return on_edge();
      if (next.kind == step_kind::converged)
        return next.eps == a.eps ? classify(a, search_slope(slope_), nan())
                                 : classify(advance(a, next.eps), search_slope(slope_), nan());
      previous_ = a;
      a = evaluate(next.eps);
    }
    // Not reached (bisection in ln ε closes the bracket on the normal
    // numbers in far fewer steps), but a projection inside a time step must
    // answer: the nearest point of the chord between the bracket's sides, a
    // point of L.
    return on_edge();
  }

  static constexpr int max_iterations = 200;
  static constexpr int max_warm_iterations = 6;  // before the safeguarded search
  struct sample {
    Real eps;  // ε (0 and ∞ at the bracket's initial sides)
    force_torque_result<Real> ft;
    Real h;      // (x − 𝓕) − wε(y − 𝓣), divided by w where w < 1 (evaluate)
    Real slope;  // 𝓕′ where the profile gives it with the values (fused_value_slope)
  };
  // A warm step's sample: with 𝓕″ where bounded (Halley's steps), else 0.
  // Apart, so that the safeguarded search's samples, which it copies, do
  // not grow.
  struct warm_sample : sample {
    Real curvature;
  };
  enum class step_kind { search, converged, edge };
  struct step {
    Real eps;
    step_kind kind;
  };

  static Real inf() { return std::numeric_limits<Real>::infinity(); }
  static Real nan() { return std::numeric_limits<Real>::quiet_NaN(); }
  // The slope a result of the safeguarded search reports: where the profile
  // has 𝓕′ in closed form (not a secant's estimate), else NaN.
  static Real search_slope(Real slope) {
    if constexpr (fused_value_slope<Profile>::value || has_force_slope<Profile>()) return slope;
    static_cast<void>(slope);
    return nan();
  }

  // The common case of a contact in steady slip, tried first: steps from
  // the contact's last ratio without the bracket, in plain arithmetic, for a
  // profile with a closed-form slope and where every factor of h and its
  // slope stays within 2^±32 (so that no product of three can leave the
  // normal numbers of any type, and plain products are product()'s).
  // Halley's steps where 𝓕″ is bounded (Hertz), else Newton's; a step of
  // half the ratio or more damped (damped_ratio), after which h need only
  // not grow.  It gives up, leaving `start` at its last ratio for the
  // safeguarded search, on h not halved (grown, after a damped step), a
  // slope that is not negative, a ratio out of scale, or six samples.
  // Otherwise it ends as that search does (a convergence test for the
  // step's order, the advance; sticking decided at the root, at_root).
  bool warm_steps(Real& start, const curve_point<Real>* from, projection& result) {
    if constexpr (fused_value_slope<Profile>::value || has_force_slope<Profile>()) {
      if (!(well_scaled(start) && well_scaled(w_) && x_ <= scale_limit() && y_ <= scale_limit()))
        return false;
      Real last_h = inf();
      if (from) step_from_point(*from, start);
      for (int i = 0; i < max_warm_iterations; ++i) {
        const warm_sample a = evaluate_slope(start);
        const warm_outcome o = warm_iteration(a, last_h, start, result);
        if (o != warm_outcome::stepped) return o == warm_outcome::done;
      }
    }
    static_cast<void>(start), static_cast<void>(from), static_cast<void>(result);
    return false;
  }
  // The first warm step from a curve point that a previous projection left
  // (no evaluation): `start` moves to where it leads, damped (damped_ratio),
  // if the slope there is negative and the ratio it gives well scaled, and is
  // left at the point's ratio otherwise.  Nothing is decided on this sample
  // (no sticking test, no convergence, and the next sample need not halve
  // its h): the point is the caller's, and every result rests on the
  // profile's own values.  A NaN 𝓕″ gives Newton's step (warm_step_from); any
  // other NaN or ∞ a step the test below refuses, or 0 (an infinite slope).
  void step_from_point(const curve_point<Real>& c, Real& start) const {
    warm_sample a{{c.ratio, {c.force, c.torque}, Real(0), c.slope}, c.curvature};
    a.h = (x_ - a.ft.force) - w_ * a.eps * (y_ - a.ft.torque);
    const warm_step s = warm_step_from(a);
    const Real next = damped_ratio(a.eps, s.delta);
    if (s.slope < 0 && well_scaled(next)) start = next;
  }
  // ε + δ, or for r = |δ|/ε ≥ 1/2 the factor 1 + r (at most 16) up or down:
  // up as Newton's step, down as in ln ε (positive), so that a start far off
  // reaches Newton's regime in a few samples without the safeguarded search
  // (15 % of the LAMMPS pour's warm projections left for it before:
  // docs/performance.md).  NaN stays NaN.
  static Real damped_ratio(Real eps, Real delta) {
    using std::fabs;
    const Real r = fabs(delta) / eps;
    if (r < Real(0.5)) return eps + delta;
    const Real factor = (std::min)(1 + r, Real(16));
    return delta > 0 ? eps * factor : eps / factor;
  }
  enum class warm_outcome { done, stepped, given_up };
  // One warm step from the sample a: done (result set), stepped (`next` and
  // `last_h` advanced) or given up.
  warm_outcome warm_iteration(const warm_sample& a, Real& last_h, Real& next, projection& result) {
    using std::fabs;
    if (a.h == 0) return result = at_root(a, a.slope, a.curvature), warm_outcome::done;
    // 1/ε does not wait for the evaluation: one division off the steps' path.
    const Real inverse = 1 / a.eps;
    const warm_step next_step = warm_step_from(a);
    if (!(next_step.slope < 0) || !(fabs(a.h) <= last_h / 2)) return warm_outcome::given_up;
    const Real r = fabs(next_step.delta) * inverse, next_eps = a.eps + next_step.delta;
    if (r <= boost::math::tools::epsilon<Real>())
      return result = at_root(a, a.slope, a.curvature), warm_outcome::done;
    const bool halley = next_step.order == 3;
    if (r * r * (halley ? r : Real(1)) <= converged_product()) {
      slope_ = a.slope;
      curvature_ = halley ? a.curvature : Real(0);
      const sample b = advance(a, next_eps);
      return result = at_root(b, b.slope, halley ? a.curvature : nan()), warm_outcome::done;
    }
    const bool far = !(r < Real(0.5));
    const Real damped = far ? damped_ratio(a.eps, next_step.delta) : next_eps;
    if (!well_scaled(damped)) return warm_outcome::given_up;
    next = damped;
    last_h = far ? 2 * fabs(a.h) : fabs(a.h);
    return warm_outcome::stepped;
  }
  static Real scale_limit() { return Real(4294967296.0); }  // 2^32
  static bool well_scaled(Real v) { return v >= 1 / scale_limit() && v <= scale_limit(); }

  struct warm_step {
    Real delta;  // the step in ε
    Real slope;  // dh/dε
    int order;   // 3 for Halley's step, 2 for Newton's
  };
  // Newton's step n = −h/h′, or Halley's n/(1 + n h″/(2h′)) with
  // h″ = −𝓕″(1 + wε²) − 3wε𝓕′ where 𝓕″ is bounded and the correction
  // n h″/(2h′) is at most a half (further out, the step is not yet in
  // Halley's regime), as −2hh′/(2h′² − hh″): one division, which the steps
  // wait for.
  warm_step warm_step_from(const warm_sample& a) const {
    using std::fabs;
    const Real e = a.eps, dh = -(a.slope * (1 + w_ * e * e) + w_ * (y_ - a.ft.torque));
    if constexpr (fused_value_slope<Profile>::bounded_curvature) {
      const Real d2h = -(a.curvature * (1 + w_ * e * e) + 3 * w_ * e * a.slope);
      const Real hd2h = a.h * d2h, dh2 = dh * dh;
      if (fabs(hd2h) <= dh2) return {-2 * a.h * dh / (2 * dh2 - hd2h), dh, 3};
    }
    return {-a.h / dh, dh, 2};
  }

  // 𝓕, 𝓣, 𝓕′ (and 𝓕″ where bounded) and h at ε, h in plain arithmetic
  // (warm_steps).
  warm_sample evaluate_slope(Real eps) const {
    warm_sample a{{eps, {}, Real(0), Real(0)}, Real(0)};
    if constexpr (fused_value_slope<Profile>::value) {
      constexpr bool curvature = fused_value_slope<Profile>::bounded_curvature;
      const auto all = fused_value_slope<Profile>::template at<curvature>(profile_, eps);
      a.ft = all.value;
      a.slope = all.slope;
      a.curvature = all.curvature;
    } else {
      a.ft = profile_.force_torque(eps);
      a.slope = force_slope(profile_, eps);
    }
    a.h = (x_ - a.ft.force) - w_ * eps * (y_ - a.ft.torque);
    return a;
  }

  // h, divided by w where w < 1 (the same root and signs): for a tiny w,
  // w(y − 𝓣) in the slope would otherwise be subnormal and carry no digits
  // (w = 7e-321).  wε(y − 𝓣) as one product: w·ε alone can underflow
  // (w = 1e-187, ε = 1e-234) where the whole is a normal number.
  sample evaluate(Real eps) const {
    force_torque_result<Real> ft;
    Real slope = 0;
    if constexpr (fused_value_slope<Profile>::value) {
      const auto both = fused_value_slope<Profile>::template at<false>(profile_, eps);
      ft = both.value;
      slope = both.slope;
    } else {
      ft = profile_.force_torque(eps);
    }
    const Real h = w_ < 1 ? (x_ - ft.force) / w_ - product(eps, y_ - ft.torque)
                          : (x_ - ft.force) - product(w_, eps, y_ - ft.torque);
    return {eps, ft, h, slope};
  }
  // The curve point at the converged ratio `next`, from the last sample and
  // the slope of its Newton step, to first order: 𝓕 + 𝓕′Δ and 𝓣 − ε𝓕′Δ
  // (𝓣′ = −ε𝓕′).  Converged means r·max(r, the slope's uncertainty) ≤
  // epsilon^(4/3), r = |Δ|/ε (next_ratio), so the terms left out, of order
  // r² and r times the uncertainty, are below rounding: one evaluation of
  // the profile saved per projection.  After Halley's step (curvature_ set,
  // r³ ≤ epsilon^(4/3)) to second order: 𝓕 + 𝓕′Δ + 𝓕″Δ²/2 and
  // 𝓣 − ε(𝓕′Δ + 𝓕″Δ²/2) − 𝓕′Δ²/2 (𝓣″ = −𝓕′ − ε𝓕″), the terms left out of
  // order r³.  The sample's slope is 𝓕′ at `next` to the same order less
  // one (𝓕′ + 𝓕″Δ after Halley's step, 𝓕′ of the last sample otherwise).
  sample advance(const sample& a, Real next) const {
    const Real delta = next - a.eps;
    if (curvature_ == 0) {
      const Real df = slope_ * delta;
      return {next, {a.ft.force + df, a.ft.torque - a.eps * df}, Real(0), slope_};
    }
    const Real df = (slope_ + curvature_ * delta / 2) * delta;
    return {next,
            {a.ft.force + df, a.ft.torque - a.eps * df - slope_ * delta * delta / 2},
            Real(0),
            slope_ + curvature_ * delta};
  }

  // dh/dε (h as evaluate() scales it) for a slope 𝓕′ = `slope`.
  Real h_slope(const sample& a, Real slope) const {
    if (w_ < 1) return -(slope / w_ + product(slope, a.eps, a.eps) + (y_ - a.ft.torque));
    return -(slope + product(slope, w_, a.eps, a.eps) + product(w_, y_ - a.ft.torque));
  }

  // A given ratio, or where the root lies if P is far from L (x − 𝓕 ≈ x,
  // y − 𝓣 ≈ y), kept within three decades of 1.
  Real first_ratio(Real start) const {
    using boost::math::tools::max_value;
    using boost::math::tools::min_value;
    // The search stays among the normal numbers (below them 𝓕's differences
    // and the ratio itself lose their digits; the ends are edges, shrink()).
    if (start > 0 && start < inf())
      return (std::min)((std::max)(start, min_value<Real>()), max_value<Real>());
    return (std::min)((std::max)(x_ / (w_ * y_), Real(1e-3)), Real(1e3));
  }

  // P in the quadrilateral (0, 0), (1, 0), C, (0, ⟨r⟩), counter-clockwise:
  // on the left of the edges (1, 0) → C and C → (0, ⟨r⟩).
  bool inside_quadrilateral(const force_torque_result<Real>& c) const {
    const Real f = c.force, t = c.torque;
    return t * (1 - x_) >= (1 - f) * y_ && -f * (y_ - t) >= (top_ - t) * (x_ - f);
  }

  void narrow(const sample& a) {
    if (a.h > 0)
      lo_ = a;
    else
      hi_ = a;
  }

  // 𝓕′(ε) and how far it may be off, relative: the closed form (0), or the
  // secant through the previous sample if it is within 10 % (off by about
  // their distance, plus the rounding of the difference), or else a forward
  // difference (one more evaluation; off by about its step, √epsilon, plus
  // rounding).  A secant over a wider gap, as after a bisection, is not
  // trusted: a wrong slope gives a small step far from the root.
  struct slope_estimate {
    Real slope, uncertainty;
  };
  slope_estimate force_slope_at(const sample& a) const {
    if constexpr (fused_value_slope<Profile>::value) {
      return {a.slope, Real(0)};
    } else if constexpr (has_force_slope<Profile>()) {
      return {force_slope(profile_, a.eps), Real(0)};
    } else {
      using std::fabs;
      const Real gap = fabs(a.eps - previous_.eps) / a.eps;
      if (gap > 0 && gap <= Real(0.1)) return secant_slope(a, previous_, gap);
      const Real e = a.eps * (1 + difference_step());
      return secant_slope(a, {e, profile_.force_torque(e), Real(0), Real(0)}, difference_step());
    }
  }
  // The secant of 𝓕 while 𝓕 ≤ 1/2; above, where 𝓕 approaches 1 and its
  // differences round away (to 0 once 𝓕 rounds to 1), the secant of 𝓣
  // through 𝓣′ = −ε𝓕′ at the midpoint.  The uncertainty adds the relative
  // rounding of the difference, epsilon (|u| + |v|)/|u − v|.
  static slope_estimate secant_slope(const sample& a, const sample& b, Real gap) {
    using std::fabs;
    const bool by_force = a.ft.force <= Real(0.5);
    const Real u = by_force ? a.ft.force : a.ft.torque, v = by_force ? b.ft.force : b.ft.torque;
    const Real rounding = boost::math::tools::epsilon<Real>() * (fabs(u) + fabs(v)) / fabs(u - v);
    const Real slope =
        by_force ? (u - v) / (a.eps - b.eps) : -(u - v) / ((a.eps - b.eps) * ((a.eps + b.eps) / 2));
    return {slope, gap + rounding};
  }

  // epsilon^(4/3): (r m)^0.75 ≤ epsilon (next_ratio).
  static Real converged_product() {
    using std::cbrt;
    static const Real p =
        boost::math::tools::epsilon<Real>() * cbrt(boost::math::tools::epsilon<Real>());
    return p;
  }
  // The relative step of the first difference quotient, √epsilon.
  static Real difference_step() {
    using std::sqrt;
    static const Real h = sqrt(boost::math::tools::epsilon<Real>());
    return h;
  }

  // Newton's step in ε (dh/dε = −𝓕′(1 + wε²) − w(y − 𝓣), over w where w < 1), kept inside the
  // bracket; where it leaves it, or has not halved h since the last sample
  // (far from the root, where h is not near linear), a step that shrinks the
  // bracket instead.  Converged once the error after this step is predicted
  // below epsilon: (r m)^0.75 with r the relative step and m the larger of r
  // (Newton's quadratic term) and the slope's uncertainty (the secant's); the
  // power 0.75 allows for the order lost where 𝓕″ is singular (Boussinesq's
  // at ε = 1, where Newton has order 1.5).  A step below epsilon is not taken.
  step next_ratio(const sample& a) {
    using boost::math::tools::epsilon;
    using std::fabs;
    const slope_estimate d = force_slope_at(a);
    slope_ = d.slope;
    const Real slope = h_slope(a, d.slope);
    const Real next = a.eps - a.h / slope;
    const bool slow = previous_.eps > 0 && fabs(a.h) > fabs(previous_.h) / 2;
    // An infinite slope or h (wε² or wε(y − 𝓣) beyond the largest value)
    // would give a zero step and a false convergence.
    const bool finite = (boost::math::isfinite)(slope) && (boost::math::isfinite)(a.h);
    if (slope < 0 && !slow && finite) {
      const Real r = fabs(next - a.eps) / a.eps;
      // A converged step is taken even if rounding put it on a side of the bracket.
      if (r <= epsilon<Real>()) return {a.eps, step_kind::converged};
      if (r * (std::max)(r, d.uncertainty) <= converged_product())
        return {next, step_kind::converged};
      const bool normal = next >= boost::math::tools::min_value<Real>();
      if (next > lo_.eps && next < hi_.eps && normal) return {next, step_kind::search};
    }
    return shrink();
  }

  // Bisection in ln ε, or towards an open side by a factor that squares on
  // each use (8, 64, 4096, …: the normal numbers' range in about ten steps);
  // where that would leave the normal numbers, or the bracket is as narrow as
  // rounding allows without a root (a jump of 𝓕), the chord between the
  // sides is the answer.
  step shrink() {
    using boost::math::tools::epsilon;
    using boost::math::tools::max_value;
    using boost::math::tools::min_value;
    using std::sqrt;
    if (lo_.eps == 0) {
      const Real next = hi_.eps / reach();
      return next >= min_value<Real>() ? step{next, step_kind::search}
                                       : step{Real(0), step_kind::edge};
    }
    if (hi_.eps == inf()) {
      const Real next = lo_.eps * reach();
      return next <= max_value<Real>() ? step{next, step_kind::search}
                                       : step{inf(), step_kind::edge};
    }
    if (hi_.eps - lo_.eps <= 4 * epsilon<Real>() * hi_.eps) return {hi_.eps, step_kind::edge};
    return {sqrt(lo_.eps) * sqrt(hi_.eps), step_kind::search};
  }
  Real reach() {
    Real r = reach_;
    reach_ = r * r;  // +∞ once past the largest value: the next step ends the search
    return r;
  }

  // A root of h: P − C(ε) lies along the normal (ε, 1), outward (C is P's
  // projection) or inward (down and left, into L: P sticks), as y − 𝓣, of
  // x − 𝓕's sign, says; one comparison for classify's six products.
  projection at_root(const sample& a, Real slope, Real curvature) const {
    if (a.ft.torque >= y_) return sticking();
    return on_sample(a, slope, curvature);
  }
  // A converged sample: sticking after all (inside its quadrilateral), else
  // the result, with 𝓕′ and 𝓕″ there as known.
  projection classify(const sample& a, Real slope, Real curvature) const {
    if (inside_quadrilateral(a.ft)) return sticking();
    return on_sample(a, slope, curvature);
  }

  // The nearest point of the chord between the bracket's sides (an edge of
  // L where 𝓕 jumps, or the last stretch to an end).
  projection on_edge() const {
    using std::sqrt;
    const Real df = hi_.ft.force - lo_.ft.force, dt = hi_.ft.torque - lo_.ft.torque;
    const Real px = x_ - lo_.ft.force, py = y_ - lo_.ft.torque;
    // P is inside if it lies on the inner side of the chord (to its right,
    // going from the ε = 0 side to the ε = ∞ side) by more than the rounding
    // of the sides' 𝓕 and 𝓣 can decide (a chord 1e-308 long beside C(0) has
    // dt = 𝓣(1e-308) − ⟨r⟩, a rounding), or in a sample's quadrilateral.
    using std::fabs;
    const Real cross = df * py - dt * px;
    const Real rounding = 4 * boost::math::tools::epsilon<Real>() *
                          (fabs(py) * (1 + fabs(df)) + fabs(px) * (top_ + fabs(dt)));
    if (cross < -rounding || inside_quadrilateral(lo_.ft) || inside_quadrilateral(hi_.ft))
      return sticking();
    // The metric's products taken with the larger of 1 and w divided out,
    // so that w·py·dt cannot overflow (w up to the largest value).
    const Real wf = w_ > 1 ? 1 / w_ : Real(1), wt = w_ > 1 ? Real(1) : w_;
    const Real norm = wf * df * df + wt * dt * dt;
    const Real along = norm > 0 ? (wf * px * df + wt * py * dt) / norm : Real(0);
    const Real lambda = along > 0 ? (std::min)(along, Real(1)) : Real(0);
    const Real ratio = lo_.eps == 0 ? Real(0) : hi_.eps == inf() ? inf() : sqrt(lo_.eps * hi_.eps);
    return on_curve(ratio, {lo_.ft.force + lambda * df, lo_.ft.torque + lambda * dt});
  }

  projection sticking() const { return {x_, y_, true, std::numeric_limits<Real>::quiet_NaN()}; }
  static projection on_curve(Real ratio, const force_torque_result<Real>& c) {
    return {c.force, c.torque, false, ratio, {ratio, c.force, c.torque}};
  }
  static projection on_sample(const sample& a, Real slope, Real curvature) {
    return {
        a.ft.force, a.ft.torque, false, a.eps, {a.eps, a.ft.force, a.ft.torque, slope, curvature}};
  }

  const Profile& profile_;
  Real x_, y_, w_, top_;
  sample lo_, hi_, previous_;  // the search's, set where it starts (not for a stick)
  Real reach_;
  Real slope_;      // 𝓕′ of the last Newton step (advance)
  Real curvature_;  // 𝓕″ of the last step if it was Halley's, else 0 (advance)
};
}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_LIMIT_PROJECTOR_HPP
