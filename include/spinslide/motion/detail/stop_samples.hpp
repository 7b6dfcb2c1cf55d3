//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file motion/detail/stop_samples.hpp
/// The motion at requested times during an integration to the stop
/// (docs/theory.md §9; motion/detail/stop_integrator.hpp): inside an accepted panel,
/// from its interpolants, and between the last panel and the stop.

#ifndef SPINSLIDE_MOTION_DETAIL_STOP_SAMPLES_HPP
#define SPINSLIDE_MOTION_DETAIL_STOP_SAMPLES_HPP

#include <spinslide/motion/detail/stop_panel.hpp>
#include <spinslide/motion/motion_types.hpp>

#include <boost/math/tools/toms748_solve.hpp>

#include <cstddef>
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

/// The requested times in order, and the samples given so far.
template <class Real>
class time_cursor {
 public:
  explicit time_cursor(stop_request<Real> request) : request_(request) {}

  /// Whether a requested time at or before t is still to be sampled.
  bool due_by(Real t) const { return next_ < request_.times.size() && request_.times[next_] <= t; }
  bool done() const { return next_ >= request_.times.size(); }
  /// The next requested time.
  Real next() const { return request_.times[next_]; }
  /// The sample at the next requested time.
  void give(const motion_sample<Real>& m) {
    request_.at_times.push_back(m);
    ++next_;
  }

 private:
  stop_request<Real> request_;
  std::size_t next_ = 0;
};

/// Where an accepted panel started: the integrals and q there.
struct panel_start {
  leg_position at;
  double q = 0;
};

/// The requested times inside an accepted panel, which ends at t_end: t(x) =
/// t_k solved on the panel's interpolants (TOMS 748), then u, ŝ_l, ŝ_o and q
/// there.
template <class Profile, class Real = typename Profile::value_type>
void sample_panel(const stop_leg<Profile>& leg, const leg_panel& pn, const panel_start& start,
                  Real t_end, time_cursor<Real>& times) {
  using values = stop_rule::values;
  if (!times.due_by(t_end)) return;
  const stop_rule& r = stop_rule::rule();
  const values c_u = r.coefficients(pn.du), c_t = r.coefficients(pn.d_time);
  const values c_lead = r.coefficients(pn.d_lead), c_other = r.coefficients(pn.d_other);
  auto at_x = [&](double x) {
    leg_position p = start.at;
    p.u += r.integral_to(x, c_u);
    p.time += r.integral_to(x, c_t);
    p.lead_travel += r.integral_to(x, c_lead);
    p.other_travel += r.integral_to(x, c_other);
    p.s = pn.s + pn.h * pn.grading.map((1 + x) / 2);
    return p;
  };
  const values c_q = pn.in_u ? r.coefficients(pn.dq) : values{};
  auto q_at = [&](double x, const leg_position& p) {
    return pn.in_u ? start.q + r.integral_to(x, c_q) : leg.path().q_of(p.s);
  };
  while (times.due_by(t_end)) {
    const Real tk = times.next();
    auto miss = [&](double x) { return static_cast<double>(leg.time_of(at_x(x).time) - tk); };
    double x = 1;
    if (miss(-1) >= 0) {
      x = -1;
    } else if (miss(1) > 0) {
      boost::uintmax_t iters = 100;
      const auto b = boost::math::tools::toms748_solve(
          miss, -1.0, 1.0, boost::math::tools::eps_tolerance<double>(50), iters);
      x = (b.first + b.second) / 2;
    }
    const leg_position p = at_x(x);
    motion_sample<Real> m = leg.sample_at(q_at(x, p), p);
    m.time = tk;
    times.give(m);
  }
}

/// The motion at time t between `last` (the last panel's end) and `rest`
/// (the stop): a uniform deceleration.
template <class Real>
motion_sample<Real> tail_sample(Real t, const motion_sample<Real>& last,
                                const motion_sample<Real>& rest) {
  if (!(t < rest.time) || !(rest.time > last.time)) {
    motion_sample<Real> m = rest;
    m.time = t;
    return m;
  }
  const Real f = (t - last.time) / (rest.time - last.time), left = 1 - f, gone = f * (2 - f);
  return {t,
          last.speed * left,
          last.spin * left,
          last.ratio,
          last.distance + (rest.distance - last.distance) * gone,
          last.angle + (rest.angle - last.angle) * gone};
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_DETAIL_STOP_SAMPLES_HPP
