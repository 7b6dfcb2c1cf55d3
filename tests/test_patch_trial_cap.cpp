//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The trial cap of a DEM contact on a flat patch (contact/patch_trial_cap.hpp):
// the capped friction is μN times the friction wrench of its slip, nearest to
// the trial in the springs' energy metric among sampled points of the set,
// the rewritten springs give it with the damping, a trial inside is kept,
// and a 256-gon caps as the round disk's cap_trial_state does.
#include <gtest/gtest.h>

#include <spinslide/contact/patch_trial_cap.hpp>
#include <spinslide/contact/trial_cap.hpp>
#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/polygon_patch.hpp>
#include <spinslide/values/profile.hpp>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "regular_polygon.hpp"

namespace {

using spinslide::centre_of_pressure;
using spinslide::polygon_patch;
using vec2 = std::array<double, 2>;
using trial = spinslide::spring_trial<vec2, double>;

spinslide::spring_stiffness<double> springs(double kt, double kw) {
  return {spinslide::tangential_stiffness<double>{kt}, spinslide::twisting_stiffness<double>{kw}};
}
spinslide::patch_force_contact<double> load(double n, double mu) {
  return {spinslide::normal_force<double>{n}, spinslide::friction_coefficient<double>{mu}};
}

TEST(PatchTrialCap, OnTheSetNearestAndSpringsGiveIt) {
  const std::vector<vec2> sole{{-0.1, -0.04}, {0.12, -0.04}, {0.12, 0.06}, {-0.1, 0.06}};
  const std::vector<polygon_patch<double>> patches{
      polygon_patch<double>(sole),
      polygon_patch<double>(sole, centre_of_pressure<double>{{0.1, 0.05}})};
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(-1, 1);
  const double kt = 2000, kw = 3, n = 10, mu = 0.4, mun = n * mu;
  int slips = 0, sticks = 0;
  for (const auto& p : patches) {
    for (int k = 0; k < 60; ++k) {
      const double reach = k % 2 ? 0.004 : 0.001;
      const trial t{
          {reach * u(rng), reach * u(rng)}, 0.1 * u(rng), {u(rng), u(rng)}, 0.05 * u(rng)};
      const auto r = spinslide::cap_trial_state(p, t, springs(kt, kw), load(n, mu));
      const std::array<double, 3> f{-kt * t.displacement[0] + t.damping_force[0],
                                    -kt * t.displacement[1] + t.damping_force[1],
                                    -kw * t.twist + t.damping_torque};
      // The springs give the result with the damping.
      EXPECT_NEAR(-kt * r.displacement[0] + t.damping_force[0], r.force[0], 1e-12 * mun);
      EXPECT_NEAR(-kt * r.displacement[1] + t.damping_force[1], r.force[1], 1e-12 * mun);
      EXPECT_NEAR(-kw * r.twist + t.damping_torque, r.torque, 1e-12 * mun);
      if (r.sticking) {
        ++sticks;
        EXPECT_EQ(r.force[0], f[0]);
        EXPECT_EQ(r.torque, f[2]);
        continue;
      }
      ++slips;
      const auto w = spinslide::friction_wrench(p, r.slip);
      EXPECT_NEAR(r.force[0], mun * w.force[0], 1e-12 * mun);
      EXPECT_NEAR(r.force[1], mun * w.force[1], 1e-12 * mun);
      EXPECT_NEAR(r.torque, mun * w.torque, 1e-12 * mun * p.radius());
      const auto energy = [&](double fx, double fy, double tq) {
        return ((fx - f[0]) * (fx - f[0]) + (fy - f[1]) * (fy - f[1])) / kt +
               (tq - f[2]) * (tq - f[2]) / kw;
      };
      const double best = energy(r.force[0], r.force[1], r.torque);
      for (int j = 0; j < 300; ++j) {
        const auto q = spinslide::friction_wrench(p, {{u(rng), u(rng)}, u(rng) / p.radius()});
        EXPECT_GE(energy(mun * q.force[0], mun * q.force[1], mun * q.torque), best * (1 - 1e-12));
      }
    }
  }
  EXPECT_GT(slips, 30);
  EXPECT_GT(sticks, 10);
}

TEST(PatchTrialCap, ManyGonCapsAsTheRoundDisk) {
  const double a = 0.02;
  const polygon_patch<double> p(spinslide_test::regular_polygon(256, a));
  std::mt19937_64 rng(43);
  std::uniform_real_distribution<double> u(-1, 1);
  const double kt = 5000, kw = 0.8, n = 4, mu = 0.5, mun = n * mu;
  for (int k = 0; k < 60; ++k) {
    const trial t{{0.001 * u(rng), 0.001 * u(rng)}, 0.05 * u(rng), {0, 0}, 0};
    const auto flat = spinslide::cap_trial_state(p, t, springs(kt, kw), load(n, mu));
    const auto round = spinslide::cap_trial_state(
        spinslide::uniform_disk<>(), t, springs(kt, kw),
        spinslide::force_contact<double>{spinslide::patch_radius<double>{a},
                                         spinslide::normal_force<double>{n},
                                         spinslide::friction_coefficient<double>{mu}});
    EXPECT_NEAR(flat.force[0], round.force[0], 2e-4 * mun);
    EXPECT_NEAR(flat.force[1], round.force[1], 2e-4 * mun);
    EXPECT_NEAR(flat.torque, round.torque, 2e-4 * mun * a);
  }
}

TEST(PatchTrialCap, BadArgumentsAreDomainErrors) {
  const polygon_patch<double> p({{0, 0}, {1, 0}, {0, 1}});
  const trial t{{0.1, 0}, 0, {0, 0}, 0};
  EXPECT_THROW(spinslide::cap_trial_state(p, t, springs(0, 1), load(1, 0.5)), std::domain_error);
  EXPECT_THROW(spinslide::cap_trial_state(p, t, springs(1, 1), load(-1, 0.5)), std::domain_error);
  const trial bad{{NAN, 0}, 0, {0, 0}, 0};
  EXPECT_THROW(spinslide::cap_trial_state(p, bad, springs(1, 1), load(1, 0.5)), std::domain_error);
  // No load: nothing is held, and the springs give only the damping.
  const auto free = spinslide::cap_trial_state(p, t, springs(2, 1), load(0, 0.5));
  EXPECT_FALSE(free.sticking);
  EXPECT_EQ(free.force[0], 0.0);
  EXPECT_EQ(free.displacement[0], 0.0);
}

}  // namespace
