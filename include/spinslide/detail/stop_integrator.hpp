//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file detail/stop_integrator.hpp
/// The integration of a throw through its stop (docs/theory.md §9): the
/// motion is a one-dimensional autonomous flow of the ratio, so the time,
/// distance and angle are nested integrals over the log of the ratio, taken
/// with Gauss–Legendre panels up to where the rest of the motion is known in
/// closed form.  The types it returns are in motion_types.hpp.

#ifndef SPINSLIDE_DETAIL_STOP_INTEGRATOR_HPP
#define SPINSLIDE_DETAIL_STOP_INTEGRATOR_HPP

#include <spinslide/detail/checks.hpp>
#include <spinslide/detail/gauss_panel.hpp>
#include <spinslide/detail/product.hpp>
#include <spinslide/detail/singular_ratios.hpp>
#include <spinslide/motion_types.hpp>
#include <spinslide/terminal.hpp>

#include <boost/math/policies/error_handling.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace spinslide {
namespace detail {

/// What an integration to the stop is asked for besides the stop itself.
template <class Real>
struct stop_request {
  const char* function;                        ///< the entry point, named in errors
  const std::vector<Real>& times;              ///< sample times (sorted; may be empty)
  std::vector<motion_sample<Real>>& at_times;  ///< the samples at `times`
};

/// The limits of one integration: panels (accepted or not) before
/// evaluation_error, and the error allowed per panel relative to the totals.
struct stop_limits {
  int max_panels = 20000;
  double tolerance = 1e-12;
};

// One throw integrated to its stop.  In the variable of a leg, u = −ln(L_now/L)
// with L the leading motion (ω "by spin", v "by speed") where the leg starts,
// q = ln ε (by spin) or ln(1/ε) (by speed), and the flow dq/du = F(q):
//   by spin:  F = 1 − γ(𝓕/ε)/𝓣,  t = γL t̂, s = γLM ŝ, θ = γL² θ̂, G = 1/𝓣;
//   by speed: F = 1 − (ε𝓣/𝓕)/γ,  t = L t̂,  s = L² ŝ,  θ = LM θ̂,  G = 1/𝓕;
// t̂′ = e^{−u}G, and ŝ′, θ̂′ = e^{−2u}G times ρ = e^{q − q_start} for the other
// motion's distance or angle.  q is monotone, so u, t̂, ŝ and θ̂ are nested
// integrals over a parameter s of the path q(s): q∞ + Δe^{−s} towards a finite
// zero q∞ of F (the log makes the approach to the zero regular), q_start ± s
// towards ±∞.  Panels break at the profile's singular ratios (ε = 1, and
// ε = b for an annulus: 𝓕″ and 𝓣″ are log-singular there, the panels beside
// them are graded; detail/singular_ratios.hpp) and at ε = 10⁸, where the leg hands over to the
// other variable.  The rest after the last panel is in closed form where G
// tends to a finite limit (G is monotone along the path, so the rest lies
// between e^{−u}G and e^{−u}G∞); towards ε = ∞ in the variable, a bound on the
// remaining motion decides (the other motion stops first).
template <class Profile, class Observer>
class stop_integrator {
 public:
  using Real = typename Profile::value_type;

  stop_integrator(const Profile& p, const throw_input<Real>& in, Observer observe,
                  stop_request<Real> request, stop_limits limits = {})
      : p_(p), in_(in), observe_(observe), request_(request), limits_(limits) {
    // The right-hand side is evaluated in Real: for float its rounding sets the floor.
    limits_.tolerance = (std::max)(limits_.tolerance,
                                   10 * static_cast<double>(std::numeric_limits<Real>::epsilon()));
    BOOST_MATH_STD_USING
    const ratio_list<Real> edges = singular_ratios(p);
    for (std::size_t i = 0; i < edges.size(); ++i)
      log_edges_[i] = static_cast<double>(Real(log(edges[i])));
    edges_ = edges.size();
  }

  stop_result<Real> run() {
    if (in_.v0 == 0 || in_.omega0 == 0) return uniform_motion();
    out_.terminal = terminal_motion(p_, in_.gamma, clamped_quotient());
    start_first_leg();
    for (int panels = 0; panels < limits_.max_panels; ++panels) {
      if (advance()) return out_;
    }
    out_.time = boost::math::policies::raise_evaluation_error<Real>(
        request_.function, "No stop found after %1% panels.", Real(limits_.max_panels),
        typename Profile::policy_type());
    return out_;
  }

 private:
  using rule = gauss_panel<20>;
  using values = rule::values;
  static constexpr std::size_t n_nodes = rule::size;

  // The flow at one point of the path.
  struct flow_point {
    double q = 0;                 // ln ε or ln(1/ε)
    double rate = 0;              // F = dq/du
    double inverse_rate = 0;      // 1/F = du/dq
    double log_inverse_rate = 0;  // ln|1/F| where X overflowed, else ∞ (log_inverse)
    double noise = 0;             // the relative rounding error of 1/F
    double g = 0;                 // G = 1/𝓣 or 1/𝓕
    flow_terms<Real> terms{0, 0, 0, 0};
  };

