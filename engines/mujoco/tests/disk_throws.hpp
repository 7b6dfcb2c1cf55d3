//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Random throws of the disk of engines/mujoco/examples/mujoco_disk (R = 6 cm,
// μ = 0.2) in MuJoCo (random_throws.hpp), coupled with a pair_friction of any
// profile, against the exact stops of a disk with that pressure: the one
// loop of test_mujoco.cpp's and test_mujoco_profiles.cpp's throw tests.
#ifndef SPINSLIDE_ENGINES_MUJOCO_TESTS_DISK_THROWS_HPP
#define SPINSLIDE_ENGINES_MUJOCO_TESTS_DISK_THROWS_HPP

#include <spinslide/contact/pair_friction.hpp>
#include <spinslide/engines/mujoco.hpp>

#include "../examples/mujoco_disk/scene.hpp"
#include "random_throws.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <vector>

namespace disk_throws {

/// The throws of `seed` (at most `throws` of them; random_throws::count by
/// default) at the time steps `steps`, each from the disk settled on its
/// floor, with the disk coupled by `friction` and the exact stops of
/// `profile`, its pressure; what summarize() makes of them, per step.
template <class Profile>
std::map<double, random_throws::step_statistics> run(
    const char* name, const Profile& profile, const spinslide::pair_friction<double>& friction,
    const std::vector<double>& steps, unsigned seed, std::size_t throws = random_throws::count) {
  using spinslide::mujoco::coupled_friction;
  using spinslide::mujoco::geom_name;
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
    frictions.back()->couple(geom_name{"disk"}, geom_name{"floor"}, friction);
    mujoco_scene::settle_and_throw(m, rest.back().get(), 0.0, 0.0,
                                   [&] { frictions.back()->step(rest.back().get()); });
    gamma = m->body_inertia[5] / (m->body_mass[1] * 0.06 * 0.06);
  }
  std::vector<random_throws::throw_case> cs =
      random_throws::cases({0.06, gamma, 0.2, 9.81, steps}, seed, profile);
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
  return random_throws::summarize(name, cs, os);
}

}  // namespace disk_throws

#endif  // SPINSLIDE_ENGINES_MUJOCO_TESTS_DISK_THROWS_HPP
