//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Cost of one (𝓕, 𝓣) pair of each built-in profile, by its own method
// (closed forms or ring quadrature) and tabulated, over 4096 log-uniform ε in
// [1e-3, 1e3].  Baseline: the uniform disk's closed forms, disk.hpp.  Also:
// Hertz by the ring quadrature (a radial_profile of its pressure: what hertz
// cost before its closed forms), a weighted sum of closed-form profiles, and
// the coupling inverses ε(𝓕) and 𝓣(𝓕) at the forces of the same ratios;
// and Hertz's fast path against the forms it replaced (below).
//   ./build/release/benchmarks/bench_profiles
#include <benchmark/benchmark.h>

#include <spinslide/spinslide.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "ratio_reporter.hpp"

namespace {

const std::vector<double>& inputs() {
  static const std::vector<double> xs = [] {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-3, 3);
    std::vector<double> v(4096);
    for (auto& x : v) x = std::pow(10.0, u(rng));
    return v;
  }();
  return xs;
}

template <class P>
void pairs(benchmark::State& state, const P& profile) {
  const auto& xs = inputs();
  for (auto _ : state) {
    for (double x : xs) {
      auto r = profile.force_torque(x);
      benchmark::DoNotOptimize(r);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(xs.size()));
}

template <class P>
void exact(benchmark::State& state) {
  pairs(state, P());
}
template <class P>
void tabulated(benchmark::State& state) {
  static const spinslide::tabulated_profile<> tab{P()};
  state.counters["pieces"] = static_cast<double>(tab.pieces());
  pairs(state, tab);
}

struct cd_annulus : spinslide::annulus<> {
  cd_annulus() : spinslide::annulus<>(0.125) {}
};
struct thin_annulus : spinslide::annulus<> {
  thin_annulus() : spinslide::annulus<>(0.9) {}
};

// p ∝ √(1 − r²) by the ring quadrature.
auto hertz_by_quadrature() {
  return spinslide::radial_profile(
      [](double r, double one_minus_r) { return std::sqrt(one_minus_r * (1 + r)); });
}
void quadrature_hertz(benchmark::State& state) { pairs(state, hertz_by_quadrature()); }

struct hertz_plus_boussinesq
    : spinslide::weighted_sum<double, spinslide::hertz<>, spinslide::boussinesq<>> {
  hertz_plus_boussinesq()
      : spinslide::weighted_sum<double, spinslide::hertz<>, spinslide::boussinesq<>>(
            {0.7, 0.3}, spinslide::hertz<>(), spinslide::boussinesq<>()) {}
};

// ε(𝓕) and 𝓣(𝓕) = 𝓣(ε(𝓕)) at the forces of the benchmark's ratios.
template <class P, bool Curve>
void inverse(benchmark::State& state) {
  const P profile;
  std::vector<double> forces;
  for (double x : inputs()) {
    const double f = profile.force(x);
    if (f < 1) forces.push_back(f);
  }
  for (auto _ : state) {
    for (double f : forces) {
      const double r =
          Curve ? spinslide::torque_at_force(profile, f) : spinslide::ratio_from_force(profile, f);
      benchmark::DoNotOptimize(r);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(forces.size()));
}

BENCHMARK_TEMPLATE(exact, spinslide::uniform_disk<>);
BENCHMARK_TEMPLATE(exact, cd_annulus);
BENCHMARK_TEMPLATE(exact, thin_annulus);
BENCHMARK_TEMPLATE(exact, spinslide::ring<>);
BENCHMARK_TEMPLATE(exact, spinslide::hertz<>);
BENCHMARK_TEMPLATE(exact, spinslide::boussinesq<>);
BENCHMARK_TEMPLATE(exact, hertz_plus_boussinesq);
BENCHMARK(quadrature_hertz);
BENCHMARK_TEMPLATE(tabulated, spinslide::uniform_disk<>);
BENCHMARK_TEMPLATE(tabulated, cd_annulus);
BENCHMARK_TEMPLATE(tabulated, thin_annulus);
BENCHMARK_TEMPLATE(tabulated, spinslide::ring<>);
BENCHMARK_TEMPLATE(tabulated, spinslide::hertz<>);
BENCHMARK_TEMPLATE(tabulated, spinslide::boussinesq<>);
BENCHMARK_TEMPLATE(inverse, spinslide::uniform_disk<>, false);
BENCHMARK_TEMPLATE(inverse, spinslide::hertz<>, false);
BENCHMARK_TEMPLATE(inverse, spinslide::boussinesq<>, false);
BENCHMARK_TEMPLATE(inverse, spinslide::uniform_disk<>, true);
BENCHMARK_TEMPLATE(inverse, spinslide::hertz<>, true);
BENCHMARK_TEMPLATE(inverse, spinslide::boussinesq<>, true);

// Hertz's fast path (values/detail/hertz_fast.hpp) against the closed forms and
// series it replaced for double (still the path of long double and wider
// types), over 4096 log-uniform ε in [13/10, 1e3], where it applies: 𝓕, 𝓣,
// 𝓕′ and 𝓕″ together (what the limit-set projection's warm steps take), each
// ratio independent ("throughput"), and each call waiting for the one
// before, as the projection's steps do ("latency").
const std::vector<double>& fast_hertz_inputs() {
  static const std::vector<double> xs = [] {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> u(std::log10(1.3), 3);
    std::vector<double> v(4096);
    for (auto& x : v) x = std::pow(10.0, u(rng));
    return v;
  }();
  return xs;
}
template <bool Fast>
spinslide::detail::value_slope<double> hertz_value_slope(double e) {
  using spinslide::detail::hertz_load;
  if (Fast) return spinslide::detail::elastic_value_and_slope<hertz_load, true>(e);
  return spinslide::detail::elastic_forms_value_and_slope<hertz_load, true>(e);
}
template <bool Fast>
void hertz_value_slope_throughput(benchmark::State& state) {
  const auto& xs = fast_hertz_inputs();
  for (auto _ : state) {
    for (double x : xs) {
      auto r = hertz_value_slope<Fast>(x);
      benchmark::DoNotOptimize(r);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(xs.size()));
}
template <bool Fast>
void hertz_value_slope_latency(benchmark::State& state) {
  const auto& xs = fast_hertz_inputs();
  for (auto _ : state) {
    double carry = 0;
    for (double x : xs) {
      const auto r = hertz_value_slope<Fast>(x + carry);
      carry = 0 * r.curvature;  // the next ratio waits for this result
    }
    benchmark::DoNotOptimize(carry);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(xs.size()));
}
BENCHMARK_TEMPLATE(hertz_value_slope_throughput, false);
BENCHMARK_TEMPLATE(hertz_value_slope_throughput, true);
BENCHMARK_TEMPLATE(hertz_value_slope_latency, false);
BENCHMARK_TEMPLATE(hertz_value_slope_latency, true);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  spinslide_bench::ratio_reporter reporter("exact<spinslide::uniform_disk<>>");
  reporter.add_comparison("hertz_value_slope_throughput<true>",
                          "hertz_value_slope_throughput<false>");
  reporter.add_comparison("hertz_value_slope_latency<true>", "hertz_value_slope_latency<false>");
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
