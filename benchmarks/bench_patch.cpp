//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Cost of a flat patch's friction wrench (values/friction_wrench.hpp) for a
// rectangle (the 0.22 × 0.10 sole) over 4096 twists whose ratio
// ε = |v|/(aω), a = 0.11, is log-uniform in [1e-3, 1e3] (the instantaneous
// centre from inside the sole to 1e3 sizes away), in random directions and
// both spin senses: uniform and linear pressure; near centres only (ε in
// [1e-3, 1]: the edge sums), moderate (ε in [5, 50]: the expansion at high
// order), far (ε in [1e2, 1e4]); friction_dissipation over the mixed twists
// (the wrench and the Hessian at once); pure sliding (ω = 0); the no-tension pressure built from
// its centre of pressure (one patch per item); and a tensor Gauss–Legendre quadrature of the same
// wrench with as many points as it needs for 1e-6 and for 1e-10 over a sample of the twists
// (counted at start-up; the counter `points` says how many).  Baseline: the uniform disk's
// spinslide::force_torque over the same ε.
//   ./build/release/benchmarks/bench_patch --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <spinslide/values/disk.hpp>
#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/patch_dissipation.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <boost/math/quadrature/gauss.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "ratio_reporter.hpp"

namespace {

using twist = spinslide::planar_twist<double>;
using point = std::array<double, 2>;

const std::vector<point>& sole() {
  static const std::vector<point> v{{-0.11, -0.05}, {0.11, -0.05}, {0.11, 0.05}, {-0.11, 0.05}};
  return v;
}

struct sample {
  double eps;
  twist w;
};

std::vector<sample> samples(double lo, double hi, bool slide) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(std::log10(lo), std::log10(hi)),
      phi(0, 6.283185307179586);
  std::vector<sample> out(4096);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double eps = std::pow(10.0, u(rng)), a = phi(rng);
    const double omega = slide ? 0.0 : (i % 2 ? 1.0 : -1.0);
    out[i] = {eps, {{eps * 0.11 * std::cos(a), eps * 0.11 * std::sin(a)}, omega}};
  }
  return out;
}

const std::vector<sample>& mixed() {
  static const std::vector<sample> s = samples(1e-3, 1e3, false);
  return s;
}

