//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// throw: how a sliding, spinning flat body on a table stops, in SI units.
//
//   throw R MU V0 OMEGA0 [--gamma G] [--gravity G] [--profile NAME]
//
//   R        contact radius [m], > 0
//   MU       friction coefficient, > 0
//   V0       initial speed [m/s], >= 0
//   OMEGA0   initial spin [rad/s], >= 0
//   --gamma G     I/(m R²), > 0 (default 0.5, a uniform disk)
//   --gravity G   [m/s²], > 0 (default 9.81)
//   --profile P   pressure profile: disk (default), annulus:B (hole of radius
//                 B·R, 0 <= B < 1), hertz, boussinesq, ring
//
// Prints the stop time, the distance slid, the angle turned and the ratio
// ε = v/(Rω) at the stop (docs/theory.md §8–9).  Example, the paper's CD:
//   throw 0.06 0.2 0.8 20 --profile annulus:0.125 --gamma 0.5078125
#include <spinslide/spinslide.hpp>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace {

const char* usage =
    "usage: throw R MU V0 OMEGA0 [--gamma G] [--gravity G] [--profile NAME]\n"
    "  R       contact radius [m], > 0\n"
    "  MU      friction coefficient, > 0\n"
    "  V0      initial speed [m/s], >= 0\n"
    "  OMEGA0  initial spin [rad/s], >= 0\n"
    "  --gamma G    I/(m R^2), > 0 (default 0.5: a uniform disk)\n"
    "  --gravity G  [m/s^2], > 0 (default 9.81)\n"
    "  --profile P  disk (default), annulus:B (0 <= B < 1), hertz, boussinesq, ring\n";

struct bad_argument : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The whole of `text` as a finite number, with `positive` (> 0) or not (>= 0).
double number(const char* name, const std::string& text, bool positive) {
  errno = 0;
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  const bool parsed = !text.empty() && end == text.c_str() + text.size() && errno != ERANGE;
  if (!parsed || !std::isfinite(x) || (positive ? !(x > 0) : !(x >= 0)))
    throw bad_argument(std::string("bad ") + name + ": '" + text + "' (expected a finite number " +
                       (positive ? "> 0" : ">= 0") + ")");
  return x;
}

const char* regime_name(spinslide::terminal_regime r) {
  switch (r) {
    case spinslide::terminal_regime::pure_sliding:
      return "pure sliding to the end: eps -> infinity";
    case spinslide::terminal_regime::pure_spinning:
      return "pure spinning to the end: eps -> 0";
    case spinslide::terminal_regime::sliding_and_spinning:
      return "sliding and spinning to the end: eps -> eps0";
  }
  return "";
}

template <class Profile>
int run(const Profile& profile, const std::string& profile_name, double R, double mu, double v0,
        double omega0, double gamma, double g) {
  const auto r = spinslide::simulate_throw_si(
      profile, spinslide::disk_radius{R}, spinslide::friction_coefficient{mu},
      spinslide::gravity{g}, gamma, spinslide::initial_speed{v0}, spinslide::initial_spin{omega0});
  std::printf("profile %s, gamma = %g, R = %g m, mu = %g, g = %g m/s^2\n", profile_name.c_str(),
              gamma, R, mu, g);
  std::printf("throw: v0 = %g m/s, omega0 = %g rad/s (eps0 = v0/(R omega0) = %g)\n", v0, omega0,
              omega0 > 0 ? v0 / (R * omega0) : INFINITY);
  std::printf("stop time      t     = %.9g s\n", r.time);
  std::printf("distance       s     = %.9g m\n", r.distance);
  std::printf("rotation       theta = %.9g rad (%.6g turns)\n", r.angle,
              r.angle / (2 * boost::math::constants::pi<double>()));
  std::printf("ratio at stop  eps   = %.9g (%s)\n", r.terminal.ratio,
              regime_name(r.terminal.regime));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::string positional[4];
    int count = 0;
    double gamma = 0.5, g = 9.81;
    std::string profile = "disk";
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw bad_argument("missing value after " + a);
        return argv[++i];
      };
      if (a == "-h" || a == "--help") {
        std::fputs(usage, stdout);
        return 0;
      } else if (a == "--gamma") {
        gamma = number("--gamma", value(), true);
      } else if (a == "--gravity") {
        g = number("--gravity", value(), true);
      } else if (a == "--profile") {
        profile = value();
      } else if (a.size() > 1 && a[0] == '-' && !(a[1] >= '0' && a[1] <= '9') && a[1] != '.') {
        throw bad_argument("unknown option " + a);
      } else {
        if (count == 4) throw bad_argument("too many arguments: '" + a + "'");
        positional[count++] = a;
      }
    }
    if (count < 4) throw bad_argument("expected R, MU, V0 and OMEGA0");
    const double R = number("R", positional[0], true);
    const double mu = number("MU", positional[1], true);
    const double v0 = number("V0", positional[2], false);
    const double omega0 = number("OMEGA0", positional[3], false);
    if (v0 == 0 && omega0 == 0) throw bad_argument("V0 and OMEGA0 are both 0: nothing moves");
    if (profile == "disk")
      return run(spinslide::uniform_disk<>(), profile, R, mu, v0, omega0, gamma, g);
    if (profile == "hertz") return run(spinslide::hertz<>(), profile, R, mu, v0, omega0, gamma, g);
    if (profile == "boussinesq")
      return run(spinslide::boussinesq<>(), profile, R, mu, v0, omega0, gamma, g);
    if (profile == "ring") return run(spinslide::ring<>(), profile, R, mu, v0, omega0, gamma, g);
    if (profile.rfind("annulus:", 0) == 0) {
      const double b = number("annulus inner ratio", profile.substr(8), false);
      if (!(b < 1))
        throw bad_argument("bad annulus inner ratio: '" + profile.substr(8) +
                           "' (expected 0 <= B < 1)");
      return run(spinslide::annulus<>(b), profile, R, mu, v0, omega0, gamma, g);
    }
    throw bad_argument("unknown profile '" + profile + "'");
  } catch (const bad_argument& e) {
    std::fprintf(stderr, "throw: %s\n%s", e.what(), usage);
    return 2;
  } catch (const std::domain_error& e) {
    std::fprintf(stderr, "throw: %s\n", e.what());
    return 2;
  }
}
