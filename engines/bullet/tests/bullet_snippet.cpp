//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The Bullet snippet of docs/engines.md (between "snippet begin" and
// "snippet end", shown there verbatim; the test engines.bullet_snippet_in_docs
// checks that): a coin (R = 12 mm, 2 mm thick, 7.1 g, μ = 0.3) thrown on a
// table at 0.1 m/s and 8 rad/s.  Passes (exit code 0) if the coin comes to
// rest where spinslide's own integration of the throw stops it, to 1 % of
// the distance and of the angle.
#include <btBulletDynamicsCommon.h>
#include <spinslide/engines/bullet.hpp>
#include <spinslide/spinslide.hpp>

#include <cmath>
#include <cstdio>

int main() try {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btBoxShape table_shape(btVector3(1, 1, 0.05));
  btCylinderShapeZ coin_shape(btVector3(0.012, 0.012, 0.001));
  btVector3 inertia;
  coin_shape.calculateLocalInertia(0.0071, inertia);
  btRigidBody table(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &table_shape));
  btRigidBody coin(btRigidBody::btRigidBodyConstructionInfo(0.0071, nullptr, &coin_shape, inertia));
  btTransform pose;
  pose.setIdentity();
  pose.setOrigin(btVector3(0, 0, -0.05));
  table.setWorldTransform(pose);
  pose.setOrigin(btVector3(0, 0, 0.001));
  coin.setWorldTransform(pose);

  // snippet begin
  spinslide::bullet::coupled_friction_solver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
  world.setGravity(btVector3(0, 0, -9.81));
  world.addRigidBody(&table);
  world.addRigidBody(&coin);
  solver.couple(
      &coin, &table,
      spinslide::pair_friction(spinslide::uniform_disk<>(), spinslide::patch_radius<double>{0.012},
                               spinslide::friction_coefficient<double>{0.3}));
  coin.setLinearVelocity(btVector3(0.1, 0, 0));
  coin.setAngularVelocity(btVector3(0, 0, 8));
  for (int i = 0; i < 10000; ++i) world.stepSimulation(1e-5, 1, 1e-5);  // 0.1 s
  // snippet end

  const double gamma = static_cast<double>(inertia.z()) / (0.0071 * 0.012 * 0.012);
  const auto exact = spinslide::simulate_throw_si(
      spinslide::uniform_disk<>(), spinslide::disk_radius{0.012},
      spinslide::friction_coefficient{0.3}, spinslide::gravity{9.81}, gamma,
      spinslide::initial_speed{0.1}, spinslide::initial_spin{8.0});
  const btVector3 at = coin.getCenterOfMassPosition();
  const double distance = std::hypot(static_cast<double>(at.x()), static_cast<double>(at.y()));
  btScalar yaw, pitch, roll;
  coin.getWorldTransform().getBasis().getEulerZYX(yaw, pitch, roll);
  const double angle = static_cast<double>(yaw);
  const double v = static_cast<double>(coin.getLinearVelocity().length());
  const double w = static_cast<double>(coin.getAngularVelocity().length());
  std::printf(
      "distance %.6f m (exact %.6f), angle %.5f rad (exact %.5f), at rest: v = %.1e m/s, "
      "omega = %.1e rad/s\n",
      distance, exact.distance, angle, exact.angle, v, w);
  world.removeRigidBody(&coin);
  world.removeRigidBody(&table);
  const bool ok = std::fabs(distance / exact.distance - 1) < 0.01 &&
                  std::fabs(angle / exact.angle - 1) < 0.01 && v < 1e-6 && w < 1e-4;
  return ok ? 0 : 1;
} catch (const std::exception& e) {
  std::fprintf(stderr, "bullet_snippet: %s\n", e.what());
  return 1;
}
