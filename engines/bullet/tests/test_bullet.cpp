//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// spinslide::bullet::coupled_friction_solver: its misuse checks, and physics
// inside Bullet against closed forms that do not come from the library (a
// coin on a slope; a ball that slides into rolling; a ball spinning in place
// under Hertz's pivoting torque; a coin sliding on a free plank, whose
// friction must leave the pair's momentum alone).  Thrown coins are tested in
// test_bullet_throws.cpp, a body on two feet in test_bullet_feet.cpp.
#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>
#include <spinslide/engines/bullet.hpp>
#include <spinslide/values/profile.hpp>

#include "../examples/bullet_coin/scene.hpp"
#include "bullet_world.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>

namespace {

using bullet_scene::coin_friction;
using bullet_scene::coin_half_thickness;
using bullet_scene::coin_radius;
using bullet_scene::g;
using bullet_test::ball_dt;
using bullet_test::ball_mass;
using bullet_test::ball_mu;
using bullet_test::ball_patch;
using bullet_test::ball_radius;
using bullet_test::coin_dt;
using bullet_test::coin_mass;
using bullet_test::coin_mu;
using bullet_test::moment_of_inertia;
using bullet_test::pi;
using bullet_test::world;
using spinslide::friction_coefficient;
using spinslide::hertz_radius;
using spinslide::pair_friction;
using spinslide::patch_radius;
using spinslide::bullet::coupled_friction_solver;

pair_friction<double> ball_friction() {
  return pair_friction(spinslide::hertz<>(),
                       hertz_radius(ball_radius, patch_radius<double>{ball_patch}),
                       friction_coefficient<double>{ball_mu});
}

}  // namespace

TEST(BulletAdapter, RefusesMisuse) {
  world w;
  btRigidBody* coin = w.add_coin(btVector3(0, 0, coin_half_thickness));
  coupled_friction_solver& s = w.plugin();
  EXPECT_THROW(s.couple(nullptr, w.table(), coin_friction()), std::invalid_argument);
  EXPECT_THROW(s.couple(coin, nullptr, coin_friction()), std::invalid_argument);
  EXPECT_THROW(s.couple(coin, coin, coin_friction()), std::invalid_argument);
  EXPECT_FALSE(s.coupled(coin, w.table()));
  EXPECT_THROW(s.report(coin, w.table()), std::out_of_range);
  EXPECT_FALSE(s.decouple(coin, w.table()));
}

TEST(BulletAdapter, CouplesAndDecouplesPairsInEitherOrder) {
  world w;
  btRigidBody* coin = w.add_coin(btVector3(0, 0, coin_half_thickness));
  coupled_friction_solver& s = w.plugin();
  s.couple(coin, w.table(), coin_friction());
  s.couple(w.table(), coin, coin_friction());  // the same pair: replaces it
  EXPECT_TRUE(s.coupled(coin, w.table()));
  EXPECT_TRUE(s.coupled(w.table(), coin));
  EXPECT_FALSE(s.report(coin, w.table()).touching());  // no step yet
  w.coin_steps(10);
  const auto r = s.report(w.table(), coin);
  EXPECT_TRUE(r.touching());
  EXPECT_EQ(r.patch_radius, coin_radius);
  EXPECT_GT(r.normal_impulse, 0.0);
  EXPECT_TRUE(s.decouple(coin, w.table()));
  EXPECT_FALSE(s.decouple(w.table(), coin));  // only one entry for both orders
  EXPECT_FALSE(s.coupled(w.table(), coin));
  EXPECT_THROW(s.report(coin, w.table()), std::out_of_range);
  w.coin_steps(10);  // Bullet's own friction again
}

TEST(BulletAdapter, NeedsWarmStartingForTheNormalImpulses) {
  // Without SOLVER_USE_WARMSTARTING Bullet does not write the normal
  // impulses back: a coupled pair's step throws; an uncoupled world steps.
  world w;
  btRigidBody* coin = w.add_coin(btVector3(0, 0, coin_half_thickness));
  w.dynamics().getSolverInfo().m_solverMode &= ~SOLVER_USE_WARMSTARTING;
  EXPECT_NO_THROW(w.coin_steps(10));
  w.plugin().couple(coin, w.table(), coin_friction());
  EXPECT_THROW(w.step(coin_dt), std::logic_error);
}

