//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Cost of one throw's stop time (the paper's disk, γ = 1/2) over 256 throws
// with ε = v0/ω0 log-uniform in [1e-2, 1e2], ω0 = 1:
//   - spinslide::stop_time(v0, ω0): the tabulated throw (after its one-time build);
//   - spinslide::simulate_throw: the integration through the stop in x = −ln ω;
//   - baseline: Boost.Odeint runge_kutta_dopri5 (dense output, 1e-12) on the
//     (v, ω) system of dimensionless_motion, with the stop located as the
//     first zero of v by bisection on the dense output.
// Also prints the baseline's largest relative error against spinslide.
// And many throws at once (batch_throws.hpp), as throws per second on one
// thread against all cores (std::thread::hardware_concurrency()), over the
// same throws: stop_results of the integration (the 256 throws above) and of
// the tabulated throw (65536 throws, ε as above); wall-clock time.
//   ./build/release/benchmarks/bench_dynamics
#include <benchmark/benchmark.h>

#include <spinslide/spinslide.hpp>

#include <boost/numeric/odeint.hpp>

#include <cmath>
#include <cstdio>
#include <random>
#include <thread>
#include <vector>

#include "ratio_reporter.hpp"

namespace {

namespace odeint = boost::numeric::odeint;
using state = spinslide::motion_state<double>;

const std::vector<double>& ratios() {
  static const std::vector<double> xs = [] {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-2, 2);
    std::vector<double> v(256);
    for (auto& x : v) x = std::pow(10.0, u(rng));
    return v;
  }();
  return xs;
}

double odeint_stop_time(double v0, double w0) {
  static const spinslide::dimensionless_motion<spinslide::uniform_disk<>> sys(
      spinslide::uniform_disk<>(), 0.5);
  auto stepper = odeint::make_dense_output(1e-12, 1e-12, odeint::runge_kutta_dopri5<state>());
  state x = {v0, w0, 0, 0};
  stepper.initialize(x, 0.0, 1e-3);
  for (int i = 0; i < 1000000; ++i) {
    stepper.do_step(sys);
    const state& c = stepper.current_state();
    if (c[0] <= 0 || c[1] <= 0) {
      // Event: the first zero of v (or ω) inside the last step, by bisection.
      double lo = stepper.previous_time(), hi = stepper.current_time();
      state y;
      for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
        const double mid = (lo + hi) / 2;
        stepper.calc_state(mid, y);
        (y[0] <= 0 || y[1] <= 0 ? hi : lo) = mid;
      }
      return (lo + hi) / 2;
    }
  }
  return NAN;
}

template <class F>
void throws(benchmark::State& s, F f) {
  const auto& xs = ratios();
  for (auto _ : s) {
    for (double e : xs) {
      double t = f(e, 1.0);
      benchmark::DoNotOptimize(t);
    }
  }
  s.SetItemsProcessed(s.iterations() * static_cast<int64_t>(xs.size()));
}

void stop_time_tabulated(benchmark::State& s) {
  spinslide::stop_time(1.0, 1.0);  // build the table outside the timing
  throws(s, [](double v, double w) { return spinslide::stop_time(v, w); });
}
void simulate_throw_integration(benchmark::State& s) {
  throws(s, [](double v, double w) {
    return spinslide::simulate_throw(spinslide::uniform_disk<>(), 0.5, v, w).time;
  });
}
void odeint_dopri5_event_location(benchmark::State& s) { throws(s, odeint_stop_time); }

const std::vector<spinslide::throw_start<double>>& starts(std::size_t n) {
  static std::vector<spinslide::throw_start<double>> s;
  if (s.size() != n) {
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> u(-2, 2);
    s.clear();
    for (std::size_t i = 0; i < n; ++i) s.push_back({std::pow(10.0, u(rng)), 1.0});
  }
  return s;
}

template <class Batch>
void batch(benchmark::State& s, std::size_t n, unsigned threads, Batch f) {
  const auto& in = starts(n);
  spinslide::batch_options o;
  o.threads = threads;
  for (auto _ : s) {
    auto r = f(in, o);
    benchmark::DoNotOptimize(r.data());
  }
  s.SetItemsProcessed(s.iterations() * static_cast<int64_t>(in.size()));
}

auto integrated = [](const std::vector<spinslide::throw_start<double>>& in,
                     const spinslide::batch_options& o) {
  return spinslide::stop_results(spinslide::uniform_disk<>(), 0.5, in, o);
};
const spinslide::tabulated_throw<spinslide::uniform_disk<>>& disk_table() {
  static const spinslide::tabulated_throw<spinslide::uniform_disk<>> table(
      spinslide::uniform_disk<>(), 0.5);
  return table;
}
auto tabulated = [](const std::vector<spinslide::throw_start<double>>& in,
                    const spinslide::batch_options& o) {
  return spinslide::stop_results(disk_table(), in, o);
};
void batch_integrated_1_thread(benchmark::State& s) { batch(s, 256, 1, integrated); }
void batch_integrated_all_cores(benchmark::State& s) { batch(s, 256, 0, integrated); }
void batch_tabulated_1_thread(benchmark::State& s) { batch(s, 65536, 1, tabulated); }
void batch_tabulated_all_cores(benchmark::State& s) { batch(s, 65536, 0, tabulated); }

BENCHMARK(odeint_dopri5_event_location)->Unit(benchmark::kMicrosecond);
BENCHMARK(simulate_throw_integration)->Unit(benchmark::kMicrosecond);
BENCHMARK(stop_time_tabulated)->Unit(benchmark::kMicrosecond);
BENCHMARK(batch_integrated_1_thread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(batch_integrated_all_cores)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(batch_tabulated_1_thread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(batch_tabulated_all_cores)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  double worst_odeint = 0, worst_table = 0;
  for (double e : ratios()) {
    const double ref = spinslide::simulate_throw(spinslide::uniform_disk<>(), 0.5, e, 1.0).time;
    worst_odeint = std::max(worst_odeint, std::fabs(odeint_stop_time(e, 1.0) / ref - 1));
    worst_table = std::max(worst_table, std::fabs(spinslide::stop_time(e, 1.0) / ref - 1));
  }
  std::printf(
      "largest relative difference from simulate_throw: odeint baseline %.2e, tabulated %.2e\n",
      worst_odeint, worst_table);
  benchmark::Initialize(&argc, argv);
  disk_table();  // built outside the timing
  std::printf("all cores: %u threads (std::thread::hardware_concurrency())\n",
              std::thread::hardware_concurrency());
  spinslide_bench::ratio_reporter reporter(
      "odeint_dopri5_event_location",
      {{"batch_integrated_1_thread/real_time", "batch_integrated_all_cores/real_time"},
       {"batch_tabulated_1_thread/real_time", "batch_tabulated_all_cores/real_time"}});
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
