//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The box scenes of issue 42 item 6 (engines/testing/box_scenes.hpp) in
// MuJoCo, run with any step function: MuJoCo's own friction (mj_step, condim
// 3, 4 or 6) or the adapter's (coupled_friction::step); what each run
// measures.  Used by engines/mujoco/tests/test_mujoco_box.cpp and the
// example beside it (main.cpp).
#ifndef SPINSLIDE_EXAMPLES_MUJOCO_BOX_RUNS_HPP
#define SPINSLIDE_EXAMPLES_MUJOCO_BOX_RUNS_HPP

#include <mujoco/mujoco.h>

#include "../mujoco_disk/scene.hpp"
#include "box_scenes.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

namespace box_runs {

using stepper = std::function<void(mjData*)>;

// MuJoCo's friction (condim 3, 4, 6 with its default torsional 0.005 m and
// rolling 1e-4 m coefficients) or none (condim 1).  The box starts at rest
// on the floor with the orientation `quat` and its centre at `height`.
struct scene {
  int condim = 1;
  const char* cone = "elliptic";
  double step = 1e-4;
  std::array<double, 3> gravity{0, 0, -box_scenes::gravity};
  double height = box_scenes::half_height;
  std::array<double, 4> quat{1, 0, 0, 0};
};

inline std::string box_xml(const scene& s) {
  char xml[1500];
  std::snprintf(xml, sizeof xml,
                "<mujoco><option timestep='%g' solver='Newton' integrator='Euler' cone='%s' "
                "gravity='%.17g %.17g %.17g'/>"
                "<default><geom condim='%d' friction='%g 0.005 0.0001'/></default><worldbody>"
                "<geom name='floor' type='plane' size='5 5 0.1'/>"
                "<body name='box' pos='0 0 %.17g' quat='%.17g %.17g %.17g %.17g'><freejoint/>"
                "<geom name='box' type='box' size='%g %g %g' mass='%g'/></body>"
                "</worldbody></mujoco>",
                s.step, s.cone, s.gravity[0], s.gravity[1], s.gravity[2], s.condim,
                box_scenes::friction, s.height, s.quat[0], s.quat[1], s.quat[2], s.quat[3],
                box_scenes::half_length, box_scenes::half_width, box_scenes::half_height,
                box_scenes::mass);
  return xml;
}

// The box's yaw (its free joint's quaternion turned about z only).
inline double yaw(const mjData* d) { return 2 * std::atan2(d->qpos[6], d->qpos[3]); }

inline void settle(const mjModel* m, mjData* d, const stepper& step, double seconds = 0.1) {
  const auto steps = static_cast<int>(std::lround(seconds / m->opt.timestep));
  for (int i = 0; i < steps; ++i) step(d);
}

// The throw: when the sliding (the centre below 1 mm/s) and the spin
// (below 0.01 rad/s) stopped, or, if given, when `stopped` first says so
// (the adapter's sticking report); the turn and the displacement at the end
// (0.5 s).
using box_scenes::throw_outcome;
inline throw_outcome run_throw(const mjModel* m, mjData* d, const stepper& step,
                               const std::function<bool()>& stopped = nullptr) {
  settle(m, d, step);
  for (int i = 0; i < 6; ++i) d->qvel[i] = 0;
  d->qvel[0] = box_scenes::throw_speed;
  d->qvel[5] = box_scenes::throw_spin;
  d->time = 0;
  const double x0 = d->qpos[0], y0 = d->qpos[1], yaw0 = yaw(d);
  throw_outcome o;
  while (d->time < 0.5 - m->opt.timestep / 2) {
    step(d);
    for (int j = 0; j < 6; ++j) o.finite = o.finite && std::isfinite(d->qvel[j]);
    const bool reported = static_cast<bool>(stopped);
    const bool at_rest = reported && stopped();
    if (o.slide_stop < 0 && (reported ? at_rest : std::hypot(d->qvel[0], d->qvel[1]) < 1e-3))
      o.slide_stop = d->time;
    if (o.spin_stop < 0 && (reported ? at_rest : std::fabs(d->qvel[5]) < 1e-2))
      o.spin_stop = d->time;
  }
  o.turn = yaw(d) - yaw0;
  o.x = d->qpos[0] - x0;
  o.y = d->qpos[1] - y0;
  return o;
}

// The slope (gravity tilted by α about y): how far the box moves along it
// in 1 s after 0.5 s to settle.
inline double slope_creep(const mjModel* m, mjData* d, const stepper& step) {
  settle(m, d, step, 0.5);
  const double x0 = d->qpos[0], y0 = d->qpos[1];
  settle(m, d, step, 1.0);
  return std::hypot(d->qpos[0] - x0, d->qpos[1] - y0);
}

// The push (box_scenes::push, applied through xfrc_applied at the centre
// of mass, turned with the box, with the moment of its point of action)
// from a slide at start_speed.
inline box_scenes::pushed_state run_push(const mjModel* m, mjData* d, const stepper& step) {
  settle(m, d, step);
  for (int i = 0; i < 6; ++i) d->qvel[i] = 0;
  d->qvel[0] = box_scenes::start_speed;
  d->time = 0;
  const double x0 = d->qpos[0], y0 = d->qpos[1], yaw0 = yaw(d);
  const box_scenes::body_wrench w = box_scenes::push();
  const double mass = m->body_mass[1];
  const auto steps = static_cast<int>(std::lround(box_scenes::push_time / m->opt.timestep));
  for (int i = 0; i < steps; ++i) {
    const double c = std::cos(yaw(d)), s = std::sin(yaw(d));
    mjtNum* f = d->xfrc_applied + 6;  // body 1
    f[0] = mass * (c * w.fx - s * w.fy);
    f[1] = mass * (s * w.fx + c * w.fy);
    f[2] = 0;
    // At the face's height the push also pitches the box by −h f about its
    // body y: the moment that cancels the friction's at the face.
    const double pitch = -box_scenes::half_height * w.fx;
    f[3] = mass * (-s * pitch);
    f[4] = mass * (c * pitch);
    f[5] = mass * w.torque;
    step(d);
  }
  const double c = std::cos(yaw(d)), s = std::sin(yaw(d));
  return {yaw(d) - yaw0,
          d->qpos[0] - x0,
          d->qpos[1] - y0,
          c * d->qvel[0] + s * d->qvel[1],
          -s * d->qvel[0] + c * d->qvel[1],
          d->qvel[5]};
}

// The box dropped from 3 cm, tilted by 0.5 rad about (1, 0.6, 0) (it lands on
// a corner, falls onto an edge, then its face), thrown at 0.4 m/s and
// spinning at 6 rad/s, for 1 s: true if every velocity stayed finite
// (`observe` is called after every step).
inline scene tipping_scene(int condim = 1, const char* cone = "elliptic") {
  scene s;
  s.condim = condim;
  s.cone = cone;
  s.height = 0.03 + 0.07;
  const double half = 0.25, n = std::hypot(1.0, 0.6);
  s.quat = {std::cos(half), std::sin(half) / n, 0.6 * std::sin(half) / n, 0};
  return s;
}
inline bool run_tipping(const mjModel* m, mjData* d, const stepper& step,
                        const std::function<void()>& observe = nullptr) {
  d->qvel[0] = 0.4;
  d->qvel[5] = 6;
  bool finite = true;
  const auto steps = static_cast<int>(std::lround(1.0 / m->opt.timestep));
  for (int i = 0; i < steps; ++i) {
    step(d);
    if (observe) observe();
    for (int j = 0; j < 7; ++j) finite = finite && std::isfinite(d->qpos[j]);
    for (int j = 0; j < 6; ++j) finite = finite && std::isfinite(d->qvel[j]);
  }
  return finite;
}

}  // namespace box_runs

#endif  // SPINSLIDE_EXAMPLES_MUJOCO_BOX_RUNS_HPP
