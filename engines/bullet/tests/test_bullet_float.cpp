//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The Bullet adapter in Bullet's float build (btScalar = float; Debian
// installs it beside the double one, and engines/bullet/tests/CMakeLists.txt
// builds this program against it): every profile couples a pair through
// pair_friction there too, and thrown pucks stop at the exact stop of a disk
// with that pressure (the library's throw, γ = 1/2).
//
// The body is a steel puck of 5 cm radius and 2 cm thickness at Δt = 1e-4 s,
// not the 2 mm coin of the double tests: float Bullet does not hold that coin
// on its face, with its own friction as with the adapter (measured: the coin
// tilts at tens of rad/s and leaves the table while it slides; with Bullet's
// friction at rest it creeps at 1e-3 of its start).  The puck rests with
// speeds of float's rounding left, up to about 1e-5 of the starts: "at
// rest" is below 1e-4 here (1e-6 in double).
//
// Measured (this test, 20 throws per profile): in float the stops are late
// by +0.18 % to +6.7 %, medians +0.33 % to +0.43 %, and 2 Boussinesq throws
// moved again after resting; the same puck, throws and adapter against
// Bullet's double build: -0.008 % to +0.19 %, medians +0.02 % to +0.06 %,
// none moved again.  The adapter computes in double in both; the difference
// is float Bullet's contact (its normal impulse).  The bounds below hold
// float's, and still tell the profiles apart (their stops differ by 10 %
// and more).
#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>
#include <spinslide/contact/pair_friction.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include "coin_throws.hpp"

#include <cstdio>
#include <random>
#include <type_traits>
#include <vector>

namespace {

static_assert(std::is_same<btScalar, float>::value, "this test is for Bullet's float build");

const coin_throws::puck puck{0.05, 0.01, 1e-4};

template <class Profile>
void expect_exact_stops(const char* name, const Profile& profile) {
  const coin_throws::stop_errors errors = coin_throws::run(
      profile,
      spinslide::pair_friction(profile, spinslide::patch_radius<double>{puck.radius},
                               spinslide::friction_coefficient<double>{bullet_scene::coin_mu}),
      1e-4, 20, std::mt19937_64(41), puck);
  EXPECT_EQ(errors.never, 0) << name;
  EXPECT_LE(errors.moved_again, 4) << name;
  const std::vector<double>& e = errors.relative;
  ASSERT_FALSE(e.empty()) << name;
  const double median = e[e.size() / 2];
  std::printf(
      "Bullet (float), %s: %zu throws, stop error %+.4f %% to %+.4f %%, median %+.4f %%, "
      "%d moved again\n",
      name, e.size(), 100 * e.front(), 100 * e.back(), 100 * median, errors.moved_again);
  EXPECT_GT(e.front(), -5e-3) << name;
  EXPECT_LT(median, 1e-2) << name;
  EXPECT_LT(e.back(), 0.1) << name;
}

TEST(BulletFloat, TheUniformDiskStopsAtItsExactStop) {
  expect_exact_stops("uniform disk", spinslide::uniform_disk<>());
}

TEST(BulletFloat, ARingStopsAtItsExactStop) { expect_exact_stops("ring", spinslide::ring<>()); }

TEST(BulletFloat, BoussinesqsPunchStopsAtItsExactStop) {
  expect_exact_stops("Boussinesq", spinslide::boussinesq<>());
}

TEST(BulletFloat, ATabulatedProfileStopsAtItsExactStop) {
  expect_exact_stops("tabulated Hertz", spinslide::tabulated_profile<>(spinslide::hertz<>()));
}

}  // namespace
