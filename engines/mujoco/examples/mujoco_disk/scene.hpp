//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The paper's disk on a floor as a MuJoCo model (engines/mujoco/examples/mujoco_disk and
// benchmarks/bench_engines): R = 0.06 m, 1 cm thick, 0.1 kg (γ = 1/2), μ = 0.2,
// time step 1e-4 s, Newton solver, with MuJoCo's own friction (condim 3, 4 or
// 6, elliptic or pyramidal cone) or none (condim 1, for spinslide).
#ifndef SPINSLIDE_EXAMPLES_MUJOCO_SCENE_HPP
#define SPINSLIDE_EXAMPLES_MUJOCO_SCENE_HPP

#include <mujoco/mujoco.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

namespace mujoco_scene {

constexpr double radius = 0.06, half_thickness = 0.005, mass = 0.1, friction = 0.2;
constexpr double gravity = 9.81, time_step = 1e-4;

// MuJoCo's friction of a contact (condim ≥ 3) or none (condim 1).
struct friction_model {
  const char* name;  // for tables and plots
  int condim;        // 1: frictionless (spinslide adds it)
  const char* cone;  // "elliptic" or "pyramidal"
};

// The model's XML.  The torsional coefficient (2/3)μR is right for pure spin
// of a uniformly pressed disk; rolling friction (condim 6) is 0.
inline std::string disk_xml(const friction_model& f, double step = time_step) {
  char xml[1200];
  std::snprintf(xml, sizeof xml,
                "<mujoco model='disk'>\n"
                "  <option timestep='%g' solver='Newton' integrator='Euler' cone='%s'/>\n"
                "  <default><geom condim='%d' friction='%g %g 0'/></default>\n"
                "  <worldbody>\n"
                "    <geom name='floor' type='plane' size='5 5 0.1'/>\n"
                "    <body name='disk' pos='0 0 %g'>\n"
                "      <freejoint/>\n"
                "      <geom name='disk' type='cylinder' size='%g %g' mass='%g'/>\n"
                "    </body>\n"
                "  </worldbody>\n"
                "</mujoco>\n",
                step, f.cone, f.condim, friction, 2.0 / 3.0 * friction * radius, half_thickness,
                radius, half_thickness, mass);
  return xml;
}

struct model_deleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct data_deleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using model_ptr = std::unique_ptr<mjModel, model_deleter>;
using data_ptr = std::unique_ptr<mjData, data_deleter>;

// Compiles `xml` from memory (MuJoCo's virtual file system).
inline model_ptr load(const std::string& xml) {
  auto vfs = std::make_unique<mjVFS>();  // 2 MB: not on the stack
  mj_defaultVFS(vfs.get());
  const int size = static_cast<int>(xml.size());
  if (mj_makeEmptyFileVFS(vfs.get(), "scene.xml", size) != 0)
    throw std::runtime_error("mujoco_scene: cannot make the model file in MuJoCo's VFS");
  const int index = mj_findFileVFS(vfs.get(), "scene.xml");
  std::copy(xml.begin(), xml.end(), static_cast<char*>(vfs->filedata[index]));
  std::array<char, 1000> error{};
  mjModel* m = mj_loadXML("scene.xml", vfs.get(), error.data(), static_cast<int>(error.size()));
  mj_deleteVFS(vfs.get());
  if (m == nullptr) throw std::runtime_error(std::string("mujoco_scene: ") + error.data());
  return model_ptr(m);
}

// Lets the disk settle on the floor at rest (0.05 s), then throws it: speed
// v0 along x [m/s], spin ω0 about z [rad/s].  `step` advances one step.
template <class Step>
void settle_and_throw(const mjModel* m, mjData* d, double v0, double omega0, Step step) {
  mj_resetData(m, d);
  const auto steps = static_cast<int>(std::lround(0.05 / m->opt.timestep));
  for (int i = 0; i < steps; ++i) step();
  for (int i = 0; i < 6; ++i) d->qvel[i] = 0;
  d->qvel[0] = v0;
  d->qvel[5] = omega0;  // the free joint's angular velocity is in the body frame: z is up
  d->time = 0;
}

// The velocity [m/s] of the centre of the disk's lower face (the contact
// patch's centre) and the disk's spin about the vertical [rad/s].  Not the
// centre of mass: MuJoCo's soft contacts let the disk rock, which moves its
// centre of mass while the patch stays put.
struct patch_motion {
  double speed, spin;
};
inline patch_motion disk_patch_motion(const mjData* d) {
  // The free joint's qvel: the origin's velocity in the world frame, then the
  // angular velocity in the body frame.  (mj_objectVelocity would read cvel,
  // which mj_step leaves at the start of the step.)
  const mjtNum* q = d->qvel;
  const mjtNum* rot = d->xmat + 9;  // the body's orientation, row-major
  std::array<double, 3> w{};
  for (std::size_t i = 0; i < 3; ++i)
    w[i] = rot[3 * i] * q[3] + rot[3 * i + 1] * q[4] + rot[3 * i + 2] * q[5];
  const std::array<double, 3> r{-half_thickness * rot[2], -half_thickness * rot[5],
                                -half_thickness * rot[8]};  // to the lower face's centre
  const double vx = q[0] + w[1] * r[2] - w[2] * r[1];
  const double vy = q[1] + w[2] * r[0] - w[0] * r[2];
  return {std::hypot(vx, vy), w[2]};
}

}  // namespace mujoco_scene

#endif  // SPINSLIDE_EXAMPLES_MUJOCO_SCENE_HPP
