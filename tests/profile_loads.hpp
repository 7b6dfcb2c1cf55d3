//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The two loads of tests/reference/profile_reference.csv that are no built-in
// profile, built from the library's pieces as a user builds them: shared by
// the profile tests (test_profiles, test_tabulated).
#ifndef SPINSLIDE_TESTS_PROFILE_LOADS_HPP
#define SPINSLIDE_TESTS_PROFILE_LOADS_HPP

#include <spinslide/spinslide.hpp>

namespace spinslide_test {

inline auto two_tier() {
  using namespace spinslide;
  // 60% of the load on r < 1/2, 40% on 1/2 < r < 1, uniform within each.
  return weighted_sum({0.6, 0.4}, scaled<uniform_disk<>>(uniform_disk<>(), 0.5), annulus<>(0.5));
}
inline auto parabolic() {
  return spinslide::radial_profile([](double r) { return (1 - r) * (1 + r); });
}

}  // namespace spinslide_test

#endif  // SPINSLIDE_TESTS_PROFILE_LOADS_HPP
