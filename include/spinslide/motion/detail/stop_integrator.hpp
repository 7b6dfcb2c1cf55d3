//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file motion/detail/stop_integrator.hpp
/// The integration of a throw through its stop (docs/theory.md §9): the
/// motion is a one-dimensional autonomous flow of the ratio, so the time,
/// distance and angle are nested integrals over the log of the ratio, taken
/// with Gauss–Legendre panels up to where the rest of the motion is known in
/// closed form.  The types it returns are in motion_types.hpp.
///
/// The parts, in the way Boost.Odeint separates a stepper from its control:
/// - motion/detail/stop_flow.hpp: the flow of the ratio in a leg's variable;
/// - motion/detail/stop_leg.hpp: a leg, its path q(s), its scales and samples;
/// - motion/detail/stop_panel.hpp: a panel, its construction and error estimate;
/// - motion/detail/panel_width_controller.hpp: the width of the next panel;
/// - motion/detail/stop_tail.hpp: the rest of a leg after its last panel;
/// - motion/detail/stop_samples.hpp: the motion at requested times;
/// - motion/detail/uniform_stop.hpp: throws that start without spin or speed;
/// - this header: the driver, which strings the legs and panels together.

#ifndef SPINSLIDE_MOTION_DETAIL_STOP_INTEGRATOR_HPP
#define SPINSLIDE_MOTION_DETAIL_STOP_INTEGRATOR_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/motion/detail/panel_width_controller.hpp>
#include <spinslide/motion/detail/stop_leg.hpp>
#include <spinslide/motion/detail/stop_panel.hpp>
#include <spinslide/motion/detail/stop_samples.hpp>
#include <spinslide/motion/detail/stop_tail.hpp>
#include <spinslide/motion/detail/uniform_stop.hpp>
#include <spinslide/motion/motion_types.hpp>
#include <spinslide/motion/terminal.hpp>
#include <spinslide/values/detail/singular_ratios.hpp>

#include <boost/math/policies/error_handling.hpp>
#include <boost/math/tools/precision.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

namespace spinslide {
namespace detail {

/// The limits of one integration: panels (accepted or not) before
/// evaluation_error, and the error allowed per panel relative to the totals.
struct stop_limits {
  int max_panels = 20000;
  double tolerance = 1e-12;
};

/// One throw integrated to its stop.  The motion is integrated in legs
/// (motion/detail/stop_leg.hpp): in the variable of the leading motion, ω ("by
/// spin") or v ("by speed"), from the start to the terminal ratio, or to
/// ε = 10⁸ in that variable, where the leg hands over to the other variable.
/// Each leg is a sequence of panels (motion/detail/stop_panel.hpp) along the path
/// q(s), which break at the profile's singular ratios (ε = 1, and ε = b for
/// an annulus: 𝓕″ and 𝓣″ are log-singular there, and the panels beside them
/// are graded; values/detail/singular_ratios.hpp) and at ε = 10⁸.  The rest after
/// the last panel is in closed form where G tends to a finite limit; towards
/// ε = ∞ in the variable, a bound on the remaining motion decides (the other
/// motion stops first; motion/detail/stop_tail.hpp).
template <class Profile, class Observer>
class stop_integrator {
 public:
  using value_type = typename Profile::value_type;
  using Real = value_type;

  stop_integrator(const Profile& p, const throw_input<Real>& in, Observer observe,
                  stop_request<Real> request, stop_limits limits = {})
      : p_(p),
        in_(in),
        observe_(observe),
        request_(request),
        times_(request),
        max_panels_(limits.max_panels),
        // The right-hand side is evaluated in Real: for float its rounding sets the floor.
        widths_((std::max)(limits.tolerance,
                           10 * static_cast<double>(std::numeric_limits<Real>::epsilon()))) {
    BOOST_MATH_STD_USING
    const ratio_list<Real> edges = singular_ratios(p);
    for (std::size_t i = 0; i < edges.size(); ++i)
      log_edges_[i] = static_cast<double>(Real(log(edges[i])));
    edges_ = edges.size();
  }

