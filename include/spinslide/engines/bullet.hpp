//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file bullet.hpp
/// The Bullet adapter (docs/engines.md, "Bullet"): coupled sliding and
/// spinning friction for chosen pairs of Bullet collision objects.
///
/// coupled_friction_solver is Bullet's own sequential-impulse solver with one
/// step added.  For the coupled pairs it first switches Bullet's friction off
/// (the points' combined friction and spinning friction are set to 0, so
/// Bullet solves their normal contacts only), runs Bullet's solve, and then,
/// per coupled manifold, takes the normal impulse Λ that Bullet has just
/// applied in this step, the relative slip and spin at the patch centre and
/// the pair's effective inverse mass W there, and applies the exact impulse
/// law of impulse_friction.hpp (stick, or slip on the coupled limit set).
/// This happens inside btDiscreteDynamicsWorld::solveConstraints, before
/// integrateTransforms moves the bodies with their velocities: the friction
/// of a step sees that step's normal impulse (no lag) and acts on that step's
/// motion.
///
/// Not included by spinslide.hpp: it needs Bullet (btBulletDynamicsCommon.h)
/// and the target spinslide::bullet.

#ifndef SPINSLIDE_ENGINES_BULLET_HPP
#define SPINSLIDE_ENGINES_BULLET_HPP

#include <btBulletDynamicsCommon.h>

#include <spinslide/engines/joint_pairs.hpp>
#include <spinslide/engines/pair_friction.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace spinslide {
namespace bullet {

/// What the solver did for one coupled pair at the last step.
struct pair_report {
  bool touching = false;      ///< the pair had a manifold with a normal impulse this step
  double normal_impulse = 0;  ///< Λ, the sum of the manifold's normal impulses [N·s]
  double patch_radius = 0;    ///< the radius a used [m]
  bool sticking = false;      ///< the friction impulse stopped the contact exactly
  /// ε = |v⁺|/(a|ω⁺|) after the step (NaN when sticking or without contact,
  /// as in every adapter's report)
  double ratio = std::numeric_limits<double>::quiet_NaN();
  std::array<double, 3> centre{};  ///< the patch centre (world) [m]
};

/// Bullet's btSequentialImpulseConstraintSolver with spinslide's coupled
/// friction for the pairs registered with couple().  Pass it to
/// btDiscreteDynamicsWorld as its constraint solver.  Every other contact
/// keeps Bullet's own friction.  Bullet must write the normal impulses back
/// to the contact points, which it does only with SOLVER_USE_WARMSTARTING in
/// the world's solver mode (Bullet's default); without it, solveGroup throws
/// std::logic_error.
class coupled_friction_solver : public btSequentialImpulseConstraintSolver {
 public:
  /// Couples the pair (a, b), in either order, with `friction` (its patch
  /// profile, radius and μ: pair_friction.hpp).  A null object or a == b
  /// throws std::invalid_argument.  Coupling a pair again replaces its
  /// settings.
  void couple(const btCollisionObject* a, const btCollisionObject* b,
              const engines::pair_friction& friction) {
    static const char* function = "spinslide::bullet::coupled_friction_solver::couple";
    if (a == nullptr || b == nullptr)
      throw std::invalid_argument(std::string(function) + ": a null collision object");
    if (a == b)
      throw std::invalid_argument(std::string(function) + ": an object cannot touch itself");
    pairs_.insert_or_assign(key(a, b), pair_state{friction, pair_report{}});
  }

  /// Removes the pair's coupling (Bullet's own friction applies to it again
  /// from the next step); false if it was not coupled.
  bool decouple(const btCollisionObject* a, const btCollisionObject* b) {
    return pairs_.erase(key(a, b)) > 0;
  }

  /// True if the pair is coupled.
  bool coupled(const btCollisionObject* a, const btCollisionObject* b) const {
    return pairs_.count(key(a, b)) > 0;
  }

  /// The pair's report from the last step; std::out_of_range if the pair is
  /// not coupled.
  const pair_report& report(const btCollisionObject* a, const btCollisionObject* b) const {
    const auto it = pairs_.find(key(a, b));
    if (it == pairs_.end())
      throw std::out_of_range("spinslide::bullet::coupled_friction_solver::report: not coupled");
    return it->second.last;
  }

  /// Clears the pairs' reports, then Bullet's own preparation; called by
  /// btDiscreteDynamicsWorld once per step, before the islands are solved.
  void prepareSolve(int numBodies, int numManifolds) override {
    for (auto& p : pairs_) p.second.last = pair_report{};
    btSequentialImpulseConstraintSolver::prepareSolve(numBodies, numManifolds);
  }

