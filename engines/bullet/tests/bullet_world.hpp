//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// What the tests of spinslide::bullet::coupled_friction_solver share
// (test_bullet.cpp, test_bullet_throws.cpp, test_bullet_feet.cpp): the coin
// and the ball they throw, and the world of engines/bullet/examples/bullet_coin they throw
// them in.
#ifndef SPINSLIDE_TESTS_ENGINES_BULLET_WORLD_HPP
#define SPINSLIDE_TESTS_ENGINES_BULLET_WORLD_HPP

#include <btBulletDynamicsCommon.h>
#include <spinslide/engines/bullet.hpp>

#include "../examples/bullet_coin/scene.hpp"

#include <memory>
#include <optional>

namespace bullet_test {

using bullet_scene::coin_half_thickness;
using bullet_scene::coin_radius;
using bullet_scene::g;

constexpr double pi = 3.14159265358979323846;

// The coin of engines/bullet/examples/bullet_coin (scene.hpp: R = 12 mm, 2 mm thick, on wood,
// μ = 0.3), 7.1 g, stepped at 1e-5 s.
constexpr double coin_mass = 0.0071, coin_mu = bullet_scene::coin_mu, coin_dt = 1e-5;
// A billiard ball: R = 28.6 mm, 0.17 kg, on cloth (μ = 0.2), stepped at 1e-4 s,
// with Hertz's patch whose 1 mm minimum decides (Bullet's √(Rδ) is ~1e-9 m).
constexpr double ball_radius = 0.0286, ball_mass = 0.17, ball_mu = 0.2, ball_dt = 1e-4;
constexpr double ball_patch = 1e-3;

// The example's world (scene.hpp) with coupled_friction_solver, `gravity`
// and, unless asked not to, its table with the top face centred at the
// origin.
class world : public bullet_scene::scene {
 public:
  explicit world(const btVector3& gravity = btVector3(0, 0, -g), bool with_table = true)
      : scene(bullet_scene::friction::plugin,
              with_table ? std::optional<btVector3>(btVector3(0, 0, 0)) : std::nullopt, gravity) {}

  btRigidBody* add_coin(const btVector3& origin) {
    return add(std::make_unique<btCylinderShapeZ>(
                   btVector3(coin_radius, coin_radius, coin_half_thickness)),
               coin_mass, origin);
  }
  btRigidBody* add_ball() {
    return add(std::make_unique<btSphereShape>(ball_radius), ball_mass,
               btVector3(0, 0, ball_radius));
  }
  // n steps of coin_dt.
  void coin_steps(int n) {
    for (int i = 0; i < n; ++i) step(coin_dt);
  }
};

inline double moment_of_inertia(const btRigidBody* body, int axis) {
  return 1 / static_cast<double>(body->getInvInertiaDiagLocal()[axis]);
}

}  // namespace bullet_test

#endif  // SPINSLIDE_TESTS_ENGINES_BULLET_WORLD_HPP
