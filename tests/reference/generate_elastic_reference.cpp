//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Generates tests/reference/elastic_reference.csv: 𝓕(ε), 𝓣(ε) and 𝓕′(ε) of
// the Hertz (p ∝ √(1 − r²)) and Boussinesq (p ∝ 1/√(1 − r²)) pressures on the
// unit disk, by quadrature of the ring kernel over the load, in
// cpp_bin_float_50, with nothing of spinslide's closed forms:
//
//   𝓕(ε) = ∫₀¹ w(r) f_F(r, ε) dr,   𝓣(ε) = ∫₀¹ w(r) f_T(r, ε) dr,
//   r < ε (c = r/ε):  f_F = (2/π) E(c),                  f_T = (2/π) ε [E(c) − (1 − c²)K(c)],
//   r > ε (c = ε/r):  f_F = (2/π) [E(c) − (1 − c²)K(c)]/c, f_T = (2/π) r E(c),
//
// (docs/theory.md (R1)–(R2), themselves checked against the 2-D area
// integrals of tests/reference/profile_reference.csv) with the loads per unit
// radius w = 3r√(1 − r²) (Hertz) and w = r/√(1 − r²) (Boussinesq).  With
// r = sin φ, w dr becomes 3 sin φ cos² φ dφ and sin φ dφ: smooth, so that
// tanh_sinh integrates the rim to full precision.  The φ-range is split at
// r = ε, where the kernel's derivative is log-singular; K and E are Boost's
// ellint_1 and ellint_2.  𝓕′ is the central difference of the quadrature
// with h = min(1e-15·max(ε, 1), 1e-12·|ε − 1|) (𝓕‴ grows as |ε − 1|^(−3/2)
// above 1), and the second-order backward difference at ε = 1 (below which 𝓕
// is a polynomial): truncation errors below 1e-24 relative.
//
// The ε: a log grid 1e-6 … 1e6 (8 per decade), 120 points on [0.9, 3], the
// branch points of the library's evaluation (1, 13/10, 3/2) and their
// neighbours in double (nextafter), √2 (where 2 − ε² = 0) and 1 ± 1e-9.
//
//   ./build/release/tests/generate_elastic_reference > tests/reference/elastic_reference.csv
//   (about 5 minutes on one core; progress on stderr)
#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

using big = boost::multiprecision::cpp_bin_float_50;

struct pair {
  big force, torque;
};

// The ring kernel at radius r, ratio ε.
pair kernel(const big& r, const big& eps) {
  const big& two_div_pi = boost::math::constants::two_div_pi<big>();
  if (r == eps) return {two_div_pi, two_div_pi * eps};
  const bool inside = r < eps;
  const big c = inside ? big(r / eps) : big(eps / r);
  const big K = boost::math::ellint_1(c), E = boost::math::ellint_2(c);
  const big b = E - (1 - c * c) * K;
  if (inside) return {two_div_pi * E, two_div_pi * eps * b};
  return {two_div_pi * b / c, two_div_pi * r * E};
}

// ∫ w(r) (f_F, f_T) dr with r = sin φ over φ ∈ [0, π/2], split at r = ε.
pair integrate(bool hertz, const big& eps) {
  using std::asin;
  using std::cos;
  using std::sin;
  static boost::math::quadrature::tanh_sinh<big> q(12);
  const big& half_pi = boost::math::constants::half_pi<big>();
  const big tol("1e-40");
  auto weight = [hertz](const big& phi) {
    const big c = cos(phi);
    return hertz ? big(3 * sin(phi) * c * c) : big(sin(phi));
  };
  pair total{0, 0};
  auto segment = [&](const big& a, const big& b) {
    // Mapped to t ∈ [0, 1] by hand (tanh_sinh on multiprecision intervals
    // away from 0 can trip an assertion in Boost 1.74).
    auto at = [&](const big& t) { return a + (b - a) * t; };
    auto f = [&](const big& t) {
      const big phi = at(t);
      return weight(phi) * kernel(sin(phi), eps).force;
    };
    auto g = [&](const big& t) {
      const big phi = at(t);
      return weight(phi) * kernel(sin(phi), eps).torque;
    };
    total.force += (b - a) * q.integrate(f, big(0), big(1), tol);
    total.torque += (b - a) * q.integrate(g, big(0), big(1), tol);
  };
  if (eps < 1) {
    const big split = asin(eps);
    segment(big(0), split);
    segment(split, half_pi);
  } else {
    segment(big(0), half_pi);
  }
  return total;
}

