//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// spinslide::mujoco::coupled_friction and spinslide::engines::pair_friction:
// their input checks, and physics inside MuJoCo against closed forms that do
// not come from the library (a block on a slope; a ball that slides into
// rolling; a ball spinning in place under Hertz's pivoting torque).
#include <gtest/gtest.h>
#include <spinslide/engines/mujoco.hpp>
#include <spinslide/spinslide.hpp>

#include "../../examples/mujoco_disk/scene.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

namespace {

using spinslide::friction_coefficient;
using spinslide::patch_radius;
using spinslide::engines::hertz_radius;
using spinslide::engines::pair_friction;
using spinslide::mujoco::coupled_friction;
using spinslide::mujoco::geom_id;
using spinslide::mujoco::geom_name;

constexpr double pi = 3.14159265358979323846;

pair_friction disk_friction(double mu = 0.2) {
  return pair_friction(spinslide::uniform_disk<>(), patch_radius<double>{0.06},
                       friction_coefficient<double>{mu});
}

mujoco_scene::model_ptr frictionless_disk() {
  return mujoco_scene::load(mujoco_scene::disk_xml({"spinslide", 1, "elliptic"}));
}

// A ball of radius 0.0286 m and 0.17 kg (a billiard ball) on a floor.
mujoco_scene::model_ptr ball(const char* integrator = "Euler") {
  char xml[800];
  std::snprintf(xml, sizeof xml,
                "<mujoco><option timestep='1e-4' solver='Newton' integrator='%s'/>"
                "<default><geom condim='1'/></default><worldbody>"
                "<geom name='floor' type='plane' size='5 5 0.1'/>"
                "<body name='ball' pos='0 0 0.0286'><freejoint/>"
                "<geom name='ball' type='sphere' size='0.0286' mass='0.17'/></body>"
                "</worldbody></mujoco>",
                integrator);
  return mujoco_scene::load(xml);
}

// The ball on the floor, coupled with Hertz's law (a = √(Rδ), μ = 0.2), at
// rest after 0.5 s.
struct resting_ball {
  mujoco_scene::model_ptr model = ball();
  mujoco_scene::data_ptr data{mj_makeData(model.get())};
  std::unique_ptr<coupled_friction> friction = std::make_unique<coupled_friction>(model.get());
  resting_ball() {
    friction->couple(geom_name{"ball"}, geom_name{"floor"},
                     pair_friction(spinslide::hertz<>(), hertz_radius{0.0286},
                                   friction_coefficient<double>{0.2}));
    for (int i = 0; i < 5000; ++i) friction->step(data.get());
  }
};

}  // namespace

TEST(PairFriction, RefusesBadSettings) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const double a : {0.0, -1.0, nan, inf})
    EXPECT_THROW(pair_friction(spinslide::uniform_disk<>(), patch_radius<double>{a},
                               friction_coefficient<double>{0.2}),
                 std::domain_error)
        << a;
  for (const double mu : {-0.1, nan, inf})
    EXPECT_THROW(pair_friction(spinslide::uniform_disk<>(), patch_radius<double>{0.01},
                               friction_coefficient<double>{mu}),
                 std::domain_error)
        << mu;
  for (const double r : {0.0, -1.0, nan})
    EXPECT_THROW(
        pair_friction(spinslide::hertz<>(), hertz_radius{r}, friction_coefficient<double>{0.2}),
        std::domain_error)
        << r;
}

TEST(PairFriction, RadiusIsFixedOrHertzs) {
  const pair_friction fixed = disk_friction();
  EXPECT_EQ(fixed.radius(0.0), 0.06);
  EXPECT_EQ(fixed.radius(1e-3), 0.06);
  const pair_friction curved(spinslide::hertz<>(), hertz_radius{0.02},
                             friction_coefficient<double>{0.3});
  EXPECT_DOUBLE_EQ(curved.radius(2e-6), std::sqrt(0.02 * 2e-6));
  EXPECT_DOUBLE_EQ(curved.radius(0.0), 1e-6 * 0.02);   // the floor
  EXPECT_DOUBLE_EQ(curved.radius(-1.0), 1e-6 * 0.02);  // separated: no depth
  EXPECT_EQ(curved.friction(), 0.3);
}

