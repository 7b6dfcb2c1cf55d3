//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file plate_motion.hpp
/// The equations of motion of a flat plate thrown on a plane, as an odeint
/// system (sys(x, dxdt, t)) in time (docs/plate_dynamics.md, "The model"):
/// the plate's contact face is a polygon_patch (its centre of mass above the
/// patch origin, its normal load mg), its radius of gyration k = √(I/m), the
/// friction coefficient μ and gravity g.  In the body frame, u the velocity
/// of the centre, ω the spin, θ the orientation and X the world position,
///   du/dt = μg F(u, ω) − ω ẑ × u,   dω/dt = μg τ(u, ω)/k²,
///   dθ/dt = ω,                      dX/dt = R(θ) u,
/// with (F, τ) = friction_wrench(patch, {u, ω}) per unit μN.  plate_throw.hpp
/// integrates a throw through its stop; plate_terminal.hpp finds how it ends.

#ifndef SPINSLIDE_MOTION_PLATE_MOTION_HPP
#define SPINSLIDE_MOTION_PLATE_MOTION_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/base/named_inputs.hpp>
#include <spinslide/motion/throw_inputs.hpp>
#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <array>
#include <cmath>
#include <utility>

namespace spinslide {

/// The state plate_motion integrates: {u_x, u_y, ω, θ, X, Y} (the body-frame
/// velocity of the centre, the spin, the orientation, the world position).
template <class Real>
using plate_state = std::array<Real, 6>;

/// A plate of face `patch` and radius of gyration k under friction μ and
/// gravity g; every length in the patch's unit, time in the unit of g.
template <class Real>
class plate_motion {
 public:
  using value_type = Real;  ///< the floating type

  /// k, μ and g finite and > 0, otherwise std::domain_error naming the argument.
  plate_motion(polygon_patch<Real> patch, gyration_radius<Real> k, friction_coefficient<Real> mu,
               gravity<Real> g)
      : patch_(std::move(patch)),
        k_(positive("gyration_radius", k.value)),
        deceleration_(positive("friction_coefficient", mu.value) * positive("gravity", g.value)) {}

  /// odeint's system call: x = {u_x, u_y, ω, θ, X, Y} → dx/dt.  At rest (u = 0
  /// and ω = 0) the friction vanishes: the plate stays at rest.  Never throws
  /// for finite x.
  template <class State, class Time>
  void operator()(const State& x, State& dxdt, Time /*t*/) const {
    const Real ux = x[0], uy = x[1], w = x[2];
    Real fx = 0, fy = 0, tau = 0;
    if (ux != 0 || uy != 0 || w != 0) {
      const planar_wrench<Real> f = detail::wrench_of(patch_, planar_twist<Real>{{ux, uy}, w});
      fx = f.force[0];
      fy = f.force[1];
      tau = f.torque;
    }
    BOOST_MATH_STD_USING
    const Real c = cos(Real(x[3])), s = sin(Real(x[3]));
    // The body frame turns with ω: d(R u)/dt = R (du/dt + ω ẑ × u) = μg R F.
    dxdt[0] = deceleration_ * fx + w * uy;
    dxdt[1] = deceleration_ * fy - w * ux;
    dxdt[2] = deceleration_ * tau / (k_ * k_);
    dxdt[3] = w;
    dxdt[4] = c * ux - s * uy;
    dxdt[5] = s * ux + c * uy;
  }

  /// The contact face.
  const polygon_patch<Real>& patch() const { return patch_; }
  /// k = √(I/m).
  Real radius_of_gyration() const { return k_; }
  /// μg, the deceleration of pure sliding.
  Real deceleration() const { return deceleration_; }

 private:
  static Real positive(const char* name, Real x) {
    return detail::checked_constructor_argument(
        "spinslide::plate_motion<%1%>::plate_motion(patch, gyration_radius, friction_coefficient, "
        "gravity)",
        name, x, detail::argument_rule::finite_positive);
  }
  polygon_patch<Real> patch_;
  Real k_;
  Real deceleration_;
};

}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_PLATE_MOTION_HPP
