//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Quick start: the friction force 𝓕(ε) and torque 𝓣(ε) of a uniformly
// pressed disk that slides with speed v and spins with angular speed ω,
// ε = v/(Rω), and the limits stated by Farkas, Bartels, Unger & Wolf (2003).
#include <spinslide/spinslide.hpp>

#include <boost/math/constants/constants.hpp>

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

  const double pi = boost::math::constants::pi<double>();
  std::printf("\nThe paper's limits, computed / exact:\n");
  std::printf("  F(0)   = %.17g   (0)\n", spinslide::force(0.0));
  std::printf("  T(0)   = %.17g   (2/3     = %.17g)\n", spinslide::torque(0.0), 2.0 / 3.0);
  std::printf("  F(1)   = %.17g   (8/(3pi) = %.17g)\n", spinslide::force(1.0), 8 / (3 * pi));
  std::printf("  T(1)   = %.17g   (8/(9pi) = %.17g)\n", spinslide::torque(1.0), 8 / (9 * pi));
  std::printf("  F'(1)  = %.17g   (4/(3pi) = %.17g)\n", spinslide::force_derivative(1.0),
              4 / (3 * pi));
  std::printf("  T'(1)  = %.17g   (-4/(3pi) = %.17g)\n", spinslide::torque_derivative(1.0),
              -4 / (3 * pi));
  std::printf("  F(inf) = %.17g   (1)\n",
              spinslide::force(std::numeric_limits<double>::infinity()));
  std::printf("  T(inf) = %.17g   (0)\n",
              spinslide::torque(std::numeric_limits<double>::infinity()));
  std::printf(
      "  T(1e6) = %.17g   (~ 1/(4 eps) = %.17g; the printed closed form cancels to 0 here)\n",
      spinslide::torque(1e6), 0.25e-6);

  std::printf("\nBad input is a domain error: ");
  try {
    spinslide::force(-1.0);
  } catch (const std::domain_error& e) {
    std::printf("%s\n", e.what());
  }
  return 0;
}