  // Where the integration stands: the parameter s and the integrals there.
  // plain2 = ∫e^{−2u}G and rho2 = ∫ρe^{−2u}G: ŝ and θ̂ by the variable.
  struct position {
    double s = 0, u = 0, t = 0, plain2 = 0, rho2 = 0;
  };

  // One panel [s, s + h] of the path: the integrands at its nodes (per unit
  // of the panel's x ∈ [−1, 1]), u at the nodes, and its error estimate.
  // A panel is in s, or in u where the flow is slow (there 1/F carries the
  // rounding of F, a difference of O(1) terms, and the ratio hardly moves);
  // then q at its nodes comes from the collocation q = q_a + ∫F du (Picard
  // iteration, which converges at once where F and F′ are small) and dq
  // holds F per unit x.
  struct panel {
    double s = 0, h = 0;
    bool grade_end = false, grade_start = false, in_u = false;
    values du, dt, e2, e2_rho, dq;  // every node set by make_panel(_in_u)
    double q_end = 0, err = 0;
  };

  // ------------------------------------------------------------ the phases

  // Pure sliding, pure spinning or rest decelerate uniformly: exact.
  stop_result<Real> uniform_motion() {
    if (in_.v0 == 0 && in_.omega0 == 0) {
      out_.terminal = {terminal_regime::pure_spinning, Real(0)};
      return uniform(0, 0, 0);
    }
    if (in_.omega0 == 0) {  // pure sliding: 𝓕(∞) = 1, v = v0 − t
      out_.time = in_.v0;
      out_.terminal = {terminal_regime::pure_sliding, std::numeric_limits<Real>::infinity()};
      return uniform(1, 0, out_.terminal.ratio);
    }
    // pure spinning: 𝓣(0) = ⟨r⟩, ω = ω0 − ⟨r⟩t/γ.  (γω0)/⟨r⟩, not ω0/rate:
    // ⟨r⟩/γ overflows for a subnormal γ; and where γω0 leaves the normal
    // range, a product without spurious over- or underflow (a subnormal
    // ω0/⟨r⟩ rounded away 20%; found by fuzz_stop_time).
    using boost::math::tools::max_value;
    using boost::math::tools::min_value;
    const Real gw = in_.gamma * in_.omega0;
    out_.time = gw >= min_value<Real>() && gw <= max_value<Real>()
                    ? Real(gw / p_.mean_radius())
                    : detail::product(in_.gamma, in_.omega0, Real(1 / p_.mean_radius()));
    out_.terminal = {terminal_regime::pure_spinning, Real(0)};
    return uniform(0, p_.mean_radius() / in_.gamma, 0);
  }

  // The motion at time t of a uniform deceleration (a_v, a_w) that stops at out_.time.
  motion_sample<Real> uniform_at(Real t, Real a_v, Real a_w, Real ratio) const {
    const Real v0 = in_.v0, w0 = in_.omega0;
    const bool moving = t < out_.time;
    const Real te = moving ? t : out_.time;
    // The speeds lost by te; at the stop exactly v0 and ω0 (a ∞ · 0 there
    // otherwise, for a subnormal γ).  te (v0 − Δv/2), not v0 te − a te²/2,
    // which is ∞ − ∞ at the largest speeds (both found by fuzz_stop_time).
    const Real dv = moving ? Real(a_v * te) : v0, dw = moving ? Real(a_w * te) : w0;
    const Real v = v0 - dv, w = w0 - dw;
    // The mean speed times te; 0 for a speed that stays 0, even where te overflows.
    auto travelled = [te](Real x0, Real dx) {
      const Real mean = x0 - dx / 2;
      return mean == 0 ? Real(0) : Real(te * mean);
    };
    return {t,     v > 0 ? v : Real(0), w > 0 ? w : Real(0),
            ratio, travelled(v0, dv),   travelled(w0, dw)};
  }

  stop_result<Real> uniform(Real a_v, Real a_w, Real ratio) {
    observe_(uniform_at(0, a_v, a_w, ratio));
    const motion_sample<Real> end = uniform_at(out_.time, a_v, a_w, ratio);
    observe_(end);
    for (const Real& t : request_.times)
      request_.at_times.push_back(uniform_at(t, a_v, a_w, ratio));
    out_.distance = end.distance;
    out_.angle = end.angle;
    return out_;
  }

  // ε0 = v0/ω0 for terminal_motion, kept finite and > 0 where the quotient
  // over- or underflows (only its side of the flow's zeros matters there).
  Real clamped_quotient() const {
    using boost::math::tools::max_value;
    using boost::math::tools::min_value;
    const Real quotient = in_.v0 / in_.omega0;
    return quotient > max_value<Real>() ? max_value<Real>()
           : quotient > 0               ? quotient
                                        : min_value<Real>();
  }

  // ------------------------------------------------------------ the legs

