//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// What the parts of bench_disk share (bench_disk.cpp registers the
// benchmarks, in the order they run, and says what they measure): the
// inputs, the scalar loop, and the benchmarks each part defines.
//   bench_disk_methods.cpp     (𝓕, 𝓣) of the uniform disk by the literal
//                              closed form, the AGM, quadrature, a rational
//                              bound and spinslide, and the contact law;
//   bench_disk_projection.cpp  the projection onto the limit set, the impulse
//                              law and the spring-history law, per profile.
#ifndef SPINSLIDE_BENCHMARKS_BENCH_DISK_HPP
#define SPINSLIDE_BENCHMARKS_BENCH_DISK_HPP

#include <benchmark/benchmark.h>

#include <spinslide/values/tabulated.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace spinslide_bench {

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

template <class Real, class F>
void scalar(benchmark::State& state, F f) {
  const auto& xs = inputs<Real>();
  for (auto _ : state) {
    for (const Real& x : xs) {
      auto r = f(x);
      benchmark::DoNotOptimize(r);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(xs.size()));
}

// The tabulated CD annulus (b = 1/8), one of the projection's profiles.
using tabulated_cd = spinslide::tabulated_profile<>;

// bench_disk_methods.cpp
void literal_boost_default_policy(benchmark::State& s);
void literal_boost_no_promotion(benchmark::State& s);
void agm_closed_form(benchmark::State& s);
void boost_tanh_sinh_quadrature(benchmark::State& s);
void rational_8_8_scalar(benchmark::State& s);
void rational_8_8_array(benchmark::State& s);
void spinslide_force_torque_double(benchmark::State& s);
void spinslide_force_plus_torque_double(benchmark::State& s);
void spinslide_batch_double(benchmark::State& s);
void spinslide_force_torque_float(benchmark::State& s);
void spinslide_batch_float(benchmark::State& s);
void spinslide_force_torque_long_double(benchmark::State& s);
void spinslide_force_torque_cpp_bin_float_50(benchmark::State& s);
void contact_law_uniform_disk(benchmark::State& s);
void contact_law_tabulated_disk(benchmark::State& s);
void tabulated_disk_force_torque(benchmark::State& s);
// The largest relative error of each double method over the inputs.
void print_accuracy();

// bench_disk_projection.cpp, for P = spinslide::uniform_disk<>,
// spinslide::hertz<> and tabulated_cd
template <class P>
void profile_force_torque(benchmark::State& s);
template <class P>
void profile_force_torque_chained(benchmark::State& s);
template <class P>
void projection_sliding_warm(benchmark::State& s);
template <class P>
void projection_sliding_from_point(benchmark::State& s);
template <class P>
void projection_sliding_cold(benchmark::State& s);
template <class P>
void projection_sticking_warm(benchmark::State& s);
template <class P>
void impulse_sliding_warm(benchmark::State& s);
template <class P>
void impulse_sliding_from_point(benchmark::State& s);
template <class P>
void impulse_sliding_cold(benchmark::State& s);
template <class P>
void impulse_sticking(benchmark::State& s);
template <class P>
void spring_sliding_warm(benchmark::State& s);
template <class P>
void spring_sticking(benchmark::State& s);

}  // namespace spinslide_bench

#endif  // SPINSLIDE_BENCHMARKS_BENCH_DISK_HPP