void disk(benchmark::State& state) {
  const auto& s = mixed();
  for (auto _ : state) {
    for (const auto& x : s) {
      auto r = spinslide::force_torque(x.eps);
      benchmark::DoNotOptimize(r);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(s.size()));
}

void wrenches(benchmark::State& state, const spinslide::polygon_patch<double>& p,
              const std::vector<sample>& s) {
  for (auto _ : state) {
    for (const auto& x : s) {
      auto r = spinslide::friction_wrench(p, x.w);
      benchmark::DoNotOptimize(r);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(s.size()));
}

const spinslide::polygon_patch<double>& uniform_sole() {
  static const spinslide::polygon_patch<double> p(sole());
  return p;
}
const spinslide::polygon_patch<double>& linear_sole() {
  static const spinslide::polygon_patch<double> p(
      sole(), spinslide::centre_of_pressure<double>{{0.015, -0.005}});
  return p;
}

void rectangle_uniform(benchmark::State& state) { wrenches(state, uniform_sole(), mixed()); }
void rectangle_linear(benchmark::State& state) { wrenches(state, linear_sole(), mixed()); }
void rectangle_near(benchmark::State& state) {
  static const std::vector<sample> s = samples(1e-3, 1, false);
  wrenches(state, linear_sole(), s);
}
void rectangle_moderate(benchmark::State& state) {
  static const std::vector<sample> s = samples(5, 50, false);
  wrenches(state, linear_sole(), s);
}
void rectangle_far(benchmark::State& state) {
  static const std::vector<sample> s = samples(1e2, 1e4, false);
  wrenches(state, linear_sole(), s);
}
// friction_dissipation: D, its gradient (the wrench) and its Hessian at once.
void rectangle_dissipation(benchmark::State& state) {
  for (auto _ : state) {
    for (const auto& x : mixed()) {
      auto r = spinslide::friction_dissipation(linear_sole(), x.w);
      benchmark::DoNotOptimize(r);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(mixed().size()));
}
void rectangle_sliding(benchmark::State& state) {
  static const std::vector<sample> s = samples(1, 1, true);
  wrenches(state, linear_sole(), s);
}

// The no-tension pressure from (the sole, a centre beyond the kern).
void no_tension_construction(benchmark::State& state) {
  std::vector<point> centres;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(0.06, 0.1), y(0.015, 0.04);
  for (int i = 0; i < 256; ++i) centres.push_back({x(rng), y(rng)});
  for (auto _ : state) {
    for (const auto& c : centres) {
      spinslide::polygon_patch<double> p(sole(), spinslide::centre_of_pressure<double>{c});
      benchmark::DoNotOptimize(p);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(centres.size()));
}

// The wrench by n × n Gauss–Legendre points on the rectangle (K points per
// panel, n/K panels a side), of the raw integrand −p û, −p x × û.
struct gauss_wrench {
  int panels;
  template <unsigned K>
  std::array<double, 3> at(const spinslide::polygon_patch<double>& p, const twist& w) const {
    using rule = boost::math::quadrature::gauss<double, K>;
    std::array<double, 3> sum{};
    const double hx = 0.22 / panels, hy = 0.10 / panels;
    for (int i = 0; i < panels; ++i) {
      for (int j = 0; j < panels; ++j) {
        const double x0 = -0.11 + (i + 0.5) * hx, y0 = -0.05 + (j + 0.5) * hy;
        auto node = [&](double xi, double wx, double eta, double wy) {
          const double x = x0 + xi * hx / 2, y = y0 + eta * hy / 2;
          const double ux = w.velocity[0] - w.omega * y, uy = w.velocity[1] + w.omega * x;
          const double s = std::hypot(ux, uy);
          if (!(s > 0)) return;
          const double f = p.pressure({x, y}) * wx * wy * hx * hy / 4 / s;
          sum[0] -= f * ux;
          sum[1] -= f * uy;
          sum[2] -= f * (x * uy - y * ux);
        };
        const auto& a = rule::abscissa();
        const auto& wt = rule::weights();
        for (std::size_t k = 0; k < a.size(); ++k)
          for (std::size_t l = 0; l < a.size(); ++l)
            for (int sk : {1, -1})
              for (int sl : {1, -1}) {
                if ((k == 0 && sk < 0 && K % 2) || (l == 0 && sl < 0 && K % 2)) continue;
                node(sk * a[k], wt[k], sl * a[l], wt[l]);
              }
      }
    }
    return sum;
  }
};

// The fewest panels (of 10 × 10 points) whose worst error over 64 of the
// mixed twists is within `tolerance`.
int panels_for(double tolerance) {
  const auto& s = mixed();
  for (int panels = 1; panels <= 512; panels *= 2) {
    double worst = 0;
    for (std::size_t i = 0; i < s.size(); i += s.size() / 64) {
      const auto exact = spinslide::friction_wrench(linear_sole(), s[i].w);
      const auto q = gauss_wrench{panels}.at<10>(linear_sole(), s[i].w);
      worst = std::fmax(worst, std::fmax(std::fabs(q[0] - exact.force[0]),
                                         std::fmax(std::fabs(q[1] - exact.force[1]),
                                                   std::fabs(q[2] - exact.torque) / 0.121)));
    }
    if (worst <= tolerance) return panels;
  }
  return 512;
}

void gauss_quadrature(benchmark::State& state, double tolerance) {
  static std::array<int, 2> found{0, 0};
  int& panels = found[tolerance > 1e-8 ? 0 : 1];
  if (panels == 0) panels = panels_for(tolerance);
  state.counters["points"] = 100.0 * panels * panels;
  const auto& s = mixed();
  const std::size_t stride = 64;  // a sample: the quadrature is slow
  for (auto _ : state) {
    for (std::size_t i = 0; i < s.size(); i += stride) {
      auto r = gauss_wrench{panels}.at<10>(linear_sole(), s[i].w);
      benchmark::DoNotOptimize(r);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(s.size() / stride));
}
void gauss_1e6(benchmark::State& state) { gauss_quadrature(state, 1e-6); }
void gauss_1e10(benchmark::State& state) { gauss_quadrature(state, 1e-10); }

BENCHMARK(disk);
BENCHMARK(rectangle_uniform);
BENCHMARK(rectangle_linear);
BENCHMARK(rectangle_near);
BENCHMARK(rectangle_moderate);
BENCHMARK(rectangle_far);
BENCHMARK(rectangle_dissipation);
BENCHMARK(rectangle_sliding);
BENCHMARK(no_tension_construction);
BENCHMARK(gauss_1e6);
BENCHMARK(gauss_1e10);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  spinslide_bench::ratio_reporter reporter("disk");
  for (const char* name :
       {"rectangle_uniform", "rectangle_linear", "rectangle_near", "rectangle_moderate",
        "rectangle_far", "rectangle_dissipation", "rectangle_sliding", "no_tension_construction",
        "gauss_1e6", "gauss_1e10"})
    reporter.add_comparison(name, "disk");
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
