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
/// Bullet solves their normal contacts only), runs Bullet's solve, and then
/// takes each coupled manifold as a patch (its normal impulse Λ that Bullet
/// has just applied in this step, its centre, the relative slip and spin
/// there) and solves the patches' friction together (joint_pairs.hpp, in
/// their joint inverse mass W: patches on one body push on each other
/// through it), each by the exact impulse law of impulse_friction.hpp (stick,
/// or slip on the coupled limit set).  This happens inside
/// btDiscreteDynamicsWorld::solveConstraints, before integrateTransforms
/// moves the bodies with their velocities: the friction of a step sees that
/// step's normal impulse (no lag) and acts on that step's motion.
///
/// A pair coupled with pair_friction(spinslide::own_patch{}, μ) takes the
/// contact's own patch instead of a round one: in every step the convex hull
/// of its manifold's points (those Bullet pressed, or that touch), under
/// the linear (no-tension) pressure of their normal impulses, about the
/// patch centre (contact_patch.hpp).  Bullet adds a manifold's up to 4
/// points over several frames, so a landing box is a point, then a line,
/// then its face.
///
/// Not included by spinslide.hpp: it needs Bullet (btBulletDynamicsCommon.h)
/// and the target spinslide::bullet.

#ifndef SPINSLIDE_ENGINES_BULLET_HPP
#define SPINSLIDE_ENGINES_BULLET_HPP

