//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Cost of one throw's stop, over 256 throws with ε = v0/ω0 log-uniform in
// [1e-2, 1e2], ω0 = 1, γ = 1/2 (Hertz: 0.35, inside its window), for the
// uniform disk, Hertz, Boussinesq and a tabulated profile (the CD annulus,
// b = 1/8):
//   - integration<P>: spinslide::simulate_throw, the panel integration through
//     the stop (docs/theory.md §9), stop time, distance and angle;
//   - odeint_dopri5<P> (the baseline for each profile): Boost.Odeint
//     runge_kutta_dopri5 (dense output, 1e-12) on the (v, ω) system of
//     dimensionless_motion, with the stop located as the first zero of v or ω
//     by bisection on the dense output (the stop time only);
//   - stop_time_tabulated: spinslide::stop_time(v0, ω0), the paper's disk
//     from its tabulated_throw (after the one-time build).
// The ratio lines "odeint_dopri5<P> costs N times integration<P>" are the
// speed-ups.  Also prints each method's largest relative difference from the
// throw reference (tests/reference/throw_reference.csv is the accuracy test;
// here the integration is the reference for the baseline).
// And many throws at once (batch_throws.hpp), as throws per second on one
// thread against all cores (std::thread::hardware_concurrency()), over the
// same throws: stop_results of the integration (the 256 disk throws) and of
// the tabulated throw (65536 throws, ε as above); wall-clock time.
//   ./build/release/benchmarks/bench_dynamics
#include <benchmark/benchmark.h>

#include <spinslide/spinslide.hpp>

#include <boost/numeric/odeint.hpp>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <thread>
#include <utility>
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

struct cd_annulus : spinslide::annulus<> {
  cd_annulus() : spinslide::annulus<>(0.125) {}
};
using tabulated_cd = spinslide::tabulated_profile<>;
template <class P>
const P& profile() {
  static const P p;
  return p;
}
template <>
const tabulated_cd& profile<tabulated_cd>() {
  static const tabulated_cd p{cd_annulus()};
  return p;
}

// γ = 1/2, inside every window but Hertz's, (⟨r²⟩/2, 2⟨r⟩/⟨1/r⟩) = (0.2, 0.5):
// there γ = 1/2 is the edge, where the flow creeps; Hertz is thrown at 0.35.
template <class P>
double gamma_of() {
  return 0.5;
}
template <>
double gamma_of<spinslide::hertz<>>() {
  return 0.35;
}

template <class P>
double odeint_stop_time(double v0, double w0) {
  static const spinslide::dimensionless_motion<P> sys(profile<P>(), gamma_of<P>());
  auto stepper = odeint::make_dense_output(1e-12, 1e-12, odeint::runge_kutta_dopri5<state>());
  state x = {v0, w0, 0, 0};
  stepper.initialize(x, 0.0, 1e-3);
  // odeint takes the system by value on every step: an empty lambda calling the
  // static system keeps a tabulated profile's 45 kB of tables from being
  // copied and freed per step (it made this baseline 100 ms per throw).
  const auto rhs = [](const state& s, state& ds, double t) { sys(s, ds, t); };
  for (int i = 0; i < 1000000; ++i) {
    stepper.do_step(rhs);
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

template <class P>
double integrated_stop_time(double v0, double w0) {
  return spinslide::simulate_throw(profile<P>(), gamma_of<P>(), v0, w0).time;
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
template <class P>
void integration(benchmark::State& s) {
  throws(s, integrated_stop_time<P>);
}
template <class P>
void odeint_dopri5(benchmark::State& s) {
  throws(s, odeint_stop_time<P>);
}

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

#define SPINSLIDE_BENCH_PROFILE(P)                                     \
  BENCHMARK_TEMPLATE(odeint_dopri5, P)->Unit(benchmark::kMicrosecond); \
  BENCHMARK_TEMPLATE(integration, P)->Unit(benchmark::kMicrosecond);
SPINSLIDE_BENCH_PROFILE(spinslide::uniform_disk<>)
SPINSLIDE_BENCH_PROFILE(spinslide::hertz<>)
SPINSLIDE_BENCH_PROFILE(spinslide::boussinesq<>)
SPINSLIDE_BENCH_PROFILE(tabulated_cd)
BENCHMARK(stop_time_tabulated)->Unit(benchmark::kMicrosecond);
BENCHMARK(batch_integrated_1_thread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(batch_integrated_all_cores)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(batch_tabulated_1_thread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(batch_tabulated_all_cores)->Unit(benchmark::kMillisecond)->UseRealTime();

// The largest relative difference of the baseline's stop time from the integration's.
template <class P>
void print_accuracy(const char* name) {
  double worst = 0;
  for (double e : ratios())
    worst = std::max(worst,
                     std::fabs(odeint_stop_time<P>(e, 1.0) / integrated_stop_time<P>(e, 1.0) - 1));
  std::printf("%-12s odeint_dopri5 differs from the integration by up to %.2e\n", name, worst);
}

}  // namespace

int main(int argc, char** argv) {
  print_accuracy<spinslide::uniform_disk<>>("disk");
  print_accuracy<spinslide::hertz<>>("hertz");
  print_accuracy<spinslide::boussinesq<>>("boussinesq");
  print_accuracy<tabulated_cd>("tabulated");
  double worst_table = 0;
  for (double e : ratios())
    worst_table = std::max(worst_table,
                           std::fabs(spinslide::stop_time(e, 1.0) /
                                         integrated_stop_time<spinslide::uniform_disk<>>(e, 1.0) -
                                     1));
  std::printf("tabulated_throw (disk) differs from the integration by up to %.2e\n", worst_table);
  benchmark::Initialize(&argc, argv);
  disk_table();  // built outside the timing
  std::printf("all cores: %u threads (std::thread::hardware_concurrency())\n",
              std::thread::hardware_concurrency());
  const std::string profiles[] = {"spinslide::uniform_disk<>", "spinslide::hertz<>",
                                  "spinslide::boussinesq<>", "tabulated_cd"};
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const auto& p : profiles)
    pairs.emplace_back("odeint_dopri5<" + p + ">", "integration<" + p + ">");
  pairs.emplace_back("batch_integrated_1_thread/real_time", "batch_integrated_all_cores/real_time");
  pairs.emplace_back("batch_tabulated_1_thread/real_time", "batch_tabulated_all_cores/real_time");
  spinslide_bench::ratio_reporter reporter("odeint_dopri5<spinslide::uniform_disk<>>", pairs);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
