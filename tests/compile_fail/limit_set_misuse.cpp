//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Misuse of project_to_limit_set (limit_set.hpp) must not compile.  Compiled
// by tests/compile_fail/check.cmake once per MISUSE: 0 is the correct call,
// every other value must fail with the message the test expects.
#include <spinslide/contact/limit_set.hpp>
#include <spinslide/contact/planar_metric.hpp>
#include <spinslide/values/approximations.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/tabulated.hpp>

int main() {
  const spinslide::hertz<> profile;
#if MISUSE == 0
  const auto a = spinslide::project_to_limit_set(profile, 0.5, 0.5, 1.0);
  const auto b =
      spinslide::project_to_limit_set(profile, 0.5, 0.5, 1.0, spinslide::curve_point<double>{0.6});
  // Tables, shrunk profiles and sums of profiles that obey T' = -eps F'.
  const spinslide::tabulated_profile<> table(profile);
  const spinslide::scaled<spinslide::hertz<>> shrunk(profile, 0.5);
  const spinslide::weighted_sum<double, spinslide::hertz<>, spinslide::uniform_disk<>> sum(
      {0.5, 0.5}, profile, spinslide::uniform_disk<>());
  const auto c = spinslide::project_to_limit_set(table, 0.5, 0.5, 1.0);
  const auto d = spinslide::project_to_limit_set(shrunk, 0.5, 0.5, 1.0);
  const auto e = spinslide::project_to_limit_set(sum, 0.5, 0.5, 1.0);
  // A Padé table is allowed, for evaluation, when it says so.
  const spinslide::tabulated_profile<double, boost::math::policies::policy<>, false> pade_table(
      spinslide::pade_approximation<>{});
  return a.sticking == b.sticking && c.sticking == d.sticking && e.sticking &&
                 pade_table.force(1.0) > 0
             ? 0
             : 1;
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
#elif MISUSE == 5
  // issue 26 - a table of the Padé approximants: tabulated_profile<> promises
  // a curve with normals (eps, 1), so the table itself does not compile.
  const spinslide::tabulated_profile<> table(spinslide::pade_approximation<>{});
  return spinslide::project_to_limit_set(table, 0.5, 0.5, 1.0).sticking ? 0 : 1;
#elif MISUSE == 6
  // ... nor a table that says it is of such a curve, projected.
  const spinslide::tabulated_profile<double, boost::math::policies::policy<>, false> table(
      spinslide::pade_approximation<>{});
  return spinslide::project_to_limit_set(table, 0.5, 0.5, 1.0).sticking ? 0 : 1;
#elif MISUSE == 7
  // ... nor the approximants shrunk.
  const spinslide::scaled<spinslide::pade_approximation<>> shrunk(spinslide::pade_approximation<>{},
                                                                  0.5);
  return spinslide::project_to_limit_set(shrunk, 0.5, 0.5, 1.0).sticking ? 0 : 1;
#elif MISUSE == 8
  // ... nor a sum with them as one part.
  const spinslide::weighted_sum<double, spinslide::hertz<>, spinslide::pade_approximation<>> sum(
      {0.5, 0.5}, profile, spinslide::pade_approximation<>{});
  return spinslide::project_to_limit_set(sum, 0.5, 0.5, 1.0).sticking ? 0 : 1;
#elif MISUSE == 9
  // ... nor the 3-D projection of the approximants shrunk.
  const spinslide::scaled<spinslide::pade_approximation<>> shrunk(spinslide::pade_approximation<>{},
                                                                  0.5);
  const spinslide::planar_metric<double> identity({{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}});
  return spinslide::project_to_limit_set(shrunk, spinslide::tangent_wrench<double>{1, 1, 1},
                                         identity)
                 .sticking
             ? 0
             : 1;
#endif
}
