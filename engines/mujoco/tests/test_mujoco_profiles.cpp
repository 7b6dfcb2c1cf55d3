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

#include "../examples/mujoco_disk/scene.hpp"
#include "random_throws.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

namespace {

using spinslide::friction_coefficient;
using spinslide::pair_friction;
using spinslide::patch_radius;
using spinslide::mujoco::coupled_friction;
using spinslide::mujoco::geom_name;

// The disk of engines/mujoco/examples/mujoco_disk (R = 6 cm, μ = 0.2) with
// the pressure `profile`, thrown `throws` times at 2e-3 s and 1e-3 s from
// rest on its floor.  No NaN; every throw stops from 0.1 step before its
// exact stop to 2 steps after it, and none slips again (the uniform disk's
// bounds, test_mujoco.cpp).
template <class Profile>
void expect_exact_stops(const char* name, const Profile& profile, std::size_t throws) {
  const std::vector<double> steps{2e-3, 1e-3};
  std::vector<mujoco_scene::model_ptr> models;
  std::vector<mujoco_scene::data_ptr> rest, work;
  std::vector<std::unique_ptr<coupled_friction>> frictions;
  double gamma = 0;
  for (const double dt : steps) {
    models.push_back(mujoco_scene::load(mujoco_scene::disk_xml({"spinslide", 1, "elliptic"}, dt)));
    const mjModel* m = models.back().get();
    rest.emplace_back(mj_makeData(m));
    work.emplace_back(mj_makeData(m));
    frictions.push_back(std::make_unique<coupled_friction>(m));
    frictions.back()->couple(
        geom_name{"disk"}, geom_name{"floor"},
        pair_friction(profile, patch_radius<double>{0.06}, friction_coefficient<double>{0.2}));
    mujoco_scene::settle_and_throw(m, rest.back().get(), 0.0, 0.0,
                                   [&] { frictions.back()->step(rest.back().get()); });
    gamma = m->body_inertia[5] / (m->body_mass[1] * 0.06 * 0.06);
  }
  std::vector<random_throws::throw_case> cs =
      random_throws::cases({0.06, gamma, 0.2, 9.81, steps}, 4001, profile);
  cs.resize(std::min(cs.size(), throws));
  std::vector<random_throws::outcome> os(cs.size());
  for (std::size_t k = 0; k < cs.size(); ++k) {
    const random_throws::throw_case& c = cs[k];
    const std::size_t at = k % steps.size();
    const mjModel* m = models[at].get();
    mjData* d = work[at].get();
    mj_copyData(d, m, rest[at].get());
    coupled_friction& f = *frictions[at];
    d->qvel[0] = c.speed * std::cos(c.direction);
    d->qvel[1] = c.speed * std::sin(c.direction);
    d->qvel[5] = c.spin;
    os[k] = random_throws::run(c, [&] {
      f.step(d);
      bool finite = true;
      for (int j = 0; j < 6; ++j) finite = finite && std::isfinite(d->qvel[j]);
      return random_throws::observation{finite, f.report(0)};
    });
  }
  for (const auto& entry : random_throws::summarize(name, cs, os)) {
    const random_throws::step_statistics& s = entry.second;
    EXPECT_EQ(s.not_finite, 0) << name << " " << entry.first;
    EXPECT_EQ(s.never, 0) << name << " " << entry.first;
    EXPECT_EQ(s.slipped_again, 0) << name << " " << entry.first;
    EXPECT_GE(s.quantile(0), -0.1) << name << " " << entry.first;
    EXPECT_LE(s.quantile(1), 2.0) << name << " " << entry.first;
  }
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
