//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// spinslide::bullet::coupled_friction_solver: thrown coins, sliding and
// spinning, in Bullet (issue 27): their stops against the exact stops, at
// the steps users run, and the pair's report at every step.
#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>
#include <spinslide/engines/bullet.hpp>
#include <spinslide/values/profile.hpp>

#include "../examples/bullet_coin/scene.hpp"
#include "bullet_world.hpp"
#include "coin_throws.hpp"
#include "random_throws.hpp"
#include "report_convention.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

namespace {

using bullet_scene::coin_friction;
using bullet_scene::coin_half_thickness;
using bullet_scene::coin_radius;
using bullet_scene::g;
using bullet_test::coin_mu;
using bullet_test::pi;
using bullet_test::world;

using coin_throws::stop_errors;

// The uniform coin's throws (coin_throws.hpp): its own friction, the uniform
// disk's exact stops.
stop_errors coin_stops(double dt, int throws, std::mt19937_64 rng) {
  return coin_throws::run(spinslide::uniform_disk<>(), coin_friction(), dt, throws, rng);
}

double median(const std::vector<double>& sorted) { return sorted[sorted.size() / 2]; }

}  // namespace

// issue 27 - the patch centre was the impulse-weighted mean of Bullet's few
// manifold points, which wandered 27 % of R off the coin's axis on average;
// 2107 of 10 000 random throws stopped early (median −9.9 %), mostly at
// Δt ≥ 1e-4 s.  A flat face's centre is now its geometry's (the centre of
// mass projected on the contact plane).  Measured (this test's throws,
// docs/engines.md): at Δt = 1e-5 s every stop within 0.1 % of exact; at
// 1e-4 s none early beyond the step, median within 0.5 %, the slowest from
// Bullet's normal impulse, which falls to a fifth of mg in some steps of a
// 2 mm coin (also with Bullet's own friction); at 1e-3 s and 1/240 s that
// loss of support makes the stops late by half or more (not held here).
TEST(BulletAdapter, RegressionCoinStopsMatchTheExactOnes) {
  const stop_errors fine = coin_stops(1e-5, 40, std::mt19937_64(27));
  ASSERT_EQ(fine.never, 0);
  EXPECT_EQ(fine.moved_again, 0);
  EXPECT_GT(fine.relative.front(), -1e-3);
  EXPECT_LT(fine.relative.back(), 1e-3);
  const stop_errors coarse = coin_stops(1e-4, 200, std::mt19937_64(28));
  for (const auto* e : {&fine, &coarse})
    std::printf(
        "coin stops: %zu throws, error %+.4f %% (first) %+.4f %% (median) %+.4f %% (last), "
        "%d moved again, %d never at rest\n",
        e->relative.size(), 100 * e->relative.front(), 100 * median(e->relative),
        100 * e->relative.back(), e->moved_again, e->never);
  ASSERT_EQ(coarse.never, 0);
  EXPECT_LE(coarse.moved_again, 10);  // measured 5: Bullet's normal contact (see above)
  EXPECT_GT(coarse.relative.front(), -0.01);
  EXPECT_LT(std::fabs(median(coarse.relative)), 5e-3);
}

// issue 27 - one pair_report for every adapter: report(coin, table) has the
// coin as its first body (the normal points down into the table) and
// report(table, coin) is the same step reversed; the report keeps the
// common convention at every step of a sliding and spinning throw
// (report_convention.hpp, against the coin's motion read from Bullet).
TEST(BulletAdapter, ReportKeepsTheCommonConvention) {
  world w;
  btRigidBody* coin = w.add_coin(btVector3(0, 0, coin_half_thickness));
  w.plugin().couple(w.table(), coin, coin_friction());
  constexpr double dt = 1e-4;
  for (int i = 0; i < 100; ++i) w.step(dt);  // settle
  coin->setLinearVelocity(btVector3(0.3f, 0.1f, 0));
  coin->setAngularVelocity(btVector3(0, 0, 20));
  int slipping = 0;
  for (int i = 0; i < 2000; ++i) {
    w.step(dt);
    const spinslide::pair_report r = w.plugin().report(coin, w.table());
    EXPECT_TRUE(report_convention::reversed_equal(r, w.plugin().report(w.table(), coin))) << i;
    const btVector3 centre(static_cast<btScalar>(r.centre[0]), static_cast<btScalar>(r.centre[1]),
                           static_cast<btScalar>(r.centre[2]));
    const btVector3 v = coin->getVelocityInLocalPoint(centre - coin->getCenterOfMassPosition());
    const btVector3 spin = coin->getAngularVelocity();
    report_convention::expect_kept(
        r, {static_cast<double>(v.x()), static_cast<double>(v.y()), static_cast<double>(v.z())},
        {static_cast<double>(spin.x()), static_cast<double>(spin.y()),
         static_cast<double>(spin.z())});
    if (!r.touching()) continue;
    EXPECT_NEAR(r.normal[2], -1.0, 1e-6);
    EXPECT_EQ(r.step, dt);
    slipping += r.sticking ? 0 : 1;
  }
  EXPECT_GT(slipping, 100);
  EXPECT_TRUE(w.plugin().report(coin, w.table()).sticking);
}

