//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The box scenes of issue 42 item 6 (engines/testing/box_scenes.hpp) in
// Bullet (the world of engines/bullet/examples/bullet_coin, its table's top
// at z = 0), with Bullet's own friction or the plug-in's; what each run
// measures.  Stepped at 1e-4 s.
#ifndef SPINSLIDE_ENGINES_BULLET_TESTS_BOX_RUNS_HPP
#define SPINSLIDE_ENGINES_BULLET_TESTS_BOX_RUNS_HPP

#include <btBulletDynamicsCommon.h>

#include "../examples/bullet_coin/scene.hpp"
#include "box_scenes.hpp"

#include <cmath>
#include <functional>
#include <memory>

namespace box_runs {

constexpr double step = 1e-4;

// A world with the box on its table, at rest with the orientation `turn`
// and its centre at `height`.
struct box_world {
  explicit box_world(bullet_scene::friction kind,
                     const btVector3& gravity = btVector3(0, 0, btScalar(-box_scenes::gravity)),
                     double height = box_scenes::half_height,
                     const btQuaternion& turn = btQuaternion(0, 0, 0, 1))
      : scene(std::make_unique<bullet_scene::scene>(kind, btVector3(0, 0, 0), gravity)) {
    box = scene->add(std::make_unique<btBoxShape>(btVector3(btScalar(box_scenes::half_length),
                                                            btScalar(box_scenes::half_width),
                                                            btScalar(box_scenes::half_height))),
                     box_scenes::mass, btVector3(0, 0, btScalar(height)));
    btTransform t = box->getWorldTransform();
    t.setRotation(turn);
    box->setWorldTransform(t);
  }
  void steps(double seconds) {
    const auto n = static_cast<int>(std::lround(seconds / step));
    for (int i = 0; i < n; ++i) scene->step(step);
  }
  double yaw() const {
    btScalar z = 0, y = 0, x = 0;
    box->getWorldTransform().getBasis().getEulerZYX(z, y, x);
    return static_cast<double>(z);
  }
  std::unique_ptr<bullet_scene::scene> scene;
  btRigidBody* box = nullptr;
};

// Bullet's own friction: μ per point and, if `spinning`, its spinning
// friction with the coefficient `spinning` (a length; Bullet needs a
// rolling friction > 0 to apply it).
inline void native_friction(box_world& w, double spinning) {
  w.box->setFriction(btScalar(box_scenes::friction));
  if (spinning > 0) {
    w.box->setSpinningFriction(btScalar(spinning));
    w.box->setRollingFriction(btScalar(1e-9));
  }
}

// The throw: when the sliding (the centre below 1 mm/s) and the spin
// (below 0.01 rad/s) stopped, or, if given, when `stopped` first says so
// (the plug-in's sticking report); the turn and the displacement at the end
// (0.5 s).
using box_scenes::throw_outcome;
inline throw_outcome run_throw(box_world& w, const std::function<bool()>& stopped = nullptr) {
  w.steps(0.1);
  w.box->setLinearVelocity(btVector3(btScalar(box_scenes::throw_speed), 0, 0));
  w.box->setAngularVelocity(btVector3(0, 0, btScalar(box_scenes::throw_spin)));
  const btVector3 x0 = w.box->getCenterOfMassPosition();
  const double yaw0 = w.yaw();
  throw_outcome o;
  double unwrapped = 0, last = yaw0;
  for (int i = 1; i <= static_cast<int>(std::lround(0.5 / step)); ++i) {
    w.scene->step(step);
    const btVector3 v = w.box->getLinearVelocity(), spin = w.box->getAngularVelocity();
    o.finite = o.finite && std::isfinite(static_cast<double>(v.length() + spin.length()));
    const double t = i * step;
    const bool reported = static_cast<bool>(stopped);
    const bool at_rest = reported && stopped();
    if (o.slide_stop < 0 && (reported ? at_rest : std::hypot(double(v.x()), double(v.y())) < 1e-3))
      o.slide_stop = t;
    if (o.spin_stop < 0 && (reported ? at_rest : std::fabs(double(spin.z())) < 1e-2))
      o.spin_stop = t;
    const double now = w.yaw();
    unwrapped += std::remainder(now - last, 2 * 3.14159265358979323846);
    last = now;
  }
  const btVector3 x1 = w.box->getCenterOfMassPosition();
  o.turn = unwrapped;
  o.x = double(x1.x() - x0.x());
  o.y = double(x1.y() - x0.y());
  return o;
}

// The slope: how far the box moves in 1 s after 0.5 s to settle.
inline double slope_creep(box_world& w) {
  w.steps(0.5);
  const btVector3 x0 = w.box->getCenterOfMassPosition();
  w.steps(1.0);
  return double((w.box->getCenterOfMassPosition() - x0).length());
}

// The push (box_scenes::push at its point of action, turned with the box)
// from a slide at start_speed.
inline box_scenes::pushed_state run_push(box_world& w) {
  w.steps(0.1);
  w.box->setLinearVelocity(btVector3(btScalar(box_scenes::start_speed), 0, 0));
  w.box->setAngularVelocity(btVector3(0, 0, 0));
  const btVector3 x0 = w.box->getCenterOfMassPosition();
  const double yaw0 = w.yaw();
  const box_scenes::body_wrench p = box_scenes::push();
  const double m = box_scenes::mass;
  for (int i = 0; i < static_cast<int>(std::lround(box_scenes::push_time / step)); ++i) {
    const btMatrix3x3& r = w.box->getWorldTransform().getBasis();
    const btVector3 force = r * btVector3(btScalar(m * p.fx), btScalar(m * p.fy), 0);
    const btVector3 at =
        r * btVector3(btScalar(-box_scenes::half_length), btScalar(box_scenes::push_offset),
                      btScalar(-box_scenes::half_height));
    w.box->applyForce(force, at);  // its moment about the centre of mass: at × force
    w.scene->step(step);
  }
  const btVector3 x1 = w.box->getCenterOfMassPosition();
  const double a = w.yaw(), c = std::cos(a), s = std::sin(a);
  const btVector3 v = w.box->getLinearVelocity();
  return {a - yaw0,
          double(x1.x() - x0.x()),
          double(x1.y() - x0.y()),
          c * double(v.x()) + s * double(v.y()),
          -s * double(v.x()) + c * double(v.y()),
          double(w.box->getAngularVelocity().z())};
}

// The box dropped from 3 cm above its lowest corner, tilted by 0.5 rad about
// (1, 0.6, 0) (it lands on a corner, falls onto an edge, then its face),
// thrown at 0.4 m/s and spinning at 6 rad/s, for 1 s: true if its motion
// stayed finite (`observe` is called after every step).
inline btQuaternion tipping_turn() { return btQuaternion(btVector3(1, btScalar(0.6), 0), 0.5); }
constexpr double tipping_height = 0.1;
inline bool run_tipping(box_world& w, const std::function<void()>& observe = nullptr) {
  w.box->setLinearVelocity(btVector3(btScalar(0.4), 0, 0));
  w.box->setAngularVelocity(btVector3(0, 0, 6));
  bool finite = true;
  for (int i = 0; i < static_cast<int>(std::lround(1.0 / step)); ++i) {
    w.scene->step(step);
    if (observe) observe();
    const btVector3 x = w.box->getCenterOfMassPosition(), v = w.box->getLinearVelocity(),
                    spin = w.box->getAngularVelocity();
    finite = finite && std::isfinite(double(x.length() + v.length() + spin.length()));
  }
  return finite;
}

}  // namespace box_runs

#endif  // SPINSLIDE_ENGINES_BULLET_TESTS_BOX_RUNS_HPP
