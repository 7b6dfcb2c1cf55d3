//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Every profile reaches Bullet (issue 40): pair_friction holds its profile
// in the run-time handle contact_profile, so a ring, Boussinesq's flat punch,
// a tabulated profile and a profile the handle does not name (a weighted sum,
// held erased) each couple the steel coin of engines/bullet/examples/bullet_coin
// to its table.  Each is checked against its own exact result: thrown coins
// stop at the exact stop of a disk with that pressure (the library's throw
// through its stop, γ = 1/2), as the uniform coin's do in
// test_bullet_throws.cpp.  Bullet's float build: test_bullet_float.cpp
// (float Bullet does not hold this coin on its face; a puck there).
#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>
#include <spinslide/contact/pair_friction.hpp>
#include <spinslide/engines/bullet.hpp>
#include <spinslide/motion/dynamics.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include "coin_throws.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

// Every stop within 0.1 % of the exact one (the uniform coin's bound at this
// step, test_bullet_throws.cpp).
template <class Profile>
void expect_exact_stops(const char* name, const Profile& profile) {
  const coin_throws::stop_errors errors = coin_throws::run(
      profile,
      spinslide::pair_friction(profile, spinslide::patch_radius<double>{bullet_scene::coin_radius},
                               spinslide::friction_coefficient<double>{bullet_scene::coin_mu}),
      1e-5, 6, std::mt19937_64(40));
  EXPECT_EQ(errors.never, 0) << name;
  EXPECT_EQ(errors.moved_again, 0) << name;
  const std::vector<double>& e = errors.relative;
  ASSERT_FALSE(e.empty()) << name;
  std::printf("Bullet (btScalar of %zu bytes), %s: %zu throws, stop error %+.4f %% to %+.4f %%\n",
              sizeof(btScalar), name, e.size(), 100 * e.front(), 100 * e.back());
  EXPECT_GT(e.front(), -1e-3) << name;
  EXPECT_LT(e.back(), 1e-3) << name;
}

TEST(BulletAdapter, ARingStopsAtItsExactStop) { expect_exact_stops("ring", spinslide::ring<>()); }

TEST(BulletAdapter, BoussinesqsPunchStopsAtItsExactStop) {
  expect_exact_stops("Boussinesq", spinslide::boussinesq<>());
}

TEST(BulletAdapter, ATabulatedProfileStopsAtItsExactStop) {
  expect_exact_stops("tabulated Hertz", spinslide::tabulated_profile<>(spinslide::hertz<>()));
}

// A profile the handle does not name, held as an erased_profile.
TEST(BulletAdapter, AnErasedProfileStopsAtItsExactStop) {
  expect_exact_stops("disk + ring", spinslide::weighted_sum({0.5, 0.5}, spinslide::uniform_disk<>(),
                                                            spinslide::ring<>()));
}

}  // namespace