// issue 27 - randomized throws (random_throws.hpp): the steel coin of
// engines/bullet/examples/bullet_coin at the steps users run, from 1/240 s to 1e-5 s, each
// throw from the coin settled on the table (one world per step, the coin
// put back where it settled before each throw).  No exception, no NaN;
// every throw stops, none slips again, and each stop is within 2 steps
// before to 2.5 steps after its exact stop (the measured extremes, per
// step, are in docs/engines.md, "Randomized throws").
TEST(BulletAdapter, RandomThrowsStopNearTheExactStop) {
  const std::vector<double> steps{1.0 / 240, 1e-3, 1e-4, 1e-5};
  const double thickness = 2 * coin_half_thickness;
  const double mass = 7850 * pi * coin_radius * coin_radius * thickness;
  btCylinderShapeZ shape(btVector3(coin_radius, coin_radius, thickness / 2));
  std::vector<std::unique_ptr<bullet_scene::scene>> scenes;
  std::vector<btRigidBody*> coins;
  std::vector<btTransform> settled;
  for (const double dt : steps) {
    scenes.push_back(
        std::make_unique<bullet_scene::scene>(bullet_scene::friction::plugin, btVector3(0, 0, 0)));
    coins.push_back(scenes.back()->add(&shape, mass, btVector3(0, 0, thickness / 2)));
    bullet_scene::set_coin_friction(*scenes.back(), coins.back());
    for (int i = 0; i < 300; ++i) scenes.back()->step(dt);
    settled.push_back(coins.back()->getCenterOfMassTransform());
  }
  const auto cs = random_throws::cases({coin_radius, 0.5, coin_mu, g, steps}, 2703);
  std::vector<random_throws::outcome> os(cs.size());
  for (std::size_t k = 0; k < cs.size(); ++k) {
    const random_throws::throw_case& c = cs[k];
    const std::size_t at = k % steps.size();
    bullet_scene::scene& s = *scenes[at];
    btRigidBody* coin = coins[at];
    coin->setCenterOfMassTransform(settled[at]);
    coin->setLinearVelocity(btVector3(static_cast<btScalar>(c.speed * std::cos(c.direction)),
                                      static_cast<btScalar>(c.speed * std::sin(c.direction)), 0));
    coin->setAngularVelocity(btVector3(0, 0, static_cast<btScalar>(c.spin)));
    os[k] = random_throws::run(c, [&] {
      s.step(c.dt);
      const btVector3 v = coin->getLinearVelocity(), w = coin->getAngularVelocity();
      return random_throws::observation{
          std::isfinite(static_cast<double>(v.x() + v.y() + v.z() + w.x() + w.y() + w.z())),
          s.plugin().report(coin, s.table())};
    });
  }
  for (const auto& entry : random_throws::summarize("Bullet", cs, os)) {
    const random_throws::step_statistics& s = entry.second;
    EXPECT_EQ(s.not_finite, 0) << entry.first;
    EXPECT_EQ(s.never, 0) << entry.first;
    EXPECT_EQ(s.slipped_again, 0) << entry.first;
    EXPECT_GE(s.quantile(0), -2.0) << entry.first;  // measured -1.27 at 1/240 s, -0.03 at 1e-5 s
    EXPECT_LE(s.quantile(1), 2.5) << entry.first;   // measured +1.74 at 1e-3 s, +1.00 at 1e-5 s
  }
}
