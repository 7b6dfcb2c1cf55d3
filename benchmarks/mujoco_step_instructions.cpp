//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// MuJoCo's step of bench_mujoco's disk (engines/mujoco/examples/mujoco_disk/
// scene.hpp) counted in instructions, which do not move with the machine's
// load (docs/performance.md, "Inside engines"): the scene settled (at rest)
// or thrown (sliding and spinning), then 200 steps between callgrind's
// client requests, with MuJoCo's own friction (condim 4, elliptic) or with
// spinslide's coupled pair (condim 1).  Built for the generic x86-64
// (valgrind runs no AVX-512):
//   cd build/release/benchmarks
//   valgrind --tool=callgrind ./mujoco_step_instructions native|ours [moving]
//   callgrind_annotate --inclusive=yes callgrind.out.<pid>.1
// (the dump ".1" holds the 200 steps only: its PROGRAM TOTALS over 200).
#include <spinslide/engines/mujoco.hpp>
#include <spinslide/spinslide.hpp>

#include <valgrind/callgrind.h>

#include "../engines/mujoco/examples/mujoco_disk/scene.hpp"

#include <cstdio>
#include <cstring>
#include <memory>

int main(int argc, char** argv) {
  if (argc < 2 || (std::strcmp(argv[1], "ours") != 0 && std::strcmp(argv[1], "native") != 0)) {
    std::fprintf(stderr, "usage: %s native|ours [moving]\n", argv[0]);
    return 2;
  }
  const bool ours = std::strcmp(argv[1], "ours") == 0, moving = argc > 2;
  const mujoco_scene::friction_model fm{"", ours ? 1 : 4, "elliptic"};
  const auto model = mujoco_scene::load(mujoco_scene::disk_xml(fm));
  const mujoco_scene::data_ptr data(mj_makeData(model.get()));
  mjModel* m = model.get();
  mjData* d = data.get();
  std::unique_ptr<spinslide::mujoco::coupled_friction> coupled;
  if (ours) {
    coupled = std::make_unique<spinslide::mujoco::coupled_friction>(m);
    coupled->couple(
        spinslide::mujoco::geom_name{"disk"}, spinslide::mujoco::geom_name{"floor"},
        spinslide::pair_friction(spinslide::uniform_disk<>(), spinslide::patch_radius<double>{0.06},
                                 spinslide::friction_coefficient<double>{0.2}));
  }
  auto step = [&] {
    if (coupled)
      coupled->step(d);
    else
      mj_step(m, d);
  };
  mujoco_scene::settle_and_throw(m, d, moving ? 0.3 : 0.0, moving ? 5.0 : 0.0, step);
  constexpr int steps = 200;
  CALLGRIND_ZERO_STATS;
  for (int i = 0; i < steps; ++i) step();
  CALLGRIND_DUMP_STATS_AT("steps");
  std::printf("%d steps, %d contacts at the end\n", steps, d->ncon);
  return 0;
}
