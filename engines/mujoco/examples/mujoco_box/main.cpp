//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// A 0.22 × 0.10 m box (a sole) thrown flat in MuJoCo at 0.3 m/s along its
// length, spinning at 5 rad/s (engines/testing/box_scenes.hpp): its speed
// and spin against time with MuJoCo's own friction (condim 3 pyramidal,
// condim 4) and with spinslide's, the contact's own patch, beside the exact
// rigid face's (throw_plate; docs/engines.md, "A box: the contact's own
// patch").  Writes mujoco_box.csv, mujoco_box_exact.csv and, with gnuplot,
// mujoco_box.png into the directory given (default: the current one).
// Exit status 1 if the own patch's stop is more than two steps from the
// exact stop.
//
//   ./build/release/engines/mujoco/examples/mujoco_box/mujoco_box [output_dir]

#include <spinslide/engines/mujoco.hpp>

#include "box_runs.hpp"
#include "box_scenes.hpp"
#include "gnuplot.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <string>
#include <vector>

namespace {

struct sample {
  double t, speed, spin;
};

// The throw of the scene `s`, by the adapter with the own patch if
// `coupled` (else by mj_step), every 10th step's speed and spin from the
// throw on; the outcome.
box_scenes::throw_outcome record(const box_runs::scene& s, bool coupled,
                                 std::vector<sample>& samples) {
  const auto model = mujoco_scene::load(box_runs::box_xml(s));
  const mujoco_scene::data_ptr data(mj_makeData(model.get()));
  spinslide::mujoco::coupled_friction friction(model.get());
  if (coupled)
    friction.couple(
        spinslide::mujoco::geom_name{"box"}, spinslide::mujoco::geom_name{"floor"},
        spinslide::pair_friction<double>(
            spinslide::own_patch{}, spinslide::friction_coefficient<double>{box_scenes::friction}));
  const mjModel* m = model.get();
  long steps = 0;
  const box_runs::stepper step = [&](mjData* d) {
    const double before = d->time;
    if (coupled) {
      friction.step(d);
    } else {
      mj_step(m, d);
    }
    if (before == 0) samples.clear();  // the throw starts at t = 0
    if (++steps % 10 == 0)
      samples.push_back({d->time, std::hypot(d->qvel[0], d->qvel[1]), d->qvel[5]});
  };
  const std::function<bool()> stopped = [&] { return friction.report(0).sticking; };
  return box_runs::run_throw(m, data.get(), step, coupled ? stopped : nullptr);
}

int run(const std::string& out) {
  struct model {
    const char* name;
    int condim;
    const char* cone;
  };
  const model models[] = {{"MuJoCo condim 3 pyramidal", 3, "pyramidal"},
                          {"MuJoCo condim 4", 4, "elliptic"},
                          {"spinslide (own patch)", 1, "elliptic"}};
  std::vector<std::vector<sample>> series;
  const auto exact = box_scenes::exact_throw();
  std::printf("exact: both motions stop at %.5f s, turned %.4f rad\n", exact.time, exact.rotation);
  bool ok = true;
  for (const model& m : models) {
    box_runs::scene s;
    s.condim = m.condim;
    s.cone = m.cone;
    series.emplace_back();
    const auto o = record(s, m.condim == 1, series.back());
    std::printf("%-26s slide stops %.5f s, spin %.5f s, turned %.4f rad\n", m.name, o.slide_stop,
                o.spin_stop, o.turn);
    if (m.condim == 1)
      ok = std::fabs(o.slide_stop - exact.time) <= 2 * s.step &&
           std::fabs(o.spin_stop - exact.time) <= 2 * s.step;
  }
  if (FILE* csv = spinslide_examples::open_output(out + "/mujoco_box.csv", "mujoco_box")) {
    std::fprintf(csv, "t");
    for (const model& m : models) std::fprintf(csv, ",speed (%s),spin (%s)", m.name, m.name);
    std::fprintf(csv, "\n");
    for (std::size_t i = 0; i < series[0].size(); ++i) {
      std::fprintf(csv, "%g", series[0][i].t);
      for (const auto& s : series)
        if (i < s.size()) std::fprintf(csv, ",%.6g,%.6g", s[i].speed, s[i].spin);
      std::fprintf(csv, "\n");
    }
    std::fclose(csv);
  }
  if (FILE* csv = spinslide_examples::open_output(out + "/mujoco_box_exact.csv", "mujoco_box")) {
    std::fprintf(csv, "t,speed (exact),spin (exact)\n");
    for (const auto& p : exact.path)
      std::fprintf(csv, "%.9g,%.9g,%.9g\n", p.time, std::hypot(p.velocity[0], p.velocity[1]),
                   p.omega);
    std::fclose(csv);
  }
  const std::string script =
      "set terminal pngcairo size 1100,420\nset output 'mujoco_box.png'\n"
      "set datafile separator ','\nset multiplot layout 1,2\nset key top right\n"
      "set xlabel 't [s]'\nset xrange [0:0.2]\n"
      "set title 'thrown box: speed of its centre [m/s]'\n"
      "plot 'mujoco_box_exact.csv' using 1:2 with lines lw 3 lc 'grey' title 'exact', "
      "for [m=0:2] 'mujoco_box.csv' using 1:(column(2+2*m)) with lines title columnhead(2+2*m)\n"
      "set title 'spin [rad/s]'\n"
      "plot 'mujoco_box_exact.csv' using 1:3 with lines lw 3 lc 'grey' title 'exact', "
      "for [m=0:2] 'mujoco_box.csv' using 1:(column(3+2*m)) with lines title columnhead(3+2*m)\n"
      "unset multiplot\n";
  const bool figure = spinslide_examples::plot(out, "mujoco_box.gp", script);
  std::printf("wrote %s/mujoco_box.csv, mujoco_box_exact.csv%s\n", out.c_str(),
              figure ? " and mujoco_box.png" : " (no gnuplot: no figure)");
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc > 1 ? argv[1] : ".");
  } catch (const std::exception& e) {  // a model MuJoCo refuses
    std::fprintf(stderr, "mujoco_box: %s\n", e.what());
    return 1;
  }
}
