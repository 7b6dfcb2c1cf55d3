//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The driver of tools/impulse_instructions.sh: REPS × 64 impulse_friction
// calls of bench_disk's impulse cases (the slips (ε cos ε, ε sin ε, 1) for
// 64 ratios from 1e-3 to 1e3, its coupled inverse mass, a = μ = 1), for
// PROFILE 0 (uniform disk), 1 (Hertz) or 2 (a tabulated annulus 0.3) and
// MODE 0 (sliding, from the answer's ratio times 1 + 1e-3), 1 (sliding,
// cold) or 2 (sticking: a normal impulse of 1e3).  START is the warm
// start's type (curve_point<double>, or starting_ratio<double> for headers
// older than issue 26's second session).  HANDLE 1 makes the calls through
// the run-time handle contact_profile (issue 40), as pair_friction and the
// adapters do.  It includes the umbrella, the one header every commit has
// (the headers moved into folders in issue 40).

#include <spinslide/spinslide.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

int main() {
  using namespace spinslide;
#if PROFILE == 0
  const uniform_disk<> profile;
#elif PROFILE == 1
  const hertz<> profile;
#else
  const tabulated_profile<> profile(annulus<>(0.3));
#endif
  const planar_metric<double> w({{{2.0, 0.3, 0.2}, {0.3, 1.5, -0.1}, {0.2, -0.1, 3.0}}});
  const impulse_contact<double> load{patch_radius<double>{1.0},
                                     normal_impulse<double>{MODE == 2 ? 1e3 : 1e-3},
                                     friction_coefficient<double>{1.0}};
  std::vector<std::array<double, 2>> slips;
  std::vector<double> starts;
  for (int i = 0; i < 64; ++i) {
    const double e = std::pow(10.0, -3 + 6.0 * i / 63);
    const std::array<double, 2> v{e * std::cos(e), e * std::sin(e)};
    slips.push_back(v);
    const auto first = impulse_friction(profile, v, 1.0, w, load);
    starts.push_back(MODE == 0 && !first.sticking ? first.ratio * (1 + 1e-3) : 0.0);
  }
  double sum = 0;  // (of the ratios: a field of the results before and after issue 26)
#if HANDLE
  const contact_profile<double> handle(profile);
  for (int r = 0; r < REPS; ++r)
    for (std::size_t i = 0; i < slips.size(); ++i)
      sum += handle.visit([&](const auto& p) {
        return impulse_friction(p, slips[i], 1.0, w, load, START{starts[i]}).ratio;
      });
#else
  for (int r = 0; r < REPS; ++r)
    for (std::size_t i = 0; i < slips.size(); ++i)
      sum += impulse_friction(profile, slips[i], 1.0, w, load, START{starts[i]}).ratio;
#endif
  std::printf("%g\n", sum);
}
