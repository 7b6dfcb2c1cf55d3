//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Generates tests/reference/flow_zeros.csv: every zero of the flow of the
// ratio, f(ε) = ε − γ𝓕(ε)/𝓣(ε), of loads made of thin rings and uniform
// disks, with whether it attracts (f > 0 below, f < 0 above).  Independent
// of spinslide: no elliptic integral and no ring-kernel formula, only the
// defining integrals of the ring (docs/theory.md §1, polar form):
//   𝓕_ring(r, ε) = (1/π) ∫₀^π (ε − r cosθ)/ρ dθ,
//   𝓣_ring(r, ε) = (1/π) ∫₀^π r (r − ε cosθ)/ρ dθ,   ρ² = r² + ε² − 2rε cosθ,
// evaluated in the cancellation-free form (h = sin²(θ/2), d = r − ε)
//   ρ² = d² + 4rεh,  ε − r cosθ = −d + 2rh,  r − ε cosθ = d + 2εh,
// and, for a uniform disk of radius a, the load 2r/a² dr over the rings
// (the r-integral split at r = ε).  Quadrature: Boost tanh_sinh on [0, 1]
// (intervals mapped by hand, as in generate_profile_reference).
//
// The zeros: g = f/ε = 1 − γ𝓕/(ε𝓣) is sampled in double at 20 000 ratios
// spaced evenly in ln ε over [1e-4, 1e3] (a spacing of 0.081 %, far finer
// than the distance between the zeros of these loads), every sign change is
// refined in cpp_bin_float_50 (quadrature to 1e-30) by TOMS 748 to 1e-30, and the signs at the
// ends of the scan are checked against the exact limits g(0) = 1 −
// γ⟨1/r⟩/(2⟨r⟩) and g(∞) = 1 − 2γ/⟨r²⟩ from the loads' moments (so that no
// zero lies outside the scan unless one pair does).  The smallest |g| at a
// sample without a sign change on either side is printed to stderr: a pair
// of zeros closer than the spacing would show there as a tiny value.
//
// Usage: generate_flow_zeros > tests/reference/flow_zeros.csv  (9.5 CPU minutes,
// nearly all in the cpp_bin_float_50 refinement of the disk's nested integral)
// Build: cmake --build --preset release --target generate_flow_zeros
#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <iostream>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

using big = boost::multiprecision::cpp_bin_float_50;

// One piece of a load: a thin ring (disk = false) or a uniform disk of
// radius `radius`, carrying the fraction `weight` of the load.
struct piece {
  double weight;
  double radius;
  bool disk;
};

struct load_case {
  std::string name;
  std::vector<piece> pieces;
  std::vector<double> gammas;
};

template <class T>
T quadrature_tolerance() {
  return std::is_same<T, double>::value ? T(1e-13) : T(1e-30);
}

// ∫₀¹ f(t) dt by tanh_sinh.
template <class T, class F>
T unit_integral(F f) {
  static boost::math::quadrature::tanh_sinh<T> q;
  return q.integrate(f, T(0), T(1), quadrature_tolerance<T>());
}

// Force and torque of a thin ring of radius r at ratio eps (per unit load).
template <class T>
std::pair<T, T> ring(T r, T eps) {
  using boost::multiprecision::sqrt;
  using std::sqrt;
  const T& pi = boost::math::constants::pi<T>();
  const T d = r - eps;
  auto at = [&](T t, bool force) {
    using std::sin;
    using boost::multiprecision::sin;
    const T s = sin(pi * t / 2);
    const T h = s * s;
    const T rho = sqrt(d * d + 4 * r * eps * h);
    if (rho == 0) return T(0);  // the one point θ = 0 at r = ε: measure zero
    return force ? T((-d + 2 * r * h) / rho) : T(r * (d + 2 * eps * h) / rho);
  };
  return {unit_integral<T>([&](T t) { return at(t, true); }),
          unit_integral<T>([&](T t) { return at(t, false); })};
}

// Force and torque of a uniform disk of radius a: ∫₀^a (2r/a²) ring(r) dr.
template <class T>
std::pair<T, T> disk(T a, T eps) {
  std::pair<T, T> total{0, 0};
  auto add = [&](T lo, T hi) {
    for (int which = 0; which < 2; ++which)
      (which == 0 ? total.first : total.second) += unit_integral<T>([&](T t) {
        const T r = lo + (hi - lo) * t;
        const auto ft = ring(r, eps);
        return T((hi - lo) * 2 * r / (a * a) * (which == 0 ? ft.first : ft.second));
      });
  };
  if (eps < a) {
    add(T(0), eps);
    add(eps, a);
  } else {
    add(T(0), a);
  }
  return total;
}