namespace {

// A coin on the table tilted by α about y (gravity tilted instead): settled
// for 0.1 s, then watched for 1 s.
struct slope_run {
  double moved = 0;   // down the slope in that second [m]
  double gained = 0;  // speed gained down the slope in that second [m/s]
  bool sticking = false;
};

slope_run coin_on_slope(double alpha) {
  world w(btVector3(g * std::sin(alpha), 0, -g * std::cos(alpha)));
  btRigidBody* coin = w.add_coin(btVector3(-1, 0, coin_half_thickness));
  w.plugin().couple(coin, w.table(), coin_friction());
  w.coin_steps(10000);  // settle: 0.1 s
  const double x0 = static_cast<double>(coin->getCenterOfMassPosition().x());
  const double v0 = static_cast<double>(coin->getLinearVelocity().x());
  w.coin_steps(100000);  // 1 s
  slope_run out;
  out.moved = static_cast<double>(coin->getCenterOfMassPosition().x()) - x0;
  out.gained = static_cast<double>(coin->getLinearVelocity().x()) - v0;
  out.sticking = w.plugin().report(coin, w.table()).sticking;
  return out;
}

// A billiard ball coupled with Hertz's law, settled on the table for 0.3 s.
struct resting_ball {
  world w;
  btRigidBody* ball = w.add_ball();
  resting_ball() {
    w.plugin().couple(ball, w.table(), ball_friction());
    for (int i = 0; i < 3000; ++i) w.step(ball_dt);
  }
  spinslide::bullet::pair_report report() { return w.plugin().report(ball, w.table()); }
};

// `steps` steps of the ball: the sum of the normal impulses, the end of
// the first step that stuck (-1: none), and the steps that did not stick
// after it and those before it that did not slip with a ratio.
struct ball_run {
  double impulse = 0, sticking_from = -1;
  int slipping_after = 0, not_slipping_before = 0;
};

ball_run step_ball(resting_ball& b, int steps) {
  ball_run out;
  for (int i = 0; i < steps; ++i) {
    b.w.step(ball_dt);
    const auto r = b.report();
    out.impulse += r.normal_impulse;
    if (out.sticking_from < 0 && r.sticking) out.sticking_from = (i + 1) * ball_dt;
    if (out.sticking_from < 0)
      out.not_slipping_before += r.touching() && r.ratio > 0 ? 0 : 1;
    else
      out.slipping_after += r.sticking ? 0 : 1;
  }
  return out;
}

}  // namespace

TEST(BulletAdapter, HoldsOnASlopeBelowTheFrictionAngle) {
  // The friction angle is atan 0.3 = 0.2915.  Below it (α = 0.2) the coin
  // sticks: the exact stick leaves no creep.
  const slope_run run = coin_on_slope(0.2);
  EXPECT_LT(std::fabs(run.moved), 1e-9) << "creep on a slope below the friction angle";
  EXPECT_TRUE(run.sticking);
}

TEST(BulletAdapter, SlidesDownASlopeBeyondTheFrictionAngle) {
  // Above the friction angle (α = 0.4) the coin slides down at
  // g(sin α − μ cos α).
  const double alpha = 0.4;
  const slope_run run = coin_on_slope(alpha);
  const double a = g * (std::sin(alpha) - coin_mu * std::cos(alpha));
  EXPECT_NEAR(run.gained / 1.0, a, 1e-3 * a);
  EXPECT_FALSE(run.sticking);
}

TEST(BulletAdapter, ABallSlidesIntoRollingAtFiveSeventhsOfItsSpeed) {
  // A ball thrown sliding without spin: friction μmg slows the centre and
  // spins the ball up until it rolls, at t = v0/(μg(1 + k)) with
  // v = v0 k/(1 + k), k = m r²/I (5/2 for a solid sphere and r = R).  The
  // contact point is below the centre: the adapter's lever must carry the
  // rolling.
  resting_ball b;
  btRigidBody* ball = b.ball;
  const double lever =
      static_cast<double>(ball->getCenterOfMassPosition().z()) - b.report().centre[2];
  EXPECT_NEAR(lever, ball_radius, 1e-9 * ball_radius);
  const double k = ball_mass * lever * lever / moment_of_inertia(ball, 1);
  EXPECT_NEAR(k, 2.5, 1e-8);
  const double v0 = 1.0;
  ball->setLinearVelocity(btVector3(v0, 0, ball->getLinearVelocity().z()));
  const int steps = 3000;  // 0.3 s
  const ball_run run = step_ball(b, steps);
  EXPECT_EQ(run.not_slipping_before, 0) << "the report must say slipping until the ball rolls";
  EXPECT_EQ(run.slipping_after, 0) << "the report must say sticking once the ball rolls";
  // The mean normal force over the run is the weight.
  EXPECT_NEAR(run.impulse / (steps * ball_dt), ball_mass * g, 1e-6 * ball_mass * g);
  // The slip falls by μg(1 + k)Δt per step, and the step in which it would
  // pass zero sticks: the rolling starts at the end of the step holding t.
  const double expected = v0 / (ball_mu * g * (1 + k));
  EXPECT_GE(run.sticking_from, expected);
  EXPECT_LT(run.sticking_from, expected + ball_dt);
  // The friction impulses act at the contact point, whose angular momentum
  // mvr + Iω they keep: 5v0/7 to round-off (r = R to Bullet's δ ~ 1e-17 m).
  const double v = static_cast<double>(ball->getLinearVelocity().x());
  EXPECT_NEAR(v, v0 * k / (1 + k), 1e-9 * v0);
  const btVector3 contact = ball->getVelocityInLocalPoint(btVector3(0, 0, -lever));
  EXPECT_LT(contact.length(), 1e-9);
}

