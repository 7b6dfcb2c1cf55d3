//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// A humanoid for MuJoCo, written here (docs/engines.md, "A humanoid"): 16
// bodies, 21 hinge joints held in a standing pose by joint springs (no
// actuators: it stands as a passive, damped structure), box feet and capsule
// and sphere limbs, 62 kg, 1.7 m.  Every geom of it can touch the floor; with
// spinslide every one of those pairs is coupled (condim 1 on the humanoid,
// spinslide's friction in its place), otherwise MuJoCo's own friction with
// condim 3 (sliding), 4 (and torsional) or 6 (and rolling).  Used by
// engines/mujoco/examples/mujoco_humanoid/main.cpp, engines/mujoco/tests/test_mujoco_humanoid.cpp
// and benchmarks/bench_mujoco.cpp.
#ifndef SPINSLIDE_EXAMPLES_MUJOCO_HUMANOID_HPP
#define SPINSLIDE_EXAMPLES_MUJOCO_HUMANOID_HPP

#include <mujoco/mujoco.h>
#include <spinslide/engines/mujoco.hpp>
#include <spinslide/spinslide.hpp>

#include "../mujoco_disk/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace humanoid {

constexpr double friction = 0.8;  // μ, every pair
// The radius [m] of a disk of a sole's area (0.22 × 0.1 m): MuJoCo's
// torsional friction below is that disk's.  spinslide's soles are the boxes.
constexpr double foot_patch = 0.065;
constexpr double time_step = 2e-3;

// How the humanoid's contacts with the floor get their friction.
struct friction_model {
  const char* name;  // for tables and plots
  int condim;        // 1: spinslide's (the geoms frictionless in MuJoCo)
};
inline const friction_model coupled{"spinslide", 1};
inline const friction_model sliding_only{"MuJoCo condim 3", 3};
inline const friction_model torsional{"MuJoCo condim 4", 4};
inline const friction_model rolling{"MuJoCo condim 6", 6};

// The model: the floor tilted by `slope` [rad] about y, the humanoid's pelvis
// at height `lift` above standing (its soles `lift` above the floor: a
// grazing start for lift ≈ 0).  MuJoCo's torsional friction for condim ≥ 4
// is the uniform disk's ⟨r⟩μ = (2/3)μa of the sole, its rolling friction
// 1e-4 m.
inline std::string xml(const friction_model& f, double slope = 0, double lift = 0) {
  const double torsion = 2.0 / 3.0 * friction * foot_patch;
  char head[900];
  std::snprintf(head, sizeof head,
                "<mujoco model='humanoid'>"
                "<option timestep='%g' solver='Newton' integrator='Euler' iterations='50' "
                "gravity='%.17g 0 %.17g'><flag energy='enable'/></option>"
                "<default><joint damping='150' armature='0.05' limited='true'/>"
                "<geom condim='%d' friction='%g %g 1e-4' density='1000'/></default>"
                "<worldbody><geom name='floor' type='plane' size='20 20 0.1' condim='%d'/>",
                time_step, 9.81 * std::sin(slope), -9.81 * std::cos(slope), f.condim, friction,
                torsion, f.condim);
  // Standing: the soles' bottoms at z = 0 when lift = 0 (feet 0.05 thick).
  std::string body = head;
  char pelvis[200];
  std::snprintf(pelvis, sizeof pelvis, "<body name='pelvis' pos='0 0 %.17g'><freejoint/>",
                0.925 + lift);
  body += pelvis;
  body +=
      "<geom name='pelvis' type='capsule' fromto='0 -0.09 0 0 0.09 0' size='0.09'/>"
      "<body name='torso' pos='0 0 0.1'>"
      "<joint name='abdomen_y' type='hinge' axis='0 1 0' range='-40 40' stiffness='1500'/>"
      "<joint name='abdomen_z' type='hinge' axis='0 0 1' range='-40 40' stiffness='800'/>"
      "<geom name='torso' type='capsule' fromto='0 0 0.05 0 0 0.4' size='0.12'/>"
      "<geom name='head' type='sphere' pos='0 0 0.6' size='0.1'/>";
  for (const int side : {1, -1}) {
    const char* s = side > 0 ? "left" : "right";
    char arm[1400];
    std::snprintf(
        arm, sizeof arm,
        "<body name='%s_upper_arm' pos='0 %g 0.38'>"
        "<joint name='%s_shoulder_x' type='hinge' axis='1 0 0' range='-90 90' stiffness='300'/>"
        "<joint name='%s_shoulder_y' type='hinge' axis='0 1 0' range='-90 90' stiffness='300'/>"
        "<geom name='%s_upper_arm' type='capsule' fromto='0 0 0 0 0 -0.28' size='0.04'/>"
        "<body name='%s_lower_arm' pos='0 0 -0.3'>"
        "<joint name='%s_elbow' type='hinge' axis='0 1 0' range='-120 0' stiffness='150'/>"
        "<geom name='%s_lower_arm' type='capsule' fromto='0 0 0 0 0 -0.24' size='0.035'/>"
        "<geom name='%s_hand' type='sphere' pos='0 0 -0.29' size='0.045'/>"
        "</body></body>",
        s, side * 0.19, s, s, s, s, s, s, s);
    body += arm;
  }
  body += "</body>";  // torso
  for (const int side : {1, -1}) {
    const char* s = side > 0 ? "left" : "right";
    char leg[1800];
    std::snprintf(
        leg, sizeof leg,
        "<body name='%s_thigh' pos='0 %g -0.04'>"
        "<joint name='%s_hip_x' type='hinge' axis='1 0 0' range='-30 30' stiffness='2500'/>"
        "<joint name='%s_hip_y' type='hinge' axis='0 1 0' range='-90 30' stiffness='2500'/>"
        "<joint name='%s_hip_z' type='hinge' axis='0 0 1' range='-40 40' stiffness='800'/>"
        "<geom name='%s_thigh' type='capsule' fromto='0 0 0 0 0 -0.36' size='0.065'/>"
        "<body name='%s_shin' pos='0 0 -0.4'>"
        "<joint name='%s_knee' type='hinge' axis='0 1 0' range='0 150' stiffness='2500'/>"
        "<geom name='%s_shin' type='capsule' fromto='0 0 0 0 0 -0.34' size='0.05'/>"
        "<body name='%s_foot' pos='0 0 -0.41'>"
        "<joint name='%s_ankle_y' type='hinge' axis='0 1 0' range='-50 50' stiffness='2000'/>"
        "<joint name='%s_ankle_x' type='hinge' axis='1 0 0' range='-30 30' stiffness='2000'/>"
        "<geom name='%s_foot' type='box' pos='0.04 0 -0.05' size='0.11 0.05 0.025'/>"
        "</body></body></body>",
        s, side * 0.1, s, s, s, s, s, s, s, s, s, s, s);
    body += leg;
  }
  body += "</body></worldbody></mujoco>";
  return body;
}

