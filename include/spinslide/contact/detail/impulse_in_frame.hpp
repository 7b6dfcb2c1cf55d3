//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The impulse law's ways to its answer once its frame is chosen
// (impulse_frame.hpp): the 3-D projection in the frame's units, returned in
// the limit set's (f, t = L/(μΛa)); point friction (point_friction.hpp),
// the limit a → 0 and the start for a thin set (thin_set.hpp).
#ifndef SPINSLIDE_CONTACT_DETAIL_IMPULSE_IN_FRAME_HPP
#define SPINSLIDE_CONTACT_DETAIL_IMPULSE_IN_FRAME_HPP

#include <spinslide/base/detail/vector_access.hpp>
#include <spinslide/base/friction_result.hpp>
#include <spinslide/contact/detail/impulse_frame.hpp>
#include <spinslide/contact/detail/matrix3.hpp>
#include <spinslide/contact/detail/metric_projector.hpp>
#include <spinslide/contact/detail/point_friction.hpp>
#include <spinslide/contact/detail/thin_set.hpp>
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

// Point friction's answer (point_friction.hpp, the limit a → 0) for the
// slip and μΛ of `law`, and the spin after it, σ₀ = ω + W_ωf·P₀.
template <class Real>
struct point_answer {
  point_impulse<Real> p;
  Real spin;
};

template <class Real>
point_answer<Real> point_answer_for(const law_inputs<Real>& law) {
  const auto& m = law.w.entries();
  const point_impulse<Real> p = point_friction(m, law.slip[0], law.slip[1], law.load);
  return {p, law.slip[2] + m[2][0] * p.force[0] + m[2][1] * p.force[1]};
}

// The ratio (in the profile's units) that point friction's answer leaves
// on a patch of radius a: where its slide goes on, ε = |v⁺|/(a|ω⁺|) (∞ if
// the spin after it is 0); where it stopped, the ratio where 𝓕 is the
// impulse's |P|/(μΛ), to 12 bits (0 on the circle itself); where there is
// no slide at all (P = 0), 1e-3, near pure spin.  A start for a thin set,
// which is near that limit.
template <class Profile, class Real = typename Profile::value_type>
Real point_ratio(const Profile& profile, const point_answer<Real>& q, Real a, Real load) {
  if (q.p.slip > 0) return slip_ratio(q.p.slip, a, q.spin);
  const Real f = length(q.p.force[0], q.p.force[1]) / load;
  if (!(f > 0)) return Real(1e-3);
  return f < 1 ? rough_ratio_at_force(profile, f) : Real(0);
}

// The start of a projection onto a thin set (frame.k ≤ 1e-3) given none:
// the ratio point friction's answer leaves (point_ratio, in the frame's
// units: times k).  From a start on the flat set's cap, away from it,
// Newton's steps cross D's core |s_f| ≈ k|s_t| (a cone at the scale of the
// set's thickness) in steps of that size: at k = 1e-15 it ran out of
// iterations at points that added energy.
template <class Profile, class Real = typename Profile::value_type>
Real thin_start(const Profile& profile, const impulse_frame<Real>& frame,
                const law_inputs<Real>& law) {
  return frame.k * point_ratio(profile, point_answer_for(law), frame.k * frame.c, law.load);
}

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
  const curve_point<Real> from = given || k > Real(1e-3)
                                     ? curve_point<Real>{k * s0, start.force, k * start.torque,
                                                         start.slope / k, start.curvature / (k * k)}
                                     : curve_point<Real>{thin_start(profile, frame, law)};
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

// The law's answer in the limit a → 0: point friction's impulse `q`, no
// angular impulse; the slip after the step goes on at ε = |v⁺|/(a|ω⁺|)
// (`out` carries the result's other fields).  Sticking only where the spin
// is 0 too.
template <class Vec2, class Real>
impulse_result<Vec2, Real> point_limit_result(impulse_result<Vec2, Real> out,
                                              const point_answer<Real>& q, Real a) {
  set<0>(out.force, q.p.force[0]);
  set<1>(out.force, q.p.force[1]);
  out.torque = 0;
  out.sticking = q.p.slip == 0 && q.spin == 0;
  out.ratio =
      out.sticking ? std::numeric_limits<Real>::quiet_NaN() : slip_ratio(q.p.slip, a, q.spin);
  out.point = {};
  return out;
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_IMPULSE_IN_FRAME_HPP
