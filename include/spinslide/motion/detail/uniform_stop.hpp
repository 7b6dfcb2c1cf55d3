//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file motion/detail/uniform_stop.hpp
/// A throw that starts in pure sliding, pure spinning or at rest
/// (docs/theory.md §9): it decelerates uniformly, and its stop is exact.

#ifndef SPINSLIDE_MOTION_DETAIL_UNIFORM_STOP_HPP
#define SPINSLIDE_MOTION_DETAIL_UNIFORM_STOP_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/base/detail/product.hpp>
#include <spinslide/motion/detail/stop_samples.hpp>
#include <spinslide/motion/motion_types.hpp>

#include <boost/math/tools/precision.hpp>

#include <limits>

namespace spinslide {
namespace detail {

/// A uniform deceleration of v and ω from (v0, ω0) that stops at `stop`.
template <class Real>
struct uniform_deceleration {
  Real v0, omega0;             ///< the start
  Real speed_rate, spin_rate;  ///< dv/dt and dω/dt, negated
  Real ratio;                  ///< ε all along (0 or ∞)
  Real stop;                   ///< the stop time

  /// The motion at time t.
  motion_sample<Real> at(Real t) const {
    const bool moving = t < stop;
    const Real te = moving ? t : stop;
    // The speeds lost by te; at the stop exactly v0 and ω0 (a ∞ · 0 there
    // otherwise, for a subnormal γ).  te (v0 − Δv/2), not v0 te − a te²/2,
    // which is ∞ − ∞ at the largest speeds (both found by fuzz_stop_time).
    const Real dv = moving ? Real(speed_rate * te) : v0;
    const Real dw = moving ? Real(spin_rate * te) : omega0;
    const Real v = v0 - dv, w = omega0 - dw;
    // The mean speed times te; 0 for a speed that stays 0, even where te overflows.
    auto travelled = [te](Real x0, Real dx) {
      const Real mean = x0 - dx / 2;
      return mean == 0 ? Real(0) : Real(te * mean);
    };
    return {t,     v > 0 ? v : Real(0), w > 0 ? w : Real(0),
            ratio, travelled(v0, dv),   travelled(omega0, dw)};
  }
};

/// The deceleration of a throw with v0 = 0 or ω0 = 0, and its stop time.
template <class Profile, class Real = typename Profile::value_type>
uniform_deceleration<Real> uniform_motion_of(const Profile& p, const throw_input<Real>& in) {
  if (in.v0 == 0 && in.omega0 == 0) return {in.v0, in.omega0, 0, 0, 0, 0};
  if (in.omega0 == 0)  // pure sliding: 𝓕(∞) = 1, v = v0 − t
    return {in.v0, in.omega0, 1, 0, std::numeric_limits<Real>::infinity(), in.v0};
  // pure spinning: 𝓣(0) = ⟨r⟩, ω = ω0 − ⟨r⟩t/γ.  (γω0)/⟨r⟩, not ω0/rate:
  // ⟨r⟩/γ overflows for a subnormal γ; and where γω0 leaves the normal
  // range, a product without spurious over- or underflow (a subnormal
  // ω0/⟨r⟩ rounded away 20%; found by fuzz_stop_time).
  using boost::math::tools::max_value;
  using boost::math::tools::min_value;
  const Real gw = in.gamma * in.omega0;
  const Real stop = gw >= min_value<Real>() && gw <= max_value<Real>()
                        ? Real(gw / p.mean_radius())
                        : detail::product(in.gamma, in.omega0, Real(1 / p.mean_radius()));
  return {in.v0, in.omega0, 0, p.mean_radius() / in.gamma, 0, stop};
}

/// The stop of a throw with v0 = 0 or ω0 = 0: the start and the stop
/// observed, the requested times sampled.
template <class Profile, class Observer, class Real = typename Profile::value_type>
stop_result<Real> uniform_stop(const Profile& p, const throw_input<Real>& in, Observer& observe,
                               stop_request<Real> request) {
  const uniform_deceleration<Real> motion = uniform_motion_of(p, in);
  const terminal_regime regime =
      in.v0 != 0 ? terminal_regime::pure_sliding : terminal_regime::pure_spinning;
  observe(motion.at(0));
  const motion_sample<Real> end = motion.at(motion.stop);
  observe(end);
  for (const Real& t : request.times) request.at_times.push_back(motion.at(t));
  return {motion.stop, end.distance, end.angle, {regime, motion.ratio}};
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_DETAIL_UNIFORM_STOP_HPP
