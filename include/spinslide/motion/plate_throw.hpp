//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file plate_throw.hpp
/// A flat plate (plate_motion.hpp) thrown on a plane, integrated through its
/// stop (docs/plate_dynamics.md, "Through the stop"): in s = −ln(r/r₀), r the
/// size of the twist (u, kω), the twist shrinks as e^{−s} exactly and the
/// time, turn and displacement still to come are O(e^{−s}); the integration
/// runs to e^{−s} = 1e-15 and adds them in closed form, then follows the
/// direction of the twist on to its limit (the terminal ratio and direction).

#ifndef SPINSLIDE_MOTION_PLATE_THROW_HPP
#define SPINSLIDE_MOTION_PLATE_THROW_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/motion/detail/plate_direction_flow.hpp>
#include <spinslide/motion/detail/plate_step_control.hpp>
#include <spinslide/motion/plate_motion.hpp>
#include <spinslide/values/friction_wrench.hpp>

#include <boost/math/policies/policy.hpp>
#include <boost/math/tools/config.hpp>
#include <boost/math/tools/precision.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace spinslide {

/// The plate at one instant of a throw (world frame; the velocity in the body frame).
template <class Real>
struct plate_sample {
  using value_type = Real;       ///< the floating type
  Real time;                     ///< t
  std::array<Real, 2> position;  ///< X of the centre, world frame
  Real angle;                    ///< θ, the orientation
  std::array<Real, 2> velocity;  ///< u, body frame
  Real omega;                    ///< ω
};

/// How a throw ends: the limits, as the plate stops, of the ratio
/// ε = |u|/(ℓ|ω|) (ℓ = patch.radius()) and of the slip's direction in the body
/// frame.
template <class Real>
struct plate_ending {
  using value_type = Real;  ///< the floating type
  Real ratio;               ///< ε at the stop: +∞ for pure sliding, 0 for pure spinning
  Real direction;           ///< the angle of u in the body frame (NaN for pure spinning)
  int spin_sense;           ///< the sign of ω at the stop (0 for pure sliding)
  bool converged;           ///< false if the direction still moved at the end of its integration
};

/// A throw to its stop.
template <class Real>
struct plate_throw_result {
  using value_type = Real;           ///< the floating type
  Real time;                         ///< the stop time
  Real distance;                     ///< the length of the centre's path
  std::array<Real, 2> displacement;  ///< the centre's displacement, world frame
  Real rotation;                     ///< the total turn θ_end − θ₀ (signed)
  plate_ending<Real> terminal;       ///< the limits at the stop
  bool reached_stop;  ///< false if the step limit ended the integration first (then inexact)
  std::vector<plate_sample<Real>> path;  ///< every accepted step, and the rest at the stop
};

namespace detail {

/// The integration's limits: steps per stage, the stepper's tolerance (at
/// least 512 ulp of the type: float's 7 digits cannot meet 1e-13), where the
/// closed-form tail takes over, and the span of s given to the direction.
struct plate_stop_limits {
  int max_steps = 20000;
  double tolerance = 1e-13;
  double tail_size = 1e-15;
  double terminal_span = 5000;
  double terminal_rate = 1e-11;
};

template <class Real>
plate_ending<Real> ending_of(const std::array<Real, 3>& n, Real k, Real ell, bool converged) {
  BOOST_MATH_STD_USING
  const Real slip = sqrt(n[0] * n[0] + n[1] * n[1]);
  const Real spin = fabs(n[2]) / k;
  const Real ratio = spin > 0 ? Real(slip / (ell * spin)) : std::numeric_limits<Real>::infinity();
  const Real direction =
      slip > 0 ? Real(atan2(n[1], n[0])) : std::numeric_limits<Real>::quiet_NaN();
  return {ratio, direction, n[2] > 0 ? 1 : (n[2] < 0 ? -1 : 0), converged};
}

template <class State>
void normalise_direction(State& y) {
  BOOST_MATH_STD_USING
  const auto norm = sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
  for (std::size_t i = 0; i < 3; ++i) y[i] /= norm;
}

/// One throw: the flow in s to the tail, the tails, then the direction's limit.
template <class Real>
class plate_stop_run {
  using stop_state = typename plate_stop_flow<Real>::state;
  using direction_state = typename plate_terminal_flow<Real>::state;

 public:
  plate_stop_run(const plate_motion<Real>& plate, const planar_twist<Real>& start, Real angle,
                 plate_stop_limits limits = {})
      : plate_(plate), angle0_(angle), limits_(limits) {
    BOOST_MATH_STD_USING
    const Real k = plate.radius_of_gyration();
    const Real ux = start.velocity[0], uy = start.velocity[1], kw = k * start.omega;
    r0_ = sqrt(ux * ux + uy * uy + kw * kw);
    beta_ = r0_ / plate.deceleration() * r0_ / k;
    y_ = {ux / r0_, uy / r0_, kw / r0_, 0, 0, 0, 0, 0};
  }

