//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file motion/detail/plate_direction_flow.hpp
/// A thrown plate in the variable s = −ln(r/r₀), r = |(u, kω)| the size of
/// the twist (docs/plate_dynamics.md, "Through the stop").  With n = (u, kω)/r
/// and A = (F, τ/k): n·A = −D(n) (Euler's relation for the dissipation D,
/// homogeneous of degree 1), and the Coriolis term is orthogonal to n, so
///   dr/dt = −μg D(n),   dt/ds = r/(μg D),
///   dn/ds = (A + D n)/D + β e^{−2s} (n₃/D)(n₂, −n₁, 0),   β = r₀²/(μg k):
/// r falls as e^{−s} exactly, the stop is at s = ∞ and the time, turn and
/// displacement still to come after s are O(e^{−s}) (closed-form tails); the
/// direction obeys, as s → ∞, the autonomous flow dn/ds = −∇_S ln D on the
/// unit sphere, whose fixed points are the critical points of D.

#ifndef SPINSLIDE_MOTION_DETAIL_PLATE_DIRECTION_FLOW_HPP
#define SPINSLIDE_MOTION_DETAIL_PLATE_DIRECTION_FLOW_HPP

#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <boost/math/tools/config.hpp>

#include <array>
#include <cmath>
#include <cstddef>

namespace spinslide {
namespace detail {

/// The direction n (normalised here), its wrench A = (F, τ/k) and D(n) = −n·A.
template <class Real>
struct plate_direction {
  std::array<Real, 3> n;
  std::array<Real, 3> a;
  Real dissipation;
};

template <class Real>
plate_direction<Real> direction_wrench(const polygon_patch<Real>& patch, Real k,
                                       const std::array<Real, 3>& x) {
  BOOST_MATH_STD_USING
  const Real norm = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  plate_direction<Real> d{{x[0] / norm, x[1] / norm, x[2] / norm}, {0, 0, 0}, 0};
  const planar_wrench<Real> f = wrench_of(patch, planar_twist<Real>{{d.n[0], d.n[1]}, d.n[2] / k});
  d.a = {f.force[0], f.force[1], f.torque / k};
  d.dissipation = -(d.n[0] * d.a[0] + d.n[1] * d.a[1] + d.n[2] * d.a[2]);
  return d;
}

/// The throw in s, in the units r₀ (velocity), r₀/(μg) (time), r₀²/(μg)
/// (length): y = {n₁, n₂, n₃, t, θ, X, Y, path}.  An odeint
/// system; where D is not positive (a twist that rounded to nothing) it
/// returns zero rates, and the driver's step limit ends the integration.
template <class Real>
class plate_stop_flow {
 public:
  using state = std::array<Real, 8>;

  plate_stop_flow(const polygon_patch<Real>& patch, Real k, Real beta)
      : patch_(&patch), k_(k), beta_(beta) {}

  void operator()(const state& y, state& dyds, Real s) const {
    BOOST_MATH_STD_USING
    const plate_direction<Real> d = direction_wrench(*patch_, k_, {y[0], y[1], y[2]});
    dyds.fill(0);
    if (!(d.dissipation > 0)) return;
    const Real e1 = exp(-s), e2 = e1 * e1, D = d.dissipation;
    const Real coriolis = beta_ * e2 * d.n[2] / D;
    dyds[0] = (d.a[0] + D * d.n[0]) / D + coriolis * d.n[1];
    dyds[1] = (d.a[1] + D * d.n[1]) / D - coriolis * d.n[0];
    dyds[2] = (d.a[2] + D * d.n[2]) / D;
    dyds[3] = e1 / D;
    dyds[4] = beta_ * e2 * d.n[2] / D;
    const Real c = cos(y[4]), sn = sin(y[4]);
    dyds[5] = e2 * (c * d.n[0] - sn * d.n[1]) / D;
    dyds[6] = e2 * (sn * d.n[0] + c * d.n[1]) / D;
    dyds[7] = e2 * sqrt(d.n[0] * d.n[0] + d.n[1] * d.n[1]) / D;
  }

 private:
  const polygon_patch<Real>* patch_;
  Real k_, beta_;
};

/// The autonomous direction flow at the stop, dn/ds = (A + D n)/D.
template <class Real>
class plate_terminal_flow {
 public:
  using state = std::array<Real, 3>;

  plate_terminal_flow(const polygon_patch<Real>& patch, Real k) : patch_(&patch), k_(k) {}

  void operator()(const state& y, state& dyds, Real /*s*/) const {
    const plate_direction<Real> d = direction_wrench(*patch_, k_, y);
    dyds.fill(0);
    if (!(d.dissipation > 0)) return;
    for (std::size_t i = 0; i < 3; ++i) dyds[i] = (d.a[i] + d.dissipation * d.n[i]) / d.dissipation;
  }

 private:
  const polygon_patch<Real>* patch_;
  Real k_;
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_DETAIL_PLATE_DIRECTION_FLOW_HPP
