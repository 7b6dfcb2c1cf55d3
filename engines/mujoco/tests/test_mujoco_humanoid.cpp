//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The humanoid of engines/mujoco/examples/mujoco_humanoid with every body/floor pair coupled
// (issue 27): it stands still on a slope below its friction angle, a grazing
// start raises no error, its energy rises no more than with MuJoCo's own
// friction after a push and in a fall, and its soles (each its contact's
// own patch) resist pivoting with the coupled spin friction, within μNℓ.

#include <gtest/gtest.h>

#include "../examples/mujoco_humanoid/humanoid.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

std::vector<double> soles(const humanoid::scene& s) {
  std::vector<double> at;
  for (const char* foot : {"left_foot", "right_foot"}) {
    const int b = s.body(foot);
    at.push_back(s.position(b)[0]);  // where it stands, and its turn about the vertical
    at.push_back(s.position(b)[1]);
    at.push_back(s.yaw(b));
  }
  return at;
}

std::vector<int> foot_pairs(const humanoid::scene& s) {
  std::vector<int> pairs;
  const auto ids = humanoid::body_geoms(s.model.get());
  for (std::size_t k = 0; k < ids.size(); ++k)
    if (s.model->geom_type[ids[k]] == mjGEOM_BOX) pairs.push_back(static_cast<int>(k));
  return pairs;
}

}  // namespace

// On a floor tilted by 0.1 rad (tan α = 0.1 against μ = 0.8), after 10 s in
// which the sway on the soft contacts dies out, the soles move less than
// 1e-9 m along the floor and turn less than 1e-9 rad about the vertical in
// the next 10 s, both pairs sticking.
// MuJoCo's own friction creeps there by centimetres (the example's table).
TEST(MujocoHumanoid, StandsStillOnASlope) {
  humanoid::scene s(humanoid::coupled, 0.1);
  s.run(10);
  const auto before = soles(s);
  s.run(10);
  const auto after = soles(s);
  for (std::size_t k = 0; k < before.size(); ++k) EXPECT_NEAR(after[k], before[k], 1e-9) << k;
  for (const int p : foot_pairs(s)) {
    EXPECT_TRUE(s.coupled_friction->report(static_cast<std::size_t>(p)).sticking) << p;
    EXPECT_GT(s.coupled_friction->report(static_cast<std::size_t>(p)).normal_force(), 100);
  }
}

// Set down with its soles 1e-12 and 1e-10 m into the floor, or released
// leaning so that it falls on its arm and hip (curved contacts whose patch
// starts at zero): no exception, every velocity finite.
TEST(MujocoHumanoid, GrazingStartsAndAFallRaiseNoError) {
  for (const double lift : {-1e-12, -1e-10, 0.0}) {
    humanoid::scene s(humanoid::coupled, 0, lift);
    for (int i = 0; i < 500; ++i) {
      ASSERT_NO_THROW(s.step()) << lift << " at step " << i;
      for (int k = 0; k < s.model->nv; ++k) ASSERT_TRUE(std::isfinite(s.data->qvel[k]));
    }
  }
  humanoid::scene s(humanoid::coupled);
  s.data->qpos[3] = std::cos(0.25);
  s.data->qpos[4] = std::sin(0.25);
  mj_forward(s.model.get(), s.data.get());
  int touching = 0;
  for (int i = 0; i < 2000; ++i) {
    ASSERT_NO_THROW(s.step()) << "falling, at step " << i;
    for (int k = 0; k < s.model->nv; ++k) ASSERT_TRUE(std::isfinite(s.data->qvel[k]));
    int now = 0;
    for (std::size_t p = 0; p < humanoid::body_geoms(s.model.get()).size(); ++p)
      now += s.coupled_friction->report(p).contacts > 0;
    touching = std::max(touching, now);
  }
  EXPECT_GE(touching, 4) << "the fall should bring more than the feet down";
}

// MuJoCo's energy leaves out what its soft contacts store, so after an
// impact it rises by joules with any friction.  After a 300 N push, and in
// a fall, the coupled humanoid's largest rise is within 1.5 times MuJoCo's
// own (condim 3 and 4) plus 0.1 J.
TEST(MujocoHumanoid, EnergyRisesNoMoreThanWithMuJoCosFriction) {
  auto push = [](const humanoid::friction_model& f) {
    humanoid::scene s(f);
    s.run(3);
    const int torso = s.body("torso");
    s.applied(torso)[0] = 300;
    s.run(0.2);
    s.applied(torso)[0] = 0;
    return s.largest_rise(3);
  };
  auto fall = [](const humanoid::friction_model& f) {
    humanoid::scene s(f);
    s.data->qpos[3] = std::cos(0.25);
    s.data->qpos[4] = std::sin(0.25);
    mj_forward(s.model.get(), s.data.get());
    return s.largest_rise(3);
  };
  const double push_native = std::max(push(humanoid::sliding_only), push(humanoid::torsional));
  const double fall_native = std::max(fall(humanoid::sliding_only), fall(humanoid::torsional));
  EXPECT_LE(push(humanoid::coupled), 1.5 * push_native + 0.1) << push_native;
  EXPECT_LE(fall(humanoid::coupled), 1.5 * fall_native + 0.1) << fall_native;
}

// 30 N m about the vertical on the torso: the soles resist with their spin
// friction (MuJoCo's condim 3 has none), within μNℓ of each sole (ℓ its
// patch's largest distance from the patch origin: no friction on the patch
// has a longer lever), and
// once the twist has wound into the joints the body holds (its turn changes
// by less than 1e-3 rad in the last second).
TEST(MujocoHumanoid, SolesResistPivotingWithTheirSpinFriction) {
  humanoid::scene s(humanoid::coupled);
  s.run(3);
  const int torso = s.body("torso"), pelvis = s.body("pelvis");
  auto yaw = [&] { return s.yaw(pelvis); };
  s.applied(torso)[5] = 30;
  s.run(1);
  double most = 0;
  for (int i = 0; i < 500; ++i) {
    s.step();
    for (const int p : foot_pairs(s)) {
      const auto& r = s.coupled_friction->report(static_cast<std::size_t>(p));
      const double bound = humanoid::friction * r.normal_force() * r.patch_radius;
      EXPECT_LE(std::fabs(r.friction_torque()), bound * (1 + 1e-9) + 1e-9);
      most = std::max(most, std::fabs(r.friction_torque()));
    }
  }
  const double turned = yaw();
  s.run(1);
  EXPECT_GT(most, 1.0) << "the soles' spin friction should carry part of the torque";
  EXPECT_LT(std::fabs(yaw() - turned), 1e-3);
}
