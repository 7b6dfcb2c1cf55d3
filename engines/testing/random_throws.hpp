//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Randomized throws of a disk on a table, the same for every adapter (issue
// 27): seeded, SPINSLIDE_RANDOM_THROWS of them (10 000 in release; the
// sanitize preset runs fewer), spread over the time steps users run.  Each
// throw's initial ratio ε = v0/(Rω0) is log-uniform in [1e-2, 1e2], its
// direction and spin sense uniform, and its size chosen so that its exact
// stop takes 20 to 200 steps: the stop time of a throw scales with its
// speeds (the equations of motion are homogeneous in v and ω), so one
// stop_time at unit spin gives the exact stop of the scaled throw.
//
// An adapter's test runs each throw in its engine and hands back what it
// saw: no exception and finite velocities at every step, the first step at
// which the pair reported sticking, and whether it slipped again after
// that while still in contact.  The statistics per time step are printed
// (docs/engines.md, "Randomized throws") and held to bounds the test states.
#ifndef SPINSLIDE_TESTS_ENGINES_RANDOM_THROWS_HPP
#define SPINSLIDE_TESTS_ENGINES_RANDOM_THROWS_HPP

#include <gtest/gtest.h>
#include <spinslide/contact/pair_report.hpp>
#include <spinslide/motion/dynamics.hpp>
#include <spinslide/values/profile.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <random>
#include <vector>

#ifndef SPINSLIDE_RANDOM_THROWS
#define SPINSLIDE_RANDOM_THROWS 10000
#endif

namespace random_throws {

constexpr int count = SPINSLIDE_RANDOM_THROWS;
constexpr double pi = 3.14159265358979323846;

/// One throw of a disk of radius R (γ = I/(mR²)) with friction μ under g.
struct throw_case {
  double dt;          ///< the time step [s]
  double speed;       ///< v0 [m/s]
  double direction;   ///< the angle of v0 in the table's plane [rad]
  double spin;        ///< ω0 about the table's normal (either sense) [rad/s]
  double exact_stop;  ///< the exact stop time [s]
};

/// The disk and the time steps of one adapter's throws.
struct throw_setting {
  double radius, inertia_ratio, friction, gravity;
  std::vector<double> steps;
  /// The largest turn per step |ω0|Δt [rad] a throw may start with (an
  /// engine's own cap: Box2D scales a body's spin down to turn at most
  /// b2_maxRotation = π/2 per step); a throw beyond it is drawn again.
  double max_turn = HUGE_VAL;
};

/// The throws of `s`, `count` of them from `seed`, cycling through the steps,
/// with the exact stops of a disk whose pressure is `profile` (by default
/// the paper's uniform disk).
template <class Profile = spinslide::uniform_disk<>>
std::vector<throw_case> cases(const throw_setting& s, unsigned seed,
                              const Profile& profile = Profile()) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  const double unit_time = std::sqrt(s.radius / s.gravity);  // of stop_time's dimensionless time
  std::vector<throw_case> out;
  out.reserve(count);
  for (int k = 0; k < count;) {
    const double dt = s.steps[static_cast<std::size_t>(k) % s.steps.size()];
    const double ratio = std::pow(10.0, -2 + 4 * u(rng));
    const double steps = 20 + 180 * u(rng);
    // At unit spin ω* = 1 (ω = μ√(g/R)) and v* = ε: the exact stop t1, then
    // every speed scaled by T/t1.
    const double t1 = spinslide::stop_time(profile, s.inertia_ratio, ratio, 1.0) * unit_time;
    const double scale = steps * dt / t1;
    const double omega = scale * s.friction * std::sqrt(s.gravity / s.radius);
    throw_case c{dt, ratio * s.radius * omega, 2 * pi * u(rng), u(rng) < 0.5 ? omega : -omega,
                 steps * dt};
    if (omega * dt > s.max_turn) continue;
    out.push_back(c);
    ++k;
  }
  return out;
}

/// What an engine did with one throw.
struct outcome {
  bool finite = true;          ///< every velocity finite, no exception
  double stop = -1;            ///< the end of the first step that stuck [s] (-1: never)
  bool slipped_again = false;  ///< slipped after that, in contact
};

/// What the test sees after one step: the velocities' check and the pair's
/// report.
struct observation {
  bool finite;
  spinslide::pair_report report;
};

/// Runs throw `c` (already set up in the engine) for 1.5 exact stops and 20
/// steps more, `step()` making one step and returning what it saw.  An
/// exception fails the test (it must not happen) and ends the throw.
template <class Step>
outcome run(const throw_case& c, Step&& step) {
  outcome o;
  const int n = static_cast<int>(1.5 * c.exact_stop / c.dt) + 20;
  try {
    for (int i = 1; i <= n; ++i) {
      const observation seen = step();
      o.finite = o.finite && seen.finite;
      const spinslide::pair_report& r = seen.report;
      if (r.sticking && o.stop < 0) o.stop = i * c.dt;
      if (r.touching() && !r.sticking && o.stop >= 0) o.slipped_again = true;
    }
  } catch (const std::exception& e) {
    ADD_FAILURE() << "a throw raised " << e.what();
    o.finite = false;
  }
  return o;
}

/// The outcomes of one time step.
struct step_statistics {
  int throws = 0, not_finite = 0, never = 0, slipped_again = 0;
  std::vector<double> late;  ///< (stop − exact)/Δt, sorted: the stop's lag in steps
  double quantile(double q) const {
    return late.empty() ? 0.0 : late[static_cast<std::size_t>(q * double(late.size() - 1))];
  }
};

/// The statistics per time step; printed.
inline std::map<double, step_statistics> summarize(const char* engine,
                                                   const std::vector<throw_case>& cs,
                                                   const std::vector<outcome>& os) {
  std::map<double, step_statistics> by_step;
  for (std::size_t k = 0; k < cs.size(); ++k) {
    step_statistics& s = by_step[cs[k].dt];
    ++s.throws;
    s.not_finite += os[k].finite ? 0 : 1;
    s.slipped_again += os[k].slipped_again ? 1 : 0;
    if (os[k].stop < 0)
      ++s.never;
    else
      s.late.push_back((os[k].stop - cs[k].exact_stop) / cs[k].dt);
  }
  std::printf("%s: random throws, stop - exact stop in steps (each exact stop is 20-200 steps)\n",
              engine);
  std::printf("%10s %7s %10s %6s %8s %9s %9s %9s %9s %9s\n", "dt [s]", "throws", "not finite",
              "never", "slipped", "min", "1%", "median", "99%", "max");
  for (auto& entry : by_step) {
    step_statistics& s = entry.second;
    std::sort(s.late.begin(), s.late.end());
    std::printf("%10.3g %7d %10d %6d %8d %+9.2f %+9.2f %+9.2f %+9.2f %+9.2f\n", entry.first,
                s.throws, s.not_finite, s.never, s.slipped_again, s.quantile(0), s.quantile(0.01),
                s.quantile(0.5), s.quantile(0.99), s.quantile(1));
  }
  return by_step;
}

}  // namespace random_throws

#endif  // SPINSLIDE_TESTS_ENGINES_RANDOM_THROWS_HPP
