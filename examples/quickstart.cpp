//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Quick start: the friction force 𝓕(ε) and torque 𝓣(ε) of a uniformly
// pressed disk that slides with speed v and spins with angular speed ω,
// ε = v/(Rω), and the limits stated by Farkas, Bartels, Unger & Wolf (2003).
#include <spinslide/spinslide.hpp>

#include <cstdio>
#include <limits>

int main() {
  std::printf("spinslide quick start: a uniformly pressed disk, sliding and spinning\n");
  std::printf("force  F(eps) in units of mu*N      (opposes the sliding velocity)\n");
  std::printf("torque T(eps) in units of mu*N*R    (opposes the spin)\n\n");
  std::printf("%12s %20s %20s %14s %14s\n", "eps", "F(eps)", "T(eps)", "dF/deps", "dT/deps");
  const double table[] = {0.0, 1e-3, 0.1, 0.2,  0.5, 0.653,
                          1.0, 2.0,  5.0, 10.0, 1e3, std::numeric_limits<double>::infinity()};
  for (double eps : table) {
    const auto ft = spinslide::force_torque(eps);  // one elliptic evaluation for both
    std::printf("%12g %20.17f %20.17f %14.6e %14.6e\n", eps, ft.force, ft.torque,
                spinslide::force_derivative(eps), spinslide::torque_derivative(eps));
  }

  // The exact values, to 20 digits, for comparison.
  std::printf("\nThe paper's limits, computed | exact:\n");
  std::printf("  F(0)   = %.17g | 0\n", spinslide::force(0.0));
  std::printf("  T(0)   = %.17g | 2/3      = 0.66666666666666666667\n", spinslide::torque(0.0));
  std::printf("  F(1)   = %.17g | 8/(3pi)  = 0.84882636315677512410\n", spinslide::force(1.0));
  std::printf("  T(1)   = %.17g | 8/(9pi)  = 0.28294212105225837470\n", spinslide::torque(1.0));
  std::printf("  F'(1)  = %.17g | 4/(3pi)  = 0.42441318157838756205\n",
              spinslide::force_derivative(1.0));
  std::printf("  T'(1)  = %.17g | -4/(3pi) = -0.42441318157838756205\n",
              spinslide::torque_derivative(1.0));
  const double inf = std::numeric_limits<double>::infinity();
  std::printf("  F(inf) = %.17g | 1\n", spinslide::force(inf));
  std::printf("  T(inf) = %.17g | 0\n", spinslide::torque(inf));
  std::printf("  T(1e6) = %.17g | 1/(4eps) + 1/(48eps^3) = 2.5000000000002083e-07\n",
              spinslide::torque(1e6));

  std::printf("\nBad input is a domain error: ");
  try {
    spinslide::force(-1.0);
  } catch (const std::domain_error& e) {
    std::printf("%s\n", e.what());
  }
  return 0;
}
