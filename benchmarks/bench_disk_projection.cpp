//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// bench_disk: the projection onto the limit set (limit_set.hpp), the impulse
// law (impulse_friction.hpp) and the spring-history law (spring_friction.hpp)
// of the uniform disk, Hertz and the tabulated CD, against each profile's
// force_torque; bench_disk.cpp says how the cases are made.
#include <benchmark/benchmark.h>

#include <spinslide/contact/contact_law.hpp>
#include <spinslide/contact/impulse_friction.hpp>
#include <spinslide/contact/limit_set.hpp>
#include <spinslide/contact/spring_friction.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "bench_disk.hpp"

namespace spinslide_bench {

// The projection's profiles: the uniform disk, Hertz, and a tabulated CD annulus.
template <class P>
const P& projected() {
  static const P p;
  return p;
}
template <>
const tabulated_cd& projected<tabulated_cd>() {
  static const tabulated_cd p{spinslide::annulus<>(0.125)};
  return p;
}

struct projection_case {
  double force, torque, start;
};
template <class P>
const std::vector<projection_case>& projection_cases(bool sliding) {
  static const auto make = [](bool slide) {
    std::mt19937_64 rng(43);
    std::uniform_real_distribution<double> theta(0.5, 0.99);
    std::vector<projection_case> v;
    for (double e : inputs<double>()) {
      const auto c = projected<P>().force_torque(e);
      const double q = theta(rng);
      v.push_back(slide ? projection_case{c.force + 0.2 * e, c.torque + 0.2, e * (1 + 1e-3)}
                        : projection_case{q * c.force, q * c.torque, e});
    }
    return v;
  };
  static const std::vector<projection_case> slide = make(true), stick = make(false);
  return sliding ? slide : stick;
}

template <class P>
void profile_force_torque(benchmark::State& s) {
  scalar<double>(s, [](double e) { return projected<P>().force_torque(e); });
}
// The same evaluations as a dependent chain (each ε waits for the previous
// result, as a projection's iterations do): the latency of one evaluation,
// where the loop above measures the throughput of independent ones.
template <class P>
void profile_force_torque_chained(benchmark::State& s) {
  const auto& xs = inputs<double>();
  for (auto _ : s) {
    double carry = 0;
    for (const double e : xs) {
      const auto r = projected<P>().force_torque(e + carry);
      carry = r.force * 1e-300;  // ≈ 0, but the compiler cannot know
    }
    benchmark::DoNotOptimize(carry);
  }
  s.SetItemsProcessed(s.iterations() * static_cast<int64_t>(xs.size()));
}
template <class P>
void projection(benchmark::State& s, bool sliding, bool warm) {
  const auto& cases = projection_cases<P>(sliding);
  for (auto _ : s) {
    for (const auto& c : cases) {
      const auto r =
          spinslide::project_to_limit_set(projected<P>(), c.force, c.torque, 1.0,
                                          spinslide::curve_point<double>{warm ? c.start : 0.0});
      benchmark::DoNotOptimize(r);
    }
  }
  s.SetItemsProcessed(s.iterations() * static_cast<int64_t>(cases.size()));
}
template <class P>
void projection_sliding_warm(benchmark::State& s) {
  projection<P>(s, true, true);
}
template <class P>
void projection_sliding_cold(benchmark::State& s) {
  projection<P>(s, true, false);
}
template <class P>
void projection_sticking_warm(benchmark::State& s) {
  projection<P>(s, false, true);
}
// The sliding cases from the curve point of the last step's answer (the
// projection of C(ε') + 0.2(ε', 1), ε' = ε(1 + 1e-3): the warm start's ratio,
// with 𝓕, 𝓣, 𝓕′ and 𝓕″ there), as a contact's history keeps it.
template <class P>
void projection_sliding_from_point(benchmark::State& s) {
  const auto& cases = projection_cases<P>(true);
  static const std::vector<spinslide::curve_point<double>> points = [&cases] {
    std::vector<spinslide::curve_point<double>> v;
    for (const auto& c : cases) {
      const double e = c.start;
      const auto ft = projected<P>().force_torque(e);
      v.push_back(spinslide::project_to_limit_set(projected<P>(), ft.force + 0.2 * e,
                                                  ft.torque + 0.2, 1.0,
                                                  spinslide::curve_point<double>{e})
                      .curve());
    }
    return v;
  }();
  for (auto _ : s) {
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const auto r = spinslide::project_to_limit_set(projected<P>(), cases[i].force,
                                                     cases[i].torque, 1.0, points[i]);
      benchmark::DoNotOptimize(r);
    }
  }
  s.SetItemsProcessed(s.iterations() * static_cast<int64_t>(cases.size()));
}
// The impulse law (impulse_friction.hpp) with a coupled inverse mass (a body
// whose contact point has a lever arm): each input ratio ε gives a slip
// (ε cos φ, ε sin φ, 1) with φ = ε; a normal impulse of 1e-3 lets every one
// slip, one of 1e3 stops every one.  Warm: started from the answer's ratio
// times 1 + 1e-3 (the last step's, in an engine).
struct impulse_case {
  std::array<double, 2> v;
  double spin, start;
};
const spinslide::planar_metric<double>& coupled_inverse_mass() {
  static const spinslide::planar_metric<double> w(
      {{{2.0, 0.3, 0.2}, {0.3, 1.5, -0.1}, {0.2, -0.1, 3.0}}});
  return w;
}
spinslide::impulse_contact<double> impulse_load(double normal) {
  return {spinslide::patch_radius<double>{1.0}, spinslide::normal_impulse<double>{normal},
          spinslide::friction_coefficient<double>{1.0}};
}
template <class P>
const std::vector<impulse_case>& impulse_cases() {
  static const std::vector<impulse_case> v = [] {
    std::vector<impulse_case> out;
    for (double e : inputs<double>()) {
      impulse_case c{{e * std::cos(e), e * std::sin(e)}, 1.0, 0.0};
      c.start = spinslide::impulse_friction(projected<P>(), c.v, c.spin, coupled_inverse_mass(),
                                            impulse_load(1e-3))
                    .ratio *
                (1 + 1e-3);
      out.push_back(c);
    }
    return out;
  }();
  return v;
}
template <class P>
void impulse(benchmark::State& s, double normal, bool warm) {
  const auto& cases = impulse_cases<P>();
  const auto load = impulse_load(normal);
  for (auto _ : s) {
    for (const auto& c : cases) {
      const auto r =
          spinslide::impulse_friction(projected<P>(), c.v, c.spin, coupled_inverse_mass(), load,
                                      spinslide::curve_point<double>{warm ? c.start : 0.0});
      benchmark::DoNotOptimize(r);
    }
  }
  s.SetItemsProcessed(s.iterations() * static_cast<int64_t>(cases.size()));
}
template <class P>
void impulse_sliding_warm(benchmark::State& s) {
  impulse<P>(s, 1e-3, true);
}
// The sliding cases from the curve point of the last step's answer (the
// slip with its spin 1e-3 higher: ratio, 𝓕 and 𝓣 there), as
// spinslide::pair_friction keeps it.
template <class P>
void impulse_sliding_from_point(benchmark::State& s) {
  const auto& cases = impulse_cases<P>();
  const auto load = impulse_load(1e-3);
  static const std::vector<spinslide::curve_point<double>> points = [&cases, &load] {
    std::vector<spinslide::curve_point<double>> v;
    for (const auto& c : cases)
      v.push_back(spinslide::impulse_friction(projected<P>(), c.v, c.spin * (1 + 1e-3),
                                              coupled_inverse_mass(), load)
                      .curve());
    return v;
  }();
  for (auto _ : s) {
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const auto r = spinslide::impulse_friction(projected<P>(), cases[i].v, cases[i].spin,
                                                 coupled_inverse_mass(), load, points[i]);
      benchmark::DoNotOptimize(r);
    }
  }
  s.SetItemsProcessed(s.iterations() * static_cast<int64_t>(cases.size()));
}
template <class P>
void impulse_sliding_cold(benchmark::State& s) {
  impulse<P>(s, 1e-3, false);
}
template <class P>
void impulse_sticking(benchmark::State& s) {
  impulse<P>(s, 1e3, false);
}
// The spring-history law (spring_friction.hpp), Mindlin springs: sliding
// from the steady state of each ratio ε (the springs holding μN(𝓕, a𝓣)(ε),
// the history's ratio ε and its curve point, the next increment
// (εaΔφ, 0, Δφ)), which caps back
// onto the same point; sticking from relaxed springs and a small increment.
struct spring_case {
  spinslide::spring_history<std::array<double, 2>, double> history;
  std::array<double, 2> increment;
  double twist;
};
const spinslide::spring_stiffness<double>& bench_springs() {
  static const auto k = spinslide::mindlin_springs(spinslide::tangential_stiffness<double>{1e5},
                                                   spinslide::patch_radius<double>{0.01});
  return k;
}
spinslide::force_contact<double> spring_load() {
  return {spinslide::patch_radius<double>{0.01}, spinslide::normal_force<double>{10.0},
          spinslide::friction_coefficient<double>{0.3}};
}
template <class P>
const std::vector<spring_case>& spring_cases(bool sliding) {
  static const auto make = [](bool slide) {
    std::vector<spring_case> out;
    const double a = 0.01, load = 3, dphi = 1e-4;
    const auto& k = bench_springs();
    for (double e : inputs<double>()) {
      const auto c = projected<P>().force_torque(e);
      spring_case sc{
          {{load * c.force / k.tangential.value, 0}, load * a * c.torque / k.twisting.value, {e}},
          {-e * a * dphi, 0},
          -dphi};
      // the curve point the steady slip keeps (ε, 𝓕, 𝓣, 𝓕′, 𝓕″ at ε): the
      // projection of a point on the normal at ε, from next to ε
      sc.history.curve =
          spinslide::project_to_limit_set(projected<P>(), c.force + 0.01 * 2 * e, c.torque + 0.01,
                                          2.0, spinslide::curve_point<double>{e * (1 + 1e-4)})
              .curve();
      if (!slide) sc = {{{0, 0}, 0, {}}, {1e-7, 0}, 1e-5};
      out.push_back(sc);
    }
    return out;
  };
  static const std::vector<spring_case> slide = make(true), stick = make(false);
  return sliding ? slide : stick;
}
template <class P>
void springs(benchmark::State& s, bool sliding) {
  const auto& cases = spring_cases<P>(sliding);
  const auto load = spring_load();
  for (auto _ : s) {
    for (const auto& c : cases) {
      auto h = c.history;
      const auto r = spinslide::spring_history_friction(projected<P>(), h, c.increment, c.twist,
                                                        bench_springs(), load);
      benchmark::DoNotOptimize(r);
      benchmark::DoNotOptimize(h);
    }
  }
  s.SetItemsProcessed(s.iterations() * static_cast<int64_t>(cases.size()));
}
template <class P>
void spring_sliding_warm(benchmark::State& s) {
  springs<P>(s, true);
}
template <class P>
void spring_sticking(benchmark::State& s) {
  springs<P>(s, false);
}