TEST(BulletAdapter, ABallSpinningInPlaceFeelsHertzsPivotingTorque) {
  // A ball spinning about the vertical without sliding: T = μN a 3π/16 with
  // the patch radius a the report gives, so ω falls linearly at T/I.
  resting_ball b;
  btRigidBody* ball = b.ball;
  const double a = b.report().patch_radius;
  EXPECT_EQ(a, ball_patch);  // the minimum decides: Bullet's √(Rδ) is ~1e-9 m
  const double spin0 = 20;
  ball->setAngularVelocity(btVector3(0, 0, spin0));
  const double inertia = moment_of_inertia(ball, 2);
  EXPECT_NEAR(inertia, 0.4 * ball_mass * ball_radius * ball_radius, 1e-12 * inertia);
  const int steps = 100;
  const ball_run run = step_ball(b, steps);
  EXPECT_LT(run.sticking_from, 0.0) << "a spin far from stopping cannot stick";
  const double n = run.impulse / (steps * ball_dt);
  EXPECT_NEAR(n, ball_mass * g, 1e-6 * ball_mass * g);
  const double rate = ball_mu * n * a * 3 * pi / 16 / inertia;
  const double spin = static_cast<double>(ball->getAngularVelocity().z());
  // The pure-spin impulse law is exact per step: only round-off remains.
  EXPECT_NEAR(spin, spin0 - rate * steps * ball_dt, 1e-12 * spin0);
  EXPECT_LT(ball->getLinearVelocity().length(), 1e-9);  // no sliding from spin alone
}

TEST(BulletAdapter, FrictionBetweenTwoFreeBodiesKeepsTheirMomentum) {
  // Zero gravity, no table: a coin on a free plank, pressed together by
  // equal and opposite constant forces F on one vertical line.  The
  // friction impulses on the coin and the plank are equal and opposite, and
  // so are Bullet's normal impulses: the pair's momentum (all three
  // components, the external forces cancelling) may change in a step only by
  // round-off.  The slip between them falls at μF(1/m_coin + 1/m_plank).
  world w(btVector3(0, 0, 0), false);
  const double plank_mass = 1.0, plank_half_height = 0.01, press = coin_mass * g;
  btRigidBody* plank = w.add(std::make_unique<btBoxShape>(btVector3(0.5, 0.1, plank_half_height)),
                             plank_mass, btVector3(0, 0, -plank_half_height));
  btRigidBody* coin = w.add_coin(btVector3(-0.3, 0, coin_half_thickness));
  w.plugin().couple(coin, plank, coin_friction());
  auto step = [&] {
    // The plank's force on the coin's vertical line: no couple to tilt it.
    const btVector3 line = coin->getCenterOfMassPosition() - plank->getCenterOfMassPosition();
    coin->applyCentralForce(btVector3(0, 0, -press));
    plank->applyForce(btVector3(0, 0, press), btVector3(line.x(), line.y(), 0));
    w.step(coin_dt);
  };
  for (int i = 0; i < 2000; ++i) step();  // settle: 0.02 s
  const double v0 = 0.5;
  coin->setLinearVelocity(btVector3(v0, 0, coin->getLinearVelocity().z()));
  auto momentum = [&] {
    return coin->getLinearVelocity() * coin_mass + plank->getLinearVelocity() * plank_mass;
  };
  auto slip = [&] {
    const btVector3 d = coin->getLinearVelocity() - plank->getLinearVelocity();
    return std::hypot(static_cast<double>(d.x()), static_cast<double>(d.y()));
  };
  const double scale = coin_mass * v0;  // the momentum that friction moves
  const double slip0 = slip();
  double worst = 0, impulse = 0;
  const int steps = 5000;  // 0.05 s, sliding throughout
  for (int i = 0; i < steps; ++i) {
    const btVector3 before = momentum();
    step();
    const btVector3 change = momentum() - before;
    worst = std::fmax(worst, static_cast<double>(change.length()) / scale);
    impulse += w.plugin().report(coin, plank).normal_impulse;
    ASSERT_FALSE(w.plugin().report(coin, plank).sticking) << i;
  }
  EXPECT_LT(worst, 1e-12) << "the pair's momentum changed by more than round-off in a step";
  const double n = impulse / (steps * coin_dt);
  EXPECT_NEAR(n, press, 1e-3 * press);
  const double expected = coin_mu * press * (1 / coin_mass + 1 / plank_mass) * steps * coin_dt;
  EXPECT_NEAR(slip0 - slip(), expected, 1e-3 * expected);
}