  void start_first_leg() {
    BOOST_MATH_STD_USING
    using boost::math::tools::max_value;
    using boost::math::tools::min_value;
    const Real quotient = in_.v0 / in_.omega0;
    // ln ε0 from the quotient where it is a normal number, else ln v0 − ln ω0.
    const double q =
        static_cast<double>(quotient >= min_value<Real>() && quotient <= max_value<Real>()
                                ? Real(log(quotient))
                                : Real(log(in_.v0) - log(in_.omega0)));
    // The leg starts in the variable of the terminal regime's dominant motion,
    // or in the other where its ratio would be above 10⁸.
    bool by_speed = out_.terminal.regime == terminal_regime::pure_sliding;
    double qs = by_speed ? -q : q;
    if (qs > q_flip) {
      by_speed = !by_speed;
      qs = -qs;
    }
    start_leg(by_speed, qs, by_speed ? in_.v0 : in_.omega0, by_speed ? in_.omega0 : in_.v0);
    observe_(sample_here());
  }

  void start_leg(bool by_speed, double q_start, Real lead, Real other) {
    by_speed_ = by_speed;
    lead_ = lead;
    other_ = other;
    q_start_ = q_start;
    at_ = position{};
    here_ = flow_at_q(q_start);
    // A start within rounding of the terminal ratio is at the zero: ε stays
    // (F there is noise, and a path of length 0 has no parameter).
    direction_ = here_.rate > 0 ? 1 : here_.rate < 0 ? -1 : 0;
    if (std::fabs(q_start - terminal_q()) <= 4 * 2.2e-16 * (1 + std::fabs(q_start))) direction_ = 0;
    set_target();
    set_breakpoints();
    // ∫ρe^{−2u}G in units of e^{rho_log}, where its start would underflow
    // (a ratio that collapses at once: 1/F below 1e-261).
    const double log_start = std::log(here_.g) + log_inverse(here_);
    rho_log_ = log_start < -600 ? log_start : 0;
    rho_unit_ = static_cast<Real>(std::exp(rho_log_ / 4));
    h_ = 2 / (std::max)(std::fabs(dq_ds(0) * here_.inverse_rate), 0.25);
    if (!(h_ > 0) || !std::isfinite(h_)) h_ = 1;
  }

  // The limit of q along the leg: the terminal ratio in this variable where it
  // lies ahead, else ±∞; and G there.
  // The terminal ratio as q in this variable (±∞ for ε₀ = 0 or ∞).
  double terminal_q() const {
    const Real eps = out_.terminal.ratio;
    return eps > 0 && eps < std::numeric_limits<Real>::infinity()
               ? static_cast<double>(log_ratio(eps))
           : (eps == 0) != by_speed_ ? -inf
                                     : inf;
  }

  void set_target() {
    const double q_inf = terminal_q();
    finite_target_ = std::isfinite(q_inf) && direction_ * (q_inf - q_start_) > 0;
    q_target_ = finite_target_ ? q_inf : direction_ >= 0 ? inf : -inf;
    delta_ = finite_target_ ? q_start_ - q_target_ : 0;
    g_target_ = inf;
    if (direction_ == 0 || finite_target_) {
      g_target_ = direction_ == 0 ? here_.g : flow_at_q(q_target_).g;
    } else if (direction_ < 0) {
      g_target_ = static_cast<double>(g_of(flow_terms_at(p_, by_speed_ ? inf_real() : Real(0))));
    }
  }

  // The breakpoints of the leg: the profile's singular ratios (panels beside
  // them graded) and the switch of variable at ε = 10⁸.
  void set_breakpoints() {
    s_flip_ = direction_ > 0 && !finite_target_ ? s_at(q_flip) : inf;
    grade_next_start_ = false;
    for (std::size_t i = 0; i < edges_; ++i) grade_next_start_ |= q_start_ == edge_q(i);
    find_next_edge();
  }

  // q of the i-th singular ratio in the leg's variable.
  double edge_q(std::size_t i) const { return by_speed_ ? -log_edges_[i] : log_edges_[i]; }

  // s where the path reaches q, if it lies ahead of the start and before the
  // target; else ∞.
  double s_at(double q) const {
    const bool ahead =
        direction_ * (q - q_start_) > 0 && (!finite_target_ || direction_ * (q_target_ - q) > 0);
    if (!ahead) return inf;
    return finite_target_ ? std::log(delta_ / (q - q_target_)) : direction_ * (q - q_start_);
  }

  // The next singular ratio ahead of the position: s_edge_ and q_edge_.
  void find_next_edge() {
    s_edge_ = inf;
    for (std::size_t i = 0; i < edges_; ++i) {
      const double s = s_at(edge_q(i));
      if (s > at_.s && s < s_edge_) {
        s_edge_ = s;
        q_edge_ = edge_q(i);
      }
    }
  }

  // ------------------------------------------------------------ the flow

  Real log_ratio(Real eps) const {
    BOOST_MATH_STD_USING
    return by_speed_ ? Real(-log(eps)) : Real(log(eps));
  }

  static Real inf_real() { return std::numeric_limits<Real>::infinity(); }

  Real g_of(const flow_terms<Real>& ft) const {
    return by_speed_ ? Real(1 / ft.force) : Real(1 / ft.torque);
  }

