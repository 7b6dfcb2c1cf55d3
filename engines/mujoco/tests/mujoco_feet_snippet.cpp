//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The many-contact example that opens docs/engines.md (between "snippet
// begin" and "snippet end", shown there verbatim, as is plate_on_feet.xml;
// the tests engines.mujoco_feet_snippet_in_docs and
// engines.mujoco_feet_model_in_docs check that): a plate on four coupled
// feet, thrown sliding and spinning.  Passes (exit code 0) if every foot
// sticks at the end, carries a quarter of the weight (to 1 %: the feet are
// placed symmetrically), and the plate is at rest and stays there (below
// 1e-9 m and 1e-9 rad in one more second).
#include <spinslide/engines/mujoco.hpp>
#include <spinslide/spinslide.hpp>

#include <cmath>
#include <cstdio>

int main() try {
  // snippet begin
  char error[1000] = "";
  mjModel* model = mj_loadXML("plate_on_feet.xml", nullptr, error, sizeof error);
  if (model == nullptr) throw std::runtime_error(error);
  mjData* data = mj_makeData(model);

  spinslide::mujoco::coupled_friction friction(model);
  for (const char* foot : {"foot0", "foot1", "foot2", "foot3"})
    friction.couple(
        spinslide::mujoco::geom_name{foot}, spinslide::mujoco::geom_name{"floor"},
        spinslide::pair_friction(spinslide::uniform_disk<>(), spinslide::patch_radius<double>{0.02},
                                 spinslide::friction_coefficient<double>{0.2}));
  for (int i = 0; i < 200; ++i) friction.step(data);  // settle on the feet
  data->qvel[0] = 0.3;                                // thrown at 0.3 m/s along x
  data->qvel[5] = 5;                                  // spinning at 5 rad/s
  while (data->time < 2) friction.step(data);

  for (std::size_t k = 0; k < 4; ++k) {
    const spinslide::pair_report& r = friction.report(k);
    std::printf("foot %zu: %d contact(s), N = %.4f N, %s, twisting torque %.2e N m\n", k,
                r.contacts, r.normal_force(), r.sticking ? "sticking" : "slipping",
                r.friction_torque());
  }
  // snippet end

  bool ok = true;
  for (std::size_t k = 0; k < 4; ++k) {
    const spinslide::pair_report& r = friction.report(k);
    ok = ok && r.sticking && std::fabs(r.normal_force() / (9.81 / 4) - 1) < 0.01;
  }
  const double x = data->qpos[0], y = data->qpos[1],
               turn = 2 * std::atan2(data->qpos[6], data->qpos[3]);
  const double speed = std::hypot(data->qvel[0], data->qvel[1]), spin = std::fabs(data->qvel[5]);
  while (data->time < 3) friction.step(data);
  const double drift = std::hypot(data->qpos[0] - x, data->qpos[1] - y);
  const double turned = std::fabs(2 * std::atan2(data->qpos[6], data->qpos[3]) - turn);
  std::printf(
      "plate at (%.4f, %.4f) m, turned %.4f rad; speed %.1e m/s, spin %.1e rad/s; in the "
      "next second: drift %.1e m, turn %.1e rad\n",
      x, y, turn, speed, spin, drift, turned);
  ok = ok && x > 0.01 && std::fabs(turn) > 0.01 && drift < 1e-9 && turned < 1e-9;
  mj_deleteData(data);
  mj_deleteModel(model);
  return ok ? 0 : 1;
} catch (const std::exception& e) {
  std::fprintf(stderr, "mujoco_feet_snippet: %s\n", e.what());
  return 1;
}
