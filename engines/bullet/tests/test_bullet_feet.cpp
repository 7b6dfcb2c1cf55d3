//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// spinslide::bullet::coupled_friction_solver: a body on two round feet (a
// compound shape; issue 27), coupled to the table as one pair, spun in place
// and on a slope.
#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>
#include <spinslide/engines/bullet.hpp>
#include <spinslide/values/profile.hpp>

#include "../examples/bullet_coin/scene.hpp"
#include "bullet_world.hpp"

#include <cmath>

namespace {

using bullet_scene::g;
using bullet_test::moment_of_inertia;
using spinslide::friction_coefficient;
using spinslide::pair_friction;
using spinslide::patch_radius;

// A body on two round feet (a compound of two cylinders, R = 2 cm, centres
// at ±(7, 3) cm from its centre of mass, 1 kg), coupled to the table as one
// pair: Bullet gives each foot its own manifold.
struct two_feet {
  static constexpr double a = 0.02, x = 0.07, y = 0.03, mass = 1, mu = 0.3;
  bullet_scene::scene s;
  btCylinderShapeZ foot{btVector3(a, a, 0.01)};
  btCompoundShape shape;
  btRigidBody* body;
  explicit two_feet(const btVector3& gravity = btVector3(0, 0, -g))
      : s(bullet_scene::friction::plugin, btVector3(0, 0, 0), gravity) {
    btTransform t;
    t.setIdentity();
    t.setOrigin(btVector3(x, y, 0));
    shape.addChildShape(t, &foot);
    t.setOrigin(btVector3(-x, -y, 0));
    shape.addChildShape(t, &foot);
    body = s.add(&shape, mass, btVector3(0, 0, 0.01));
    s.plugin().couple(body, s.table(),
                      pair_friction(spinslide::uniform_disk<>(), patch_radius<double>{a},
                                    friction_coefficient<double>{mu}));
  }
};

}  // namespace

// issue 27 - a compound's feet: each foot's patch is centred under that foot
// (the child shape's centre; it was the body's centre of mass for every
// manifold, so each foot saw pure spin), and the feet are solved together
// (joint_pairs.hpp; they were solved one after the other).  Spun in place,
// each foot slides at ε = d/a along its circle, and the spin falls at the
// constant rate μmg(d𝓕(ε) + a𝓣(ε))/I until it stops: the stop within 1 % at
// Δt = 1e-5 s (measured +0.54 %: Bullet's two normal loads differ a little,
// and the body drifts) and 8 % at 1e-4 s.  At 1e-4 s the stop depends on
// the last digits of every step: the spin w0 = 5 changed by ±2e-13 relative
// moved it from +2.1 % to +3.8 % and +4.4 %, and the disk's slope from its
// table (issue 41; the impulses' answers moved by up to 6e-14 relative)
// from +2.1 % to +3.1 %, and then +6.0 % and +6.1 % for the same changes
// of w0; at 1e-5 s all six gave +0.541 %.  (One foot after the other gave
// +6.2 %; a centre shared by both feet had not stopped at 1.2 exact
// stops.)  The pair's report sums both feet.
TEST(BulletAdapter, CompoundFeetSpunInPlaceStopAtTheExactTime) {
  for (const double dt : {1e-4, 1e-5}) {
    two_feet f;
    for (int i = 0; i < static_cast<int>(0.05 / dt); ++i) f.s.step(dt);
    const double w0 = 5, d = std::hypot(two_feet::x, two_feet::y), eps = d / two_feet::a;
    f.body->setAngularVelocity(btVector3(0, 0, w0));
    const double inertia = moment_of_inertia(f.body, 2);
    const spinslide::uniform_disk<> disk;
    const double exact = inertia * w0 /
                         (two_feet::mu * two_feet::mass * g *
                          (d * disk.force(eps) + two_feet::a * disk.torque(eps)));
    double stopped = -1;
    for (int i = 1; i <= static_cast<int>(1.2 * exact / dt) && stopped < 0; ++i) {
      f.s.step(dt);
      const spinslide::pair_report r = f.s.plugin().report(f.body, f.s.table());
      if (i == 10) {
        EXPECT_GE(r.contacts, 2) << "both feet, in one report";
        EXPECT_NEAR(r.normal_force(), two_feet::mass * g, 0.05 * g);
        EXPECT_NEAR(r.ratio, eps, 0.05 * eps);
      }
      if (r.sticking) stopped = i * dt;
    }
    ASSERT_GT(stopped, 0) << dt;
    EXPECT_NEAR(stopped / exact, 1, dt < 5e-5 ? 0.01 : 0.08) << dt;
  }
}

// The feet hold on a slope at 0.9 of the friction angle: below 1e-9 m and
// 1e-9 rad in 1 s at Δt = 1e-4 s (measured 6e-19 m; at 1e-3 s Bullet's
// normal contact itself rocks the feet by micrometres).  How the load is
// shared between the feet is not determined; the solve may leave one foot
// at its limit without slip, which its report then counts as slipping.
TEST(BulletAdapter, CompoundFeetHoldOnASlope) {
  const double alpha = std::atan(0.9 * two_feet::mu);
  two_feet f(btVector3(g * std::sin(alpha), 0, -g * std::cos(alpha)));
  for (int i = 0; i < 2000; ++i) f.s.step(1e-4);
  const btVector3 at = f.body->getCenterOfMassPosition();
  const btQuaternion turned = f.body->getOrientation();
  for (int i = 0; i < 10000; ++i) f.s.step(1e-4);
  EXPECT_LT((f.body->getCenterOfMassPosition() - at).length(), 1e-9);
  EXPECT_LT(static_cast<double>(f.body->getOrientation().angleShortestPath(turned)), 1e-9);
}