  flow_point flow_at_q(double q) const {
    BOOST_MATH_STD_USING
    using boost::math::tools::max_value;
    // ε from q (the largest value where 1/ε̃ overflows: ∞ is pure sliding,
    // where a model may jump); detail::flow_terms_at supplies the limits.
    const Real r = exp(Real(by_speed_ ? -q : q));
    const Real eps = (boost::math::isinf)(r) ? max_value<Real>() : r;
    flow_point f;
    f.q = q;
    f.terms = flow_terms_at(p_, eps);
    const flow_terms<Real>& ft = f.terms;
    // F = 1 − X with X = γ(𝓕/ε)/𝓣 or (ε𝓣/𝓕)/γ; and 1/F, which the panels
    // use, from 1/X where X overflows (for a huge γ or a tiny ratio the
    // ratio runs to 0 almost at once: found by fuzz_stop_time).
    const Real pull =
        by_speed_ ? Real(ft.ratio_torque / ft.force) : Real(ft.force_over_ratio / ft.torque);
    const Real x = by_speed_ ? Real(pull / in_.gamma) : Real(in_.gamma * pull);
    f.rate = static_cast<double>(1 - x);
    // 1/F from logs where X overflows keeps its digits.
    f.noise = static_cast<double>(std::numeric_limits<Real>::epsilon());
    if (x <= max_value<Real>() / 4) {
      f.noise *= static_cast<double>(1 + x) / std::fabs(f.rate);
      f.inverse_rate = static_cast<double>(1 / (1 - x));
      f.log_inverse_rate = inf;  // not needed unless asked for (log_inverse)
    } else {
      const Real ln_inverse = log_inverse_of_large(q, ft);
      f.log_inverse_rate = static_cast<double>(ln_inverse);
      f.inverse_rate = -std::exp(f.log_inverse_rate);
    }
    f.g = static_cast<double>(g_of(ft));
    return f;
  }

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
    const Real ln_g = log(in_.gamma);
    Real ln_inverse_x;
    if (by_speed_) {  // q = −ln ε
      const Real ln_rt =
          log_of(ft.ratio_torque, ft.torque, -q, p_.force_torque(max_value<Real>()).torque);
      ln_inverse_x = ln_g + log(ft.force) - ln_rt;
    } else {  // q = ln ε
      const Real ln_fr =
          log_of(ft.force_over_ratio, ft.force, -q, p_.force_torque(min_value<Real>()).force);
      ln_inverse_x = log(ft.torque) - ln_fr - ln_g;
    }
    return ln_inverse_x - log1p(-exp(ln_inverse_x));
  }

  // ln|1/F|, also where 1/F underflows.
  static double log_inverse(const flow_point& f) {
    return f.log_inverse_rate < inf ? f.log_inverse_rate : std::log(std::fabs(f.inverse_rate));
  }

  double q_of(double s) const {
    return finite_target_ ? q_target_ + delta_ * std::exp(-s) : q_start_ + direction_ * s;
  }
  double dq_ds(double s) const { return finite_target_ ? -delta_ * std::exp(-s) : direction_; }

  // ------------------------------------------------------------ the panels

  // The panel [s, s + h], its nodes graded towards a singular end (a cubic
  // map: the log singularity at a singular ratio becomes (1 − τ)⁶ log(1 − τ)).
  panel make_panel(double s, double h, bool grade_start, bool grade_end) const {
    const rule& r = rule::rule();
    panel pn;
    pn.s = s;
    pn.h = h;
    pn.grade_start = grade_start;
    pn.grade_end = grade_end;
    values g, q, log_du;
    for (std::size_t j = 0; j < n_nodes; ++j) {
      const double sj = s + h * grading(pn, (1 + r.node(j)) / 2);
      const double e = finite_target_ ? delta_ * std::exp(-sj) : 0;  // q − q∞
      const flow_point f = flow_at_q(finite_target_ ? q_target_ + e : q_of(sj));
      const double slope = finite_target_ ? -e : dq_ds(sj);
      double du = slope * f.inverse_rate * h * grading_slope(pn, (1 + r.node(j)) / 2) / 2;
      if (!(du >= 0) || !std::isfinite(du)) du = 0;  // at the zero itself, to rounding
      pn.du[j] = du;
      g[j] = f.g;
      q[j] = f.q;
      // ln|du| where du may underflow (the ratio collapses at once).
      if (rho_log_ != 0)
        log_du[j] = std::log(std::fabs(slope) * h * grading_slope(pn, (1 + r.node(j)) / 2) / 2) +
                    log_inverse(f);
    }
    const values u_rel = r.integrals_to_nodes(pn.du);
    integrate_panel(pn, u_rel, g, q);
    if (rho_log_ != 0) {
      for (std::size_t j = 0; j < n_nodes; ++j)
        pn.e2_rho[j] = rho_integrand(q[j], at_.u + u_rel[j], g[j], log_du[j]);
      pn.err = panel_error(pn);
    }
    pn.q_end = q_of(s + h);
    return pn;
  }

