//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The cost of spinslide's friction inside MuJoCo (docs/engines.md,
// docs/performance.md): one time step of the paper's disk on a floor
// (examples/mujoco_disk/scene.hpp; 3 contacts on the rim), sliding and
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

#include "../examples/mujoco_disk/scene.hpp"
#include "ratio_reporter.hpp"

#include <cstdio>
#include <memory>
#include <vector>

namespace {

enum class friction { native, none, spinslide };

void step_the_disk(benchmark::State& state, friction kind, bool moving) {
  const mujoco_scene::friction_model fm{"", kind == friction::native ? 4 : 1, "elliptic"};
  const auto model = mujoco_scene::load(mujoco_scene::disk_xml(fm));
  const mujoco_scene::data_ptr data(mj_makeData(model.get()));
  mjModel* m = model.get();
  mjData* d = data.get();
  std::unique_ptr<spinslide::mujoco::coupled_friction> coupled;
  if (kind == friction::spinslide) {
    coupled = std::make_unique<spinslide::mujoco::coupled_friction>(m);
    coupled->couple(spinslide::mujoco::geom_name{"disk"}, spinslide::mujoco::geom_name{"floor"},
                    spinslide::engines::pair_friction(
                        spinslide::uniform_disk<>(), spinslide::patch_radius<double>{0.06},
                        spinslide::friction_coefficient<double>{0.2}));
  }
  auto step = [&] {
    if (coupled)
      coupled->step(d);
    else
      mj_step(m, d);
  };
  const double v0 = moving ? 0.3 : 0.0, omega0 = moving ? 5.0 : 0.0;
  mujoco_scene::settle_and_throw(m, d, v0, omega0, step);
  const std::vector<mjtNum> qpos(d->qpos, d->qpos + m->nq), qvel(d->qvel, d->qvel + m->nv);
  int since_throw = 0;
  for (auto _ : state) {
    step();
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

BENCHMARK(mujoco_native)->Unit(benchmark::kMicrosecond);
BENCHMARK(mujoco_frictionless)->Unit(benchmark::kMicrosecond);
BENCHMARK(spinslide_in_mujoco)->Unit(benchmark::kMicrosecond);
BENCHMARK(mujoco_native_at_rest)->Unit(benchmark::kMicrosecond);
BENCHMARK(mujoco_frictionless_at_rest)->Unit(benchmark::kMicrosecond);
BENCHMARK(spinslide_in_mujoco_at_rest)->Unit(benchmark::kMicrosecond);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  spinslide_bench::ratio_reporter reporter(
      "mujoco_native", {{"spinslide_in_mujoco", "mujoco_native"},
                        {"spinslide_in_mujoco_at_rest", "mujoco_native_at_rest"}});
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
