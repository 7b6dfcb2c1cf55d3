//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// A humanoid in MuJoCo with every body/floor pair coupled (humanoid.hpp),
// side by side with MuJoCo's own friction (condim 3, 4 and 6), in four
// scenes (docs/engines.md, "A humanoid"):
//   stand: 20 s on a floor tilted by 0.1 rad: how far the soles move in the
//          last 10 s (after the sway of the soft contacts has died out);
//   push:  300 N on the torso for 0.2 s: how far the feet slide, and whether
//          the energy ever rises once the push is over;
//   fall:  released leaning 0.5 rad to the side: it falls on its arm and
//          hip (curved contacts that start grazing); the energy's largest
//          rise;
//   pivot: 30 N·m about the vertical on the torso for 1.5 s: the body turns
//          on its soles, whose spin friction resists (MuJoCo's condim 3 has
//          none); the turn and the twisting torque under the left sole;
// and the cost of a step.  Writes mujoco_humanoid.csv (energy and turn
// against time) and, with gnuplot, mujoco_humanoid.png, into the directory
// given (default: the current one).  Exit status 1 if the coupled humanoid
// throws, its energy rises after a push, or it drifts standing.
//
//   ./build/release/engines/mujoco/examples/mujoco_humanoid/mujoco_humanoid [output_dir]

#include "humanoid.hpp"

#include "gnuplot.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using humanoid::friction_model;

const friction_model* const models[] = {&humanoid::coupled, &humanoid::sliding_only,
                                        &humanoid::torsional, &humanoid::rolling};

struct row {
  double stand_drift = 0;   // soles' largest displacement in the last 10 s standing [m]
  double push_slide = 0;    // soles' largest displacement from the push on [m]
  double push_rise = 0;     // the energy's largest rise after the push [J]
  double fall_rise = 0;     // the energy's largest rise in the fall [J]
  double pivot_turn = 0;    // the pelvis' turn about the vertical at the end [rad]
  double pivot_torque = 0;  // the twisting torque under the left sole, mid-pivot [N m]
  double step_us = 0;       // one step, standing [µs]
};

double sole_shift(const humanoid::scene& s, const std::vector<double>& from) {
  double most = 0;
  std::size_t k = 0;
  for (const char* foot : {"left_foot", "right_foot"}) {
    const int b = s.body(foot);
    most = std::max(most,
                    std::hypot(s.position(b)[0] - from[2 * k], s.position(b)[1] - from[2 * k + 1]));
    ++k;
  }
  return most;
}

std::vector<double> soles(const humanoid::scene& s) {
  std::vector<double> at;
  for (const char* foot : {"left_foot", "right_foot"}) {
    const int b = s.body(foot);
    at.push_back(s.position(b)[0]);
    at.push_back(s.position(b)[1]);
  }
  return at;
}

// The twisting torque under the left sole [N m]: spinslide's angular impulse
// over the step, or MuJoCo's torsional contact forces about the normal.
double sole_torque(const humanoid::scene& s) {
  const int foot = mj_name2id(s.model.get(), mjOBJ_GEOM, "left_foot");
  if (s.coupled_friction) {
    const auto ids = humanoid::body_geoms(s.model.get());
    const auto at = std::find(ids.begin(), ids.end(), foot) - ids.begin();
    return std::fabs(s.coupled_friction->report(static_cast<std::size_t>(at)).friction_torque());
  }
  double t = 0;
  for (int i = 0; i < s.data->ncon; ++i) {
    const mjContact& c = s.data->contact[i];
    if (c.geom1 != foot && c.geom2 != foot) continue;
    if (c.dim < 4) continue;
    mjtNum f[6];
    mj_contactForce(s.model.get(), s.data.get(), i, f);
    t += f[3];
  }
  return std::fabs(t);
}