  panel make_panel_in_u(double h) const {
    const rule& r = rule::rule();
    panel pn;
    pn.s = at_.s;
    pn.h = h;
    pn.in_u = true;
    values q{}, g{}, u_rel{};
    // The first guess: exact for a linear flow towards the zero q∞
    // (q − q∞ ∝ e^{−λu}), else Euler's.
    const double x = here_.q - q_target_, lam = finite_target_ ? -here_.rate / x : 0;
    for (std::size_t j = 0; j < n_nodes; ++j) {
      u_rel[j] = h * (1 + r.node(j)) / 2;
      q[j] = lam > 0 && std::isfinite(lam) ? q_target_ + x * std::exp(-lam * u_rel[j])
                                           : here_.q + here_.rate * u_rel[j];
      pn.du[j] = h / 2;
    }
    // q is settled when its change moves the rest of the motion by a tenth
    // of the tolerance (G changes like q: d ln G/dq is O(1)).
    const double rest_t = std::exp(-at_.u) * here_.g;
    const double settled = (std::max)(1e-15 * (1 + std::fabs(here_.q)),
                                      limits_.tolerance / 10 * (at_.t + rest_t) / rest_t);
    double change = inf;
    for (int it = 0; it < 8 && !(change <= settled); ++it) {
      for (std::size_t j = 0; j < n_nodes; ++j) {
        const flow_point f = flow_at_q(q[j]);
        pn.dq[j] = f.rate * h / 2;
        g[j] = f.g;
      }
      const values dq = r.integrals_to_nodes(pn.dq);
      change = 0;
      for (std::size_t j = 0; j < n_nodes; ++j) {
        const double qn = here_.q + dq[j];
        change = (std::max)(change, std::fabs(qn - q[j]));
        q[j] = qn;
      }
    }
    integrate_panel(pn, u_rel, g, q);
    pn.q_end = here_.q + r.integral(pn.dq);
    if (!(change <= settled)) pn.err = inf;
    return pn;
  }

  // The integrands at the nodes from u (relative to the panel's start), G and q.
  void integrate_panel(panel& pn, const values& u_rel, const values& g, const values& q) const {
    for (std::size_t j = 0; j < n_nodes; ++j) {
      const double decay = std::exp(-(at_.u + u_rel[j]));
      pn.dt[j] = decay * g[j] * pn.du[j];
      pn.e2[j] = pn.dt[j] * decay;
      pn.e2_rho[j] = rho_integrand(q[j], at_.u + u_rel[j], g[j]) * pn.du[j];
    }
    pn.err = panel_error(pn);
  }

  // s where the path is at q (after a panel in u).
  double s_of(double q) const {
    if (!finite_target_) return direction_ * (q - q_start_);
    const double x = (q - q_target_) / delta_;
    return x > 0 ? -std::log(x) : at_.s;
  }

  // s − s_panel in units of h at τ ∈ [0, 1], and its derivative: cubic
  // towards one singular end, and 10τ³ − 15τ⁴ + 6τ⁵ (flat to third order at
  // both) for a panel between two singular ratios.
  static double grading(const panel& pn, double tau) {
    if (pn.grade_end && pn.grade_start) return tau * tau * tau * (10 - tau * (15 - 6 * tau));
    if (!pn.grade_end && !pn.grade_start) return tau;
    const double o = pn.grade_end ? 1 - tau : tau;
    return pn.grade_end ? 1 - o * o * o : o * o * o;
  }
  static double grading_slope(const panel& pn, double tau) {
    if (pn.grade_end && pn.grade_start) return 30 * tau * tau * (1 - tau) * (1 - tau);
    if (!pn.grade_end && !pn.grade_start) return 1;
    const double o = pn.grade_end ? 1 - tau : tau;
    return 3 * o * o;
  }

  // The panel's error relative to the totals: u at the nodes (its
  // interpolation error, weighted by the motion left), and each Gauss sum
  // (the square of its relative interpolation error, the order it converges at).
  double panel_error(const panel& pn) const {
    const rule& r = rule::rule();
    const double rest_t = std::exp(-at_.u) * here_.g;
    const double rest_2 = rest_t * std::exp(-at_.u) / 2;
    auto sum_error = [&](const values& f, double total) {
      const double c0 = std::fabs(r.coefficient(0, f));
      if (!(c0 > 0)) return 0.0;
      const double rel = r.tail(f) / c0;
      return rel * rel * 2 * c0 / total;
    };
    double err = 2 * r.tail(pn.du) * rest_t / (at_.t + rest_t);
    err = (std::max)(err, sum_error(pn.dt, at_.t + rest_t));
    err = (std::max)(err, sum_error(pn.e2, at_.plain2 + rest_2));
    const double rest_rho = rest_at_rate();
    err = (std::max)(err, sum_error(pn.e2_rho, at_.rho2 + rest_rho));
    return std::isnan(err) ? std::numeric_limits<double>::infinity() : err;
  }

  // Whether the rounding of F, amplified in 1/F, would decide a panel in s:
  // over a panel u moves by a few units, so its error is about 4·noise times
  // the part of the motion still to come; then the panel is taken in u.
  bool noise_dominates() const {
    const double rest_t = std::exp(-at_.u) * here_.g;
    return !(4 * here_.noise * rest_t <= limits_.tolerance / 2 * (at_.t + rest_t));
  }

