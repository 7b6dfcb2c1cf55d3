//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The inner triangle of every limit set: sticking decided without evaluating
// the profile (limit_projector.hpp, trial_cap.hpp, impulse_friction.hpp).
#ifndef SPINSLIDE_CONTACT_DETAIL_STICKING_TRIANGLE_HPP
#define SPINSLIDE_CONTACT_DETAIL_STICKING_TRIANGLE_HPP

namespace spinslide {
namespace detail {

// True if (f, t) lies in the triangle (0, 0), (1, 0), (0, ⟨r⟩) (`top` =
// ⟨r⟩), which lies in every profile's L (convex, with those three points):
// sticking, without evaluating the profile.
template <class Real>
bool in_sticking_triangle(Real f, Real t, Real top) {
  return f + t / top <= 1;
}
// The same for a force (fx, fy) and a torque t ≥ 0, without a square root:
// |f|² ≤ (1 − t/⟨r⟩)² (a square that overflows is outside, one that
// underflows inside, as they are).
template <class Real>
bool in_sticking_triangle(Real fx, Real fy, Real t, Real top) {
  const Real room = 1 - t / top;
  return room >= 0 && fx * fx + fy * fy <= room * room;
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_STICKING_TRIANGLE_HPP
