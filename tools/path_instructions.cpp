//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The driver of tools/path_instructions.py (issue 41; docs/performance.md,
// "Instruction counts"): every path an engine's step calls, on fixed inputs,
// each case's loop between callgrind's client requests (its count zeroed
// before, dumped after under the case's name), so that one run under
// `valgrind --tool=callgrind` counts them all.  Alone it runs the same loops
// and prints the cases, their calls and the warm starts' offsets.
//
// The inputs, for each profile and type: the 64 ratios ε = 10^(−3 + 6i/63).
//   force_torque   the profile's 𝓕, 𝓣 at each ratio: the unit of every ratio below.
//   projection     project_to_limit_set(profile, f, t, 1) of C(ε) + 0.2(ε, 1),
//                  whose answer is C(ε) (its displacement is along the normal).
//   trial_cap      cap_trial_state of the DEM springs whose trial is that point,
//                  in 3-D vectors (as the LAMMPS plugin calls it), weight 1.
//   impulse        impulse_friction of the slips (ε cos ε, ε sin ε, 1) in a
//                  coupled metric, a = μ = 1, Λ = 1e-3 (1e3 when sticking).
//   impulse_handle the same through the run-time handle contact_profile, as
//                  pair_friction and the engine adapters call it (double).
//   patch_wrench   friction_wrench of the 0.22 × 0.10 rectangle (issue 42; as
//                  bench_patch) at the twists v = 0.11 ε (cos 2.4i, sin 2.4i),
//                  ω = ±1: uniform pressure, and linear with its centre at
//                  (0.015, −0.005) (double; the unit is the disk's force_torque).
//   patch_no_tension the polygon_patch of that rectangle with its centre of
//                  pressure beyond the kern, at 64 points of [0.06, 0.1] × [0.015, 0.04].
//   patch_impulse  the impulse law of that rectangle (uniform) under a box
//                  (patch_impulse below); its unit is the uniform patch_wrench.
// The modes:
//   warm      from the stored state (the curve() a contact keeps) of the
//             previous answer, which was the answer for ε·(1 + 1e-3) (the
//             projections), or for the spin 1e-3 higher (the impulse);
//   spread    the same with a previous answer 1–100 % off: ε·(1 + u)^±1, u
//             log-uniform in [0.01, 1] (the impulse: the spin so scaled);
//   cold      no stored state;
//   sticking  a trial far inside the set: q·C(ε), q uniform in [0.1, 0.7]
//             (the impulse: Λ = 1e3).
// "loop" is the bare loop (read the inputs, add up the results), which the
// script subtracts from every count.
#include <spinslide/spinslide.hpp>
#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <valgrind/callgrind.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using namespace spinslide;

constexpr int repetitions = 4;
enum class mode { warm, spread, cold, sticking };
const char* const mode_names[] = {"warm", "spread", "cold", "sticking"};
constexpr mode all_modes[] = {mode::warm, mode::spread, mode::cold, mode::sticking};

// An opaque copy: the compiler can neither hoist a call out of the
// repetitions nor drop its result.
template <class T>
T opaque(T v) {
  __asm__ volatile("" : "+m"(v));
  return v;
}

template <class Real>
std::vector<Real> ratios() {
  std::vector<Real> v;
  for (int i = 0; i < 64; ++i) v.push_back(static_cast<Real>(std::pow(10.0, -3 + 6.0 * i / 63)));
  return v;
}

// The previous answer's ratio factor of each input: 1 + 1e-3, or 1–100 % off
// either way; the sticking factor q.
std::vector<double> factors(mode m) {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> f;
  for (int i = 0; i < 64; ++i) {
    const double u = std::pow(10.0, -2 + 2 * unit(rng));
    if (m == mode::warm) f.push_back(1 + 1e-3);
    if (m == mode::spread) f.push_back(i % 2 ? 1 + u : 1 / (1 + u));
    if (m == mode::cold) f.push_back(1);
    if (m == mode::sticking) f.push_back(0.1 + 0.6 * unit(rng));
  }
  return f;
}

// Counts `calls` runs of body(i) for i = 0 .. 63, `repetitions` times,
// under the name `name`, and prints it.
template <class Body>
void count(const std::string& name, Body&& body) {
  double sum = 0;
  CALLGRIND_ZERO_STATS;
  for (int r = 0; r < repetitions; ++r)
    for (int i = 0; i < 64; ++i) sum += body(opaque(i));
  CALLGRIND_DUMP_STATS_AT(name.c_str());
  std::printf("case %s %d %g\n", name.c_str(), 64 * repetitions, sum);
}

// The median of |ratio/ε − 1| over the stored starts: how far off "warm" is.
void print_offset(const std::string& name, std::vector<double> off) {
  std::sort(off.begin(), off.end());
  std::printf("offset %s %.3g\n", name.c_str(), off[off.size() / 2]);
}

template <class Real>
struct planar_case {
  Real force, torque;
  curve_point<Real> start;
};