  stop_result<Real> run() {
    if (in_.v0 == 0 || in_.omega0 == 0) return uniform_stop(p_, in_, observe_, request_);
    out_.terminal = terminal_motion(p_, in_.gamma, clamped_quotient());
    start_first_leg();
    for (int panels = 0; panels < max_panels_; ++panels) {
      if (advance()) return out_;
    }
    out_.time = boost::math::policies::raise_evaluation_error<Real>(
        request_.function, "No stop found after %1% panels.", Real(max_panels_),
        typename Profile::policy_type());
    return out_;
  }

 private:
  using variable = panel_width_controller::variable;
  static constexpr double inf = std::numeric_limits<double>::infinity();
  static constexpr double q_flip = 18.420680743952367;  // ln 10⁸

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
    leg_start<Real> start;
    start.by_speed = out_.terminal.regime == terminal_regime::pure_sliding;
    start.q = start.by_speed ? -q : q;
    if (start.q > q_flip) {
      start.by_speed = !start.by_speed;
      start.q = -start.q;
    }
    start.lead = start.by_speed ? in_.v0 : in_.omega0;
    start.other = start.by_speed ? in_.omega0 : in_.v0;
    start_leg(start);
    observe_(sample_here());
  }

  void start_leg(const leg_start<Real>& start) {
    leg_.emplace(p_, in_.gamma, start, out_.terminal.ratio);
    at_ = leg_position{};
    here_ = leg_->first();
    set_breakpoints();
    widths_.restart(leg_->first_width());
  }

  // The rest of the motion in the other variable, from where ε reached 10⁸.
  void switch_variable() {
    const motion_sample<Real> now = sample_here();
    const bool by_speed = leg_->by_speed();
    leg_start<Real> start;
    start.by_speed = !by_speed;
    start.q = -here_.q;
    start.lead = by_speed ? now.spin : now.speed;
    start.other = by_speed ? now.speed : now.spin;
    start.time = now.time;
    start.distance = now.distance;
    start.angle = now.angle;
    start_leg(start);
  }

  // ------------------------------------------------------------ breakpoints

  // The breakpoints of the leg: the profile's singular ratios (panels beside
  // them graded) and the switch of variable at ε = 10⁸.
  void set_breakpoints() {
    const leg_path& path = leg_->path();
    s_flip_ = path.direction > 0 && !path.finite_target ? path.s_ahead(q_flip) : inf;
    grade_next_start_ = false;
    for (std::size_t i = 0; i < edges_; ++i) grade_next_start_ |= path.q_start == edge_q(i);
    find_next_edge();
  }

  // q of the i-th singular ratio in the leg's variable.
  double edge_q(std::size_t i) const { return leg_->by_speed() ? -log_edges_[i] : log_edges_[i]; }

  // The next singular ratio ahead of the position: s_edge_ and q_edge_.
  void find_next_edge() {
    s_edge_ = inf;
    for (std::size_t i = 0; i < edges_; ++i) {
      const double s = leg_->path().s_ahead(edge_q(i));
      if (s > at_.s && s < s_edge_) {
        s_edge_ = s;
        q_edge_ = edge_q(i);
      }
    }
  }

  // ------------------------------------------------------------ the panels

  // Whether the rounding of F, amplified in 1/F, would decide a panel in s:
  // over a panel u moves by a few units, so its error is about 4·noise times
  // the part of the motion still to come; then the panel is taken in u.
  bool noise_dominates() const {
    const double rest_t = std::exp(-at_.u) * here_.g;
    return !(4 * here_.noise * rest_t <= widths_.tolerance() / 2 * (at_.time + rest_t));
  }

