//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Pressure profiles: their moments, 𝓕 and 𝓣 at a few ratios, the coupling
// curve, and the paper's claim that the CD's hole (an annulus with b = 0.125)
// hardly matters.  Its output is the tables of docs/profiles.md:
//   ./build/release/examples/profiles
#include <spinslide/spinslide.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>

namespace {

template <class P>
void row(const char* name, const P& p) {
  std::printf("| %-26s | %.6f | %.6f | %.6f |", name, p.mean_radius(), p.mean_inverse_radius(),
              p.mean_square_radius());
  for (double e : {0.1, 0.653, 1.0, 3.0}) {
    const auto ft = p.force_torque(e);
    std::printf(" %.6f / %.6f |", ft.force, ft.torque);
  }
  std::printf(" %.6f |\n", spinslide::torque_at_force(p, 0.5));
}

template <class P>
void tabulate(const char* name, const P& p) {
  const auto t0 = std::chrono::steady_clock::now();
  const spinslide::tabulated_profile<> tab(p);
  const auto t1 = std::chrono::steady_clock::now();
  double worst = 0;
  for (double e = 1e-8; e < 1e8; e *= 1.013) {
    const auto a = tab.force_torque(e), b = p.force_torque(e);
    worst = std::max({worst, std::fabs(a.force / b.force - 1), std::fabs(a.torque / b.torque - 1)});
  }
  std::printf("| %-26s | %4zu | %2d | %7.1f | %.1e |\n", name, tab.pieces(), tab.deepest_level(),
              std::chrono::duration<double, std::milli>(t1 - t0).count(), worst);
}

}  // namespace

int main() {
  using namespace spinslide;
  const auto two_tier =
      weighted_sum({0.6, 0.4}, scaled<uniform_disk<>>(uniform_disk<>(), 0.5), annulus<>(0.5));
  const auto parabolic = radial_profile([](double r) { return (1 - r) * (1 + r); });

  std::printf(
      "Profiles: moments, F / T at eps = 0.1, 0.653, 1, 3, and the limit curve T at F = 0.5\n\n");
  std::printf(
      "| profile | ⟨r⟩ | ⟨1/r⟩ | ⟨r²⟩ | eps = 0.1 | eps = 0.653 | eps = 1 | eps = 3 | T(F = 0.5) "
      "|\n");
  std::printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
  row("uniform_disk", uniform_disk<>());
  row("annulus(0.125) (the CD)", annulus<>(0.125));
  row("annulus(0.9)", annulus<>(0.9));
  row("hertz", hertz<>());
  row("boussinesq", boussinesq<>());
  row("ring", ring<>());
  row("two-tier 60% on r < 1/2", two_tier);
  row("radial_profile 1 - r^2", parabolic);

  // The paper: "deviation from the full disk case is not significant".
  const annulus<> cd(0.125);
  const uniform_disk<> disk;
  double dF = 0, eF = 0, dT = 0, eT = 0;
  for (double e = 1e-4; e < 1e4; e *= 1.001) {
    const double f = std::fabs(cd.force(e) - disk.force(e)),
                 t = std::fabs(cd.torque(e) - disk.torque(e));
    if (f > dF) dF = f, eF = e;
    if (t > dT) dT = t, eT = e;
  }
  std::printf("\nThe CD (annulus b = 0.125) against the full disk, over 1e-4 <= eps <= 1e4:\n\n");
  std::printf("| quantity | largest difference | at eps | relative to the disk's value there |\n");
  std::printf("| --- | ---: | ---: | ---: |\n");
  std::printf("| force F | %.5f | %.4g | %.2f%% |\n", dF, eF, 100 * dF / disk.force(eF));
  std::printf("| torque T | %.5f | %.4g | %.2f%% |\n", dT, eT, 100 * dT / disk.torque(eT));
  std::printf("| torque at eps = 0 | %.5f | 0 | %.2f%% |\n", cd.torque(0.0) - disk.torque(0.0),
              100 * (cd.torque(0.0) - disk.torque(0.0)) / disk.torque(0.0));

  std::printf(
      "\nTabulated profiles (degree-8 pieces in t = eps/(1+eps)), worst relative error over "
      "1e-8..1e8:\n\n");
  std::printf("| profile | pieces | deepest level | build ms | worst error |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: |\n");
  tabulate("uniform_disk", disk);
  tabulate("annulus(0.125)", cd);
  tabulate("hertz", hertz<>());
  tabulate("boussinesq", boussinesq<>());
  tabulate("ring", ring<>());
  tabulate("two-tier", two_tier);
  return 0;
}
