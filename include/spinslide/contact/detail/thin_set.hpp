//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The impulse law on a thin set (impulse_frame's `point`: k = a/c below
// 16√κ ε_mach, where the 3-D projection in the slip's variables cannot
// resolve the answer), exactly, in the impulse's own variables
// (docs/theory.md §11, "A patch that starts at zero").
//
// The answer (P, L) and the slip after it, v⁺ = v + W_ff P + W_fω L and
// ω⁺ = ω + W_ωf·P + W_ωω L, satisfy the law at the end of the step: P =
// −μΛ𝓕(ε) v⁺/|v⁺|, L = −μΛa𝓣(ε) sign ω⁺, ε = |v⁺|/(a|ω⁺|).  For a trial
// ratio ε and the spin's sign σ̂ (below) take L = −σ̂μΛa𝓣(ε); then the P
// nearest the stopping one on the disk |P| ≤ μΛ𝓕(ε) in W_ff, for the slip
// v + W_fω L, is point friction's (point_friction.hpp): on the circle with
// v⁺ = −λP, λ ≥ 0, or inside it with v⁺ = 0.  What is left is one equation
// in ε,
//   h(ε) = |v⁺| − aε·σ̂ω⁺ = 0,
// whose every root is the law's answer: |v⁺| > 0 gives σ̂ω⁺ > 0 and all
// three conditions above; |v⁺| = 0 gives ω⁺ = 0 too, the stopping impulse
// inside the set (sticking).  The answer is unique (the energy is strictly
// convex, the set convex), so h has one root.  With σ̂ the sign of
// point friction's spin after the step, σ₀ = ω + W_ωf·P₀ (P₀ the answer at
// ε = ∞, L = 0), h(0) = |v⁺| ≥ 0 and h(ε) → −∞ as ε → ∞ (ω⁺ → σ₀): h
// changes sign, the root is bracketed, and TOMS 748 finds it.  (σ₀ = 0:
// the answer is ε = ∞ itself, P₀ and L = 0, the spin stopped.)
//
// Every quantity keeps its own scale: P is point friction's on a circle of
// radius μΛ𝓕(ε) (to a few ulp of μΛ), L is μΛa𝓣(ε) at a root ε (to a few
// ulp of μΛa⟨r⟩ where ε is; near the rim, ε ≈ k^(−1/3), the problem itself
// is conditioned worse: docs/theory.md), and |v⁺| is λ|P|, no cancellation.
// Where the slide goes on (|P₀| = μΛ) the root is near ε₀ = |v⁺₀|/(a|σ₀|)
// (within about κk); where it stops, near the ratio where 𝓕 = |P₀|/(μΛ).
#ifndef SPINSLIDE_CONTACT_DETAIL_THIN_SET_HPP
#define SPINSLIDE_CONTACT_DETAIL_THIN_SET_HPP

#include <spinslide/base/detail/product.hpp>
#include <spinslide/contact/detail/matrix3.hpp>
#include <spinslide/contact/detail/point_friction.hpp>
#include <spinslide/contact/planar_metric.hpp>
#include <spinslide/values/force_torque_result.hpp>

#include <boost/config.hpp>
#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/tools/precision.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace spinslide {
namespace detail {

// What the law is found from: W, the slip before the step and μΛ.
template <class Real>
struct law_inputs {
  const planar_metric<Real>& w;
  const vector3<Real>& slip;
  Real load;
};

// The impulse at one trial ratio (see the file's comment).
template <class Real>
struct thin_trial {
  Real ratio;                    // ε
  force_torque_result<Real> ft;  // 𝓕(ε), 𝓣(ε)
  point_impulse<Real> p;         // P, and |v⁺| (0: inside the disk)
  Real torque;                   // L = −σ̂μΛa𝓣(ε)
  Real spin;                     // ω⁺
  Real miss;                     // h(ε) = |v⁺| − aε·σ̂ω⁺
};

template <class Profile>
class thin_set {
  using Real = typename Profile::value_type;

