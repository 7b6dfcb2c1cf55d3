//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// MuJoCo's steps of bench_mujoco's scenes counted in instructions, which do
// not move with the machine's load (issue 41; docs/performance.md, "Inside
// engines"), for tools/path_instructions.py: each case's steps between
// callgrind's client requests (the count zeroed before, dumped after under
// the case's name), so that one run under `valgrind --tool=callgrind`
// counts them all, with MuJoCo's own friction ("native": condim 4,
// elliptic) and with spinslide's coupled pairs ("ours": condim 1 and
// spinslide::mujoco::coupled_friction).  The cases, as bench_mujoco's:
//   disk_at_rest      the disk of mujoco_disk_bench.hpp settled, 200 steps;
//   disk_sliding      the same thrown at 0.3 m/s and 5 rad/s, 200 steps;
//   humanoid_standing the humanoid (engines/mujoco/examples/mujoco_humanoid)
//                     after 3 s standing, 500 steps;
//   humanoid_falling  the first 500 steps of its fall from a 0.5 rad tilt.
// Each ours is held to issue 41's goal as a multiple of the same scene's
// native step (step_instruction_budgets.txt; the CTest test
// mujoco.step_instructions).  Alone it runs the same steps and prints the
// cases.  By hand:
//   python3 tools/path_instructions.py build/release/engines/mujoco/tests/mujoco_step_instructions
#include <valgrind/callgrind.h>

#include "../../../benchmarks/mujoco_disk_bench.hpp"
#include "../examples/mujoco_humanoid/humanoid.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

namespace {

// `steps` calls of step() counted under `name`, printed as
// tools/path_instructions.py reads them ("case NAME CALLS CHECKSUM"; a
// step's effect is MuJoCo's data, so the checksum is 0).
template <class Step>
void count(const std::string& name, int steps, Step&& step) {
  CALLGRIND_ZERO_STATS;
  for (int i = 0; i < steps; ++i) step();
  CALLGRIND_DUMP_STATS_AT(name.c_str());
  std::printf("case %s %d 0\n", name.c_str(), steps);
}

void disk(bool ours, bool sliding) {
  using mujoco_disk_bench::friction;
  mujoco_disk_bench::scene s(ours ? friction::spinslide : friction::native, sliding ? 0.3 : 0.0,
                             sliding ? 5.0 : 0.0);
  count(std::string("mujoco_step.") + (sliding ? "disk_sliding" : "disk_at_rest") + ".double." +
            (ours ? "ours" : "native"),
        200, [&] { s.step(); });
}

void humanoid_case(bool ours, bool falling) {
  humanoid::scene s(ours ? humanoid::coupled : humanoid::torsional);
  if (falling) {  // bench_mujoco's fall: the pelvis turned 0.5 rad about x
    s.data->qpos[3] = std::cos(0.25);
    s.data->qpos[4] = std::sin(0.25);
    mj_forward(s.model.get(), s.data.get());
  } else {
    s.run(3.0);
  }
  count(std::string("mujoco_step.") + (falling ? "humanoid_falling" : "humanoid_standing") +
            ".double." + (ours ? "ours" : "native"),
        500, [&] { s.step(); });
}

}  // namespace

int main() try {
  // The bare loop, which path_instructions.py subtracts from every count.
  count("loop.double", 500, [] {});
  for (const bool ours : {false, true}) {
    disk(ours, false);
    disk(ours, true);
    humanoid_case(ours, false);
    humanoid_case(ours, true);
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "mujoco_step_instructions: %s\n", e.what());
  return 1;
}
