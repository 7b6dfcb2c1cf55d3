//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file motion/detail/stop_leg.hpp
/// One leg of the integration to the stop (docs/theory.md §9;
/// motion/detail/stop_integrator.hpp): the stretch of the motion integrated in one
/// variable, its path q(s), its scales, and the motion at a point of it.
///
/// In the leg's variable (motion/detail/stop_flow.hpp), with L the leading motion and
/// M the other one where the leg starts, and t₀, s₀, θ₀ the motion before it:
///   by spin:  t = t₀ + γL t̂,  s = s₀ + γLM ŝ_o,  θ = θ₀ + γL² ŝ_l;
///   by speed: t = t₀ + L t̂,   s = s₀ + L² ŝ_l,   θ = θ₀ + LM ŝ_o;
/// with t̂ = ∫e^{−u}G du, ŝ_l = ∫e^{−2u}G du (the leading motion's own travel)
/// and ŝ_o = ∫ρe^{−2u}G du (the other motion's), ρ = e^{q − q_start}.

#ifndef SPINSLIDE_MOTION_DETAIL_STOP_LEG_HPP
#define SPINSLIDE_MOTION_DETAIL_STOP_LEG_HPP

#include <spinslide/base/detail/product.hpp>
#include <spinslide/motion/detail/stop_flow.hpp>
#include <spinslide/motion/motion_types.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace spinslide {
namespace detail {

/// Where a leg starts: its variable, q, the two motions, and the motion so far.
template <class Real>
struct leg_start {
  bool by_speed = false;
  double q = 0;       ///< ln ε (by spin) or ln(1/ε) (by speed)
  Real lead = 0;      ///< L: ω by spin, v by speed
  Real other = 0;     ///< M: the other motion
  Real time = 0;      ///< t₀
  Real distance = 0;  ///< s₀
  Real angle = 0;     ///< θ₀
};

/// The scaled integrals at a point of a leg.
struct leg_position {
  double s = 0;             ///< the path's parameter (leg_path)
  double u = 0;             ///< −ln(L_now/L)
  double time = 0;          ///< t̂ = ∫e^{−u}G
  double lead_travel = 0;   ///< ŝ_l = ∫e^{−2u}G
  double other_travel = 0;  ///< ŝ_o = ∫ρe^{−2u}G, in units of e^{rho_log} (stop_leg)
};

/// The path of q along a leg in a parameter s that keeps the panels regular:
/// q∞ + Δe^{−s} towards a finite zero q∞ of F (the log makes the approach to
/// the zero regular), q_start ± s towards ±∞.  q is monotone along a leg.
struct leg_path {
  static constexpr double inf = std::numeric_limits<double>::infinity();

  double q_start = 0;
  double q_target = 0;  ///< the zero ahead, or ±∞
  double delta = 0;     ///< q_start − q_target towards a finite zero, else 0
  int direction = 0;    ///< the sign of F at the start; 0 at a zero of the flow
  bool finite_target = false;

  /// The path from `first`, the flow where the leg starts, given q of the
  /// terminal ratio in this variable (±∞ for ε₀ = 0 or ∞).
  template <class Real>
  static leg_path from(const flow_point<Real>& first, double q_terminal) {
    leg_path path;
    path.q_start = first.q;
    path.direction = first.rate > 0 ? 1 : first.rate < 0 ? -1 : 0;
    // A start within rounding of the terminal ratio is at the zero: ε stays
    // (F there is noise, and a path of length 0 has no parameter).  Both are
    // logs taken in Real and rounded to double.
    const double rounding = (std::max)(std::numeric_limits<double>::epsilon(),
                                       static_cast<double>(std::numeric_limits<Real>::epsilon()));
    if (std::fabs(first.q - q_terminal) <= 4 * rounding * (1 + std::fabs(first.q)))
      path.direction = 0;
    path.finite_target = std::isfinite(q_terminal) && path.direction * (q_terminal - first.q) > 0;
    path.q_target = path.finite_target ? q_terminal : path.direction >= 0 ? inf : -inf;
    path.delta = path.finite_target ? first.q - path.q_target : 0;
    return path;
  }

  double q_of(double s) const {
    return finite_target ? q_target + delta * std::exp(-s) : q_start + direction * s;
  }
  double dq_ds(double s) const { return finite_target ? -delta * std::exp(-s) : direction; }

  /// s where the path reaches q, if q lies ahead of the start and before the
  /// target; else ∞.
  double s_ahead(double q) const {
    const bool ahead =
        direction * (q - q_start) > 0 && (!finite_target || direction * (q_target - q) > 0);
    if (!ahead) return inf;
    return finite_target ? std::log(delta / (q - q_target)) : direction * (q - q_start);
  }

  /// s where the path is at q (after a panel in u); `otherwise` where q is
  /// at or past the zero.
  double s_of(double q, double otherwise) const {
    if (!finite_target) return direction * (q - q_start);
    const double x = (q - q_target) / delta;
    return x > 0 ? -std::log(x) : otherwise;
  }
};

/// One leg: the flow in its variable, its path, its scales, and the motion
/// at a point of it.
template <class Profile>
class stop_leg {
 public:
  using value_type = typename Profile::value_type;
  using Real = value_type;
  static constexpr double inf = std::numeric_limits<double>::infinity();