 public:
  // a > 0 and μΛ > 0, finite; `sign` σ̂ = ±1.
  thin_set(const Profile& profile, const law_inputs<Real>& law, Real a, Real sign)
      : p_(profile), m_(law.w.entries()), s_(law.slip), load_(law.load), a_(a), sign_(sign) {}

  // (Out of line: a call site of the profile's values that the common
  // path's inlining does not see; inlined, it cost Boussinesq's float
  // projection 51 instructions, tools/path_instructions.py.)
  // A ratio that is not a number (from a bracket whose misses overflowed)
  // is not evaluated: its miss is NaN, which ends the search.
  BOOST_NOINLINE thin_trial<Real> at(Real eps) const {
    thin_trial<Real> t{};
    t.ratio = eps;
    if (!(eps >= 0)) return unresolved(t);
    t.ft = p_.force_torque(eps);
    t.torque = -sign_ * product(load_, a_, t.ft.torque);
    const Real vx = s_[0] + m_[0][2] * t.torque, vy = s_[1] + m_[1][2] * t.torque;
    const Real bound = load_ * t.ft.force;
    t.p = bound > 0 ? point_friction(m_, vx, vy, bound)
                    : point_impulse<Real>{{Real(0), Real(0)}, length(vx, vy)};
    t.spin = s_[2] + m_[2][0] * t.p.force[0] + m_[2][1] * t.p.force[1] + m_[2][2] * t.torque;
    t.miss = t.p.slip - a_ * eps * (sign_ * t.spin);
    return t;
  }

  // The root of h from `guess` (> 0): a bracket grown by factors of 2 from
  // there, then TOMS 748 to the type's precision.  The answer at the root;
  // where h keeps its sign up to the largest ratio (the spin all but
  // stopped) or down to the smallest (the slide all but stopped), the
  // answer at that end.  A miss that is not a number (an overflow of an
  // extreme input) ends the search: the caller checks the answer.
  thin_trial<Real> solve(Real guess) const {
    using boost::math::tools::max_value;
    using boost::math::tools::min_value;
    thin_trial<Real> lo = at(guess), hi = lo;
    if (lo.miss > 0) {
      while (hi.miss > 0 && hi.ratio < max_value<Real>() / 4) {
        lo = hi;
        hi = at(2 * hi.ratio);
      }
      if (!(hi.miss < 0)) return hi;  // 0: the root; > 0: the spin all but stopped
    } else {
      while (lo.miss < 0 && lo.ratio > min_value<Real>() * 4) {
        hi = lo;
        lo = at(lo.ratio / 2);
      }
      if (!(lo.miss > 0)) return lo;  // 0: the root; < 0: the slide all but stopped
    }
    // TOMS 748 interpolates between the ends' misses: both must be numbers
    // (an extreme input's misses overflow; fuzz_impulse found a NaN ratio
    // reaching the profile, which refused it).
    if (!((boost::math::isfinite)(lo.miss) && (boost::math::isfinite)(hi.miss)))
      return unresolved(lo);
    auto miss = [this](Real e) {
      const Real h = at(e).miss;
      return h == h ? h : Real(0);  // not a number: end here
    };
    std::uintmax_t steps = max_steps;
    const auto r = boost::math::tools::toms748_solve(
        miss, lo.ratio, hi.ratio, lo.miss, hi.miss,
        boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 1), steps);
    return at((r.first + r.second) / 2);
  }

 private:
  // `t` marked as no answer (its miss NaN: the caller's answer is then point
  // friction's, the limit's guaranteed one).
  static thin_trial<Real> unresolved(thin_trial<Real> t) {
    t.miss = std::numeric_limits<Real>::quiet_NaN();
    return t;
  }

  static constexpr std::uintmax_t max_steps = 4 * std::numeric_limits<Real>::digits;

  const Profile& p_;
  const matrix3<Real>& m_;
  const vector3<Real>& s_;
  Real load_, a_, sign_;
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_THIN_SET_HPP