  // The next panel: tried, and accepted or shrunk.  True once stopped.
  bool advance() {
    if (direction_ == 0) return finish_with_rest();
    if (std::isfinite(g_target_) ? rest_in_closed_form() : rest_is_negligible())
      return finish_with_rest();
    const bool slow = noise_dominates();
    const double s_break = (std::min)(s_edge_, s_flip_);
    double h = slow ? h_u_ : h_;
    const bool to_break = !slow && at_.s + h >= s_break;
    if (to_break) h = s_break - at_.s;
    const panel pn = slow ? make_panel_in_u(h)
                          : make_panel(at_.s, h, grade_next_start_, to_break && s_break == s_edge_);
    const double tol = limits_.tolerance;
    const double factor = pn.err > 0 ? 0.9 * std::pow(tol / pn.err, 0.125) : 4;
    if (pn.err > tol && h > 1e-9 * (1 + (slow ? at_.u : at_.s))) {
      (slow ? h_u_ : h_) = h * (std::max)(0.1, (std::min)(0.5, factor));
      return false;
    }
    (slow ? h_u_ : h_) = h * (std::max)(0.5, (std::min)(4.0, factor));
    accept(pn, slow ? s_of(pn.q_end) : to_break ? s_break : at_.s + h);
    if (at_.s >= s_flip_) switch_variable();
    return false;
  }

  void accept(const panel& pn, double s_end) {
    const rule& r = rule::rule();
    const position before = at_;
    here_before_q_ = here_.q;
    at_.s = s_end;
    at_.u += r.integral(pn.du);
    at_.t += r.integral(pn.dt);
    at_.plain2 += r.integral(pn.e2);
    at_.rho2 += r.integral(pn.e2_rho);
    grade_next_start_ = pn.grade_end;
    // At a breakpoint q is exactly the singular ratio's or ln 10⁸.
    here_ = flow_at_q(pn.in_u            ? pn.q_end
                      : s_end == s_edge_ ? q_edge_
                      : s_end == s_flip_ ? q_flip
                                         : pn.q_end);
    if (s_end >= s_edge_) find_next_edge();  // passed
    const motion_sample<Real> now = sample_here();
    sample_times_in(pn, before, now.time);
    observe_(now);
  }

  // The rest of the leg in the other variable, from where ε reached 10⁸.
  void switch_variable() {
    const motion_sample<Real> now = sample_here();
    t_off_ = now.time;
    s_off_ = now.distance;
    th_off_ = now.angle;
    start_leg(!by_speed_, -here_.q, by_speed_ ? now.spin : now.speed,
              by_speed_ ? now.speed : now.spin);
  }

  // ------------------------------------------------------------ the stop

  // The rest of the motion, where G tends to G∞ along the path: it lies
  // between e^{−u}G and e^{−u}G∞ (and alike for ∫e^{−2u}G), so once that
  // interval is below the tolerance of the totals the estimate for an
  // exponential approach, e^{−u}(G∞ + (G − G∞)/(1 + λ)), is added.  For
  // ∫ρe^{−2u}G: the same towards a finite zero, or, where it is smaller (and
  // towards ε = 0), the bound ρe^{−2u}max(G, G∞) (ρ grows at most like e^u,
  // since F ≤ 1) with the estimate at the present rate, ρe^{−2u}G/(2 − F).
  // ρe^{−2u} is taken as one exponential (ρ alone may overflow).
  bool rest_in_closed_form() {
    const double lam = rest_rate();
    const double decay = std::exp(-at_.u), g = here_.g, gi = g_target_;
    const double rest_t = decay * (gi + (g - gi) / (1 + lam));
    const double half2 = decay * decay / 2, w2 = 2 / (2 + lam);
    const double rest_plain = half2 * (gi + (g - gi) * w2);
    const double rho2 = rho_integrand(here_.q, at_.u, g);
    double rest_rho = rest_at_rate(), bound_rho = rho2 * (std::max)(1.0, gi / g);
    if (finite_target_) {
      const double rho2_i = rho_integrand(q_target_, at_.u, gi);
      if (std::fabs(rho2 - rho2_i) / 2 <= bound_rho) {
        rest_rho = (rho2_i + (rho2 - rho2_i) * w2) / 2;
        bound_rho = std::fabs(rho2 - rho2_i) / 2;
      }
    }
    const double tol = limits_.tolerance;
    const bool small = decay * std::fabs(g - gi) <= tol * (at_.t + rest_t) &&
                       half2 * std::fabs(g - gi) <= tol * (at_.plain2 + rest_plain) &&
                       bound_rho <= tol * (at_.rho2 + rest_rho);
    if (!small) return false;
    tail_start_ = sample_here();
    at_.t += rest_t;
    at_.plain2 += rest_plain;
    at_.rho2 += rest_rho;
    return true;
  }

  // ρe^{−2u}G·e^{log_factor} in units of e^{rho_log}, taken as one exponential
  // (ρ alone may overflow, and in a collapse the factor underflows).
  double rho_integrand(double q, double u, double g, double log_factor = 0) const {
    return std::exp(q - q_start_ - 2 * u - rho_log_ + log_factor) * g;
  }

