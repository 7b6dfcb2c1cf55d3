//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file motion/detail/stop_flow.hpp
/// The flow of the ratio along one leg of the integration to the stop
/// (docs/theory.md §9; motion/detail/stop_integrator.hpp): in the leg's variable
/// q = ln ε ("by spin") or ln(1/ε) ("by speed"), its rate dq/du = F(q), the
/// inverse 1/F that the panels integrate, with its rounding, and
/// G = 1/𝓣 or 1/𝓕, the time it takes per unit of e^{−u}.

#ifndef SPINSLIDE_MOTION_DETAIL_STOP_FLOW_HPP
#define SPINSLIDE_MOTION_DETAIL_STOP_FLOW_HPP

#include <spinslide/motion/detail/ratio_flow.hpp>

#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/tools/precision.hpp>

#include <cmath>
#include <limits>

namespace spinslide {
namespace detail {

/// The flow at one point of a leg.
template <class Real>
struct flow_point {
  double q = 0;                 ///< ln ε or ln(1/ε)
  double rate = 0;              ///< F = dq/du
  double inverse_rate = 0;      ///< 1/F = du/dq
  double log_inverse_rate = 0;  ///< ln|1/F| where X overflowed, else ∞ (log_inverse)
  double noise = 0;             ///< the relative rounding error of 1/F
  double g = 0;                 ///< G = 1/𝓣 or 1/𝓕
  flow_terms<Real> terms{0, 0, 0, 0};
};

/// ln|1/F|, also where 1/F underflows.
template <class Real>
double log_inverse(const flow_point<Real>& f) {
  return f.log_inverse_rate < std::numeric_limits<double>::infinity()
             ? f.log_inverse_rate
             : std::log(std::fabs(f.inverse_rate));
}

/// The flow in one leg's variable.  In u = −ln(L_now/L), with L the leading
/// motion (ω by spin, v by speed) where the leg starts:
///   by spin:  F = 1 − γ(𝓕/ε)/𝓣,  G = 1/𝓣;
///   by speed: F = 1 − (ε𝓣/𝓕)/γ,  G = 1/𝓕.
template <class Profile>
class leg_flow {
 public:
  using value_type = typename Profile::value_type;
  using Real = value_type;

  leg_flow(const Profile& p, Real inertia_ratio, bool by_speed)
      : p_(&p), gamma_(inertia_ratio), by_speed_(by_speed) {}

  bool by_speed() const { return by_speed_; }
  Real inertia_ratio() const { return gamma_; }

  /// q of the ratio ε in this variable.
  Real log_ratio(Real eps) const {
    BOOST_MATH_STD_USING
    return by_speed_ ? Real(-log(eps)) : Real(log(eps));
  }

  /// G from the profile's terms.
  Real g_of(const flow_terms<Real>& ft) const {
    return by_speed_ ? Real(1 / ft.force) : Real(1 / ft.torque);
  }

  /// G where q runs to −∞ (ε → 0 by spin, ε → ∞ by speed).
  double g_towards_minus_infinity() const {
    const Real eps = by_speed_ ? std::numeric_limits<Real>::infinity() : Real(0);
    return static_cast<double>(g_of(flow_terms_at(*p_, eps)));
  }

  /// The flow at q.
  flow_point<Real> at(double q) const {
    BOOST_MATH_STD_USING
    using boost::math::tools::max_value;
    // ε from q (the largest value where 1/ε̃ overflows: ∞ is pure sliding,
    // where a model may jump); detail::flow_terms_at supplies the limits.
    const Real r = exp(Real(by_speed_ ? -q : q));
    const Real eps = (boost::math::isinf)(r) ? max_value<Real>() : r;
    flow_point<Real> f;
    f.q = q;
    f.terms = flow_terms_at(*p_, eps);
    const flow_terms<Real>& ft = f.terms;
    // F = 1 − X with X = γ(𝓕/ε)/𝓣 or (ε𝓣/𝓕)/γ; and 1/F, which the panels
    // use, from 1/X where X overflows (for a huge γ or a tiny ratio the
    // ratio runs to 0 almost at once: found by fuzz_stop_time).
    const Real pull =
        by_speed_ ? Real(ft.ratio_torque / ft.force) : Real(ft.force_over_ratio / ft.torque);
    const Real x = by_speed_ ? Real(pull / gamma_) : Real(gamma_ * pull);
    f.rate = static_cast<double>(1 - x);
    // 1/F from logs where X overflows keeps its digits.
    f.noise = static_cast<double>(std::numeric_limits<Real>::epsilon());
    if (x <= max_value<Real>() / 4) {
      f.noise *= static_cast<double>(1 + x) / std::fabs(f.rate);
      f.inverse_rate = static_cast<double>(1 / (1 - x));
      f.log_inverse_rate = std::numeric_limits<double>::infinity();  // not needed (log_inverse)
    } else {
      const Real ln_inverse = log_inverse_of_large(q, ft);
      f.log_inverse_rate = static_cast<double>(ln_inverse);
      f.inverse_rate = -std::exp(f.log_inverse_rate);
    }
    f.g = static_cast<double>(g_of(ft));
    return f;
  }

 private:
  // ln(1/(X − 1)) for X > max/4, from ln(1/X) = ln 𝓣 − ln(𝓕/ε) − ln γ (by
  // spin) or ln γ + ln 𝓕 − ln(ε𝓣) (by speed), so that 1/F keeps its digits
  // where it underflows.  Where 𝓕/ε (or ε𝓣) overflowed or took an infinite
  // limit (⟨1/r⟩ or ⟨r²⟩ = ∞: the ratio collapses at once), it is 𝓕/ε with 𝓕
  // at ε, or at the smallest normal ratio where ε underflowed (ε𝓣 alike).
  Real log_inverse_of_large(double q, const flow_terms<Real>& ft) const {
    BOOST_MATH_STD_USING
    using boost::math::tools::max_value;
    using boost::math::tools::min_value;
    auto log_of = [](Real pair_term, Real single, double log_eps, Real at_edge) {
      if (pair_term > 0 && (boost::math::isfinite)(pair_term)) return Real(log(pair_term));
      return Real(log(single >= min_value<Real>() ? single : at_edge) + Real(log_eps));
    };
    const Real ln_g = log(gamma_);
    Real ln_inverse_x;
    if (by_speed_) {  // q = −ln ε
      const Real ln_rt =
          log_of(ft.ratio_torque, ft.torque, -q, p_->force_torque(max_value<Real>()).torque);
      ln_inverse_x = ln_g + log(ft.force) - ln_rt;
    } else {  // q = ln ε
      const Real ln_fr =
          log_of(ft.force_over_ratio, ft.force, -q, p_->force_torque(min_value<Real>()).force);
      ln_inverse_x = log(ft.torque) - ln_fr - ln_g;
    }
    return ln_inverse_x - log1p(-exp(ln_inverse_x));
  }

  const Profile* p_;
  Real gamma_;
  bool by_speed_;
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_DETAIL_STOP_FLOW_HPP
