//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file motion/detail/plate_step_control.hpp
/// The step control of a plate's throw (plate_throw.hpp): odeint's
/// Cash–Karp 5(4) error stepper and the standard controller on it (Hairer,
/// Nørsett & Wanner, Solving ODEs I, §II.4: the error in the max norm,
/// relative to 1 + |x|; the step scaled by 0.9·err^{−1/5}, within [0.2, 5]).
/// Not Fehlberg 7(8): its error estimate vanishes for quadrature-like
/// components (the time, turn and position here), and its results wandered
/// by 1e-9 at a tolerance of 1e-13; Cash–Karp's converge as the tolerance
/// (docs/plate_dynamics.md, "Accuracy").  Held by value, not through odeint's
/// controlled_runge_kutta, whose copy of a default-built stepper with std::array state reads
/// uninitialised members (g++'s -Wuninitialized).

#ifndef SPINSLIDE_MOTION_DETAIL_PLATE_STEP_CONTROL_HPP
#define SPINSLIDE_MOTION_DETAIL_PLATE_STEP_CONTROL_HPP

#include <boost/math/tools/config.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_cash_karp54.hpp>

#include <cmath>
#include <cstddef>

namespace spinslide {
namespace detail {

template <class State, class Real>
class plate_step_control {
 public:
  explicit plate_step_control(Real tolerance) : tolerance_(tolerance) {}

  /// One try from (s, x) with step ds: true and (s, x) advanced if accepted;
  /// ds becomes the next step to try either way.
  template <class System>
  bool try_step(const System& system, State& x, Real& s, Real& ds) {
    BOOST_MATH_STD_USING
    State trial = x, error = x;
    stepper_.do_step(system, trial, s, ds, error);
    Real worst = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      worst = fmax(worst, fabs(error[i]) / (tolerance_ * (1 + fabs(trial[i]))));
    if (!(worst <= 1)) {
      // A NaN error (a step into nothing) shrinks the step as much as allowed.
      ds *= worst > 1 ? fmax(Real(0.2), Real(0.9) * pow(worst, Real(-1) / 4)) : Real(0.2);
      return false;
    }
    s += ds;
    x = trial;
    ds *= worst > 0 ? fmin(Real(5), Real(0.9) * pow(worst, Real(-1) / 5)) : Real(5);
    return true;
  }

 private:
  boost::numeric::odeint::runge_kutta_cash_karp54<State, Real, State, Real> stepper_;
  Real tolerance_;
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_DETAIL_PLATE_STEP_CONTROL_HPP