TEST(PairFriction, StickingStopsTheContactExactly) {
  // W = diag(2, 2, 50): the impulse that stops (0.01, 0, 0.01) is
  // -(0.005, 0, 0.0002): (f, t) = (0.25, 0.17) in units of μΛ = 0.02 and μΛa, inside the set.
  pair_friction f = disk_friction();
  const spinslide::planar_metric<double> w({{{2, 0, 0}, {0, 2, 0}, {0, 0, 50}}});
  const auto p = f.impulse({0.01, 0.0}, 0.01, w, spinslide::normal_impulse<double>{0.1}, 0.0);
  EXPECT_TRUE(p.sticking);
  EXPECT_DOUBLE_EQ(p.force[0], -0.005);
  EXPECT_EQ(p.force[1], 0.0);
  EXPECT_DOUBLE_EQ(p.torque, -0.0002);
}

TEST(PairFriction, SlidingFollowsTheProfile) {
  // Pure sliding far beyond the cap: the force is μΛ along -v for both
  // profiles (F(∞) = 1), and the angular impulse a·μΛ·T(ε) differs with the
  // profile.  A light W keeps the motion sliding.
  const spinslide::planar_metric<double> w({{{1e-3, 0, 0}, {0, 1e-3, 0}, {0, 0, 1e-3}}});
  pair_friction disk = disk_friction();
  pair_friction sphere(spinslide::hertz<>(), patch_radius<double>{0.06},
                       friction_coefficient<double>{0.2});
  const auto pd = disk.impulse({1.0, 0.0}, 0.0, w, spinslide::normal_impulse<double>{1.0}, 0.0);
  const auto ps = sphere.impulse({1.0, 0.0}, 0.0, w, spinslide::normal_impulse<double>{1.0}, 0.0);
  EXPECT_FALSE(pd.sticking);
  EXPECT_NEAR(pd.force[0], -0.2, 1e-12);
  EXPECT_NEAR(ps.force[0], -0.2, 1e-12);
  // Spinning in place: |L| = μΛ a T(0): 2/3 for the disk, 3π/16 for Hertz.
  const auto qd = disk.impulse({0.0, 0.0}, 10.0, w, spinslide::normal_impulse<double>{1.0}, 0.0);
  const auto qs = sphere.impulse({0.0, 0.0}, 10.0, w, spinslide::normal_impulse<double>{1.0}, 0.0);
  EXPECT_NEAR(qd.torque, -0.2 * 0.06 * 2.0 / 3.0, 1e-14);
  EXPECT_NEAR(qs.torque, -0.2 * 0.06 * 3 * pi / 16, 1e-14);
}

TEST(MujocoAdapter, RefusesMisuse) {
  EXPECT_THROW(coupled_friction(nullptr), std::invalid_argument);
  const auto disk = frictionless_disk();
  coupled_friction f(disk.get());
  EXPECT_THROW(f.couple(geom_name{"disk"}, geom_name{"table"}, disk_friction()),
               std::invalid_argument);
  EXPECT_THROW(f.couple(geom_id{0}, geom_id{0}, disk_friction()), std::invalid_argument);
  EXPECT_THROW(f.couple(geom_id{0}, geom_id{2}, disk_friction()), std::invalid_argument);
  EXPECT_THROW(f.step(nullptr), std::invalid_argument);
  // Geoms with MuJoCo's own friction (condim 3) would get it twice.
  const auto frictional = mujoco_scene::load(mujoco_scene::disk_xml({"native", 3, "elliptic"}));
  coupled_friction g(frictional.get());
  EXPECT_THROW(g.couple(geom_name{"disk"}, geom_name{"floor"}, disk_friction()),
               std::invalid_argument);
  // RK4 does not split into mj_step1 and mj_step2.
  const auto rk4 = ball("RK4");
  EXPECT_THROW(coupled_friction{rk4.get()}, std::invalid_argument);
}

