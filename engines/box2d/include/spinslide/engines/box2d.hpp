//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)

/// \file box2d.hpp
/// spinslide's coupled friction for bodies lying on a table in a top-down
/// Box2D world (2.4; docs/engines.md, "Box2D").
///
///     spinslide::box2d::table_friction table(spinslide::gravity{9.81});
///     table.couple(puck, spinslide::pair_friction(...));
///     for (...) { table.apply(dt); world.Step(dt, 8, 3); }
///
/// A top-down world has no normal contact with the table: its normal force
/// is the body's weight m g.  Before each step, apply() gives each added
/// body the impulse of the velocity-level law (impulse_friction.hpp) over the
/// step, with the body's own inverse mass and inertia about its centre of
/// mass (where the patch is centred), and Λ = m g Δt: exact stick, slip on
/// the coupled limit set, no velocity scale.  It sees the velocity the body
/// has when it is called: forces that the step itself will apply (collisions,
/// ApplyForce) act after it, as friction of the next step sees them.
///
/// A body's report (pair_report.hpp) has the body as its first body and the
/// table as its second: the table lies below the world's plane, so the
/// normal is (0, 0, −1) and the spin impulse about it is minus the angular
/// impulse Box2D applies (about +z).
#ifndef SPINSLIDE_ENGINES_BOX2D_HPP
#define SPINSLIDE_ENGINES_BOX2D_HPP

#include <box2d/box2d.h>
#include <spinslide/base/detail/checks.hpp>
#include <spinslide/base/named_inputs.hpp>
#include <spinslide/contact/joint_pairs.hpp>
#include <spinslide/contact/pair_friction.hpp>
#include <spinslide/contact/pair_report.hpp>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace spinslide {
namespace box2d {

/// A body's last step (pair_report.hpp; see the file's comment).
using pair_report = spinslide::pair_report;

/// The friction of bodies lying on a table, for a top-down Box2D world (see
/// the file's comment).
class table_friction {
 public:
  /// A table under gravity g (finite and > 0; otherwise std::domain_error).
  explicit table_friction(spinslide::gravity<double> g)
      : gravity_(detail::checked_constructor_argument("spinslide::box2d::table_friction", "gravity",
                                                      g.value,
                                                      detail::argument_rule::finite_positive)) {}

  /// Couples `body` (a dynamic body with mass; it must outlive its use here)
  /// with `friction` (its patch: pair_friction.hpp); returns its index for
  /// report().  A null or massless body is std::invalid_argument, and so is
  /// an own_patch friction: a top-down table has no contact points to build
  /// a patch from (give the patch's profile and radius).
  std::size_t couple(b2Body* body, const spinslide::pair_friction<double>& friction) {
    static const char* function = "spinslide::box2d::table_friction::couple";
    detail::required(function, "the body", body);
    if (!(body->GetMass() > 0)) detail::refuse(function, "a dynamic body with mass is needed");
    if (friction.uses_own_patch())
      detail::refuse(function,
                     "an own_patch friction, but a top-down table has no contact points to build "
                     "the patch from; give a round profile and its radius");
    bodies_.push_back({body, friction, pair_report{}});
    return bodies_.size() - 1;
  }

  /// Applies each body's friction impulse for a step of `dt` seconds
  /// (finite and > 0; otherwise std::domain_error).
  void apply(double dt) {
    detail::checked_constructor_argument("spinslide::box2d::table_friction::apply", "dt", dt,
                                         detail::argument_rule::finite_positive);
    for (auto& b : bodies_) apply_one(b, dt);
  }

  /// Body `index`'s last step (the index couple() returned); an index beyond
  /// the bodies added is std::out_of_range, naming both.
  const pair_report& report(std::size_t index) const {
    return bodies_[detail::checked_index("spinslide::box2d::table_friction::report", "body", index,
                                         bodies_.size())]
        .last;
  }

 private:
  struct entry {
    b2Body* body;
    spinslide::pair_friction<double> friction;
    pair_report last;
  };

  void apply_one(entry& e, double dt) const {
    b2Body& b = *e.body;
    // A sleeping body is at rest: nothing to resist, and no impulse wakes
    // it (a first version woke every body each step, so none ever slept).
    if (!b.IsAwake()) {
      e.friction.forget();
      e.last = resting(b, dt, e.friction.radius(0));
      return;
    }
    const double m = b.GetMass();
    if (!(m > 0)) {  // made static or kinematic since: friction does not move it
      e.last = pair_report{};
      return;
    }
    const b2Vec2 c = b.GetLocalCenter();
    // GetInertia() is about the body's origin; W needs it about the centre
    // (0 for a body with fixed rotation: no spin response).
    const double inertia = static_cast<double>(b.GetInertia()) - m * (c.x * c.x + c.y * c.y);
    const planar_metric<double> w = conditioned_metric(detail::matrix3<double>{
        {{1 / m, 0, 0}, {0, 1 / m, 0}, {0, 0, inertia > 0 ? 1 / inertia : 0.0}}});
    const b2Vec2 v = b.GetLinearVelocity();
    const auto p = e.friction.impulse({v.x, v.y}, b.GetAngularVelocity(), w,
                                      normal_impulse<double>{m * gravity_ * dt}, 0.0);
    b.ApplyLinearImpulseToCenter(
        b2Vec2(static_cast<float>(p.force[0]), static_cast<float>(p.force[1])), false);
    b.ApplyAngularImpulse(static_cast<float>(p.torque), false);
    e.last = resting(b, dt, e.friction.radius(0));
    e.last.sticking = p.sticking;
    e.last.ratio = p.ratio;
    e.last.friction_impulse = {p.force[0], p.force[1], 0.0};
    e.last.spin_impulse = -p.torque;  // about the normal (0, 0, -1)
  }

  // A body's report before its friction: one contact with the table, Λ =
  // m g Δt at its centre of mass, sticking (a sleeping body's whole report).
  pair_report resting(const b2Body& b, double dt, double radius) const {
    pair_report r;
    r.contacts = 1;
    r.step = dt;
    r.normal_impulse = static_cast<double>(b.GetMass()) * gravity_ * dt;
    r.patch_radius = radius;
    const b2Vec2 centre = b.GetWorldCenter();
    r.centre = {static_cast<double>(centre.x), static_cast<double>(centre.y), 0.0};
    r.normal = {0.0, 0.0, -1.0};
    r.sticking = true;
    return r;
  }

  double gravity_;
  std::vector<entry> bodies_;
};

}  // namespace box2d
}  // namespace spinslide

#endif  // SPINSLIDE_ENGINES_BOX2D_HPP
