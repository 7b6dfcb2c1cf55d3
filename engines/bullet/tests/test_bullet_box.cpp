//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Issue 42 item 6 in Bullet: a 0.22 × 0.10 m box (engines/testing/box_scenes.hpp)
// thrown flat, sliding and spinning; on a slope at 0.9 of its friction
// angle; pushed at an offset point; tipped onto an edge and a corner.  With
// Bullet's own friction, without and with its spinning friction (the
// numbers docs/engines.md records, "A box: the contact's own patch").
#include <gtest/gtest.h>

#include <spinslide/values/friction_wrench.hpp>

#include "box_checks.hpp"
#include "box_runs.hpp"
#include "box_scenes.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>

namespace {

using bullet_scene::friction;

// Bullet's spinning friction set to the face's own pure-spin torque per
// unit normal force, μ⟨|r|⟩ (the exact wrench of a spin about the centre).
double spinning_coefficient() {
  const auto w =
      spinslide::friction_wrench(box_scenes::face(), spinslide::planar_twist<double>{{0, 0}, 1});
  return box_scenes::friction * std::fabs(w.torque);
}

struct native_model {
  const char* name;
  double spinning;
};
const native_model natives[] = {{"friction only", 0},
                                {"spinning friction", spinning_coefficient()}};

}  // namespace

// Bullet's friction stops the thrown box's sliding and spin apart from the
// exact stop.
TEST(BulletBoxNative, ThrownBoxStopsApartFromTheExactStop) {
  const auto exact = box_scenes::exact_throw();
  std::printf("exact: both stop at %.4f s, turned %.4f rad, moved (%.4f, %.4f) m\n", exact.time,
              exact.rotation, exact.displacement[0], exact.displacement[1]);
  for (const native_model& n : natives) {
    box_runs::box_world w(friction::native);
    box_runs::native_friction(w, n.spinning);
    const auto o = box_runs::run_throw(w);
    std::printf("%-18s slide stops %.4f s, spin %.4f s, turned %.4f rad, moved (%.4f, %.4f) m\n",
                n.name, o.slide_stop, o.spin_stop, o.turn, o.x, o.y);
    EXPECT_TRUE(o.finite);
    EXPECT_GT(std::fmax(std::fabs(o.slide_stop - exact.time), std::fabs(o.spin_stop - exact.time)),
              2 * box_runs::step)
        << n.name;
  }
}

TEST(BulletBoxNative, OnASlopeAtNineTenthsOfTheFrictionAngle) {
  const double alpha = box_scenes::slope_angle();
  const btVector3 g(btScalar(box_scenes::gravity * std::sin(alpha)), 0,
                    btScalar(-box_scenes::gravity * std::cos(alpha)));
  for (const native_model& n : natives) {
    box_runs::box_world w(friction::native, g);
    box_runs::native_friction(w, n.spinning);
    const double creep = box_runs::slope_creep(w);
    std::printf("%-18s moves %.3e m in 1 s\n", n.name, creep);
    EXPECT_TRUE(std::isfinite(creep));
  }
}

TEST(BulletBoxNative, PushedAtAnOffsetPoint) {
  const auto exact = box_scenes::exact_push();
  std::printf("exact: after %.2f s turned %.4f rad, moved (%.4f, %.4f) m, spin %.4f rad/s\n",
              box_scenes::push_time, exact.angle, exact.x, exact.y, exact.omega);
  for (const native_model& n : natives) {
    box_runs::box_world w(friction::native);
    box_runs::native_friction(w, n.spinning);
    const auto o = box_runs::run_push(w);
    std::printf("%-18s turned %.4f rad, moved (%.4f, %.4f) m, spin %.4f rad/s\n", n.name, o.angle,
                o.x, o.y, o.omega);
    EXPECT_TRUE(std::isfinite(o.angle + o.x + o.y));
  }
}

TEST(BulletBoxNative, TippingOntoAnEdgeAndACornerStaysFinite) {
  for (const native_model& n : natives) {
    box_runs::box_world w(friction::native, btVector3(0, 0, btScalar(-box_scenes::gravity)),
                          box_runs::tipping_height, box_runs::tipping_turn());
    box_runs::native_friction(w, n.spinning);
    EXPECT_TRUE(box_runs::run_tipping(w)) << n.name;
  }
}

namespace {

// The box coupled to the table with its own patch.
void own_patch_friction(box_runs::box_world& w) {
  w.scene->plugin().couple(
      w.box, w.scene->table(),
      spinslide::pair_friction<double>(
          spinslide::own_patch{}, spinslide::friction_coefficient<double>{box_scenes::friction}));
}

}  // namespace

TEST(BulletBoxPatch, ThrownBoxStopsBothMotionsAtTheExactStop) {
  box_runs::box_world w(friction::plugin);
  own_patch_friction(w);
  box_checks::expect_exact_stop(
      box_runs::run_throw(
          w, [&] { return w.scene->plugin().report(w.box, w.scene->table()).sticking; }),
      box_runs::step, "own patch");
}

TEST(BulletBoxPatch, HoldsOnASlopeAtNineTenthsOfTheFrictionAngle) {
  const double alpha = box_scenes::slope_angle();
  box_runs::box_world w(friction::plugin,
                        btVector3(btScalar(box_scenes::gravity * std::sin(alpha)), 0,
                                  btScalar(-box_scenes::gravity * std::cos(alpha))));
  own_patch_friction(w);
  const double creep = box_runs::slope_creep(w);
  std::printf("own patch: moves %.3e m in 1 s on the slope\n", creep);
  EXPECT_LT(creep, 1e-9);
  EXPECT_TRUE(w.scene->plugin().report(w.box, w.scene->table()).sticking);
}

TEST(BulletBoxPatch, PushedAtAnOffsetPointTurnsAsTheExactLimitSurfaceSays) {
  box_runs::box_world w(friction::plugin);
  own_patch_friction(w);
  box_checks::expect_exact_push(box_runs::run_push(w), "own patch");
}

// The box lands on a corner (Bullet's manifold then has one point: a point
// patch), falls onto an edge (a line) and its face: no exception, no NaN.
TEST(BulletBoxPatch, TippingOntoAnEdgeAndACornerRunsWithoutNaN) {
  box_runs::box_world w(friction::plugin, btVector3(0, 0, btScalar(-box_scenes::gravity)),
                        box_runs::tipping_height, box_runs::tipping_turn());
  own_patch_friction(w);
  std::array<int, 5> steps_with{};  // steps with 0, 1, 2, 3, 4 pressed points
  const auto count = [&] {
    const int n = w.scene->plugin().report(w.box, w.scene->table()).contacts;
    ++steps_with[static_cast<std::size_t>(n < 4 ? n : 4)];
  };
  EXPECT_NO_THROW(EXPECT_TRUE(box_runs::run_tipping(w, count)));
  std::printf("steps with 1, 2, 3, 4 pressed points: %d, %d, %d, %d\n", steps_with[1],
              steps_with[2], steps_with[3], steps_with[4]);
  EXPECT_GT(steps_with[1], 0);
  EXPECT_GT(steps_with[2], 0);
  EXPECT_GT(steps_with[4], 0);
}
