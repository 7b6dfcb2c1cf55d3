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
// test_bullet_throws.cpp.  Built twice, against Bullet's double and its float
// build (test_bullet_profiles_float: btScalar = float).
#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>
#include <spinslide/contact/pair_friction.hpp>
#include <spinslide/engines/bullet.hpp>
#include <spinslide/motion/dynamics.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include "../examples/bullet_coin/scene.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

using bullet_scene::coin_half_thickness;
using bullet_scene::coin_mu;
using bullet_scene::coin_radius;
using bullet_scene::g;
constexpr double pi = 3.14159265358979323846;

// Throws of the coin coupled with `profile` (v0* in [0.1, 2.1], ω0* in
// [0.1, 3.1]) at Δt = 1e-5 s: (Bullet's stop − the exact stop)/the exact
// stop of each, sorted; a throw that never rests, or moves again, fails.
template <class Profile>
std::vector<double> stop_errors(const Profile& profile, int throws, unsigned seed) {
  const double thickness = 2 * coin_half_thickness, dt = 1e-5;
  const double mass = 7850 * pi * coin_radius * coin_radius * thickness;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> out;
  for (int k = 0; k < throws; ++k) {
    const double vs = 0.1 + 2 * u(rng), ws = 0.1 + 3 * u(rng);
    const double v0 = vs * coin_mu * std::sqrt(g * coin_radius),
                 w0 = ws * coin_mu * std::sqrt(g / coin_radius);
    bullet_scene::scene s(bullet_scene::friction::plugin, btVector3(0, 0, 0));
    const auto r = static_cast<btScalar>(coin_radius);
    btCylinderShapeZ shape(btVector3(r, r, static_cast<btScalar>(thickness / 2)));
    btRigidBody* coin = s.add(&shape, mass, btVector3(0, 0, btScalar(thickness / 2)));
    s.plugin().couple(
        coin, s.table(),
        spinslide::pair_friction(profile, spinslide::patch_radius<double>{coin_radius},
                                 spinslide::friction_coefficient<double>{coin_mu}));
    for (int i = 0; i < 300; ++i) s.step(1e-5);  // settle on the table
    coin->setLinearVelocity(btVector3(btScalar(v0), 0, coin->getLinearVelocity().z()));
    coin->setAngularVelocity(btVector3(0, 0, btScalar(w0)));
    const double exact = spinslide::stop_time(profile, 0.5, vs, ws) * std::sqrt(coin_radius / g);
    double stopped = -1;
    const int steps = static_cast<int>(3 * exact / dt) + 10;
    for (int i = 1; i <= steps; ++i) {
      s.step(dt);
      const btVector3 v = coin->getLinearVelocity();
      const double w = coin->getAngularVelocity().z();
      const bool rest =
          std::hypot(double(v.x()), double(v.y())) < 1e-6 * v0 && std::fabs(w) < 1e-6 * w0;
      EXPECT_TRUE(std::isfinite(double(v.x() + v.y() + v.z()) + w));
      if (rest && stopped < 0) stopped = i * dt;
      EXPECT_FALSE(!rest && stopped >= 0) << "moved again after resting, throw " << k;
    }
    EXPECT_GE(stopped, 0) << "never at rest, throw " << k;
    if (stopped >= 0) out.push_back((stopped - exact) / exact);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Every stop within 0.1 % of the exact one (the uniform coin's bound at this
// step, test_bullet_throws.cpp).
template <class Profile>
void expect_exact_stops(const char* name, const Profile& profile) {
  const std::vector<double> e = stop_errors(profile, 6, 40);
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
