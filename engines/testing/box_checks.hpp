//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// What the adapters' box runs (box_scenes.hpp) are held to with the
// contact's own patch, in every engine: the thrown box stops sliding and
// spinning within two steps of the exact stop, turned and moved as the
// exact face within 1 %; the pushed box turns, spins and moves as the
// exact face within 1 % (sideways within 2 % of its path: the box's 1 cm
// height shifts the engine's pressure by the inertial force at its centre
// of mass, which the uniform face of the reference leaves out; 0.3 mm here,
// 0.03 mm for a 1 mm box).
#ifndef SPINSLIDE_TESTS_ENGINES_BOX_CHECKS_HPP
#define SPINSLIDE_TESTS_ENGINES_BOX_CHECKS_HPP

#include <gtest/gtest.h>

#include "box_scenes.hpp"

#include <cmath>
#include <cstdio>

namespace box_checks {

inline void expect_exact_stop(const box_scenes::throw_outcome& o, double step, const char* what) {
  const auto exact = box_scenes::exact_throw();
  std::printf(
      "%s, step %g: slide stops %.5f s, spin %.5f s (exact %.5f: %+.2f and %+.2f steps), turned "
      "%.4f rad (exact %.4f), moved (%.4f, %.4f) m (exact (%.4f, %.4f))\n",
      what, step, o.slide_stop, o.spin_stop, exact.time, (o.slide_stop - exact.time) / step,
      (o.spin_stop - exact.time) / step, o.turn, exact.rotation, o.x, o.y, exact.displacement[0],
      exact.displacement[1]);
  EXPECT_TRUE(o.finite) << what;
  EXPECT_LE(std::fabs(o.slide_stop - exact.time), 2 * step) << what;
  EXPECT_LE(std::fabs(o.spin_stop - exact.time), 2 * step) << what;
  EXPECT_NEAR(o.turn, exact.rotation, 0.01 * exact.rotation) << what;
  EXPECT_NEAR(o.x, exact.displacement[0], 0.01 * exact.displacement[0]) << what;
}

inline void expect_exact_push(const box_scenes::pushed_state& o, const char* what) {
  const auto exact = box_scenes::exact_push();
  std::printf(
      "%s: turned %.4f rad (exact %.4f), moved (%.4f, %.4f) m (exact (%.4f, %.4f)), spin %.4f "
      "rad/s (exact %.4f)\n",
      what, o.angle, exact.angle, o.x, o.y, exact.x, exact.y, o.omega, exact.omega);
  EXPECT_NEAR(o.angle, exact.angle, 0.01 * std::fabs(exact.angle)) << what;
  EXPECT_NEAR(o.omega, exact.omega, 0.01 * std::fabs(exact.omega)) << what;
  EXPECT_NEAR(o.x, exact.x, 0.01 * std::fabs(exact.x)) << what;
  EXPECT_NEAR(o.y, exact.y, 0.02 * std::fabs(exact.x)) << what;
}

}  // namespace box_checks

#endif  // SPINSLIDE_TESTS_ENGINES_BOX_CHECKS_HPP
