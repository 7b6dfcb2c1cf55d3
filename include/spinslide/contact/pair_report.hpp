//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)

/// \file pair_report.hpp
/// What an engine adapter did at one coupled pair in its last step: one type
/// for every adapter (MuJoCo, Bullet, Box2D; docs/engines.md, "Reports").
///
/// Vectors are in world axes.  The pair has a first and a second body (the
/// order the report was asked in); the normal points from the first into the
/// second, and the friction impulses are those on the first body (the second
/// gets their opposites).  The impulses are over the step; the *_force()
/// members divide them by it.
#ifndef SPINSLIDE_CONTACT_PAIR_REPORT_HPP
#define SPINSLIDE_CONTACT_PAIR_REPORT_HPP

#include <array>
#include <cstddef>
#include <limits>

namespace spinslide {

/// One coupled pair's last step (see the file's comment).
struct pair_report {
  int contacts = 0;                ///< the engine's contact points between the two (0: apart)
  double step = 0;                 ///< the time step Δt [s] (0 before the first step)
  double normal_impulse = 0;       ///< Λ, their summed normal impulse over the step [N s]
  double penetration = 0;          ///< the deepest penetration δ [m]
  double patch_radius = 0;         ///< the patch radius a used [m]
  std::array<double, 3> centre{};  ///< the patch centre [m]
  std::array<double, 3> normal{};  ///< the unit contact normal, from the first body to the second
  bool sticking = false;           ///< the friction impulse stopped the pair's relative motion
  /// ε = |v|/(a|ω|) of the pair's slip after the step: NaN when sticking or
  /// apart, in every adapter.
  double ratio = std::numeric_limits<double>::quiet_NaN();
  std::array<double, 3> friction_impulse{};  ///< on the first body, in the tangent plane [N s]
  double spin_impulse =
      0;  ///< the friction's angular impulse on the first body about `normal` [N m s]

  /// True if the two touched in the step.
  bool touching() const { return contacts > 0; }
  /// N = Λ/Δt [N] (0 before the first step).
  double normal_force() const { return per_step(normal_impulse); }
  /// The mean friction force on the first body over the step [N].
  std::array<double, 3> friction_force() const {
    return {per_step(friction_impulse[0]), per_step(friction_impulse[1]),
            per_step(friction_impulse[2])};
  }
  /// The mean friction torque on the first body about `normal` [N m].
  double friction_torque() const { return per_step(spin_impulse); }

  /// The same step seen from the second body: the normal and the friction
  /// impulse reversed (the spin impulse about the reversed normal is the
  /// same number).
  pair_report reversed() const {
    pair_report r = *this;
    for (std::size_t k = 0; k < 3; ++k) {
      r.normal[k] = -normal[k];
      r.friction_impulse[k] = -friction_impulse[k];
    }
    return r;
  }

 private:
  double per_step(double impulse) const { return step > 0 ? impulse / step : 0.0; }
};

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_PAIR_REPORT_HPP