  // ∫ρe^{−2u}G from here if F stayed as it is: ρe^{−2u}G/(2 − F) (F ≤ 1;
  // 2 − F = 1 + X, whose log is −ln|1/F| where X overflowed).
  double rest_at_rate() const {
    const double two_minus = 2 - here_.rate;
    const double log_two_minus =
        std::isfinite(two_minus) ? std::log(two_minus) : -log_inverse(here_);
    return rho_integrand(here_.q, at_.u, here_.g, -log_two_minus);
  }

  // λ of the approach q − q∞ ∝ e^{−λu}: −F/(q − q∞) at a finite zero, else 1.
  double rest_rate() const {
    if (!finite_target_) return 1;
    const double lam = -here_.rate / (here_.q - q_target_);
    return lam >= 0 && std::isfinite(lam) ? lam : 0;
  }

  // Towards ε = ∞ in this variable the other motion stops first: a bound on
  // the remaining time.  ε moves monotonically, so 𝓕 (growing ε) or 𝓣
  // (falling ε) only grows from here, and both motions stop within
  // v/𝓕 = ω/(𝓕/ε) or γω/𝓣 = γv/(ε𝓣) respectively.  Once that bound, and the
  // distance and angle it allows, are below 1e-18 of their totals (or below
  // the smallest subnormal), stop.  (Where the flow only creeps towards ∞, at
  // the edges of the inertia window, the switch at 10⁸ may be astronomically
  // far.)  The bound is taken in logs, where neither motion under- or
  // overflows; each bound is the larger of its two forms (a NaN form is
  // ignored); at a zero of the flow ε stays, and both bounds hold.
  bool rest_is_negligible() {
    BOOST_MATH_STD_USING
    const motion_sample<Real> now = sample_here();
    const Real ln_lead = log(lead_) - Real(at_.u);
    const Real ln_other = log(other_) + Real(here_.q - q_start_) - Real(at_.u);
    const Real ln_v = by_speed_ ? ln_lead : ln_other, ln_w = by_speed_ ? ln_other : ln_lead;
    const flow_terms<Real>& ft = here_.terms;
    auto larger = [](Real a, Real b) { return a >= b || b != b ? a : b; };
    const Real ln_by_force = larger(ln_v - log(ft.force), ln_w - log(ft.force_over_ratio));
    const Real ln_by_torque =
        log(in_.gamma) + larger(ln_w - log(ft.torque), ln_v - log(ft.ratio_torque));
    const double rate = here_.rate;
    const Real ln_left = rate == 0                           ? (std::min)(ln_by_force, ln_by_torque)
                         : (by_speed_ ? rate < 0 : rate > 0) ? ln_by_force
                                                             : ln_by_torque;
    const Real ln_tiny = log(Real(1e-18)), ln_floor = log(std::numeric_limits<Real>::denorm_min());
    auto negligible = [&](Real ln_part, Real total) {
      return ln_part <= ln_tiny + log(total) || ln_part < ln_floor;
    };
    if (!(negligible(ln_left, now.time) && negligible(ln_v + ln_left, now.distance) &&
          negligible(ln_w + ln_left, now.angle)))
      return false;
    tail_start_ = now;
    return true;
  }

  // The stop: the rest state observed and given to the times at or after it;
  // times between the last panel and the stop see a uniform deceleration.
  bool finish_with_rest() {
    if (direction_ == 0) {  // at a zero of the flow from the start: ε stays
      tail_start_ = sample_here();
      at_.t += here_.g;
      at_.plain2 += here_.g / 2;
      at_.rho2 += here_.g / 2;
    }
    const motion_sample<Real> end = sample_here();
    out_.time = end.time;
    out_.distance = end.distance;
    out_.angle = end.angle;
    const motion_sample<Real> rest{out_.time, 0, 0, out_.terminal.ratio, out_.distance, out_.angle};
    for (; next_time_ < request_.times.size(); ++next_time_)
      request_.at_times.push_back(in_tail(request_.times[next_time_], rest));
    observe_(rest);
    return true;
  }

  // At time t between the last panel and the stop: uniform deceleration.
  motion_sample<Real> in_tail(Real t, const motion_sample<Real>& rest) const {
    const motion_sample<Real>& a = tail_start_;
    if (!(t < rest.time) || !(rest.time > a.time)) {
      motion_sample<Real> m = rest;
      m.time = t;
      return m;
    }
    const Real f = (t - a.time) / (rest.time - a.time), left = 1 - f, gone = f * (2 - f);
    return {t,
            a.speed * left,
            a.spin * left,
            a.ratio,
            a.distance + (rest.distance - a.distance) * gone,
            a.angle + (rest.angle - a.angle) * gone};
  }

  // ------------------------------------------------------------ the samples