std::vector<double> ratios() {
  std::vector<double> e;
  for (int i = -48; i <= 48; ++i) e.push_back(std::pow(10.0, i / 8.0));
  for (int i = 0; i < 120; ++i) e.push_back(0.9 + 2.1 * (i + 0.5) / 120);
  for (double x : {1.0, 1.3, 1.5}) {
    e.push_back(x);
    e.push_back(std::nextafter(x, 0.0));
    e.push_back(std::nextafter(x, 2.0));
  }
  e.push_back(std::sqrt(2.0));
  e.push_back(1 - 1e-9);
  e.push_back(1 + 1e-9);
  return e;
}

// 𝓕′ at ε from the quadrature: central differences with a step small
// against |ε − 1| (𝓕‴ grows as |ε − 1|^(−3/2) above 1); at ε = 1 the
// second-order backward difference (𝓕 is a polynomial below 1).
big derivative(bool hertz, const big& e, const big& f) {
  using std::fabs;
  const big scale = e > 1 ? e : big(1);
  if (e == 1) {
    const big h("1e-15");
    return (3 * f - 4 * integrate(hertz, e - h).force + integrate(hertz, e - 2 * h).force) /
           (2 * h);
  }
  big h = big("1e-15") * scale;
  const big near_one = big("1e-12") * fabs(e - 1);
  if (near_one < h) h = near_one;
  return (integrate(hertz, e + h).force - integrate(hertz, e - h).force) / (2 * h);
}

void print(const char* name, double eps, const pair& v, const big& derivative) {
  std::printf("%s,%a,%s,%s,%s\n", name, eps, v.force.str(45, std::ios_base::scientific).c_str(),
              v.torque.str(45, std::ios_base::scientific).c_str(),
              derivative.str(35, std::ios_base::scientific).c_str());
}

void run() {
  std::printf(
      "# spinslide reference: F(eps), T(eps) and F'(eps) of the Hertz (p ~ sqrt(1-r^2)) and\n"
      "# Boussinesq (p ~ 1/sqrt(1-r^2)) pressures on the unit disk, by tanh_sinh quadrature of\n"
      "# the ring kernel (E, K from Boost ellint_1/ellint_2) over the load, cpp_bin_float_50,\n"
      "# tolerance 1e-40; F' by central difference, h = min(1e-15 max(eps,1), 1e-12 |eps-1|)\n"
      "# (second-order backward difference at eps = 1).\n"
      "# generated by tests/reference/generate_elastic_reference.cpp\n"
      "# columns: profile, eps (exact, hex), F, T, F'\n");
  const auto start = std::chrono::steady_clock::now();
  const std::vector<double> eps = ratios();
  for (int profile = 0; profile < 2; ++profile) {
    const bool hertz = profile == 0;
    for (std::size_t i = 0; i < eps.size(); ++i) {
      const big e = eps[i];
      const pair v = integrate(hertz, e);
      const big d = derivative(hertz, e, v.force);
      print(hertz ? "hertz" : "boussinesq", eps[i], v, d);
      std::fflush(stdout);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "%s %zu/%zu eps=%g (%.0f s)\n", hertz ? "hertz" : "boussinesq", i + 1,
                   eps.size(), eps[i], seconds);
    }
  }
}

}  // namespace

int main() {
  try {
    run();
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "generate_elastic_reference: %s\n", e.what());
    return 2;
  }
}