// The 2-D points of the projection and the trial cap, with their starts
// (`project` gives the previous answer's curve() for a point).
template <class Real, class Profile, class Project>
std::vector<planar_case<Real>> planar_cases(const Profile& p, mode m, Project project) {
  std::vector<planar_case<Real>> v;
  const auto eps = ratios<Real>();
  const auto f = factors(m);
  for (int i = 0; i < 64; ++i) {
    const auto c = p.force_torque(eps[i]);
    if (m == mode::sticking) {
      v.push_back({Real(f[i]) * c.force, c.torque * Real(f[i]), {}});
      continue;
    }
    curve_point<Real> start{};
    if (m != mode::cold) {
      const Real e = eps[i] * Real(f[i]);
      const auto prev = p.force_torque(e);
      start = project(prev.force + Real(0.2) * e, prev.torque + Real(0.2), curve_point<Real>{});
    }
    v.push_back({c.force + Real(0.2) * eps[i], c.torque + Real(0.2), start});
  }
  return v;
}

template <class Real, class Profile>
void projection(const std::string& tag, const Profile& p, mode m) {
  auto project = [&](Real f, Real t, const curve_point<Real>& s) {
    return project_to_limit_set(p, f, t, Real(1), s).curve();
  };
  const auto cases = planar_cases<Real>(p, m, project);
  count("projection." + tag + "." + mode_names[int(m)], [&](int i) {
    const auto& c = cases[i];
    return double(project_to_limit_set(p, c.force, c.torque, Real(1), c.start).force);
  });
}

// The trial cap as the LAMMPS plugin calls it: 3-vectors, a = N = μ = 1,
// k_t = k_θ = 1 (the weight a²k_t/k_θ = 1), no damping; the trial force
// f·(cos ε, sin ε, 0), torque t.
template <class Real, class Profile>
void trial_cap(const std::string& tag, const Profile& p, mode m) {
  using vec = std::array<Real, 3>;
  const spring_stiffness<Real> k{tangential_stiffness<Real>{1}, twisting_stiffness<Real>{1}};
  const force_contact<Real> contact{patch_radius<Real>{1}, normal_force<Real>{1},
                                    friction_coefficient<Real>{1}};
  auto trial = [](Real f, Real t, Real angle) {
    using std::cos;
    using std::sin;
    return spring_trial<vec, Real>{vec{-f * cos(angle), -f * sin(angle), 0}, -t, vec{}, 0};
  };
  auto cap = [&](Real f, Real t, const curve_point<Real>& s) {
    return cap_trial_state(p, trial(f, t, Real(0.5)), k, contact, s).curve();
  };
  const auto cases = planar_cases<Real>(p, m, cap);
  const auto eps = ratios<Real>();
  std::vector<spring_trial<vec, Real>> trials;  // built before the count
  for (int i = 0; i < 64; ++i) trials.push_back(trial(cases[i].force, cases[i].torque, eps[i]));
  count("trial_cap." + tag + "." + mode_names[int(m)], [&](int i) {
    return double(cap_trial_state(p, trials[i], k, contact, cases[i].start).torque);
  });
}

// Through the run-time handle (issue 40), as pair_friction and the engine
// adapters call it, when `handle` is given.
template <class Real, class Profile>
void impulse(const std::string& tag, const Profile& p, mode m,
             const contact_profile<Real>* handle = nullptr) {
  const planar_metric<Real> w({{{2, Real(0.3), Real(0.2)},
                                {Real(0.3), Real(1.5), Real(-0.1)},
                                {Real(0.2), Real(-0.1), 3}}});
  const impulse_contact<Real> load{patch_radius<Real>{1},
                                   normal_impulse<Real>{Real(m == mode::sticking ? 1e3 : 1e-3)},
                                   friction_coefficient<Real>{1}};
  const auto eps = ratios<Real>();
  const auto f = factors(m);
  std::vector<std::array<Real, 2>> slips;
  std::vector<curve_point<Real>> starts;
  std::vector<double> off;
  for (int i = 0; i < 64; ++i) {
    using std::cos;
    using std::sin;
    slips.push_back({eps[i] * cos(eps[i]), eps[i] * sin(eps[i])});
    curve_point<Real> s{};
    if (m == mode::warm || m == mode::spread) {
      s = impulse_friction(p, slips[i], Real(f[i]), w, load).curve();
      const Real now = impulse_friction(p, slips[i], Real(1), w, load).ratio;
      if (s.ratio > 0 && now > 0) off.push_back(std::fabs(double(s.ratio / now) - 1));
    }
    starts.push_back(s);
  }
  const std::string name =
      std::string(handle ? "impulse_handle." : "impulse.") + tag + "." + mode_names[int(m)];
  if (!off.empty()) print_offset(name, off);
  if (handle) {
    count(name, [&](int i) {
      return double(handle->visit([&](const auto& q) {
        return impulse_friction(q, slips[i], Real(1), w, load, starts[i]).torque;
      }));
    });
    return;
  }
  count(name, [&](int i) {
    return double(impulse_friction(p, slips[i], Real(1), w, load, starts[i]).torque);
  });
}

