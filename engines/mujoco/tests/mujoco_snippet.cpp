//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The MuJoCo snippet of docs/engines.md (between "snippet begin" and
// "snippet end", shown there verbatim; the test engines.mujoco_snippet_in_docs
// checks that), run on the paper's disk thrown at 0.3 m/s and 5 rad/s.  Passes
// (exit code 0) if the disk comes to rest where spinslide's own integration
// of the throw stops it, to 1 % of the distance and of the angle.
#include <spinslide/engines/mujoco.hpp>
#include <spinslide/spinslide.hpp>

#include "../examples/mujoco_disk/scene.hpp"

#include <cmath>
#include <cstdio>

int main() try {
  const auto owned_model = mujoco_scene::load(mujoco_scene::disk_xml({"spinslide", 1, "elliptic"}));
  const mujoco_scene::data_ptr owned_data(mj_makeData(owned_model.get()));
  const mjModel* model = owned_model.get();
  mjData* data = owned_data.get();
  const double v0 = 0.3, omega0 = 5;
  data->qvel[0] = v0;
  data->qvel[5] = omega0;

  // snippet begin
  spinslide::mujoco::coupled_friction friction(model);
  friction.couple(
      spinslide::mujoco::geom_name{"disk"}, spinslide::mujoco::geom_name{"floor"},
      spinslide::pair_friction(spinslide::uniform_disk<>(), spinslide::patch_radius<double>{0.06},
                               spinslide::friction_coefficient<double>{0.2}));
  while (data->time < 0.5) friction.step(data);  // instead of mj_step(model, data)
  // snippet end

  const double gamma = model->body_inertia[5] / (model->body_mass[1] * 0.06 * 0.06);
  const auto exact = spinslide::simulate_throw_si(
      spinslide::uniform_disk<>(), spinslide::disk_radius{0.06},
      spinslide::friction_coefficient{0.2}, spinslide::gravity{9.81}, gamma,
      spinslide::initial_speed{v0}, spinslide::initial_spin{omega0});
  const double distance = std::hypot(data->qpos[0], data->qpos[1]);
  const double angle = 2 * std::atan2(data->qpos[6], data->qpos[3]);  // quaternion about z
  const double speed = std::hypot(data->qvel[0], data->qvel[1]), spin = std::fabs(data->qvel[5]);
  std::printf(
      "distance %.6f m (exact %.6f), angle %.5f rad (exact %.5f), at rest: v = %.1e m/s, "
      "omega = %.1e rad/s\n",
      distance, exact.distance, angle, exact.angle, speed, spin);
  const bool ok = std::fabs(distance / exact.distance - 1) < 0.01 &&
                  std::fabs(angle / exact.angle - 1) < 0.01 && speed < 1e-6 && spin < 1e-4;
  return ok ? 0 : 1;
} catch (const std::exception& e) {
  std::fprintf(stderr, "mujoco_snippet: %s\n", e.what());
  return 1;
}
