//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Every profile reaches MuJoCo (issue 40): pair_friction holds its profile in
// the run-time handle contact_profile, so a ring, Boussinesq's flat punch, a
// tabulated profile and a profile the handle does not name (a weighted sum,
// held erased) each couple the paper's disk in MuJoCo.  Each is checked
// against its own exact result: random throws stop at the exact stop of a
// disk with that pressure (the library's throw through its stop, a result
// that does not come from the engine), as the uniform disk's do in
// test_mujoco.cpp.
#include <gtest/gtest.h>
#include <spinslide/contact/pair_friction.hpp>
#include <spinslide/engines/mujoco.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include "disk_throws.hpp"

#include <cstddef>

namespace {

using spinslide::friction_coefficient;
using spinslide::pair_friction;
using spinslide::patch_radius;

// The disk of engines/mujoco/examples/mujoco_disk (R = 6 cm, μ = 0.2) with
// the pressure `profile`, thrown `throws` times at 2e-3 s and 1e-3 s from
// rest on its floor.  No NaN; every throw stops from 0.1 step before its
// exact stop to 2 steps after it, and none slips again (the uniform disk's
// bounds, test_mujoco.cpp).
void expect_within_bounds(const char* name, double step, const random_throws::step_statistics& s) {
  EXPECT_EQ(s.not_finite, 0) << name << " " << step;
  EXPECT_EQ(s.never, 0) << name << " " << step;
  EXPECT_EQ(s.slipped_again, 0) << name << " " << step;
  EXPECT_GE(s.quantile(0), -0.1) << name << " " << step;
  EXPECT_LE(s.quantile(1), 2.0) << name << " " << step;
}

template <class Profile>
void expect_exact_stops(const char* name, const Profile& profile, std::size_t throws) {
  const auto outcomes = disk_throws::run(
      name, profile,
      pair_friction(profile, patch_radius<double>{0.06}, friction_coefficient<double>{0.2}),
      {2e-3, 1e-3}, 4001, throws);
  for (const auto& entry : outcomes) expect_within_bounds(name, entry.first, entry.second);
}

TEST(MujocoAdapter, ARingStopsAtItsExactStop) {
  expect_exact_stops("MuJoCo, ring", spinslide::ring<>(), 40);
}

TEST(MujocoAdapter, BoussinesqsPunchStopsAtItsExactStop) {
  expect_exact_stops("MuJoCo, Boussinesq", spinslide::boussinesq<>(), 40);
}

TEST(MujocoAdapter, ATabulatedProfileStopsAtItsExactStop) {
  expect_exact_stops("MuJoCo, tabulated Hertz",
                     spinslide::tabulated_profile<>(spinslide::hertz<>()), 40);
}

// A profile the handle does not name, held as an erased_profile.
TEST(MujocoAdapter, AnErasedProfileStopsAtItsExactStop) {
  const auto mixed =
      spinslide::weighted_sum({0.5, 0.5}, spinslide::uniform_disk<>(), spinslide::ring<>());
  ASSERT_TRUE(spinslide::contact_profile<double>(mixed).erased());
  expect_exact_stops("MuJoCo, disk + ring", mixed, 40);
}

}  // namespace