  // t, s, θ from the scaled integrals, each a product taken without spurious
  // over- or underflow (γ, L and M may each be near the ends of the type).
  Real unit_of_time() const { return by_speed_ ? Real(1) : in_.gamma; }
  Real time_of(double t_hat) const {
    return t_off_ + detail::product(unit_of_time(), lead_, Real(t_hat));
  }
  Real distance_of(double plain2, double rho2) const {
    return s_off_ + (by_speed_ ? detail::product(lead_, lead_, Real(plain2))
                               : detail::product(in_.gamma, lead_, other_, Real(rho2), rho_unit_,
                                                 rho_unit_, rho_unit_, rho_unit_));
  }
  Real angle_of(double plain2, double rho2) const {
    return th_off_ + (by_speed_ ? detail::product(lead_, other_, Real(rho2), rho_unit_, rho_unit_,
                                                  rho_unit_, rho_unit_)
                                : detail::product(in_.gamma, lead_, lead_, Real(plain2)));
  }

  motion_sample<Real> sample_at(double q, const position& at) const {
    BOOST_MATH_STD_USING
    const Real leading = detail::product(lead_, Real(exp(-Real(at.u))));
    const Real following = detail::product(other_, Real(exp(Real(q - q_start_) - Real(at.u))));
    const Real r = exp(Real(q));
    motion_sample<Real> m;
    m.time = time_of(at.t);
    m.distance = distance_of(at.plain2, at.rho2);
    m.angle = angle_of(at.plain2, at.rho2);
    m.spin = by_speed_ ? following : leading;
    m.speed = by_speed_ ? leading : following;
    m.ratio = by_speed_ ? (r > 0 ? Real(1 / r) : inf_real()) : r;
    return m;
  }
  motion_sample<Real> sample_here() const { return sample_at(here_.q, at_); }

  // The requested times inside an accepted panel: t(x) = t_k solved on the
  // panel's interpolants (TOMS 748), then u, ŝ, θ̂ and q there.
  void sample_times_in(const panel& pn, const position& before, Real t_end) {
    const auto& times = request_.times;
    if (next_time_ >= times.size() || !(times[next_time_] <= t_end)) return;
    const rule& r = rule::rule();
    const values c_u = r.coefficients(pn.du), c_t = r.coefficients(pn.dt);
    const values c_plain = r.coefficients(pn.e2), c_rho = r.coefficients(pn.e2_rho);
    auto at_x = [&](double x) {
      position p = before;
      p.u += r.integral_to(x, c_u);
      p.t += r.integral_to(x, c_t);
      p.plain2 += r.integral_to(x, c_plain);
      p.rho2 += r.integral_to(x, c_rho);
      p.s = pn.s + pn.h * grading(pn, (1 + x) / 2);
      return p;
    };
    const values c_q = pn.in_u ? r.coefficients(pn.dq) : values{};
    auto q_at = [&](double x, const position& p) {
      return pn.in_u ? here_before_q_ + r.integral_to(x, c_q) : q_of(p.s);
    };
    for (; next_time_ < times.size() && times[next_time_] <= t_end; ++next_time_) {
      const Real tk = times[next_time_];
      auto miss = [&](double x) { return static_cast<double>(time_of(at_x(x).t) - tk); };
      double x = 1;
      if (miss(-1) >= 0) {
        x = -1;
      } else if (miss(1) > 0) {
        boost::uintmax_t iters = 100;
        const auto b = boost::math::tools::toms748_solve(
            miss, -1.0, 1.0, boost::math::tools::eps_tolerance<double>(50), iters);
        x = (b.first + b.second) / 2;
      }
      const position p = at_x(x);
      motion_sample<Real> m = sample_at(q_at(x, p), p);
      m.time = tk;
      request_.at_times.push_back(m);
    }
  }

  // ------------------------------------------------------------ the members

  static constexpr double inf = std::numeric_limits<double>::infinity();
  static constexpr double q_flip = 18.420680743952367;  // ln 10⁸

  const Profile& p_;
  const throw_input<Real> in_;
  Observer observe_;
  stop_request<Real> request_;
  stop_limits limits_;
  std::array<double, ratio_list<Real>::capacity> log_edges_{};  // ln ε of the singular ratios
  std::size_t edges_ = 0;
  stop_result<Real> out_{0, 0, 0, {terminal_regime::sliding_and_spinning, Real(0)}};
  std::size_t next_time_ = 0;

  // The leg: its variable, scales (L, M) and offsets where it starts, and its path.
  bool by_speed_ = false;
  Real lead_ = 0, other_ = 0, t_off_ = 0, s_off_ = 0, th_off_ = 0;
  double q_start_ = 0, q_target_ = 0, delta_ = 0, g_target_ = 0;
  int direction_ = 0;
  bool finite_target_ = false;
  double s_edge_ = inf, q_edge_ = 0;  // the next singular ratio along s, and its q
  double s_flip_ = inf;               // ε = 10⁸ along s
  double rho_log_ = 0;                // ∫ρe^{−2u}G is in units of e^{rho_log}
  Real rho_unit_ = 1;                 // e^{rho_log/4}

  // The progress: position, the flow there, the next panel's width.
  position at_{};
  flow_point here_{};
  double h_ = 1, h_u_ = 1;
  double here_before_q_ = 0;  // q where the last accepted panel started
  bool grade_next_start_ = false;
  motion_sample<Real> tail_start_{};
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_DETAIL_STOP_INTEGRATOR_HPP