// The benchmarks of bench_disk.cpp's SPINSLIDE_BENCH_PROJECTION, for its
// three profiles.
#define SPINSLIDE_BENCH_PROJECTION_INSTANCES(P)                      \
  template void profile_force_torque<P>(benchmark::State&);          \
  template void profile_force_torque_chained<P>(benchmark::State&);  \
  template void projection_sliding_warm<P>(benchmark::State&);       \
  template void projection_sliding_from_point<P>(benchmark::State&); \
  template void projection_sliding_cold<P>(benchmark::State&);       \
  template void projection_sticking_warm<P>(benchmark::State&);      \
  template void impulse_sliding_warm<P>(benchmark::State&);          \
  template void impulse_sliding_from_point<P>(benchmark::State&);    \
  template void impulse_sliding_cold<P>(benchmark::State&);          \
  template void impulse_sticking<P>(benchmark::State&);              \
  template void spring_sliding_warm<P>(benchmark::State&);           \
  template void spring_sticking<P>(benchmark::State&);
SPINSLIDE_BENCH_PROJECTION_INSTANCES(spinslide::uniform_disk<>)
SPINSLIDE_BENCH_PROJECTION_INSTANCES(spinslide::hertz<>)
SPINSLIDE_BENCH_PROJECTION_INSTANCES(tabulated_cd)

}  // namespace spinslide_bench