// g(ε) = 1 − γ𝓕/(ε𝓣) of the load.
template <class T>
T flow_g(const load_case& c, T gamma, T eps) {
  T force = 0, torque = 0;
  for (const piece& p : c.pieces) {
    const auto ft = p.disk ? disk(T(p.radius), eps) : ring(T(p.radius), eps);
    force += T(p.weight) * ft.first;
    torque += T(p.weight) * ft.second;
  }
  return 1 - gamma * force / (eps * torque);
}

// The exact limits g(0) and g(∞) from the moments ⟨r⟩, ⟨1/r⟩, ⟨r²⟩.
std::pair<double, double> limits(const load_case& c, double gamma) {
  double mean = 0, inverse = 0, square = 0;
  for (const piece& p : c.pieces) {
    mean += p.weight * (p.disk ? 2 * p.radius / 3 : p.radius);
    inverse += p.weight * (p.disk ? 2 / p.radius : 1 / p.radius);
    square += p.weight * (p.disk ? p.radius * p.radius / 2 : p.radius * p.radius);
  }
  return {1 - gamma * inverse / (2 * mean), 1 - 2 * gamma / square};
}

int run_case(const load_case& c, double gamma) {
  const std::size_t n = 20000;
  const double lo = 1e-4, hi = 1e3;
  std::vector<double> eps(n), g(n);
  for (std::size_t i = 0; i < n; ++i) {
    eps[i] = lo * std::pow(hi / lo, double(i) / double(n - 1));
    g[i] = flow_g<double>(c, gamma, eps[i]);
  }
  const auto lim = limits(c, gamma);
  int failures = 0;
  if ((g.front() > 0) != (lim.first > 0) || (g.back() > 0) != (lim.second > 0)) {
    std::cerr << c.name << " gamma " << gamma << ": the scan's end signs differ from the limits\n";
    ++failures;
  }
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i + 1 < n; ++i)
    if ((g[i - 1] > 0) == (g[i] > 0) && (g[i] > 0) == (g[i + 1] > 0))
      smallest = std::fmin(smallest, std::fabs(g[i]));
  std::cerr << c.name << " gamma " << gamma << ": g(0) = " << lim.first
            << ", g(inf) = " << lim.second << ", smallest |g| away from sign changes " << smallest
            << "\n";
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if ((g[i] > 0) == (g[i + 1] > 0)) continue;
    const big gm = big(gamma);
    auto f = [&](const big& e) { return flow_g<big>(c, gm, e); };
    boost::uintmax_t iters = 200;
    const auto r = boost::math::tools::toms748_solve(
        f, big(eps[i]), big(eps[i + 1]), boost::math::tools::eps_tolerance<big>(100), iters);
    const big zero = (r.first + r.second) / 2;
    std::cout << c.name << "," << gamma << "," << zero.str(30, std::ios_base::scientific) << ","
              << (g[i] > 0 ? 1 : 0) << "\n";
  }
  return failures;
}

}  // namespace

int run() {
  const std::vector<load_case> cases = {
      // The load: 10 % on a ring at r = 0.1, 90 % on the rim.
      {"two_rings", {{0.1, 0.1, false}, {0.9, 1.0, false}}, {0.8, 0.81, 0.826, 0.86}},
      // Three rings, up to four zeros (and ε → 0 attracting).
      {"three_rings",
       {{0.01, 0.01, false}, {0.09, 0.1, false}, {0.9, 1.0, false}},
       {0.5, 0.6, 0.7, 0.82}},
      // A small central disk and the rim.
      {"disk_and_ring", {{0.1, 0.15, true}, {0.9, 1.0, false}}, {0.7, 0.86}},
  };
  std::cout << "# load,gamma,zero,attracting (generate_flow_zeros.cpp)\n";
  int failures = 0;
  for (const auto& c : cases)
    for (double gamma : c.gammas) failures += run_case(c, gamma);
  return failures == 0 ? 0 : 1;
}

int main() {
  try {
    return run();
  } catch (const std::exception& e) {
    std::cerr << "generate_flow_zeros: " << e.what() << "\n";
    return 2;
  }
}