// The humanoid's geoms that can touch the floor: every geom but the floor.
inline std::vector<int> body_geoms(const mjModel* m) {
  std::vector<int> ids;
  for (int g = 0; g < m->ngeom; ++g)
    if (m->geom_bodyid[g] != 0) ids.push_back(g);
  return ids;
}

// A pair's friction for one of the humanoid's geoms: the feet are flat
// soles, each its contact's own patch (the hull of MuJoCo's contact points
// under their normal forces: the sole's face, or its edge or corner as the
// foot rolls), the capsules and spheres curved (Hertz's patch from MuJoCo's
// penetration, from 0: a grazing touch is point friction).
inline spinslide::pair_friction<double> friction_of(const mjModel* m, int geom) {
  const spinslide::friction_coefficient<double> mu{friction};
  if (m->geom_type[geom] == mjGEOM_BOX)
    return spinslide::pair_friction<double>(spinslide::own_patch{}, mu);
  return spinslide::pair_friction(
      spinslide::hertz<>(),
      spinslide::hertz_radius{m->geom_size[3 * static_cast<std::size_t>(geom)]}, mu);
}

// A humanoid scene: the model, its data and, for the coupled model, the
// friction with every body/floor pair coupled.
struct scene {
  mujoco_scene::model_ptr model;
  mujoco_scene::data_ptr data;
  std::unique_ptr<spinslide::mujoco::coupled_friction> coupled_friction;

  explicit scene(const friction_model& f, double slope = 0, double lift = 0)
      : model(mujoco_scene::load(xml(f, slope, lift))), data(mj_makeData(model.get())) {
    mj_forward(model.get(), data.get());  // positions, energy: defined from the start
    if (f.condim != 1) return;
    coupled_friction = std::make_unique<spinslide::mujoco::coupled_friction>(model.get());
    const spinslide::mujoco::geom_id floor{0};
    for (const int g : body_geoms(model.get()))
      coupled_friction->couple(spinslide::mujoco::geom_id{g}, floor, friction_of(model.get(), g));
  }
  void step() {
    if (coupled_friction)
      coupled_friction->step(data.get());
    else
      mj_step(model.get(), data.get());
  }
  // Kinetic plus potential energy (gravity and the joint springs) [J].
  double energy() const {
    mj_energyPos(model.get(), data.get());
    mj_energyVel(model.get(), data.get());
    return data->energy[0] + data->energy[1];
  }
  int body(const char* name) const { return mj_name2id(model.get(), mjOBJ_BODY, name); }
  // A body's position (3 entries) and its applied force and torque (6).
  const mjtNum* position(int b) const { return data->xpos + 3 * static_cast<std::size_t>(b); }
  mjtNum* applied(int b) { return data->xfrc_applied + 6 * static_cast<std::size_t>(b); }
  // A body's turn about the vertical [rad].
  double yaw(int b) const {
    const mjtNum* r = data->xmat + 9 * static_cast<std::size_t>(b);
    return std::atan2(r[3], r[0]);
  }
  // `seconds` of steps.
  void run(double seconds) {
    const int steps = static_cast<int>(std::lround(seconds / time_step));
    for (int i = 0; i < steps; ++i) step();
  }
  // The largest rise of the energy above its lowest value so far over
  // `seconds` of steps, recording every tenth step's energy in `trace`.
  double largest_rise(double seconds, std::vector<double>* trace = nullptr) {
    double lowest = energy(), rise = 0;
    const int steps = static_cast<int>(std::lround(seconds / time_step));
    for (int i = 0; i < steps; ++i) {
      step();
      const double e = energy();
      rise = std::max(rise, e - lowest);
      lowest = std::min(lowest, e);
      if (trace && i % 10 == 0) trace->push_back(e);
    }
    return rise;
  }
};

}  // namespace humanoid

#endif  // SPINSLIDE_EXAMPLES_MUJOCO_HUMANOID_HPP
