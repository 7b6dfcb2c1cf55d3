// Consumer smoke test shared by the find_package, add_subdirectory and
// FetchContent packaging tests. It only checks exact limits that are part of
// the specification plus physical bounds, never tabulated interior values.
#include <spinslide/spinslide.hpp>
// Where the consumer found an engine, its adapter's target must exist and
// compile (the consumers' CMakeLists define these).
#ifdef SPINSLIDE_CONSUME_MUJOCO
#include <spinslide/engines/mujoco.hpp>
#endif
#ifdef SPINSLIDE_CONSUME_BULLET
#include <spinslide/engines/bullet.hpp>
#endif
#ifdef SPINSLIDE_CONSUME_BOX2D
#include <spinslide/engines/box2d.hpp>
#endif

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace {

int failures = 0;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "spinslide consumer check FAILED: %s\n", what);
    ++failures;
  }
}

}  // namespace

// The adapters that were linked: each refuses a null argument.
void check_engines() {
#ifdef SPINSLIDE_CONSUME_MUJOCO
  bool refused = false;
  try {
    spinslide::mujoco::coupled_friction f(nullptr);
  } catch (const std::invalid_argument&) {
    refused = true;
  }
  check(refused, "spinslide::mujoco::coupled_friction refuses a null model");
#endif
#ifdef SPINSLIDE_CONSUME_BULLET
  spinslide::bullet::coupled_friction_solver solver;
  check(!solver.coupled(nullptr, nullptr), "spinslide::bullet: nothing coupled");
#endif
#ifdef SPINSLIDE_CONSUME_BOX2D
  bool refused_gravity = false;
  try {
    spinslide::box2d::table_friction table(spinslide::gravity{-1.0});
  } catch (const std::domain_error&) {
    refused_gravity = true;
  }
  check(refused_gravity, "spinslide::box2d::table_friction refuses g < 0");
#endif
}

int main() {
  check_engines();
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
