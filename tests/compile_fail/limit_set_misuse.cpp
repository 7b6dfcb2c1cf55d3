//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Misuse of project_to_limit_set (limit_set.hpp) must not compile.  Compiled
// by tests/compile_fail/check.cmake once per MISUSE: 0 is the correct call,
// every other value must fail with the message the test expects.
#include <spinslide/approximations.hpp>
#include <spinslide/limit_set.hpp>
#include <spinslide/profile.hpp>

int main() {
  const spinslide::hertz<> profile;
#if MISUSE == 0
  const auto a = spinslide::project_to_limit_set(profile, 0.5, 0.5, 1.0);
  const auto b = spinslide::project_to_limit_set(profile, 0.5, 0.5, 1.0,
                                                 spinslide::starting_ratio<double>{0.6});
  return a.sticking == b.sticking ? 0 : 1;
#elif MISUSE == 1
  // Integers: 1 is not a double of the profile.
  return spinslide::project_to_limit_set(profile, 1, 0, 1).sticking ? 0 : 1;
#elif MISUSE == 2
  // Another floating type than the profile's.
  return spinslide::project_to_limit_set(profile, 0.5f, 0.5f, 1.0f).sticking ? 0 : 1;
#elif MISUSE == 3
  // A plain number where the starting ratio goes: is it a ratio or a weight?
  return spinslide::project_to_limit_set(profile, 0.5, 0.5, 1.0, 0.6).sticking ? 0 : 1;
#elif MISUSE == 4
  // The Padé approximants: their curve's normal is not (eps, 1).
  const spinslide::pade_approximation<> pade;
  return spinslide::project_to_limit_set(pade, 0.5, 0.5, 1.0).sticking ? 0 : 1;
#endif
}
