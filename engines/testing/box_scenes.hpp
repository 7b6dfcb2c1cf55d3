//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The box scenes of issue 42 item 6, engine-independent: a 0.22 × 0.10 m box
// face (a humanoid's sole), 1 cm thick, 1 kg, μ = 0.3, g = 9.81, and the
// exact answers the engines' runs are held to:
//  - thrown flat at 0.3 m/s along its length spinning at 5 rad/s: the exact
//    stop of the rigid face under uniform pressure (throw_plate, plate
//    item 5, checked there against scipy to 1e-9);
//  - on a slope at 0.9 of its friction angle: it holds;
//  - pushed in its body frame by a force along its length at a point of its
//    rear face offset from its axis, at the face's height (so that the push
//    and the friction tip it by nothing but the inertial force): its motion
//    by the exact friction wrench (friction_wrench) under uniform pressure,
//    integrated here by classical Runge–Kutta at 1e-5 s (the engine's
//    friction comes from the impulse law's projection, not from this);
//  - tipped onto an edge and a corner: dropped tilted, spinning and sliding.
#ifndef SPINSLIDE_TESTS_ENGINES_BOX_SCENES_HPP
#define SPINSLIDE_TESTS_ENGINES_BOX_SCENES_HPP

#include <spinslide/motion/plate_motion.hpp>
#include <spinslide/motion/plate_throw.hpp>
#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <array>
#include <cmath>
#include <cstddef>

namespace box_scenes {

constexpr double half_length = 0.11, half_width = 0.05, half_height = 0.005;
constexpr double mass = 1, friction = 0.3, gravity = 9.81;
constexpr double throw_speed = 0.3, throw_spin = 5;
// The push: its force along the body's x, as a multiple of μmg, at the rear
// face's point (−half_length, offset, −half_height) from the centre of mass;
// started from a slide at start_speed along x (from rest the slip has no
// direction yet).
constexpr double push_force = 1.05, push_offset = 0.03, start_speed = 0.05, push_time = 0.3;

// The box's moment of inertia about its vertical axis, over its mass.
inline double gyration_squared() {
  return (4 * half_length * half_length + 4 * half_width * half_width) / 12;
}

// The contact face about its centre.
inline spinslide::polygon_patch<double> face() {
  return spinslide::polygon_patch<double>({{-half_length, -half_width},
                                           {half_length, -half_width},
                                           {half_length, half_width},
                                           {-half_length, half_width}});
}

// The thrown face's exact stop (time, turn, displacement).
inline spinslide::plate_throw_result<double> exact_throw() {
  const spinslide::plate_motion<double> plate(
      face(), spinslide::gyration_radius<double>{std::sqrt(gyration_squared())},
      spinslide::friction_coefficient<double>{friction}, spinslide::gravity<double>{gravity});
  return spinslide::throw_plate(plate,
                                spinslide::planar_twist<double>{{throw_speed, 0}, throw_spin});
}

// What a throw in an engine measured: when the sliding and the spin
// stopped, the turn and the displacement of the centre at the end, and
// whether the motion stayed finite.
struct throw_outcome {
  double slide_stop = -1, spin_stop = -1, turn = 0, x = 0, y = 0;
  bool finite = true;
};

// The slope's angle: tan α = 0.9 μ.
inline double slope_angle() { return std::atan(0.9 * friction); }

// The push's force and torque about the centre of mass, body frame (per
// unit mass: the force in m/s², the torque in m²/s²).
struct body_wrench {
  double fx, fy, torque;
};
inline body_wrench push() {
  const double f = push_force * friction * gravity;
  return {f, 0, -push_offset * f};  // (−a, d) × (f, 0) = −d f
}

// The pushed box after push_time by the exact law: turn θ and the centre's
// world displacement (x, y), its body-frame velocity and spin.
struct pushed_state {
  double angle, x, y, ux, uy, omega;
};

// d/dt of (u_x, u_y, ω, θ, X, Y) under the push and the exact friction.
inline std::array<double, 6> push_rate(const spinslide::polygon_patch<double>& patch,
                                       const std::array<double, 6>& s) {
  const body_wrench w = push();
  const auto f =
      spinslide::friction_wrench(patch, spinslide::planar_twist<double>{{s[0], s[1]}, s[2]});
  const double mg = friction * gravity, c = std::cos(s[3]), sn = std::sin(s[3]);
  return {w.fx + mg * f.force[0] + s[2] * s[1],
          w.fy + mg * f.force[1] - s[2] * s[0],
          (w.torque + mg * f.torque) / gyration_squared(),
          s[2],
          c * s[0] - sn * s[1],
          sn * s[0] + c * s[1]};
}

inline pushed_state exact_push() {
  const auto patch = face();
  std::array<double, 6> s{start_speed, 0, 0, 0, 0, 0};
  const double h = 1e-5;
  const auto steps = static_cast<int>(std::lround(push_time / h));
  for (int i = 0; i < steps; ++i) {
    const auto k1 = push_rate(patch, s);
    std::array<double, 6> y{};
    for (std::size_t j = 0; j < 6; ++j) y[j] = s[j] + h / 2 * k1[j];
    const auto k2 = push_rate(patch, y);
    for (std::size_t j = 0; j < 6; ++j) y[j] = s[j] + h / 2 * k2[j];
    const auto k3 = push_rate(patch, y);
    for (std::size_t j = 0; j < 6; ++j) y[j] = s[j] + h * k3[j];
    const auto k4 = push_rate(patch, y);
    for (std::size_t j = 0; j < 6; ++j) s[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
  }
  return {s[3], s[4], s[5], s[0], s[1], s[2]};
}

}  // namespace box_scenes

#endif  // SPINSLIDE_TESTS_ENGINES_BOX_SCENES_HPP
