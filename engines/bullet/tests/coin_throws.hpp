//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Thrown coins in Bullet against their exact stops: the one loop of
// test_bullet_throws.cpp (the uniform coin), test_bullet_profiles.cpp (every
// profile) and test_bullet_float.cpp (Bullet's float build, a puck).
#ifndef SPINSLIDE_ENGINES_BULLET_TESTS_COIN_THROWS_HPP
#define SPINSLIDE_ENGINES_BULLET_TESTS_COIN_THROWS_HPP

#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>
#include <spinslide/contact/pair_friction.hpp>
#include <spinslide/engines/bullet.hpp>
#include <spinslide/motion/dynamics.hpp>

#include "../examples/bullet_coin/scene.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace coin_throws {

/// What the throws of one setting gave.
struct stop_errors {
  std::vector<double> relative;  ///< (Bullet's stop − the exact stop)/the exact stop, sorted
  int never = 0;                 ///< throws not at rest within three exact stop times
  int moved_again = 0;           ///< throws that moved again after coming to rest
};

/// The thrown body: a steel cylinder on its face (γ = 1/2), and what counts
/// as rest.  The default is the coin of engines/bullet/examples/bullet_coin.
struct puck {
  double radius = bullet_scene::coin_radius;
  double half_thickness = bullet_scene::coin_half_thickness;
  /// "At rest": the horizontal speed and R|ω| below this fraction of their starts.
  double rest = 1e-6;
};

/// Random throws of `body`
/// (v0* in [0.1, 2.1], ω0* in [0.1, 3.1], drawn from `rng`), coupled to the
/// table by `friction`, stepped at `dt`, against the exact stop of the same
/// throw of a disk whose pressure is `profile` (stop_time at γ = 1/2): "at
/// rest" is both the horizontal speed and R|ω| below `body.rest` of their starts.
template <class Profile>
stop_errors run(const Profile& profile, const spinslide::pair_friction<double>& friction, double dt,
                int throws, std::mt19937_64 rng, const puck& body = {}) {
  using bullet_scene::coin_mu;
  using bullet_scene::g;
  constexpr double pi = 3.14159265358979323846;
  const double coin_radius = body.radius;
  const double thickness = 2 * body.half_thickness;
  const double mass = 7850 * pi * coin_radius * coin_radius * thickness;
  std::uniform_real_distribution<double> u(0, 1);
  stop_errors out;
  for (int k = 0; k < throws; ++k) {
    const double vs = 0.1 + 2 * u(rng), ws = 0.1 + 3 * u(rng);
    const double v0 = vs * coin_mu * std::sqrt(g * coin_radius),
                 w0 = ws * coin_mu * std::sqrt(g / coin_radius);
    bullet_scene::scene s(bullet_scene::friction::plugin, btVector3(0, 0, 0));
    const auto r = static_cast<btScalar>(coin_radius);
    btCylinderShapeZ shape(btVector3(r, r, static_cast<btScalar>(thickness / 2)));
    btRigidBody* coin = s.add(&shape, mass, btVector3(0, 0, static_cast<btScalar>(thickness / 2)));
    s.plugin().couple(coin, s.table(), friction);
    for (int i = 0; i < 300; ++i) s.step(1e-5);  // settle on the table
    coin->setLinearVelocity(btVector3(btScalar(v0), 0, coin->getLinearVelocity().z()));
    coin->setAngularVelocity(btVector3(0, 0, btScalar(w0)));
    const double exact = spinslide::stop_time(profile, 0.5, vs, ws) * std::sqrt(coin_radius / g);
    double stopped = -1;
    bool again = false;
    const int steps = static_cast<int>(3 * exact / dt) + 10;
    for (int i = 1; i <= steps; ++i) {
      s.step(dt);
      const btVector3 v = coin->getLinearVelocity();
      const double w = double(coin->getAngularVelocity().z());
      EXPECT_TRUE(std::isfinite(double(v.x() + v.y() + v.z()) + w));
      const bool rest = std::hypot(double(v.x()), double(v.y())) < body.rest * v0 &&
                        std::fabs(w) < body.rest * w0;
      if (rest && stopped < 0) stopped = i * dt;
      if (!rest && stopped >= 0) {
        again = true;
        stopped = -1;
      }
    }
    if (stopped < 0) {
      ++out.never;
      continue;
    }
    out.moved_again += again;
    out.relative.push_back((stopped - exact) / exact);
  }
  std::sort(out.relative.begin(), out.relative.end());
  return out;
}

}  // namespace coin_throws

#endif  // SPINSLIDE_ENGINES_BULLET_TESTS_COIN_THROWS_HPP
