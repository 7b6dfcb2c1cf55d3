//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file ring_kernel.hpp
/// The ring kernel of docs/theory.md §6 — the friction force and torque of a
/// thin ring of load — and its quadrature over a radial load, on which every
/// profile without a closed form is built.
#ifndef SPINSLIDE_VALUES_DETAIL_RING_KERNEL_HPP
#define SPINSLIDE_VALUES_DETAIL_RING_KERNEL_HPP

#include <spinslide/values/force_torque_result.hpp>

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>

#include <cmath>
#include <utility>

namespace spinslide {
namespace detail {

// The policy the profiles evaluate their elliptic integrals with: the
// caller's, without promotion (a quadrature sums many kernel values, so a
// wider type buys nothing but time).
template <class Policy>
using kernel_policy =
    typename boost::math::policies::normalise<Policy, boost::math::policies::promote_float<false>,
                                              boost::math::policies::promote_double<false>>::type;

/// The ring kernel (theory (R1)–(R2)): force and torque, per unit load, of a
/// thin ring of radius r, at ratio ε.  `distance` is |r − ε|, computed by the
/// caller without cancellation (quadrature nodes near r = ε know it exactly).
/// With c = min(r, ε)/max(r, ε), y = 1 − c², K = R_F(0, y, 1) and
/// B̃ = (y/3) R_D(0, 1, y) = (E − yK)/c² (DLMF 19.25.1):
///   r < ε:  f_F = (2/π) E(c) = (2/π)(yK + c²B̃),   f_T = (2/π) r c B̃,
///   r > ε:  f_F = (2/π) c B̃,                      f_T = (2/π) r (yK + c²B̃).
/// Every term is non-negative; as r → ε (y → 0) yK → 0 and B̃ → 1.
template <class T, class Policy>
force_torque_result<T> ring_kernel(T r, T eps, T distance, const Policy& pol) {
  using boost::math::constants::two_div_pi;
  const bool inside = r < eps;  // the ring lies inside the circle through P
  const T big = inside ? eps : r;
  const T c = inside ? T(r / eps) : T(eps / r);
  const T y = (distance / big) * ((r + eps) / big);  // big² could overflow
  // For a subnormal y (a quadrature node within about the smallest normal
  // number of r = ε), Boost's R_F and R_D return NaN; the limits yK = 0 and
  // B̃ = 1 are then exact to far below an ulp (the corrections are O(y ln y)).
  T yK = 0, Bt = 1;
  if (y >= boost::math::tools::min_value<T>()) {
    yK = y * boost::math::ellint_rf(T(0), y, T(1), pol);
    Bt = y / 3 * boost::math::ellint_rd(T(0), T(1), y, pol);
  }
  if (inside) return {two_div_pi<T>() * (yK + c * c * Bt), two_div_pi<T>() * r * c * Bt};
  return {two_div_pi<T>() * c * Bt, two_div_pi<T>() * r * (yK + c * c * Bt)};
}

template <class T>
struct ring_node {
  T r;            // the radius
  T one_minus_r;  // 1 − r, exact near r = 1
};

// ∫ w(r) (f_F, f_T)(r, ε) dr over [inner, 1], split at r = ε where the kernel's
// derivative has its logarithmic singularity.  w(node) is the load per unit
// radius; Boost's tanh_sinh handles integrable endpoint singularities of w
// (such as Boussinesq's 1/√(1−r)) given the exact complement 1 − r.
template <class T, class Weight, class Policy>
force_torque_result<T> ring_integral(const Weight& w, T inner, T eps, const Policy& pol) {
  BOOST_MATH_STD_USING
  // One integrator per thread and type: tanh_sinh extends its abscissa
  // tables lazily, which must not race.
  static thread_local boost::math::quadrature::tanh_sinh<T, Policy> q;
  // tanh_sinh stops when two levels agree to `tol`; its error is then about
  // tol², except where a feature of width ε sits at an endpoint (ε → 0),
  // which the default root_epsilon misjudged by 1e-12 at ε = 1e-6.
  static const T tol = pow(boost::math::tools::epsilon<T>(), T(0.75));
  force_torque_result<T> total{0, 0};
  auto segment = [&](T a, T b) {
    // tanh_sinh passes x and xc: xc < 0 is a − x, xc > 0 is b − x.
    auto node = [&](T x, T xc) {
      const T from_a = xc < 0 ? T(-xc) : T(x - a);
      const T to_b = xc > 0 ? xc : T(b - x);
      const T one_minus_r = b == 1 ? to_b : T(1 - x);
      const T distance = a == eps ? from_a : (b == eps ? to_b : T(abs(x - eps)));
      return std::make_pair(ring_node<T>{x, one_minus_r}, distance);
    };
    auto force = [&](T x, T xc) {
      const auto n = node(x, xc);
      return T(w(n.first) * ring_kernel(x, eps, n.second, pol).force);
    };
    auto torque = [&](T x, T xc) {
      const auto n = node(x, xc);
      return T(w(n.first) * ring_kernel(x, eps, n.second, pol).torque);
    };
    total.force += q.integrate(force, a, b, tol);
    total.torque += q.integrate(torque, a, b, tol);
  };
  if (inner < eps && eps < 1) {
    segment(inner, eps);
    segment(eps, T(1));
  } else {
    segment(inner, T(1));
  }
  return total;
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DETAIL_RING_KERNEL_HPP
