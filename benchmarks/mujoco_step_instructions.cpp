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
#include <valgrind/callgrind.h>

#include "mujoco_disk_bench.hpp"

#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
  if (argc < 2 || (std::strcmp(argv[1], "ours") != 0 && std::strcmp(argv[1], "native") != 0)) {
    std::fprintf(stderr, "usage: %s native|ours [moving]\n", argv[0]);
    return 2;
  }
  const bool ours = std::strcmp(argv[1], "ours") == 0, moving = argc > 2;
  using mujoco_disk_bench::friction;
  mujoco_disk_bench::scene scene(ours ? friction::spinslide : friction::native, moving ? 0.3 : 0.0,
                                 moving ? 5.0 : 0.0);
  constexpr int steps = 200;
  CALLGRIND_ZERO_STATS;
  for (int i = 0; i < steps; ++i) scene.step();
  CALLGRIND_DUMP_STATS_AT("steps");
  std::printf("%d steps, %d contacts at the end\n", steps, scene.data()->ncon);
  return 0;
}
