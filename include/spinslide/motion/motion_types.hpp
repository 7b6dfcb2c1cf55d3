//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file motion_types.hpp
/// What a throw's integration returns: a sample of the motion and the stop.

#ifndef SPINSLIDE_MOTION_MOTION_TYPES_HPP
#define SPINSLIDE_MOTION_MOTION_TYPES_HPP

#include <spinslide/motion/terminal_state.hpp>

namespace spinslide {

/// One sample of a trajectory, dimensionless or SI.
template <class Real>
struct motion_sample {
  using value_type = Real;  ///< the floating type
  Real time;                ///< t (t* or s)
  Real speed;               ///< v (v* or m/s)
  Real spin;                ///< ω (ω* or rad/s)
  Real ratio;               ///< ε = v*/ω* (0 or ∞ once one of them is 0)
  Real distance;            ///< distance slid so far (s* or m)
  Real angle;               ///< angle turned so far (θ* or rad)
};

/// The outcome of a throw: when and where it stops, and how ε ended.
template <class Real>
struct stop_result {
  using value_type = Real;        ///< the floating type
  Real time;                      ///< the stop time (both v and ω reach 0 then)
  Real distance;                  ///< distance slid
  Real angle;                     ///< angle turned
  terminal_state<Real> terminal;  ///< the regime and the limit of ε at the stop
};

}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_MOTION_TYPES_HPP
