//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Cost of one (𝓕, 𝓣) pair of the uniform disk over 4096 log-uniform ε in
// [1e-3, 1e3], against, in the same binary:
//   - the literal closed form with Boost's ellint_1/ellint_2, default policy
//     (double promoted to long double): the baseline;
//   - the same with promote_double<false>;
//   - K and E together by the arithmetic-geometric mean, then the closed form;
//   - Boost's tanh_sinh quadrature of the defining integral (inner integral
//     in closed form, as in tests/reference/generate_disk_reference.cpp);
//   - a degree-8/8 rational for each of 𝓕 and 𝓣: a speed bound, not a
//     method (its accuracy is printed; it cannot follow the ε = 1 singularity).
// And the projection onto the limit set (limit_set.hpp) of the uniform disk,
// Hertz and a tabulated profile (the CD annulus, b = 1/8), against that
// profile's force_torque at the same ratios:
//   - sliding: P = C(ε) + 0.2 (ε, 1) (w = 1), which projects to C(ε); "warm"
//     starts from ε(1 + 1e-3) (a contact whose ratio moved 0.1 % since the
//     last step), "cold" from no guess;
//   - sticking: P = θ C(ε), θ uniform in [0.5, 0.99] (inside L, most of them
//     outside the triangle that decides without an evaluation), warm.
// "scalar" benchmarks hand each result to benchmark::DoNotOptimize, which
// keeps the loop scalar; "array" benchmarks write output arrays in a plain
// loop, which the compiler may vectorize.
//   ./build/release/benchmarks/bench_disk
//
// The program's parts: bench_disk.hpp (what they share),
// bench_disk_methods.cpp (the disk's methods and the contact law),
// bench_disk_projection.cpp (the projection, impulse and spring laws), and
// this file (the benchmarks, registered in the order they run, and main).
#include <benchmark/benchmark.h>

#include <spinslide/values/profile.hpp>

#include <string>

#include "bench_disk.hpp"
#include "ratio_reporter.hpp"

namespace {

using spinslide_bench::agm_closed_form;
using spinslide_bench::boost_tanh_sinh_quadrature;
using spinslide_bench::contact_law_tabulated_disk;
using spinslide_bench::contact_law_uniform_disk;
using spinslide_bench::impulse_sliding_cold;
using spinslide_bench::impulse_sliding_from_point;
using spinslide_bench::impulse_sliding_warm;
using spinslide_bench::impulse_sticking;
using spinslide_bench::literal_boost_default_policy;
using spinslide_bench::literal_boost_no_promotion;
using spinslide_bench::print_accuracy;
using spinslide_bench::profile_force_torque;
using spinslide_bench::profile_force_torque_chained;
using spinslide_bench::projection_sliding_cold;
using spinslide_bench::projection_sliding_from_point;
using spinslide_bench::projection_sliding_warm;
using spinslide_bench::projection_sticking_warm;
using spinslide_bench::rational_8_8_array;
using spinslide_bench::rational_8_8_scalar;
using spinslide_bench::spinslide_batch_double;
using spinslide_bench::spinslide_batch_float;
using spinslide_bench::spinslide_force_plus_torque_double;
using spinslide_bench::spinslide_force_torque_cpp_bin_float_50;
using spinslide_bench::spinslide_force_torque_double;
using spinslide_bench::spinslide_force_torque_float;
using spinslide_bench::spinslide_force_torque_long_double;
using spinslide_bench::spring_sliding_warm;
using spinslide_bench::spring_sticking;
using spinslide_bench::tabulated_cd;
using spinslide_bench::tabulated_disk_force_torque;

#define SPINSLIDE_BENCH_PROJECTION(P)                   \
  BENCHMARK_TEMPLATE(profile_force_torque, P);          \
  BENCHMARK_TEMPLATE(profile_force_torque_chained, P);  \
  BENCHMARK_TEMPLATE(projection_sliding_warm, P);       \
  BENCHMARK_TEMPLATE(projection_sliding_from_point, P); \
  BENCHMARK_TEMPLATE(projection_sliding_cold, P);       \
  BENCHMARK_TEMPLATE(projection_sticking_warm, P);      \
  BENCHMARK_TEMPLATE(impulse_sliding_warm, P);          \
  BENCHMARK_TEMPLATE(impulse_sliding_from_point, P);    \
  BENCHMARK_TEMPLATE(impulse_sliding_cold, P);          \
  BENCHMARK_TEMPLATE(impulse_sticking, P);              \
  BENCHMARK_TEMPLATE(spring_sliding_warm, P);           \
  BENCHMARK_TEMPLATE(spring_sticking, P);
SPINSLIDE_BENCH_PROJECTION(spinslide::uniform_disk<>)
SPINSLIDE_BENCH_PROJECTION(spinslide::hertz<>)
SPINSLIDE_BENCH_PROJECTION(tabulated_cd)

BENCHMARK(literal_boost_default_policy);
BENCHMARK(literal_boost_no_promotion);
BENCHMARK(agm_closed_form);
BENCHMARK(boost_tanh_sinh_quadrature);
BENCHMARK(rational_8_8_scalar);
BENCHMARK(rational_8_8_array);
BENCHMARK(spinslide_force_torque_double);
BENCHMARK(spinslide_batch_double);
BENCHMARK(spinslide_force_plus_torque_double);
BENCHMARK(spinslide_force_torque_float);
BENCHMARK(spinslide_batch_float);
BENCHMARK(spinslide_force_torque_long_double);
BENCHMARK(spinslide_force_torque_cpp_bin_float_50);
BENCHMARK(contact_law_uniform_disk);
BENCHMARK(tabulated_disk_force_torque);
BENCHMARK(contact_law_tabulated_disk);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  print_accuracy();
  spinslide_bench::ratio_reporter reporter(
      "literal_boost_default_policy",
      {{"spinslide_force_torque_double", "rational_8_8_scalar"},
       {"spinslide_batch_double", "rational_8_8_array"},
       {"spinslide_force_torque_float", "rational_8_8_scalar"},
       {"spinslide_batch_float", "rational_8_8_array"},
       {"contact_law_uniform_disk", "spinslide_force_torque_double"},
       {"contact_law_tabulated_disk", "tabulated_disk_force_torque"}});
  for (const char* p : {"spinslide::uniform_disk<>", "spinslide::hertz<>", "tabulated_cd"}) {
    const std::string base = std::string("profile_force_torque<") + p + ">";
    const std::string chained = std::string("profile_force_torque_chained<") + p + ">";
    for (const char* kind :
         {"projection_sliding_warm", "projection_sliding_from_point", "projection_sliding_cold",
          "projection_sticking_warm", "impulse_sliding_warm", "impulse_sliding_from_point",
          "impulse_sliding_cold", "impulse_sticking", "spring_sliding_warm", "spring_sticking"}) {
      reporter.add_comparison(std::string(kind) + "<" + p + ">", base);
      reporter.add_comparison(std::string(kind) + "<" + p + ">", chained);
    }
    reporter.add_comparison(std::string("projection_sliding_from_point<") + p + ">",
                            std::string("projection_sliding_warm<") + p + ">");
  }
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
