//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The cost of spinslide's friction inside MuJoCo (docs/engines.md,
// docs/performance.md): one time step of the paper's disk on a floor
// (engines/mujoco/examples/mujoco_disk/scene.hpp; 3 contacts on the rim), sliding and
// spinning (re-thrown at 0.3 m/s and 5 rad/s every 1000 steps, 0.1 s, before
// it stops) or at rest:
//   mujoco_native: MuJoCo's own friction, condim 4 (torsional), elliptic cone
//     (the baseline);
//   mujoco_frictionless: condim 1 and no friction at all, for the engine's
//     cost without friction;
//   spinslide_in_mujoco: condim 1 and spinslide::mujoco::coupled_friction.
// The friction's own cost per step is each one's time less the frictionless
// step's; the ratio lines at the end compare them.
//   ./build/release/benchmarks/bench_mujoco
#include <benchmark/benchmark.h>
#include <spinslide/engines/mujoco.hpp>
#include <spinslide/spinslide.hpp>

#include "../engines/mujoco/examples/mujoco_humanoid/humanoid.hpp"
#include "mujoco_disk_bench.hpp"
#include "ratio_reporter.hpp"

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

namespace {

using mujoco_disk_bench::friction;

void step_the_disk(benchmark::State& state, friction kind, bool moving) {
  mujoco_disk_bench::scene scene(kind, moving ? 0.3 : 0.0, moving ? 5.0 : 0.0);
  mjModel* m = scene.model();
  mjData* d = scene.data();
  const std::vector<mjtNum> qpos(d->qpos, d->qpos + m->nq), qvel(d->qvel, d->qvel + m->nv);
  int since_throw = 0;
  for (auto _ : state) {
    scene.step();
    if (++since_throw == 1000) {
      std::copy(qpos.begin(), qpos.end(), d->qpos);
      std::copy(qvel.begin(), qvel.end(), d->qvel);
      since_throw = 0;
    }
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["contacts"] = d->ncon;
}

void mujoco_native(benchmark::State& s) { step_the_disk(s, friction::native, true); }
void mujoco_frictionless(benchmark::State& s) { step_the_disk(s, friction::none, true); }
void spinslide_in_mujoco(benchmark::State& s) { step_the_disk(s, friction::spinslide, true); }
void mujoco_native_at_rest(benchmark::State& s) { step_the_disk(s, friction::native, false); }
void mujoco_frictionless_at_rest(benchmark::State& s) { step_the_disk(s, friction::none, false); }
void spinslide_in_mujoco_at_rest(benchmark::State& s) {
  step_the_disk(s, friction::spinslide, false);
}

// The humanoid (engines/mujoco/examples/mujoco_humanoid) standing after 3 s, and walking
// through the first second of a fall (reset every 500 steps): every
// body/floor pair coupled, against MuJoCo's own friction with condim 3 and 4.
void step_the_humanoid(benchmark::State& state, const humanoid::friction_model& f, bool falling) {
  humanoid::scene s(f);
  if (falling) {
    s.data->qpos[3] = std::cos(0.25);
    s.data->qpos[4] = std::sin(0.25);
    mj_forward(s.model.get(), s.data.get());
  } else {
    for (int i = 0; i < 1500; ++i) s.step();
  }
  const std::vector<mjtNum> qpos(s.data->qpos, s.data->qpos + s.model->nq),
      qvel(s.data->qvel, s.data->qvel + s.model->nv);
  int steps = 0;
  for (auto _ : state) {
    s.step();
    if (++steps == 500) {
      std::copy(qpos.begin(), qpos.end(), s.data->qpos);
      std::copy(qvel.begin(), qvel.end(), s.data->qvel);
      steps = 0;
    }
  }
  state.SetItemsProcessed(state.iterations());
}
void humanoid_native_condim3(benchmark::State& s) {
  step_the_humanoid(s, humanoid::sliding_only, false);
}
void humanoid_native_condim4(benchmark::State& s) {
  step_the_humanoid(s, humanoid::torsional, false);
}
void humanoid_spinslide(benchmark::State& s) { step_the_humanoid(s, humanoid::coupled, false); }
void humanoid_native_condim3_falling(benchmark::State& s) {
  step_the_humanoid(s, humanoid::sliding_only, true);
}
void humanoid_native_condim4_falling(benchmark::State& s) {
  step_the_humanoid(s, humanoid::torsional, true);
}
void humanoid_spinslide_falling(benchmark::State& s) {
  step_the_humanoid(s, humanoid::coupled, true);
}

BENCHMARK(mujoco_native)->Unit(benchmark::kMicrosecond);
BENCHMARK(mujoco_frictionless)->Unit(benchmark::kMicrosecond);
BENCHMARK(spinslide_in_mujoco)->Unit(benchmark::kMicrosecond);
BENCHMARK(mujoco_native_at_rest)->Unit(benchmark::kMicrosecond);
BENCHMARK(mujoco_frictionless_at_rest)->Unit(benchmark::kMicrosecond);
BENCHMARK(spinslide_in_mujoco_at_rest)->Unit(benchmark::kMicrosecond);
BENCHMARK(humanoid_native_condim3)->Unit(benchmark::kMicrosecond);
BENCHMARK(humanoid_native_condim4)->Unit(benchmark::kMicrosecond);
BENCHMARK(humanoid_spinslide)->Unit(benchmark::kMicrosecond);
BENCHMARK(humanoid_native_condim3_falling)->Unit(benchmark::kMicrosecond);
BENCHMARK(humanoid_native_condim4_falling)->Unit(benchmark::kMicrosecond);
BENCHMARK(humanoid_spinslide_falling)->Unit(benchmark::kMicrosecond);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  spinslide_bench::ratio_reporter reporter(
      "mujoco_native", {{"spinslide_in_mujoco", "mujoco_native"},
                        {"spinslide_in_mujoco_at_rest", "mujoco_native_at_rest"},
                        {"humanoid_spinslide", "humanoid_native_condim4"},
                        {"humanoid_spinslide_falling", "humanoid_native_condim4_falling"}});
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