  // The next panel: tried, and accepted or shrunk.  True once stopped.
  bool advance() {
    if (leg_->path().direction == 0 || leg_ends()) return finish();
    const bool slow = noise_dominates();
    const variable in = slow ? variable::u : variable::s;
    const double s_break = (std::min)(s_edge_, s_flip_);
    double h = widths_.width(in);
    const bool to_break = !slow && at_.s + h >= s_break;
    if (to_break) h = s_break - at_.s;
    const panel_builder<Profile> build(*leg_, at_, here_, widths_.tolerance());
    const leg_panel pn =
        slow ? build.in_u(h)
             : build.in_s(at_.s, h, {grade_next_start_, to_break && s_break == s_edge_});
    if (!widths_.accept(in, h, pn.error, slow ? at_.u : at_.s)) return false;
    accept(pn, slow ? leg_->path().s_of(pn.q_end, at_.s) : to_break ? s_break : at_.s + h);
    if (at_.s >= s_flip_) switch_variable();
    return false;
  }

  void accept(const leg_panel& pn, double s_end) {
    const stop_rule& r = stop_rule::rule();
    const panel_start before{at_, here_.q};
    at_.s = s_end;
    at_.u += r.integral(pn.du);
    at_.time += r.integral(pn.d_time);
    at_.lead_travel += r.integral(pn.d_lead);
    at_.other_travel += r.integral(pn.d_other);
    grade_next_start_ = pn.grading.at_end;
    // At a breakpoint q is exactly the singular ratio's or ln 10⁸.
    here_ = leg_->at(pn.in_u            ? pn.q_end
                     : s_end == s_edge_ ? q_edge_
                     : s_end == s_flip_ ? q_flip
                                        : pn.q_end);
    if (s_end >= s_edge_) find_next_edge();  // passed
    const motion_sample<Real> now = sample_here();
    sample_panel(*leg_, pn, before, now.time, times_);
    observe_(now);
  }

  // ------------------------------------------------------------ the stop

  // Whether the rest of the leg is known from here (motion/detail/stop_tail.hpp):
  // if so, it is added and the tail starts here.
  bool leg_ends() {
    if (std::isfinite(leg_->g_target())) {
      const std::optional<leg_rest> rest = closed_form_rest(*leg_, at_, here_, widths_.tolerance());
      if (!rest) return false;
      tail_start_ = sample_here();
      at_.time += rest->time;
      at_.lead_travel += rest->lead_travel;
      at_.other_travel += rest->other_travel;
      return true;
    }
    const motion_sample<Real> now = sample_here();
    if (!rest_is_negligible(*leg_, at_, here_, now)) return false;
    tail_start_ = now;
    return true;
  }

  // The stop: the rest state observed and given to the times at or after it;
  // times between the last panel and the stop see a uniform deceleration.
  bool finish() {
    if (leg_->path().direction == 0) {  // at a zero of the flow from the start: ε stays
      tail_start_ = sample_here();
      at_.time += here_.g;
      at_.lead_travel += here_.g / 2;
      at_.other_travel += here_.g / 2;
    }
    const motion_sample<Real> end = sample_here();
    out_.time = end.time;
    out_.distance = end.distance;
    out_.angle = end.angle;
    const motion_sample<Real> rest{out_.time, 0, 0, out_.terminal.ratio, out_.distance, out_.angle};
    while (!times_.done()) times_.give(tail_sample(times_.next(), tail_start_, rest));
    observe_(rest);
    return true;
  }

  motion_sample<Real> sample_here() const { return leg_->sample_at(here_.q, at_); }

  // ------------------------------------------------------------ the members

  const Profile& p_;
  const throw_input<Real> in_;
  Observer observe_;
  stop_request<Real> request_;
  time_cursor<Real> times_;
  int max_panels_;
  panel_width_controller widths_;
  std::array<double, ratio_list<Real>::capacity> log_edges_{};  // ln ε of the singular ratios
  std::size_t edges_ = 0;
  stop_result<Real> out_{0, 0, 0, {terminal_regime::sliding_and_spinning, Real(0)}};

  // The leg and the progress along it.
  std::optional<stop_leg<Profile>> leg_;
  leg_position at_{};
  flow_point<Real> here_{};
  double s_edge_ = inf, q_edge_ = 0;  // the next singular ratio along s, and its q
  double s_flip_ = inf;               // ε = 10⁸ along s
  bool grade_next_start_ = false;
  motion_sample<Real> tail_start_{};
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_DETAIL_STOP_INTEGRATOR_HPP
