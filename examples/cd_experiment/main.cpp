//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// cd_experiment: the command line of the paper's experiment (cd_experiment.hpp
// and docs/experiment.md say what it does and the data format).
//
//   cd_experiment [--throws N] [--seed S] [--out DIR]      simulate, film, analyse
//   cd_experiment --analyse FILE [--out DIR]               analyse tracked frames
#include "cd_experiment.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>

using namespace cd_experiment;

int main(int argc, char** argv) {
  try {
    int throws = 60;
    unsigned seed = 2003;
    std::string dir = ".", input;
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::runtime_error("missing value after " + a);
        return argv[++i];
      };
      if (a == "--throws") {
        throws = std::stoi(value());
        if (throws < 3 || throws > 100000)
          throw std::runtime_error("--throws must be in [3, 100000]");
      } else if (a == "--seed") {
        seed = static_cast<unsigned>(std::stoul(value()));
      } else if (a == "--out") {
        dir = value();
      } else if (a == "--analyse" || a == "--analyze") {
        input = value();
      } else {
        throw std::runtime_error("unknown argument " + a +
                                 " (usage: cd_experiment [--throws N] [--seed S] [--out DIR] | "
                                 "--analyse FILE [--out DIR])");
      }
    }
    if (!input.empty()) {
      std::printf("analysing tracked frames from %s\n", input.c_str());
      return analyse(read_frames(input), dir, false);
    }
    std::printf(
        "simulating %d throws of a CD (R = %g m, hole b = %g, gamma = %g), mu = %g + %g n\n",
        throws, R, hole, gamma_cd, true_a, true_b);
    const throws_t frames = simulate(throws, seed);
    const std::string path = dir + "/cd_frames.csv";
    write_frames(path, frames);
    std::printf("filmed at %g frames/s with %g mm and %g rad of tracking noise: %s\n", fps,
                tracking_noise.position * 1e3, tracking_noise.angle, path.c_str());
    return analyse(read_frames(path), dir, true);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cd_experiment: %s\n", e.what());
    return 2;
  }
}
