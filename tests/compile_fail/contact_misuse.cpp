//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Misuse of the contact law (contact_law.hpp) must not compile: a vector must be
// a class with operator[] or members x, y (, z).  A raw pointer, as MuJoCo's
// mjtNum* (a typedef of double*), compiled and then wrote through a null
// "vector" (issue 17).  The radius, the normal force and μ are named by their
// types, and the velocity scale is required.  Compiled by tests/compile_fail/check.cmake once per
// MISUSE: 0 is the correct call, every other value must fail with the
// message the test expects.
#include <spinslide/contact/contact_law.hpp>

#include <array>

int main() {
  using namespace spinslide;
  const contact_law<> law(uniform_disk<>(), velocity_scale<double>{1e-3});
  const force_contact<double> c{patch_radius<double>{0.06}, normal_force<double>{1.0},
                                friction_coefficient<double>{0.2}};
  using mjtNum = double;
  mjtNum qvel[6] = {0.3, 0.1, 0, 0, 0, 5};
#if MISUSE == 0
  const std::array<double, 2> v{qvel[0], qvel[1]};
  const std::array<double, 3> v3{qvel[0], qvel[1], qvel[2]}, w3{qvel[3], qvel[4], qvel[5]},
      n{0, 0, 1};
  const auto planar = law(v, qvel[5], c);
  const auto spatial = law(v3, w3, contact_normal{n}, c);
  return planar.force[0] < 0 && spatial.force[0] < 0 ? 0 : 1;
#elif MISUSE == 1
  // A raw pointer for the planar velocity.
  const mjtNum* v = qvel;
  return law(v, qvel[5], c).torque < 0 ? 0 : 1;
#elif MISUSE == 2
  // Raw pointers for the 3-D vectors (MuJoCo's d->qvel + 3 and friends).
  const mjtNum* v = qvel;
  const mjtNum* w = qvel + 3;
  const mjtNum* n = qvel;
  return law(v, w, contact_normal{n}, c).force != nullptr ? 0 : 1;
#elif MISUSE == 3
  // A C array: its size is not the law's to guess, and it cannot be returned.
  const double v[2] = {0.3, 0.1};
  return law(v, qvel[5], c).torque < 0 ? 0 : 1;
#elif MISUSE == 4
  // A plain number for a vector.
  return law(0.3, qvel[5], c).torque < 0 ? 0 : 1;
#elif MISUSE == 5
  // The radius and the normal force swapped (issue 17: it compiled and gave a
  // force 240 times too small).
  const force_contact<double> swapped{normal_force<double>{1.0}, patch_radius<double>{0.06},
                                      friction_coefficient<double>{0.2}};
  return law(std::array<double, 2>{0.3, 0.1}, qvel[5], swapped).torque < 0 ? 0 : 1;
#elif MISUSE == 6
  // Radius, normal force and mu as three plain numbers (the old signature).
  return law(std::array<double, 2>{0.3, 0.1}, qvel[5], 0.06, 1.0, 0.2).torque < 0 ? 0 : 1;
#elif MISUSE == 7
  // A law without a velocity scale (the old default, 1e-6, chattered).
  const contact_law<> unscaled;
  return unscaled(std::array<double, 2>{0.3, 0.1}, qvel[5], c).torque < 0 ? 0 : 1;
#endif
}
