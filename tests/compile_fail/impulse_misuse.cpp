//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Misuse of the impulse law (impulse_friction.hpp) must not compile: the
// radius, the normal impulse and the friction coefficient are distinct types,
// so swapping two of them (a swap of radius and normal force compiled and
// gave a force 240x too small, issue 17) is an error, as is a plain number
// where one of them goes; the velocity must be a 2-component vector class.
// Compiled by tests/compile_fail/check.cmake once per MISUSE: 0 is the
// correct call, every other value must fail with the message the test
// expects.
#include <spinslide/contact/impulse_friction.hpp>
#include <spinslide/values/profile.hpp>

#include <array>

int main() {
  using namespace spinslide;
  const uniform_disk<> disk;
  const planar_metric<double> w({{{10, 0, 0}, {0, 10, 0}, {0, 0, 5000}}});
  const std::array<double, 2> v{0.3, 0.1};
  using mjtNum = double;
  const mjtNum qvel[6] = {0.3, 0.1, 0, 0, 0, 5};
#if MISUSE == 0
  const impulse_contact<double> c{patch_radius<double>{0.06}, normal_impulse<double>{1e-3},
                                  friction_coefficient<double>{0.2}};
  const impulse_contact c17{patch_radius{0.06}, normal_impulse{1e-3}, friction_coefficient{0.2}};
  return impulse_friction(disk, v, qvel[5], w, c).torque < 0 &&
                 impulse_friction(disk, v, qvel[5], w, c17).torque < 0
             ? 0
             : 1;
#elif MISUSE == 1
  // The normal impulse where the radius goes, and the radius where it goes.
  const impulse_contact<double> c{normal_impulse<double>{1e-3}, patch_radius<double>{0.06},
                                  friction_coefficient<double>{0.2}};
  return impulse_friction(disk, v, qvel[5], w, c).torque < 0 ? 0 : 1;
#elif MISUSE == 2
  // Plain numbers for the named inputs.
  const impulse_contact<double> c{0.06, 1e-3, 0.2};
  return impulse_friction(disk, v, qvel[5], w, c).torque < 0 ? 0 : 1;
#elif MISUSE == 3
  // A raw pointer for the velocity (MuJoCo's d->qvel).
  const impulse_contact<double> c{patch_radius<double>{0.06}, normal_impulse<double>{1e-3},
                                  friction_coefficient<double>{0.2}};
  return impulse_friction(disk, qvel, qvel[5], w, c).torque < 0 ? 0 : 1;
#endif
}