  /// Bullet's solve of one island, then the coupled friction (see the
  /// file's comment).  Called by btDiscreteDynamicsWorld; the arguments are
  /// Bullet's own.
  btScalar solveGroup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifold,
                      int numManifolds, btTypedConstraint** constraints, int numConstraints,
                      const btContactSolverInfo& info, btIDebugDraw* debugDrawer,
                      btDispatcher* dispatcher) override {
    if (!pairs_.empty() && !(info.m_solverMode & SOLVER_USE_WARMSTARTING))
      throw std::logic_error(
          "spinslide::bullet::coupled_friction_solver: the world's solver mode lacks "
          "SOLVER_USE_WARMSTARTING, without which Bullet does not report the normal impulses");
    for (int i = 0; i < numManifolds; ++i) {
      if (find(manifold[i]) != nullptr) switch_off_friction(*manifold[i]);
    }
    const btScalar r = btSequentialImpulseConstraintSolver::solveGroup(
        bodies, numBodies, manifold, numManifolds, constraints, numConstraints, info, debugDrawer,
        dispatcher);
    for (int i = 0; i < numManifolds; ++i) {
      if (pair_state* p = find(manifold[i])) apply_friction(*manifold[i], *p);
    }
    return r;
  }

 private:
  struct pair_state {
    engines::pair_friction friction;  // the settings and the last ratio
    pair_report last;
  };

  using pair_key = std::pair<const btCollisionObject*, const btCollisionObject*>;
  struct key_hash {
    std::size_t operator()(const pair_key& k) const {
      const std::size_t h = std::hash<const btCollisionObject*>()(k.first);
      return h ^ (std::hash<const btCollisionObject*>()(k.second) + 0x9e3779b97f4a7c15ULL +
                  (h << 6) + (h >> 2));
    }
  };

  // The patch of one manifold this step: Λ, the Λ-weighted centre, the
  // deepest penetration.
  struct patch_sum {
    double impulse = 0;
    btVector3 centre{0, 0, 0};
    double depth = 0;
  };

  static pair_key key(const btCollisionObject* a, const btCollisionObject* b) {
    return a < b ? pair_key{a, b} : pair_key{b, a};
  }

  pair_state* find(const btPersistentManifold* m) {
    if (pairs_.empty()) return nullptr;
    const auto it = pairs_.find(key(m->getBody0(), m->getBody1()));
    return it == pairs_.end() ? nullptr : &it->second;
  }

  static void switch_off_friction(btPersistentManifold& m) {
    for (int j = 0; j < m.getNumContacts(); ++j) {
      btManifoldPoint& cp = m.getContactPoint(j);
      cp.m_combinedFriction = 0;
      cp.m_combinedSpinningFriction = 0;
    }
  }

  // The points Bullet solved this step (those within the processing
  // threshold, as btSequentialImpulseConstraintSolver::convertContact).
  static patch_sum gather(const btPersistentManifold& m) {
    patch_sum s;
    for (int j = 0; j < m.getNumContacts(); ++j) {
      const btManifoldPoint& cp = m.getContactPoint(j);
      if (!(cp.getDistance() <= m.getContactProcessingThreshold())) continue;
      const double lambda = static_cast<double>(cp.m_appliedImpulse);
      if (lambda > 0) {
        s.impulse += lambda;
        s.centre += (cp.getPositionWorldOnA() + cp.getPositionWorldOnB()) *
                    static_cast<btScalar>(0.5 * lambda);
      }
      const double depth = -static_cast<double>(cp.getDistance());
      if (depth > s.depth) s.depth = depth;
    }
    if (s.impulse > 0) s.centre /= static_cast<btScalar>(s.impulse);
    return s;
  }