  plate_throw_result<Real> run() {
    BOOST_MATH_STD_USING
    const Real k = plate_.radius_of_gyration();
    const plate_stop_flow<Real> flow(plate_.patch(), k, beta_);
    const Real s_end = -log(Real(limits_.tail_size));
    Real s = 0, ds = Real(0.05);
    plate_step_control<stop_state, Real> stepper(tolerance());
    record(s);
    for (int steps = 0; s < s_end && steps < limits_.max_steps; ++steps) {
      Real step = fmin(ds, s_end - s);
      if (stepper.try_step(flow, y_, s, step)) {
        normalise_direction(y_);
        record(s);
      }
      ds = step;
    }
    const plate_direction<Real> d =
        direction_wrench(plate_.patch(), k, std::array<Real, 3>{y_[0], y_[1], y_[2]});
    const Real e1 = exp(-s), e2 = e1 * e1 / 2;
    // The rest after s, the direction frozen: ∫ e^{−s'} ds' = e^{−s}, ∫ e^{−2s'} ds' = e^{−2s}/2.
    const Real t = y_[3] + e1 / d.dissipation;
    const Real theta = y_[4] + beta_ * e2 * d.n[2] / d.dissipation;
    const Real length = plate_.deceleration() > 0 ? r0_ * r0_ / plate_.deceleration() : Real(0);
    const Real c = cos(y_[4]), sn = sin(y_[4]);
    const std::array<Real, 2> x{y_[5] + e2 * (c * d.n[0] - sn * d.n[1]) / d.dissipation,
                                y_[6] + e2 * (sn * d.n[0] + c * d.n[1]) / d.dissipation};
    plate_throw_result<Real> r;
    r.time = t * r0_ / plate_.deceleration();
    r.rotation = theta;
    r.displacement = to_world({length * x[0], length * x[1]});
    r.distance = length * (y_[7] + e2 * hypot(d.n[0], d.n[1]) / d.dissipation);
    r.terminal = terminal(s);
    r.reached_stop = !(s < s_end);
    path_.push_back({r.time, r.displacement, angle0_ + r.rotation, {0, 0}, 0});
    r.path = std::move(path_);
    return r;
  }

 private:
  Real tolerance() const {
    BOOST_MATH_STD_USING
    return fmax(Real(limits_.tolerance), 512 * boost::math::tools::epsilon<Real>());
  }

  std::array<Real, 2> to_world(const std::array<Real, 2>& x) const {
    BOOST_MATH_STD_USING
    const Real c = cos(angle0_), s = sin(angle0_);
    return {c * x[0] - s * x[1], s * x[0] + c * x[1]};
  }

  void record(Real s) {
    BOOST_MATH_STD_USING
    const Real length = r0_ * r0_ / plate_.deceleration(), r = r0_ * exp(-s);
    path_.push_back({y_[3] * r0_ / plate_.deceleration(),
                     to_world({length * y_[5], length * y_[6]}),
                     angle0_ + y_[4],
                     {r * y_[0], r * y_[1]},
                     r * y_[2] / plate_.radius_of_gyration()});
  }

  /// The direction followed on by the autonomous flow until it stops moving.
  plate_ending<Real> terminal(Real s) const {
    BOOST_MATH_STD_USING
    const Real k = plate_.radius_of_gyration();
    const plate_terminal_flow<Real> flow(plate_.patch(), k);
    direction_state n{y_[0], y_[1], y_[2]}, rate{};
    plate_step_control<direction_state, Real> stepper(tolerance());
    const Real s_end = s + Real(limits_.terminal_span);
    Real ds = Real(0.1);
    bool still = false;
    for (int steps = 0; !still && s < s_end && steps < limits_.max_steps; ++steps) {
      Real step = fmin(ds, s_end - s);
      if (stepper.try_step(flow, n, s, step)) {
        normalise_direction(n);
        flow(n, rate, s);
        still = sqrt(rate[0] * rate[0] + rate[1] * rate[1] + rate[2] * rate[2]) <
                fmax(Real(limits_.terminal_rate), 1024 * boost::math::tools::epsilon<Real>());
      }
      ds = step;
    }
    return ending_of(n, k, plate_.patch().radius(), still);
  }

  const plate_motion<Real>& plate_;
  Real angle0_;
  plate_stop_limits limits_;
  Real r0_ = 0, beta_ = 0;
  stop_state y_{};
  std::vector<plate_sample<Real>> path_;
};

}  // namespace detail

/// The throw of `plate` from the body-frame twist `start` (the centre's
/// velocity u₀ and the spin ω₀) and orientation `angle` (θ₀; the world frame
/// is the body frame turned by θ₀), from the world origin, to its stop.
/// Returns the stop time, the path length and displacement, the total turn,
/// the terminal ratio and direction, and the path (every adaptive step).
/// A non-finite component, a zero twist or a non-finite angle is a domain
/// error through `pol` (a NaN result unless it throws).  Nothing else throws.
template <class Real, class Policy = boost::math::policies::policy<>>
plate_throw_result<Real> throw_plate(const plate_motion<Real>& plate,
                                     const planar_twist<Real>& start, Real angle = 0,
                                     const Policy& pol = Policy()) {
  static const char* function = "spinslide::throw_plate<%1%>(plate_motion, planar_twist, %1%)";
  Real bad = 0;
  if (!detail::check_twist(function, start, bad, pol) ||
      !detail::check(function, "angle", angle, detail::argument_rule::finite, &bad, pol)) {
    return {bad, bad, {bad, bad}, bad, {bad, bad, 0, false}, false, {}};
  }
  return detail::plate_stop_run<Real>(plate, start, angle).run();
}

}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_PLATE_THROW_HPP
