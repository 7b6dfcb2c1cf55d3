// Consumer smoke test shared by the find_package, add_subdirectory and
// FetchContent packaging tests. It only checks exact limits that are part of
// the specification plus physical bounds, never tabulated interior values.
#include <spinslide/spinslide.hpp>

#include <cmath>
#include <cstdio>
#include <limits>

namespace {

int failures = 0;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "spinslide consumer check FAILED: %s\n", what);
    ++failures;
  }
}

}  // namespace

int main() {
  const double pi = 3.141592653589793238462643383279502884;
  const double inf = std::numeric_limits<double>::infinity();

  const double f_half = spinslide::force(0.5);
  const double t_half = spinslide::torque(0.5);
  std::printf("force(0.5) = %.17g, torque(0.5) = %.17g\n", f_half, t_half);

  // Exact limits (pure sliding, pure spinning, rolling edge case).
  check(spinslide::force(0.0) == 0.0, "force(0) == 0");
  check(std::abs(spinslide::torque(0.0) - 2.0 / 3.0) < 1e-15, "|torque(0) - 2/3| < 1e-15");
  check(std::abs(spinslide::force(1.0) - 8.0 / (3.0 * pi)) < 1e-15,
        "|force(1) - 8/(3 pi)| < 1e-15");
  check(spinslide::force(inf) == 1.0, "force(inf) == 1");

  // Physical bounds at an interior point: 0 < F < 1 and 0 < T < 2/3.
  check(std::isfinite(f_half) && f_half > 0.0 && f_half < 1.0, "0 < force(0.5) < 1");
  check(std::isfinite(t_half) && t_half > 0.0 && t_half < 2.0 / 3.0, "0 < torque(0.5) < 2/3");

  if (failures != 0) {
    std::fprintf(stderr, "%d check(s) failed\n", failures);
    return 1;
  }
  std::printf("spinslide consumer: all checks passed\n");
  return 0;
}
