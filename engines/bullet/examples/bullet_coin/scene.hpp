//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The Bullet world of engines/bullet/examples/bullet_coin, engines/bullet/tests/test_bullet*.cpp
// and benchmarks/bench_bullet.cpp (Bullet 3, double precision): a btDiscreteDynamicsWorld with
// Bullet's own solver or spinslide::bullet::coupled_friction_solver, a static box table whose top
// face is z = 0, and the coin they share: R = 12 mm, 2 mm thick, on wood
// (μ = 0.3).
#ifndef SPINSLIDE_EXAMPLES_BULLET_SCENE_HPP
#define SPINSLIDE_EXAMPLES_BULLET_SCENE_HPP

#include <btBulletDynamicsCommon.h>
#include <spinslide/engines/bullet.hpp>
#include <spinslide/spinslide.hpp>

#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace bullet_scene {

constexpr double g = 9.81;
// The coin.
constexpr double coin_radius = 0.012, coin_half_thickness = 0.001, coin_mu = 0.3;

// The friction of the world's contacts: Bullet's own (its sequential impulse
// solver) or spinslide's plug-in (coupled_friction_solver, for the pairs
// coupled to it; Bullet's own friction for the others).
enum class friction { native, plugin };

inline btTransform at(const btVector3& origin) {
  btTransform t;
  t.setIdentity();
  t.setOrigin(origin);
  return t;
}

// One Bullet world with `gravity` and the chosen solver and, unless `table_top`
// is empty, a static box 6 m × 6 m × 10 cm whose top face is centred at
// `table_top` (z = 0 in all three users; friction 1, so that a body's friction
// is the pair's: Bullet multiplies them).  The convex-convex multipoint
// iterations keep 3 to 4 points under a coin (a cylinder on a
// btStaticPlaneShape gets one new point per step and rocks on two).  Bodies
// added never sleep.
class scene {
 public:
  explicit scene(friction kind, const std::optional<btVector3>& table_top = btVector3(0, 0, 0),
                 const btVector3& gravity = btVector3(0, 0, btScalar(-g)))
      : kind_(kind),
        dispatcher_(multipoint(config_)),
        solver_(kind == friction::plugin ? new spinslide::bullet::coupled_friction_solver
                                         : new btSequentialImpulseConstraintSolver),
        world_(&dispatcher_, &broadphase_, solver_.get(), &config_),
        table_shape_(btVector3(3, 3, btScalar(table_half_height))),
        table_(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &table_shape_)) {
    world_.setGravity(gravity);
    if (table_top) {
      table_.setWorldTransform(at(
          btVector3(table_top->x(), table_top->y(), table_top->z() - btScalar(table_half_height))));
      table_.setFriction(1);
      world_.addRigidBody(&table_);
      has_table_ = true;
    }
  }
  scene(const scene&) = delete;
  scene& operator=(const scene&) = delete;
  scene(scene&&) = delete;
  scene& operator=(scene&&) = delete;
  ~scene() {
    for (auto& b : bodies_) world_.removeRigidBody(b.get());
    if (has_table_) world_.removeRigidBody(&table_);
  }

  // A body of `shape` (not kept: it must outlive the scene) and `mass` at
  // `origin`, released at rest.
  btRigidBody* add(btCollisionShape* shape, double mass, const btVector3& origin) {
    btVector3 inertia(0, 0, 0);
    shape->calculateLocalInertia(btScalar(mass), inertia);
    bodies_.push_back(std::make_unique<btRigidBody>(
        btRigidBody::btRigidBodyConstructionInfo(btScalar(mass), nullptr, shape, inertia)));
    btRigidBody* b = bodies_.back().get();
    b->setWorldTransform(at(origin));
    b->setActivationState(DISABLE_DEACTIVATION);  // no sleeping while it creeps
    world_.addRigidBody(b);
    return b;
  }
  // The same with a shape the scene keeps.
  btRigidBody* add(std::unique_ptr<btCollisionShape> shape, double mass, const btVector3& origin) {
    btRigidBody* b = add(shape.get(), mass, origin);
    shapes_.push_back(std::move(shape));
    return b;
  }

  // One step of h (fixedTimeStep = h, maxSubSteps = 1: exactly one step).
  void step(double h) { world_.stepSimulation(btScalar(h), 1, btScalar(h)); }

  // The normal impulse on `body` this step (its manifolds' points) and its
  // deepest penetration.
  std::pair<double, double> contact_of(const btRigidBody* body) const {
    double impulse = 0, depth = 0;
    for (int i = 0; i < dispatcher_.getNumManifolds(); ++i) {
      const btPersistentManifold* m = dispatcher_.getManifoldByIndexInternal(i);
      if (m->getBody0() != body && m->getBody1() != body) continue;
      for (int j = 0; j < m->getNumContacts(); ++j) {
        const btManifoldPoint& p = m->getContactPoint(j);
        if (p.getDistance() > m->getContactProcessingThreshold()) continue;
        impulse += p.m_appliedImpulse;
        depth = std::max(depth, -static_cast<double>(p.getDistance()));
      }
    }
    return {impulse, depth};
  }

  friction kind() const { return kind_; }
  btSequentialImpulseConstraintSolver& solver() { return *solver_; }
  // The plug-in (friction::plugin only).
  spinslide::bullet::coupled_friction_solver& plugin() {
    if (kind_ != friction::plugin)
      throw std::logic_error("bullet_scene: a native scene has no coupled_friction_solver");
    return static_cast<spinslide::bullet::coupled_friction_solver&>(*solver_);
  }
  btDiscreteDynamicsWorld& dynamics() { return world_; }
  btCollisionDispatcher& dispatcher() { return dispatcher_; }
  // The table; null without one.
  btRigidBody* table() { return has_table_ ? &table_ : nullptr; }

 private:
  static constexpr double table_half_height = 0.05;
  static btDefaultCollisionConfiguration* multipoint(btDefaultCollisionConfiguration& c) {
    c.setConvexConvexMultipointIterations();
    return &c;
  }
  friction kind_;
  btDefaultCollisionConfiguration config_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  btDiscreteDynamicsWorld world_;
  btBoxShape table_shape_;
  btRigidBody table_;
  bool has_table_ = false;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;  // before bodies_: outlives them
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
};

// spinslide's friction of the coin on the table: uniform pressure, a = R.
inline spinslide::pair_friction<double> coin_friction() {
  return spinslide::pair_friction(spinslide::uniform_disk<>(),
                                  spinslide::patch_radius<double>{coin_radius},
                                  spinslide::friction_coefficient<double>{coin_mu});
}

// The coin's friction with the table of `s`: in a native scene Bullet's own,
// μ per contact point, spinning friction μ·(2/3)R (the torsional coefficient
// of a uniformly pressed disk in pure spin) and a tiny rolling friction,
// without which Bullet adds no spinning friction; with the plug-in, the
// coin coupled to the table with coin_friction().
inline void set_coin_friction(scene& s, btRigidBody* coin) {
  if (s.kind() == friction::native) {
    coin->setFriction(btScalar(coin_mu));
    coin->setSpinningFriction(btScalar(coin_mu * 2.0 / 3.0 * coin_radius));
    coin->setRollingFriction(btScalar(1e-9));  // > 0, or Bullet ignores the spinning friction
  } else {
    s.plugin().couple(coin, s.table(), coin_friction());
  }
}

}  // namespace bullet_scene

#endif  // SPINSLIDE_EXAMPLES_BULLET_SCENE_HPP