row measure(const friction_model& f, std::vector<double>& fall_trace,
            std::vector<double>& pivot_trace) {
  row r;
  {
    humanoid::scene s(f, 0.1);
    s.run(10);
    const auto from = soles(s);
    const auto start = std::chrono::steady_clock::now();
    s.run(10);
    r.step_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
                    .count() /
                (10 / humanoid::time_step);
    r.stand_drift = sole_shift(s, from);
  }
  {
    humanoid::scene s(f);
    s.run(3);
    const auto from = soles(s);
    const int torso = s.body("torso");
    s.applied(torso)[0] = 300;
    s.run(0.2);
    s.applied(torso)[0] = 0;
    r.push_rise = s.largest_rise(4);
    r.push_slide = sole_shift(s, from);
  }
  {
    humanoid::scene s(f);
    s.data->qpos[3] = std::cos(0.25);  // leaning 0.5 rad about x
    s.data->qpos[4] = std::sin(0.25);
    s.data->qpos[2] += 0.02;
    mj_forward(s.model.get(), s.data.get());
    r.fall_rise = s.largest_rise(4, &fall_trace);
  }
  {
    humanoid::scene s(f);
    s.run(3);
    const int torso = s.body("torso"), pelvis = s.body("pelvis");
    const double yaw0 = s.yaw(pelvis);
    s.applied(torso)[5] = 30;
    for (int i = 0; i < 750; ++i) {
      s.step();
      if (i == 375) r.pivot_torque = sole_torque(s);
      if (i % 10 == 0) pivot_trace.push_back(s.yaw(pelvis) - yaw0);
    }
    s.applied(torso)[5] = 0;
    s.run(1);
    r.pivot_turn = s.yaw(pelvis) - yaw0;
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) try {
  const std::string out = argc > 1 ? argv[1] : ".";
  std::vector<row> rows;
  std::vector<std::vector<double>> falls(4), pivots(4);
  for (std::size_t m = 0; m < 4; ++m) {
    rows.push_back(measure(*models[m], falls[m], pivots[m]));
    std::fprintf(stderr, "mujoco_humanoid: %s done\n", models[m]->name);
  }
  std::printf(
      "| humanoid, μ = %g | standing drift, last 10 s [m] | push: slide [m] | push: energy "
      "rise after [J] | fall: energy rise [J] | pivot: turn [rad] | pivot: sole torque "
      "[N m] | step [µs] |\n",
      humanoid::friction);
  std::printf("| --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (std::size_t m = 0; m < 4; ++m) {
    const row& r = rows[m];
    std::printf("| %s | %.2g | %.3g | %.2g | %.2g | %.3f | %.2f | %.1f (%.2f×) |\n",
                models[m]->name, r.stand_drift, r.push_slide, r.push_rise, r.fall_rise,
                r.pivot_turn, r.pivot_torque, r.step_us, r.step_us / rows[2].step_us);
  }
  if (FILE* csv =
          spinslide_examples::open_output(out + "/mujoco_humanoid.csv", "mujoco_humanoid")) {
    std::fprintf(csv, "t");
    for (const auto* m : models)
      std::fprintf(csv, ",fall energy (%s),pivot turn (%s)", m->name, m->name);
    std::fprintf(csv, "\n");
    const std::size_t n = std::max(falls[0].size(), pivots[0].size());
    for (std::size_t i = 0; i < n; ++i) {
      std::fprintf(csv, "%g", 10 * humanoid::time_step * static_cast<double>(i));
      for (std::size_t m = 0; m < 4; ++m)
        std::fprintf(csv, ",%s,%s", i < falls[m].size() ? std::to_string(falls[m][i]).c_str() : "",
                     i < pivots[m].size() ? std::to_string(pivots[m][i]).c_str() : "");
      std::fprintf(csv, "\n");
    }
    std::fclose(csv);
  }
  const std::string script =
      "set terminal pngcairo size 1100,420\nset output 'mujoco_humanoid.png'\n"
      "set datafile separator ','\nset multiplot layout 1,2\nset key top right\n"
      "set title 'fall: energy [J]'\nset xlabel 't [s]'\n"
      "plot for [m=0:3] 'mujoco_humanoid.csv' using 1:(column(2+2*m)) with lines "
      "title columnhead(2+2*m)\n"
      "set title 'pivot: 30 N m about the vertical, the turn [rad]'\nset xrange [0:1.5]\n"
      "plot for [m=0:3] 'mujoco_humanoid.csv' using 1:(column(3+2*m)) with lines "
      "title columnhead(3+2*m)\nunset multiplot\n";
  const bool figure = spinslide_examples::plot(out, "mujoco_humanoid.gp", script);
  std::printf("\nwrote %s/mujoco_humanoid.csv%s\n", out.c_str(),
              figure ? " and mujoco_humanoid.png" : " (no gnuplot: no figure)");
  // MuJoCo's energy leaves out what its soft contacts and limits store, so
  // it rises by joules after an impact with any friction: the coupled
  // humanoid's rises are held to MuJoCo's own (1.5 times the largest, plus
  // 0.1 J).
  const row& c = rows[0];
  double push = 0, fall = 0;
  for (std::size_t m = 1; m < 4; ++m) {
    push = std::max(push, rows[m].push_rise);
    fall = std::max(fall, rows[m].fall_rise);
  }
  const bool ok =
      c.stand_drift < 1e-9 && c.push_rise <= 1.5 * push + 0.1 && c.fall_rise <= 1.5 * fall + 0.1;
  if (!ok) std::fprintf(stderr, "mujoco_humanoid: the coupled humanoid drifted or gained energy\n");
  return ok ? 0 : 1;
} catch (const std::exception& e) {
  std::fprintf(stderr, "mujoco_humanoid: %s\n", e.what());
  return 1;
}