template <class Real, class Profile>
void profile_paths(const std::string& name, const Profile& p, bool planar) {
  const std::string tag = name + "." + (sizeof(Real) == 4 ? "float" : "double");
  const auto eps = ratios<Real>();
  count("force_torque." + tag, [&](int i) { return double(p.force_torque(eps[i]).force); });
  for (const mode m : all_modes) {
    if (planar) projection<Real>(tag, p, m);
    if (planar) trial_cap<Real>(tag, p, m);
    impulse<Real>(tag, p, m);
  }
  if constexpr (std::is_same<Real, double>::value) {
    const contact_profile<Real> handle(p);
    for (const mode m : all_modes) impulse<Real>(tag, p, m, &handle);
  }
}

template <class Real>
void all_paths() {
  const auto eps = ratios<Real>();
  count(std::string("loop.") + (sizeof(Real) == 4 ? "float" : "double"),
        [&](int i) { return double(eps[i]); });
  profile_paths<Real>("disk", uniform_disk<Real>(), true);
  profile_paths<Real>("hertz", hertz<Real>(), true);
  profile_paths<Real>("boussinesq", boussinesq<Real>(), true);
  const Real tolerance = sizeof(Real) == 4 ? Real(1e-6) : Real(1e-13);
  profile_paths<Real>("tabulated", tabulated_profile<Real>(annulus<Real>(Real(0.3)), tolerance),
                      true);
}

// A flat patch's impulse law (issue 42, item 9: warm ≤ 8× the rectangle's
// wrench): a 2 kg box, yaw inertia 0.01 kg m², its centre 2 cm off the
// patch origin, at 64 steps of sliding up to 0.3 m/s and spin up to 5 rad/s
// under μΛ = 3e-3 (3 when sticking); warm from the answer's slip moved 1e-3,
// spread 1–100 % (its spin), cold without a start.
void patch_impulse(const polygon_patch<double>& patch, mode m) {
  const double mass = 2, inertia = 0.01;
  const std::array<double, 3> arm{-0.01, 0.02, 1};
  planar_metric<double>::matrix w{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) w[i][j] = arm[i] * arm[j] / inertia;
  w[0][0] += 1 / mass;
  w[1][1] += 1 / mass;
  const planar_metric<double> metric(w);
  const patch_impulse_contact<double> c{normal_impulse<double>{m == mode::sticking ? 10.0 : 0.01},
                                        friction_coefficient<double>{0.3}};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto f = factors(m);
  struct step {
    std::array<double, 2> v;
    double omega;
    planar_twist<double> start;
  };
  std::vector<step> steps(64);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    step& s = steps[i];
    s.v = {0.3 * u(rng), 0.3 * u(rng)};
    s.omega = 5 * u(rng);
    s.start = {{0, 0}, 0};
    if (m == mode::cold || m == mode::sticking) continue;
    const auto a = impulse_friction(patch, s.v, s.omega, metric, c).slip;
    const double off = m == mode::warm ? 1e-3 : f[i] - 1;
    s.start = {{a.velocity[0] * (1 + off), a.velocity[1] * (1 - off)}, a.omega * (1 + off)};
  }
  count(std::string("patch_impulse.rectangle.double.") + mode_names[static_cast<int>(m)],
        [&](int i) {
          const step& s = steps[static_cast<std::size_t>(i)];
          return impulse_friction(patch, s.v, s.omega, metric, c, s.start).torque;
        });
}

// The flat patch's paths (issue 42), in double, against the disk's force_torque.
void patch_paths() {
  using point = std::array<double, 2>;
  const std::vector<point> sole{{-0.11, -0.05}, {0.11, -0.05}, {0.11, 0.05}, {-0.11, 0.05}};
  const auto eps = ratios<double>();
  std::vector<planar_twist<double>> twists;
  twists.reserve(64);
  for (std::size_t i = 0; i < 64; ++i) {
    const double angle = 2.4 * static_cast<double>(i);
    twists.push_back(
        {{0.11 * eps[i] * std::cos(angle), 0.11 * eps[i] * std::sin(angle)}, i % 2 ? 1.0 : -1.0});
  }
  auto at = [](int i) { return static_cast<std::size_t>(i); };
  const polygon_patch<double> uniform(sole),
      linear(sole, centre_of_pressure<double>{{0.015, -0.005}});
  count("patch_wrench.disk.double.uniform",
        [&](int i) { return friction_wrench(uniform, twists[at(i)]).torque; });
  count("patch_wrench.disk.double.linear",
        [&](int i) { return friction_wrench(linear, twists[at(i)]).torque; });
  std::vector<point> centres;
  centres.reserve(64);
  for (int i = 0; i < 64; ++i) {
    const int column = i % 8, row = i / 8;
    centres.push_back({0.06 + 0.04 * column / 7.0, 0.015 + 0.025 * row / 7.0});
  }
  count("patch_no_tension.disk.double.construction", [&](int i) {
    return polygon_patch<double>(sole, centre_of_pressure<double>{centres[at(i)]})
        .pressure_at_origin();
  });
  for (mode m : all_modes) patch_impulse(uniform, m);
}

}  // namespace

int main() {
  all_paths<double>();
  patch_paths();
  all_paths<float>();
}
