//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// spinslide::bullet::coupled_friction_solver: its misuse checks, and physics
// inside Bullet against closed forms that do not come from the library (a
// coin on a slope; a ball that slides into rolling; a ball spinning in place
// under Hertz's pivoting torque; a coin sliding on a free plank, whose
// friction must leave the pair's momentum alone).
#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>
#include <spinslide/engines/bullet.hpp>
#include <spinslide/spinslide.hpp>

#include "../examples/bullet_coin/scene.hpp"
#include "random_throws.hpp"
#include "report_convention.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <vector>

namespace {

using bullet_scene::coin_friction;
using bullet_scene::coin_half_thickness;
using bullet_scene::coin_radius;
using bullet_scene::g;
using spinslide::friction_coefficient;
using spinslide::hertz_radius;
using spinslide::pair_friction;
using spinslide::patch_radius;
using spinslide::bullet::coupled_friction_solver;

constexpr double pi = 3.14159265358979323846;

// The coin of engines/bullet/examples/bullet_coin (scene.hpp: R = 12 mm, 2 mm thick, on wood,
// μ = 0.3), 7.1 g, stepped at 1e-5 s.
constexpr double coin_mass = 0.0071, coin_mu = bullet_scene::coin_mu, coin_dt = 1e-5;
// A billiard ball: R = 28.6 mm, 0.17 kg, on cloth (μ = 0.2), stepped at 1e-4 s,
// with Hertz's patch whose 1 mm minimum decides (Bullet's √(Rδ) is ~1e-9 m).
constexpr double ball_radius = 0.0286, ball_mass = 0.17, ball_mu = 0.2, ball_dt = 1e-4;
constexpr double ball_patch = 1e-3;

pair_friction ball_friction() {
  return pair_friction(spinslide::hertz<>(),
                       hertz_radius(ball_radius, patch_radius<double>{ball_patch}),
                       friction_coefficient<double>{ball_mu});
}

// The example's world (scene.hpp) with coupled_friction_solver, `gravity`
// and, unless asked not to, its table with the top face centred at the
// origin.
class world : public bullet_scene::scene {
 public:
  explicit world(const btVector3& gravity = btVector3(0, 0, -g), bool with_table = true)
      : scene(bullet_scene::friction::plugin,
              with_table ? std::optional<btVector3>(btVector3(0, 0, 0)) : std::nullopt, gravity) {}

  btRigidBody* add_coin(const btVector3& origin) {
    return add(std::make_unique<btCylinderShapeZ>(
                   btVector3(coin_radius, coin_radius, coin_half_thickness)),
               coin_mass, origin);
  }
  btRigidBody* add_ball() {
    return add(std::make_unique<btSphereShape>(ball_radius), ball_mass,
               btVector3(0, 0, ball_radius));
  }
  // n steps of coin_dt.
  void coin_steps(int n) {
    for (int i = 0; i < n; ++i) step(coin_dt);
  }
};

double moment_of_inertia(const btRigidBody* body, int axis) {
  return 1 / static_cast<double>(body->getInvInertiaDiagLocal()[axis]);
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

namespace {

struct stop_errors {
  std::vector<double> relative;  // (Bullet's stop − the exact stop)/the exact stop
  int never = 0;                 // throws not at rest within three exact stop times
  int moved_again = 0;           // throws that moved again after coming to rest
};

// Random throws of the steel coin (v0* in [0.1, 2.1], ω0* in [0.1, 3.1],
// drawn from `rng`) stepped at `dt` with the plug-in, against the exact stop
// of the same throw (simulate_throw's t*, the uniform disk at γ = 1/2): "at
// rest" is both the horizontal speed and R|ω| below 1e-6 of their starts.
stop_errors coin_stops(double dt, int throws, std::mt19937_64 rng) {
  const double thickness = 2 * coin_half_thickness;
  const double mass = 7850 * pi * coin_radius * coin_radius * thickness;
  std::uniform_real_distribution<double> u(0, 1);
  stop_errors out;
  for (int k = 0; k < throws; ++k) {
    const double vs = 0.1 + 2 * u(rng), ws = 0.1 + 3 * u(rng);
    const double v0 = vs * coin_mu * std::sqrt(g * coin_radius),
                 w0 = ws * coin_mu * std::sqrt(g / coin_radius);
    bullet_scene::scene s(bullet_scene::friction::plugin, btVector3(0, 0, 0));
    btCylinderShapeZ shape(btVector3(coin_radius, coin_radius, thickness / 2));
    btRigidBody* coin = s.add(&shape, mass, btVector3(0, 0, thickness / 2));
    bullet_scene::set_coin_friction(s, coin);
    for (int i = 0; i < 300; ++i) s.step(1e-5);  // settle on the table
    coin->setLinearVelocity(btVector3(v0, 0, coin->getLinearVelocity().z()));
    coin->setAngularVelocity(btVector3(0, 0, w0));
    const double exact =
        spinslide::stop_time(spinslide::uniform_disk<>(), 0.5, vs, ws) * std::sqrt(coin_radius / g);
    double stopped = -1;
    bool again = false;
    const int steps = static_cast<int>(3 * exact / dt) + 10;
    for (int i = 1; i <= steps; ++i) {
      s.step(dt);
      const btVector3 v = coin->getLinearVelocity();
      const double w = coin->getAngularVelocity().z();
      EXPECT_TRUE(std::isfinite(v.x() + v.y() + v.z() + w));
      const bool rest = std::hypot(v.x(), v.y()) < 1e-6 * v0 && std::fabs(w) < 1e-6 * w0;
      if (rest && stopped < 0) stopped = i * dt;
      if (!rest && stopped >= 0) {
        again = true;
        stopped = -1;
      }
    }
    if (stopped < 0) {
      ++out.never;
      continue;
    }
    out.moved_again += again;
    out.relative.push_back((stopped - exact) / exact);
  }
  std::sort(out.relative.begin(), out.relative.end());
  return out;
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

namespace {

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
// and the body drifts) and 3 % at 1e-4 s (measured +2.1 %; one foot after
// the other gave +6.2 %; a centre shared by both feet had not stopped at
// 1.2 exact stops).  The pair's report sums
// both feet.
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
    EXPECT_NEAR(stopped / exact, 1, dt < 5e-5 ? 0.01 : 0.03) << dt;
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
