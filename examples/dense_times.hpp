//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Where the examples sample an exact throw for a figure (issue 31): densely
// enough that no corner shows at the figure's size, also where the motion
// stops, and v, ω and ε change fastest (ω ∝ √(t_stop − t) for a disk that
// ends spinning alone, ε runs to its terminal value).
#ifndef SPINSLIDE_EXAMPLES_DENSE_TIMES_HPP
#define SPINSLIDE_EXAMPLES_DENSE_TIMES_HPP

#include <algorithm>
#include <cmath>
#include <vector>

namespace spinslide_examples {

// `even` times evenly spaced over [0, end), `near` times spaced
// geometrically in stop − t from stop/2 down to 1e-9 stop, and stop itself
// (if stop <= end): sorted, without repeats.
inline std::vector<double> times_towards_stop(double stop, double end, int even, int near) {
  std::vector<double> t;
  for (int k = 0; k < even; ++k) t.push_back(end * k / even);
  if (stop <= end) {
    for (int k = 0; k < near; ++k)
      t.push_back(stop - 0.5 * stop * std::pow(2e-9, double(k) / (near - 1)));
    t.push_back(stop);
  }
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

}  // namespace spinslide_examples

#endif  // SPINSLIDE_EXAMPLES_DENSE_TIMES_HPP