#include <btBulletDynamicsCommon.h>

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/contact/contact_patch.hpp>
#include <spinslide/contact/detail/vector3.hpp>
#include <spinslide/contact/joint_pairs.hpp>
#include <spinslide/contact/pair_friction.hpp>
#include <spinslide/contact/pair_report.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace spinslide {
namespace bullet {

/// What the solver did at one coupled pair in the last step: the report
/// every adapter gives (pair_report.hpp).
using pair_report = spinslide::pair_report;

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
  /// settings (the rule of every adapter).
  void couple(const btCollisionObject* a, const btCollisionObject* b,
              const spinslide::pair_friction<double>& friction) {
    static const char* function = "spinslide::bullet::coupled_friction_solver::couple";
    detail::required(function, "collision object a", a);
    detail::required(function, "collision object b", b);
    if (a == b) detail::refuse(function, "an object cannot touch itself (a == b)");
    pairs_.insert_or_assign(key(a, b), pair_state{friction, pair_report{}, a});
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

  /// The pair's report from the last step, with `a` as its first body (the
  /// normal from a to b, the friction impulses on a); std::out_of_range if
  /// the pair is not coupled.
  pair_report report(const btCollisionObject* a, const btCollisionObject* b) const {
    const auto it = pairs_.find(key(a, b));
    if (it == pairs_.end())
      throw std::out_of_range(
          "spinslide::bullet::coupled_friction_solver::report: the pair is not coupled");
    const pair_state& p = it->second;
    return p.first == a ? p.last : p.last.reversed();
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
      detail::refuse("spinslide::bullet::coupled_friction_solver::solveGroup",
                     "the world's solver mode lacks SOLVER_USE_WARMSTARTING, without which "
                     "Bullet does not report the normal impulses");
    for (int i = 0; i < numManifolds; ++i) {
      if (find(manifold[i]) != nullptr) switch_off_friction(*manifold[i]);
    }
    const btScalar r = btSequentialImpulseConstraintSolver::solveGroup(
        bodies, numBodies, manifold, numManifolds, constraints, numConstraints, info, debugDrawer,
        dispatcher);
    patches_.clear();
    for (int i = 0; i < numManifolds; ++i) {
      if (pair_state* p = find(manifold[i])) add_patch(*manifold[i], *p);
    }
    if (!patches_.empty()) apply_friction(static_cast<double>(info.m_timeStep));
    return r;
  }

 private:
  struct pair_state {
    spinslide::pair_friction<double> friction;  // the settings and the last curve point
    pair_report last;                           // with `first` as its first body
    const btCollisionObject* first;
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
  // deepest penetration, the points that carry a normal impulse.
  struct patch_sum {
    double impulse = 0;
    btVector3 centre{0, 0, 0};
    double depth = 0;
    int points = 0;
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
        ++s.points;
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

  // One coupled manifold of this step: its pair, bodies, patch, tangent
  // frame (t1, t2, n; n from B towards A) and lever arms.
  struct patch {
    pair_state* pair;
    const btPersistentManifold* manifold;
    btRigidBody* a;
    btRigidBody* b;
    patch_sum sum;
    btVector3 t[3];
    btVector3 ra, rb;
    // An own_patch pair's patch, in (t1, t2) about the centre.
    polygon_patch<double> own = polygon_patch<double>::point({0, 0});
  };

  // A patch's rows (slip along t1, t2, spin about n of A against B) on one
  // of its bodies: linear and angular parts, with B's sign.
  struct body_rows {
    btVector3 linear[3], angular[3];
  };
  static body_rows rows(const patch& p, const btRigidBody* body) {
    const bool first = body == p.a;
    const btVector3& r = first ? p.ra : p.rb;
    const btScalar sign = first ? 1 : -1;
    return {{p.t[0] * sign, p.t[1] * sign, btVector3(0, 0, 0)},
            {r.cross(p.t[0]) * sign, r.cross(p.t[1]) * sign, p.t[2] * sign}};
  }

  // W_pq, the slip of patch p per unit impulse of patch q: the sum over the
  // dynamic bodies they share of p's rows M⁻¹ q's rows.
  static pair_coupling::block block(const patch& p, const patch& q) {
    pair_coupling::block w{};
    for (const btRigidBody* body : {p.a, p.b}) {
      if (body == nullptr || body->getInvMass() == 0 || (body != q.a && body != q.b)) continue;
      const body_rows x = rows(p, body), y = rows(q, body);
      const btVector3 lin = body->getLinearFactor() * body->getInvMass();
      const btMatrix3x3& inertia = body->getInvInertiaTensorWorld();
      const btVector3& af = body->getAngularFactor();
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
          const btVector3 response = (inertia * y.angular[j]) * af;
          w[i][j] +=
              static_cast<double>(x.linear[i].dot(y.linear[j] * lin) + x.angular[i].dot(response));
        }
    }
    return w;
  }

  // The patch's slip (v·t1, v·t2, spin about n) before the friction.
  static detail::vector3<double> free_motion(const patch& p) {
    const btVector3& c = p.sum.centre;
    const btVector3 slip = velocity_at(p.a, c) - velocity_at(p.b, c);
    return {static_cast<double>(slip.dot(p.t[0])), static_cast<double>(slip.dot(p.t[1])),
            static_cast<double>(p.t[2].dot(spin_of(p.a) - spin_of(p.b)))};
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
  // the perpendicular onto the contact plane from the origin of the moving
  // part nearer to the contact (a coin lying on a table: the centre of its
  // face; a foot of a compound body: that child shape's centre).  The
  // impulse-weighted mean of Bullet's few manifold points wandered with
  // them, on average 27 % of a coin's radius off its axis (issue 27), which
  // biased the spin friction's lever and stopped throws early.  A curved
  // contact's is the mean of its points (one, for a sphere).
  static btVector3 patch_centre(const patch_sum& s, const btPersistentManifold& m,
                                const btVector3& n, bool flat) {
    if (!flat) return s.centre;
    bool found = false;
    btVector3 nearest(0, 0, 0);
    for (const btCollisionObject* body : {m.getBody0(), m.getBody1()}) {
      const btRigidBody* rigid = btRigidBody::upcast(body);
      if (rigid == nullptr || rigid->getInvMass() == 0) continue;
      const btVector3 c = part_origin(m, *body);
      if (!found || (c - s.centre).length2() < (nearest - s.centre).length2()) nearest = c;
      found = true;
    }
    if (!found) return s.centre;
    return nearest - n * (nearest - s.centre).dot(n);
  }

  // The origin of the part of `body` that touches in `m`: a compound's
  // child, by the shape index Bullet gives the manifold's points (a compound
  // of several feet has one manifold per touching foot); the body's centre
  // of mass otherwise.
  static btVector3 part_origin(const btPersistentManifold& m, const btCollisionObject& body) {
    const btCollisionShape* shape = body.getCollisionShape();
    if (shape != nullptr && shape->isCompound() && m.getNumContacts() > 0) {
      const auto* compound = static_cast<const btCompoundShape*>(shape);
      const btManifoldPoint& cp = m.getContactPoint(0);
      const int child = &body == m.getBody0() ? cp.m_index0 : cp.m_index1;
      if (child >= 0 && child < compound->getNumChildShapes())
        return (body.getWorldTransform() * compound->getChildTransform(child)).getOrigin();
    }
    return body.getWorldTransform().getOrigin();
  }

  // The manifold's patch, if Bullet pressed it this step.
  void add_patch(const btPersistentManifold& m, pair_state& pair) {
    patch p{&pair, &m, nullptr, nullptr, gather(m), {}, {}, {}};
    if (!(p.sum.impulse > 0)) return;
    p.a = const_cast<btRigidBody*>(btRigidBody::upcast(m.getBody0()));
    p.b = const_cast<btRigidBody*>(btRigidBody::upcast(m.getBody1()));
    // The normal of the first point (Bullet's manifolds share one normal up
    // to round-off), from B towards A; the tangent plane's axes.
    p.t[2] = m.getContactPoint(0).m_normalWorldOnB.normalized();
    btPlaneSpace1(p.t[2], p.t[0], p.t[1]);
    // A flat face cannot tilt into its support: its normal contact carries
    // the friction's tipping moment (a shift of pressure within the patch),
    // so the lever arms keep only their parts in the tangent plane.  A
    // sphere keeps the whole lever arm: that moment makes it roll.
    const bool flat = !pair.friction.curved();
    p.sum.centre = patch_centre(p.sum, m, p.t[2], flat);
    p.ra = lever(offset(p.a, p.sum.centre), p.t[2], flat);
    p.rb = lever(offset(p.b, p.sum.centre), p.t[2], flat);
    if (pair.friction.uses_own_patch()) p.own = own_patch_of(m, p);
    patches_.push_back(p);
  }

  // The manifold's own patch: its points that Bullet pressed or that touch,
  // in the tangent axes about the patch centre, loaded by their normal
  // impulses.  contact_patch never throws.
  polygon_patch<double> own_patch_of(const btPersistentManifold& m, const patch& p) {
    plane_points_.clear();
    for (int j = 0; j < m.getNumContacts(); ++j) {
      const btManifoldPoint& cp = m.getContactPoint(j);
      const double lambda = static_cast<double>(cp.m_appliedImpulse);
      if (!(cp.getDistance() <= m.getContactProcessingThreshold())) continue;
      if (!(lambda > 0) && cp.getDistance() > 0) continue;
      const btVector3 d =
          (cp.getPositionWorldOnA() + cp.getPositionWorldOnB()) * btScalar(0.5) - p.sum.centre;
      plane_points_.push_back(
          {{static_cast<double>(d.dot(p.t[0])), static_cast<double>(d.dot(p.t[1]))}, lambda});
    }
    return contact_patch(plane_points_);
  }

  // The patches' friction impulses, solved together (joint_pairs.hpp: the
  // patches on one body, such as a compound's feet, push on each other
  // through it; one patch alone is one exact projection), applied and
  // reported.
  void apply_friction(double step) {
    const std::size_t n = patches_.size();
    coupling_.reset(n);
    joint_.clear();
    for (std::size_t i = 0; i < n; ++i) {
      const patch& p = patches_[i];
      for (std::size_t j = 0; j < n; ++j) coupling_.at(i, j) = block(p, patches_[j]);
      joint_.push_back(joint_pair{std::ref(p.pair->friction), free_motion(p),
                                  normal_impulse<double>{p.sum.impulse}, p.sum.depth});
      if (p.pair->friction.uses_own_patch()) joint_.back().patch = &p.own;
    }
    solver_.solve(joint_, coupling_);
    for (std::size_t i = 0; i < n; ++i) {
      const patch& p = patches_[i];
      const joint_pair& f = joint_[i];
      const btVector3 linear = p.t[0] * static_cast<btScalar>(f.impulse[0]) +
                               p.t[1] * static_cast<btScalar>(f.impulse[1]);
      const btVector3 angular = p.t[2] * static_cast<btScalar>(f.impulse[2]);
      apply(p.a, linear, angular, p.ra);
      apply(p.b, -linear, -angular, p.rb);
      pair_report r = report_of(p, step, f, linear);
      if (p.pair->first != p.manifold->getBody0()) r = r.reversed();
      pair_state& pair = *p.pair;
      pair.last = pair.last.touching() ? merged(pair.last, r) : r;  // an earlier manifold's
    }
  }

  // A pair that touches in several manifolds in one step (a compound's
  // feet, each its own patch): their sums (contacts, Λ, the friction
  // impulses), the deepest penetration and largest radius, the Λ-weighted
  // centre and normal; sticking if every patch stuck, and then no ratio;
  // otherwise the ratio of the slipping patch with the larger Λ.
  static pair_report merged(const pair_report& x, const pair_report& y) {
    pair_report r = x;
    const double total = x.normal_impulse + y.normal_impulse;
    r.contacts = x.contacts + y.contacts;
    r.normal_impulse = total;
    r.penetration = std::fmax(x.penetration, y.penetration);
    r.patch_radius = std::fmax(x.patch_radius, y.patch_radius);
    double length = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      r.centre[k] = (x.normal_impulse * x.centre[k] + y.normal_impulse * y.centre[k]) / total;
      r.normal[k] = x.normal_impulse * x.normal[k] + y.normal_impulse * y.normal[k];
      length += r.normal[k] * r.normal[k];
      r.friction_impulse[k] = x.friction_impulse[k] + y.friction_impulse[k];
    }
    for (double& c : r.normal) c /= std::sqrt(length);
    r.spin_impulse = x.spin_impulse + y.spin_impulse;
    r.sticking = x.sticking && y.sticking;
    if (x.sticking || (!y.sticking && y.normal_impulse > x.normal_impulse)) r.ratio = y.ratio;
    return r;
  }

  // The step at a patch as its manifold's body 0 sees it: the normal from
  // body 0 to body 1 (-n; Bullet's points from 1 to 0), so the spin impulse
  // about it is -L.
  pair_report report_of(const patch& p, double step, const joint_pair& f,
                        const btVector3& linear) const {
    pair_report r;
    r.contacts = p.sum.points;
    r.step = step;
    r.normal_impulse = p.sum.impulse;
    r.penetration = p.sum.depth;
    r.patch_radius =
        p.pair->friction.uses_own_patch() ? p.own.radius() : p.pair->friction.radius(p.sum.depth);
    r.centre = vector(p.sum.centre);
    r.normal = vector(-p.t[2]);
    r.sticking = f.sticking;
    r.ratio = f.ratio;
    r.friction_impulse = vector(linear);
    r.spin_impulse = -f.impulse[2];
    return r;
  }

  static detail::vector3<double> vector(const btVector3& v) {
    return {static_cast<double>(v.x()), static_cast<double>(v.y()), static_cast<double>(v.z())};
  }

  std::unordered_map<pair_key, pair_state, key_hash> pairs_;
  // The step's workspace, kept from one step to the next.
  std::vector<patch> patches_;
  std::vector<contact_point<double>> plane_points_;
  std::vector<joint_pair> joint_;
  pair_coupling coupling_{0};
  joint_solver solver_;
};

}  // namespace bullet
}  // namespace spinslide

#endif  // SPINSLIDE_ENGINES_BULLET_HPP