TEST(MujocoAdapter, HoldsOnASlopeAndSlidesBeyondIt) {
  // The floor tilted by α about y; μ = 0.2.  Below the friction angle
  // (tan 0.15 = 0.151) the disk sticks: no creep.  Above it (tan 0.3 =
  // 0.309) it slides down at g(sin α − μ cos α).
  for (const double alpha : {0.15, 0.3}) {
    char xml[900];
    std::snprintf(xml, sizeof xml,
                  "<mujoco><option timestep='1e-4' solver='Newton' integrator='Euler' "
                  "gravity='%.17g 0 %.17g'/><default><geom condim='1'/></default><worldbody>"
                  "<geom name='floor' type='plane' size='5 5 0.1'/>"
                  "<body name='disk' pos='0 0 0.005'><freejoint/>"
                  "<geom name='disk' type='cylinder' size='0.06 0.005' mass='0.1'/></body>"
                  "</worldbody></mujoco>",
                  9.81 * std::sin(alpha), -9.81 * std::cos(alpha));
    const auto model = mujoco_scene::load(xml);
    const mujoco_scene::data_ptr data(mj_makeData(model.get()));
    coupled_friction f(model.get());
    f.couple(geom_name{"disk"}, geom_name{"floor"}, disk_friction());
    for (int i = 0; i < 5000; ++i) f.step(data.get());  // settle: 0.5 s
    const double x0 = data->qpos[0], v0 = data->qvel[0];
    for (int i = 0; i < 10000; ++i) f.step(data.get());  // 1 s
    const double moved = data->qpos[0] - x0, gained = data->qvel[0] - v0;
    if (alpha < 0.2) {
      EXPECT_LT(std::fabs(moved), 1e-9) << "creep on a slope below the friction angle";
      EXPECT_TRUE(f.report(0).sticking);
    } else {
      const double a = 9.81 * (std::sin(alpha) - 0.2 * std::cos(alpha));
      EXPECT_NEAR(gained / 1.0, a, 1e-3 * a);
      EXPECT_FALSE(f.report(0).sticking);
    }
  }
}

TEST(MujocoAdapter, ABallSlidesIntoRollingAtTwoSeventhsOfItsSpeed) {
  // A ball thrown sliding without spin: friction μmg slows the centre and
  // spins the ball up until it rolls, at t = v0/(μg(1 + k)) with
  // v = v0 k/(1 + k), k = m r²/I (5/2 for a solid sphere and r = R: 2v0/(7μg)
  // and 5v0/7).  The lever r is from the centre to MuJoCo's contact point,
  // which its soft contact puts δ/2 inside the ball.  The contact point is
  // below the centre: the adapter's Jacobians must carry the rolling.
  const resting_ball b;
  const mjModel* model = b.model.get();
  mjData* data = b.data.get();
  coupled_friction& f = *b.friction;
  const double lever = data->qpos[2] - f.report(0).centre[2];
  EXPECT_NEAR(lever, 0.0286, 1e-2 * 0.0286);  // δ/2 = 0.18 mm with the default solref
  const double k = model->body_mass[1] * lever * lever / model->body_inertia[4];
  const double v0 = 1.0;
  data->qvel[0] = v0;
  data->time = 0;
  double rolling_from = -1;
  while (data->time < 0.3) {
    f.step(data);
    if (rolling_from < 0 && f.report(0).sticking) rolling_from = data->time;
  }
  const double expected = v0 / (0.2 * 9.81 * (1 + k));
  EXPECT_NEAR(rolling_from, expected, 2e-4 + 1e-3 * expected);
  EXPECT_NEAR(data->qvel[0], v0 * k / (1 + k), 1e-4 * v0);
  EXPECT_EQ(f.report(0).contacts, 1);
}

TEST(MujocoAdapter, ABallSpinningInPlaceFeelsHertzsPivotingTorque) {
  // A ball spinning about the vertical without sliding: T = μN a 3π/16 with
  // Hertz's a = √(Rδ) from MuJoCo's penetration δ, so ω falls linearly at
  // T/I, I = 2mR²/5.
  const resting_ball b;
  mjData* data = b.data.get();
  coupled_friction& f = *b.friction;
  const double a = f.report(0).patch_radius, n = f.report(0).normal_force;
  EXPECT_NEAR(n, 0.17 * 9.81, 1e-6 * n);
  EXPECT_NEAR(a, std::sqrt(0.0286 * f.report(0).penetration), 1e-15);
  data->qvel[5] = 20;
  const double inertia = 0.4 * 0.17 * 0.0286 * 0.0286;
  const double rate = 0.2 * n * a * 3 * pi / 16 / inertia;
  for (int i = 0; i < 100; ++i) f.step(data);
  EXPECT_NEAR(data->qvel[5], 20 - rate * 100 * 1e-4, 1e-6 * 20);
  EXPECT_LT(std::hypot(data->qvel[0], data->qvel[1]), 1e-9);  // no sliding from spin alone
}
