//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Cost of one (𝓕, 𝓣) pair of the uniform disk over 4096 log-uniform ε in
// [1e-3, 1e3], against the literal closed form with Boost's ellint_1/ellint_2
// (default policy: double promoted to long double) as the baseline.
//   ./build/release/benchmarks/bench_disk
#include <benchmark/benchmark.h>

#include <spinslide/contact.hpp>
#include <spinslide/disk.hpp>
#include <spinslide/tabulated.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "ratio_reporter.hpp"

namespace {

template <class Real>
const std::vector<Real>& inputs() {
  static const std::vector<Real> xs = [] {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-3, 3);
    std::vector<Real> v(4096);
    for (auto& x : v) x = static_cast<Real>(std::pow(10.0, u(rng)));
    return v;
  }();
  return xs;
}

// The paper's closed forms (torque corrected, docs/theory.md §3), literally.
template <class Policy>
spinslide::force_torque_result<double> literal(double e, const Policy& pol) {
  using boost::math::ellint_1;
  using boost::math::ellint_2;
  const double pi = boost::math::constants::pi<double>();
  const double k = e <= 1 ? e : 1 / e, m = k * k;
  const double K = ellint_1(k, pol), E = ellint_2(k, pol);
  if (e <= 1)
    return {4 * ((1 + m) * E - (1 - m) * K) / (3 * pi * k),
            4 * ((4 - 2 * m) * E - (1 - m) * K) / (9 * pi)};
  return {4 * ((1 + m) * E - (1 - m) * K) / (3 * pi * m),
          4 * ((4 * m - 2) * E + (1 - m) * (2 - 3 * m) * K) / (9 * pi * k * m)};
}

template <class Real, class F>
void run(benchmark::State& state, F f) {
  const auto& xs = inputs<Real>();
  for (auto _ : state) {
    for (const Real& x : xs) {
      auto r = f(x);
      benchmark::DoNotOptimize(r);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(xs.size()));
}

void literal_boost_default_policy(benchmark::State& s) {
  run<double>(s, [](double e) { return literal(e, boost::math::policies::policy<>()); });
}
void literal_boost_no_promotion(benchmark::State& s) {
  using namespace boost::math::policies;
  run<double>(s, [](double e) { return literal(e, policy<promote_double<false>>()); });
}
void spinslide_force_torque_double(benchmark::State& s) {
  run<double>(s, [](double e) { return spinslide::force_torque(e); });
}
void spinslide_force_plus_torque_double(benchmark::State& s) {
  run<double>(s, [](double e) { return spinslide::force(e) + spinslide::torque(e); });
}
void spinslide_force_torque_float(benchmark::State& s) {
  run<float>(s, [](float e) { return spinslide::force_torque(e); });
}
void spinslide_force_torque_long_double(benchmark::State& s) {
  run<long double>(s, [](long double e) { return spinslide::force_torque(e); });
}
void spinslide_force_torque_cpp_bin_float_50(benchmark::State& s) {
  using mp = boost::multiprecision::cpp_bin_float_50;
  run<mp>(s, [](const mp& e) { return spinslide::force_torque(e); });
}

// The contact law per call, at the same ratios: v = (ε cos φ, ε sin φ), ω = 1, a = 1.
void contact_law_uniform_disk(benchmark::State& s) {
  static const spinslide::contact_law<> law;
  run<double>(s, [](double e) {
    const std::array<double, 2> v = {0.6 * e, 0.8 * e};
    return law(v, 1.0, 1.0, 2.0, 0.5);
  });
}
void contact_law_tabulated_disk(benchmark::State& s) {
  static const spinslide::contact_law<spinslide::tabulated_profile<>> law{
      spinslide::tabulated_profile<>(spinslide::uniform_disk<>())};
  run<double>(s, [](double e) {
    const std::array<double, 2> v = {0.6 * e, 0.8 * e};
    return law(v, 1.0, 1.0, 2.0, 0.5);
  });
}
void tabulated_disk_force_torque(benchmark::State& s) {
  static const spinslide::tabulated_profile<> tab{spinslide::uniform_disk<>()};
  run<double>(s, [](double e) { return tab.force_torque(e); });
}

BENCHMARK(literal_boost_default_policy);
BENCHMARK(literal_boost_no_promotion);
BENCHMARK(spinslide_force_torque_double);
BENCHMARK(spinslide_force_plus_torque_double);
BENCHMARK(spinslide_force_torque_float);
BENCHMARK(spinslide_force_torque_long_double);
BENCHMARK(spinslide_force_torque_cpp_bin_float_50);
BENCHMARK(contact_law_uniform_disk);
BENCHMARK(tabulated_disk_force_torque);
BENCHMARK(contact_law_tabulated_disk);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  spinslide_bench::ratio_reporter reporter(
      "literal_boost_default_policy",
      {{"contact_law_uniform_disk", "spinslide_force_torque_double"},
       {"contact_law_tabulated_disk", "tabulated_disk_force_torque"}});
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
