//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The impulse law's two ways to its answer once its frame is chosen
// (impulse_frame.hpp): the 3-D projection in the frame's units, returned in
// the limit set's (f, t = L/(μΛa)), and the limit a → 0, point friction
// (point_friction.hpp).
#ifndef SPINSLIDE_CONTACT_DETAIL_IMPULSE_IN_FRAME_HPP
#define SPINSLIDE_CONTACT_DETAIL_IMPULSE_IN_FRAME_HPP

#include <spinslide/base/detail/vector_access.hpp>
#include <spinslide/base/friction_result.hpp>
#include <spinslide/contact/detail/impulse_frame.hpp>
#include <spinslide/contact/detail/matrix3.hpp>
#include <spinslide/contact/detail/metric_projector.hpp>
#include <spinslide/contact/detail/point_friction.hpp>
#include <spinslide/contact/detail/torque_scaled.hpp>
#include <spinslide/contact/planar_metric.hpp>

#include <boost/math/tools/precision.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <array>
#include <cmath>
#include <limits>

namespace spinslide {
namespace detail {

// ε = |v|/(a|ω|) of a slip: 0 where the slide has stopped (also for a = 0),
// +∞ where aω is 0 (or underflows) and the slide goes on.
template <class Real>
Real slip_ratio(Real speed, Real a, Real spin) {
  using std::fabs;
  if (speed == 0) return 0;
  const Real across = a * fabs(spin);
  return across > 0 ? Real(speed / across) : std::numeric_limits<Real>::infinity();
}

// A ratio at which 𝓕 is near `force` (in (0, 1)), to 12 bits: a start only.
template <class Profile, class Real = typename Profile::value_type>
Real rough_ratio_at_force(const Profile& profile, Real force) {
  Real lo = 1, hi = 1;
  const Real largest = boost::math::tools::max_value<Real>() / 4;
  while (profile.force(lo) > force && lo > boost::math::tools::min_value<Real>() * 4) lo /= 4;
  while (profile.force(hi) < force && hi < largest) hi *= 4;
  auto miss = [&](Real e) { return profile.force(e) - force; };
  const Real below = miss(lo), above = miss(hi);
  if (!(below < 0 && above > 0)) return below >= 0 ? lo : hi;
  boost::uintmax_t steps = 16;
  const auto r = boost::math::tools::toms748_solve(
      miss, lo, hi, below, above, boost::math::tools::eps_tolerance<Real>(12), steps);
  return (r.first + r.second) / 2;
}

// The start of a projection onto a thin set (frame.k ≤ 1e-3) given none:
// the ratio point friction's answer leaves (the limit a → 0, which a thin
// set is near).  From a start on the flat set's cap, away from it, Newton's
// steps cross D's core |s_f| ≈ k|s_t| (a cone at the scale of the set's
// thickness) in steps of that size: at k = 1e-15 it ran out of iterations at
// points that added energy.  Its slide goes on: ε' = |v⁺|/(c|ω⁺|); it
// stopped: the ratio where 𝓕 is the impulse's |P|/(μΛ), times k.
template <class Profile, class Real = typename Profile::value_type>
Real thin_start(const Profile& profile, const impulse_frame<Real>& frame,
                const planar_metric<Real>& w, const vector3<Real>& slip, Real load) {
  using std::fabs;
  const point_impulse<Real> p = point_friction(w.entries(), slip[0], slip[1], load);
  const auto& m = w.entries();
  const Real spin = slip[2] + m[2][0] * p.force[0] + m[2][1] * p.force[1];
  if (p.slip > 0) return p.slip / fabs(frame.c * spin);  // ∞ (no start) if spin = 0
  // (No slide at all, P = 0: the thin set's answer is near pure spin, ε → 0.)
  const Real f = length(p.force[0], p.force[1]) / load;
  if (!(f > 0)) return frame.k * Real(1e-3);
  return f < 1 ? frame.k * rough_ratio_at_force(profile, f) : Real(0);
}

// What a start for a thin set is found from: W, the slip before the step
// and μΛ.
template <class Real>
struct law_inputs {
  const planar_metric<Real>& w;
  const vector3<Real>& slip;
  Real load;
};

// The nearest point of L₃ to `target` (in the frame's units) in the frame's
// metric, for a frame whose curve is scaled (k ≠ 1; impulse_friction
// projects on the profile's own curve itself), in the limit set's units,
// from `start` (in the profile's), or for a thin set without one from
// thin_start.
template <class Profile, class Real = typename Profile::value_type>
friction_result<std::array<Real, 2>, Real> project_in_frame(const Profile& profile,
                                                            const impulse_frame<Real>& frame,
                                                            const vector3<Real>& target,
                                                            const curve_point<Real>& start,
                                                            const law_inputs<Real>& law) {
  const Real s0 = start.ratio;
  // The start and the answer between the units: ε' = kε, 𝓣' = k𝓣, 𝓕′' = 𝓕′/k.
  const Real k = frame.k;
  const bool given = s0 > 0 && s0 < std::numeric_limits<Real>::infinity();
  const curve_point<Real> from =
      given || k > Real(1e-3)
          ? curve_point<Real>{k * s0, start.force, k * start.torque, start.slope / k,
                              start.curvature / (k * k)}
          : curve_point<Real>{thin_start(profile, frame, law.w, law.slip, law.load)};
  const torque_scaled<Profile> curve(profile, k);
  friction_result<std::array<Real, 2>, Real> r = metric_projector<torque_scaled<Profile>>(
      curve, target, frame.metric, frame.inverse)(from.ratio, &from);
  if (r.sticking) return r;
  r.torque /= k;
  r.ratio /= k;
  r.point.ratio /= k;
  r.point.torque /= k;
  return r;
}

// The law's answer in the limit a → 0 (frame.point): the linear impulse of
// point friction, no angular impulse; the slip after the step goes on at
// ε = |v⁺|/(a|ω⁺|) (`out` carries the result's other fields).  Sticking only
// where the spin is 0 too.
template <class Vec2, class Real>
impulse_result<Vec2, Real> point_limit_result(impulse_result<Vec2, Real> out,
                                              const planar_metric<Real>& w,
                                              const vector3<Real>& slip, Real a, Real load) {
  const point_impulse<Real> p = point_friction(w.entries(), slip[0], slip[1], load);
  const auto& m = w.entries();
  const Real spin = slip[2] + m[2][0] * p.force[0] + m[2][1] * p.force[1];
  set<0>(out.force, p.force[0]);
  set<1>(out.force, p.force[1]);
  out.torque = 0;
  out.sticking = p.slip == 0 && spin == 0;
  out.ratio = out.sticking ? std::numeric_limits<Real>::quiet_NaN() : slip_ratio(p.slip, a, spin);
  out.point = {};
  return out;
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_IMPULSE_IN_FRAME_HPP