  /// The leg from `start`; `terminal_ratio` is ε where the motion ends.
  stop_leg(const Profile& p, Real inertia_ratio, const leg_start<Real>& start, Real terminal_ratio)
      : flow_(p, inertia_ratio, start.by_speed), start_(start) {
    first_ = flow_.at(start.q);
    path_ = leg_path::from(first_, terminal_q(terminal_ratio));
    g_target_ = inf;
    if (path_.direction == 0 || path_.finite_target) {
      g_target_ = path_.direction == 0 ? first_.g : flow_.at(path_.q_target).g;
    } else if (path_.direction < 0) {
      g_target_ = flow_.g_towards_minus_infinity();
    }
    // ∫ρe^{−2u}G in units of e^{rho_log}, where its start would underflow
    // (a ratio that collapses at once: 1/F below 1e-261).
    const double log_start = std::log(first_.g) + log_inverse(first_);
    rho_log_ = log_start < -600 ? log_start : 0;
    rho_unit_ = static_cast<Real>(std::exp(rho_log_ / 4));
  }

  bool by_speed() const { return flow_.by_speed(); }
  const leg_path& path() const { return path_; }
  const leg_start<Real>& start() const { return start_; }
  Real inertia_ratio() const { return flow_.inertia_ratio(); }
  /// The flow where the leg starts.
  const flow_point<Real>& first() const { return first_; }
  /// The flow at q.
  flow_point<Real> at(double q) const { return flow_.at(q); }
  /// G where the path ends: at the zero ahead (or at the start, if it is
  /// one), where q runs to −∞; ∞ towards q = +∞.
  double g_target() const { return g_target_; }
  /// ŝ_o is in units of e^{rho_log}.
  double rho_log() const { return rho_log_; }

  /// The first panel's width: about two units of u.
  double first_width() const {
    const double h = 2 / (std::max)(std::fabs(path_.dq_ds(0) * first_.inverse_rate), 0.25);
    return h > 0 && std::isfinite(h) ? h : 1;
  }

  /// ρe^{−2u}G·e^{log_factor} in units of e^{rho_log}, taken as one
  /// exponential (ρ alone may overflow, and in a collapse the factor underflows).
  double rho_integrand(double q, double u, double g, double log_factor = 0) const {
    return std::exp(q - path_.q_start - 2 * u - rho_log_ + log_factor) * g;
  }

  /// ∫ρe^{−2u}G from `here` (at u) if F stayed as it is: ρe^{−2u}G/(2 − F)
  /// (F ≤ 1; 2 − F = 1 + X, whose log is −ln|1/F| where X overflowed).
  double rest_at_rate(const flow_point<Real>& here, double u) const {
    const double two_minus = 2 - here.rate;
    const double log_two_minus =
        std::isfinite(two_minus) ? std::log(two_minus) : -log_inverse(here);
    return rho_integrand(here.q, u, here.g, -log_two_minus);
  }

  /// t from t̂, a product taken without spurious over- or underflow (γ, L
  /// and M may each be near the ends of the type).
  Real time_of(double t_hat) const {
    const Real unit = by_speed() ? Real(1) : inertia_ratio();
    return start_.time + detail::product(unit, start_.lead, Real(t_hat));
  }

  /// The motion at q and `at`.
  motion_sample<Real> sample_at(double q, const leg_position& at) const {
    BOOST_MATH_STD_USING
    const Real leading = detail::product(start_.lead, Real(exp(-Real(at.u))));
    const Real following =
        detail::product(start_.other, Real(exp(Real(q - path_.q_start) - Real(at.u))));
    const Real r = exp(Real(q));
    motion_sample<Real> m;
    m.time = time_of(at.time);
    m.distance = distance_of(at);
    m.angle = angle_of(at);
    m.spin = by_speed() ? following : leading;
    m.speed = by_speed() ? leading : following;
    m.ratio = by_speed() ? (r > 0 ? Real(1 / r) : std::numeric_limits<Real>::infinity()) : r;
    return m;
  }

 private:
  // q of the terminal ratio in this variable (±∞ for ε₀ = 0 or ∞).
  double terminal_q(Real eps) const {
    return eps > 0 && eps < std::numeric_limits<Real>::infinity()
               ? static_cast<double>(flow_.log_ratio(eps))
           : (eps == 0) != by_speed() ? -inf
                                      : inf;
  }

  Real distance_of(const leg_position& at) const {
    const Real lead = start_.lead, other = start_.other;
    return start_.distance +
           (by_speed() ? detail::product(lead, lead, Real(at.lead_travel))
                       : detail::product(inertia_ratio(), lead, other, Real(at.other_travel),
                                         rho_unit_, rho_unit_, rho_unit_, rho_unit_));
  }
  Real angle_of(const leg_position& at) const {
    const Real lead = start_.lead, other = start_.other;
    return start_.angle +
           (by_speed() ? detail::product(lead, other, Real(at.other_travel), rho_unit_, rho_unit_,
                                         rho_unit_, rho_unit_)
                       : detail::product(inertia_ratio(), lead, lead, Real(at.lead_travel)));
  }

  leg_flow<Profile> flow_;
  leg_start<Real> start_;
  flow_point<Real> first_{};
  leg_path path_{};
  double g_target_ = inf;
  double rho_log_ = 0;  // ŝ_o is in units of e^{rho_log}
  Real rho_unit_ = 1;   // e^{rho_log/4}
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_DETAIL_STOP_LEG_HPP
