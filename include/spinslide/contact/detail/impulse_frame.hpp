//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The units the impulse law projects in (impulse_friction.hpp; docs/theory.md
// §11, "A patch that starts at zero").  The law's set is μΛ·{(f, a t)} over
// L₃ in the metric W over (P_x, P_y, L).  With the angular impulse in units
// of c, L = cτ, the set is μΛ times the curve (𝓕(ε/k), k𝓣(ε/k)), k = a/c
// (torque_scaled.hpp), in the metric CWC, C = diag(1, 1, c):
//  - c = a (k = 1, the profile's own curve) wherever SWS = CWC is well
//    conditioned: a patch radius near W's own length scale, as a coin's;
//  - otherwise c = √((W_xx + W_yy)/(2W_ωω)), W's own length scale, which
//    balances CWC's diagonal (as well conditioned as W, in practice; if not,
//    c = 1 and the metric is W itself, which planar_metric accepted);
//  - where then k, times the profile's own width 2/⟨1/r⟩ where that is
//    below 1, is below 16√κ ε_mach (κ = ‖CWC‖_F‖(CWC)⁻¹‖_F: a = 0, or a
//    patch 1e-14 of W's scale in double), no projection: the thin set's
//    answer in the impulse's own variables (thin_set.hpp; point friction,
//    point_friction.hpp, at a = 0).  Below that the 3-D projection cannot
//    resolve the answer: on a thin set the slip's force part is about
//    k|s_t|, at the rounding of s (random metrics: energy rising from
//    k = 1.6e-14 at κ = 1.8e6 down, none above).  The kernel answers each
//    component to a few ulp of its own scale (μΛ, μΛa⟨r⟩) times the
//    problem's own conditioning, where point friction was off by about κk
//    of μΛ and by all of the torque (tests/test_thin_set.cpp).
//  - a patch beyond 1/(16√κ ε_mach) of W's scale (1e13 of it in double, a
//    patch larger than any body it joins) is a bad argument, a domain error:
//    the fuzzer found the projection wrong (more energy) for a = 1e238 m.
#ifndef SPINSLIDE_CONTACT_DETAIL_IMPULSE_FRAME_HPP
#define SPINSLIDE_CONTACT_DETAIL_IMPULSE_FRAME_HPP

#include <spinslide/contact/detail/matrix3.hpp>
#include <spinslide/contact/planar_metric.hpp>

#include <boost/math/tools/precision.hpp>

#include <cmath>
#include <cstddef>
#include <limits>

namespace spinslide {
namespace detail {

template <class Real>
struct impulse_frame {
  Real c = 1;              // the angular impulse's unit: L = cτ
  Real k = 1;              // a/c: the curve's torque axis times k (1: the profile's own curve)
  bool point = false;      // a thin set: no projection (thin_set.hpp)
  bool too_large = false;  // a beyond 1/(16√κ ε_mach) times W's scale: a domain error
  matrix3<Real> metric, inverse;  // CWC and C⁻¹W⁻¹C⁻¹ (always set: scale_metric)
};

// CWC and its inverse for C = diag(1, 1, c), divided and multiplied by
// CWC's largest diagonal entry (metric_projector's own scaling, which then
// finds that entry 1 and leaves them).  (c² is normal for every c used: a
// where SWS is well conditioned, W's own scale, whose square is a ratio of
// W's diagonal entries, within its condition number, or 1.)  Symmetric:
// the upper triangle is computed and mirrored.
template <class Real>
void scale_metric(const planar_metric<Real>& w, Real c, impulse_frame<Real>& out) {
  const auto& m = w.entries();
  const auto& v = w.inverse();
  const Real corner = c * m[2][2] * c;
  const Real top = m[0][0] > m[1][1] ? (m[0][0] > corner ? m[0][0] : corner)
                                     : (m[1][1] > corner ? m[1][1] : corner);
  auto& a = out.metric;
  auto& b = out.inverse;
  a[0][0] = m[0][0] / top;
  a[1][1] = m[1][1] / top;
  a[2][2] = corner / top;
  a[0][1] = a[1][0] = m[0][1] / top;
  a[0][2] = a[2][0] = c * m[0][2] / top;
  a[1][2] = a[2][1] = c * m[1][2] / top;
  b[0][0] = v[0][0] * top;
  b[1][1] = v[1][1] * top;
  b[2][2] = v[2][2] / (c * c) * top;
  b[0][1] = b[1][0] = v[0][1] * top;
  b[0][2] = b[2][0] = v[0][2] / c * top;
  b[1][2] = b[2][1] = v[1][2] / c * top;
  out.c = c;
}

// The frame for W = `w`, the patch radius a ≥ 0 (finite) and the profile's
// own width `core` = 2/⟨1/r⟩ (1 for the uniform disk; 1e-6 for a load
// concentrated within radius 1e-6: its 𝓕 rises over ε ≈ core, and the set's
// thinness that the 3-D projection must resolve is k·core, not k).
template <class Real>
impulse_frame<Real> impulse_frame_for(const planar_metric<Real>& w, Real a, Real core = 1) {
  using std::sqrt;
  impulse_frame<Real> out;
  if (a > 0) {
    // (‖SWS‖_F‖(SWS)⁻¹‖_F ≤ κ_F(W)·max(a, 1/a)²: the exact test only where
    // that bound is not enough.)
    const Real spread = a > 1 ? a : Real(1 / a);
    const bool surely =
        w.condition_bound() * spread * spread * sqrt(std::numeric_limits<Real>::epsilon()) <= 1;
    scale_metric(w, a, out);
    if (surely || well_conditioned(out.metric, out.inverse)) return out;
  }
  const auto& m = w.entries();
  const Real balanced = sqrt((m[0][0] + m[1][1]) / (2 * m[2][2]));
  scale_metric(w, (boost::math::isfinite)(balanced) && balanced > 0 ? balanced : Real(1), out);
  if (!well_conditioned(out.metric, out.inverse)) scale_metric(w, Real(1), out);
  out.k = a / out.c;
  const Real condition = frobenius(out.metric) * frobenius(out.inverse);
  const Real thin = 16 * sqrt(condition) * std::numeric_limits<Real>::epsilon();
  const Real width = (boost::math::isfinite)(core) && core > 0 && core < 1 ? core : Real(1);
  out.point = !(out.k * width >= thin);
  out.too_large = !(out.k <= 1 / thin);
  return out;
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_IMPULSE_FRAME_HPP