  // Adds one body's share to W over the rows (t1, t2, spin n) at offset r
  // from its centre of mass: rows (t_i, r × t_i) and (0, n).
  static void add_body(std::array<std::array<double, 3>, 3>& w, const btRigidBody* body,
                       const btVector3& r, const btVector3 (&t)[3]) {
    if (body == nullptr || body->getInvMass() == 0) return;
    const btVector3 lin = body->getLinearFactor() * body->getInvMass();
    const btVector3 ang[3] = {r.cross(t[0]), r.cross(t[1]), t[2]};
    const btVector3 lin_rows[3] = {t[0], t[1], btVector3(0, 0, 0)};
    const btMatrix3x3& inertia = body->getInvInertiaTensorWorld();
    const btVector3& af = body->getAngularFactor();
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) {
        const btVector3 response = (inertia * ang[j]) * af;
        w[i][j] += static_cast<double>(lin_rows[i].dot(lin_rows[j] * lin) + ang[i].dot(response));
      }
  }

  static btVector3 velocity_at(const btRigidBody* body, const btVector3& point) {
    if (body == nullptr) return btVector3(0, 0, 0);
    return body->getVelocityInLocalPoint(point - body->getCenterOfMassPosition());
  }
  static btVector3 spin_of(const btRigidBody* body) {
    return body == nullptr ? btVector3(0, 0, 0) : body->getAngularVelocity();
  }
  static btVector3 offset(const btRigidBody* body, const btVector3& point) {
    return body == nullptr ? btVector3(0, 0, 0) : point - body->getCenterOfMassPosition();
  }

  static btVector3 lever(const btVector3& r, const btVector3& n, bool in_plane) {
    return in_plane ? r - n * r.dot(n) : r;
  }

  static void apply(btRigidBody* body, const btVector3& linear, const btVector3& angular,
                    const btVector3& r) {
    if (body == nullptr || body->getInvMass() == 0) return;
    body->applyImpulse(linear, r);
    body->applyTorqueImpulse(angular);
  }

  // The patch centre.  A flat face's is fixed by its geometry: the foot of
  // the perpendicular from the centre of mass of the moving body nearer to
  // the contact onto the contact plane (a coin lying on a table: the centre
  // of its face).  The impulse-weighted mean of Bullet's few manifold points
  // wandered with them, on average 27 % of a coin's radius off its axis
  // (issue 27), which biased the spin friction's lever and stopped throws
  // early.  A curved contact's is the mean of its points (one, for a sphere).
  static btVector3 patch_centre(const patch_sum& s, const btRigidBody* a, const btRigidBody* b,
                                const btVector3& n, bool flat) {
    if (!flat) return s.centre;
    const btRigidBody* body = nullptr;
    for (const btRigidBody* candidate : {a, b}) {
      if (candidate == nullptr || candidate->getInvMass() == 0) continue;
      const btVector3 c = candidate->getCenterOfMassPosition();
      if (body == nullptr ||
          (c - s.centre).length2() < (body->getCenterOfMassPosition() - s.centre).length2())
        body = candidate;
    }
    if (body == nullptr) return s.centre;
    const btVector3 c = body->getCenterOfMassPosition();
    return c - n * (c - s.centre).dot(n);
  }

  static void apply_friction(btPersistentManifold& m, pair_state& p) {
    patch_sum s = gather(m);
    if (!(s.impulse > 0)) return;
    auto* a = const_cast<btRigidBody*>(btRigidBody::upcast(m.getBody0()));
    auto* b = const_cast<btRigidBody*>(btRigidBody::upcast(m.getBody1()));
    // The normal of the first point (Bullet's manifolds share one normal up
    // to round-off), from B towards A; the tangent plane's axes.
    btVector3 t[3];
    t[2] = m.getContactPoint(0).m_normalWorldOnB.normalized();
    btPlaneSpace1(t[2], t[0], t[1]);
    // A flat face cannot tilt into its support: its normal contact carries
    // the friction's tipping moment (a shift of pressure within the patch),
    // so the lever arms keep only their parts in the tangent plane.  A
    // sphere keeps the whole lever arm: that moment makes it roll.
    const bool flat = !p.friction.curved();
    s.centre = patch_centre(s, a, b, t[2], flat);
    const btVector3 ra = lever(offset(a, s.centre), t[2], flat);
    const btVector3 rb = lever(offset(b, s.centre), t[2], flat);
    std::array<std::array<double, 3>, 3> w{};
    add_body(w, a, ra, t);
    add_body(w, b, rb, t);
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < i; ++j) w[i][j] = w[j][i] = (w[i][j] + w[j][i]) / 2;
    const planar_metric<double> metric = engines::conditioned_metric(w);
    const btVector3 slip = velocity_at(a, s.centre) - velocity_at(b, s.centre);
    const double spin = static_cast<double>(t[2].dot(spin_of(a) - spin_of(b)));
    const std::array<double, 2> v{static_cast<double>(slip.dot(t[0])),
                                  static_cast<double>(slip.dot(t[1]))};
    const auto f = p.friction.impulse(v, spin, metric, normal_impulse<double>{s.impulse}, s.depth);
    const btVector3 linear =
        t[0] * static_cast<btScalar>(f.force[0]) + t[1] * static_cast<btScalar>(f.force[1]);
    const btVector3 angular = t[2] * static_cast<btScalar>(f.torque);
    apply(a, linear, angular, ra);
    apply(b, -linear, -angular, rb);
    p.last = pair_report{true,
                         s.impulse,
                         p.friction.radius(s.depth),
                         f.sticking,
                         f.ratio,
                         {static_cast<double>(s.centre.x()), static_cast<double>(s.centre.y()),
                          static_cast<double>(s.centre.z())}};
  }

  std::unordered_map<pair_key, pair_state, key_hash> pairs_;
};

}  // namespace bullet
}  // namespace spinslide

#endif  // SPINSLIDE_ENGINES_BULLET_HPP
