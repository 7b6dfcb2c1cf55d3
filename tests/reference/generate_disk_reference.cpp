//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Generates tests/reference/disk_reference.csv: 𝓕, 𝓣, 𝓕' and 𝓣' of the
// uniformly pressed disk, from the paper's DEFINING AREA INTEGRALS, never from
// the elliptic closed forms that spinslide implements.
//
// With e_v = x̂, e_ω = ẑ and ρ² = x² + (y − ε)², the paper's integrals are
//   𝓕(ε) = (1/π) ∬_{x²+y²≤1} (ε − y)/ρ dx dy,
//   𝓣(ε) = (1/π) ∬ (x² + y² − ε y)/ρ dx dy,
// and differentiating under the integral sign,
//   𝓕'(ε) = (1/π) ∬ x²/ρ³ dx dy,   𝓣'(ε) = (1/π) ∬ (−ε x²/ρ³) dx dy = −ε 𝓕'(ε).
// The inner x-integral over |x| ≤ X = √(1 − y²) is elementary (c = y − ε,
// S = √(X² + c²), L = asinh(X/|c|)):
//   ∫ (ε − y)/ρ dx            = −2 c L,
//   ∫ (x² + y² − εy)/ρ dx     = X S + c (y + ε) L,
//   ∫ x²/ρ³ dx                = 2 (L − X/S),
// and the outer y-integral is done by Boost's tanh_sinh in 100-digit
// arithmetic, split at y = ε where L has its logarithmic singularity.
// `--check-2d` also evaluates a few points by nested 2-D tanh_sinh
// quadrature of the raw area integrands (no inner closed form) and checks the
// two agree, and checks 𝓣' = −ε𝓕' against a central difference of 𝓣.
//
// Usage: generate_disk_reference [--check-2d] [--compare FILE] > disk_reference.csv
//        generate_disk_reference --terminal-ratio > terminal_ratio.txt
//   --terminal-ratio  the paper's ε₀, the zero of f(ε) = ε − 𝓕/(2𝓣), with 𝓕
//                     and 𝓣 from the same area integrals, by TOMS 748 in
//                     100-digit arithmetic; prints 60 digits.
//   --compare FILE  recompute every 25th row of FILE and report the largest
//                   relative difference (exit status 1 above 1e-45).
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/asinh.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "csv.hpp"

namespace {

using big = boost::multiprecision::cpp_bin_float_100;
using boost::math::quadrature::tanh_sinh;

struct values {
  big force, torque, force_derivative, torque_derivative;
};

// Tolerance relative to the L1 norm of the integrand; cancellation between
// the integrand's parts costs at most ~ε² = 1e16, leaving > 60 digits.
const big tolerance("1e-80");

// ∫_a^b f, mapped onto [0, 1]: Boost 1.74's tanh_sinh asserts on some
// multiprecision intervals with endpoints away from 0 (its float_next
// bookkeeping), never on [0, 1].
template <class Real, class F>
Real integrate(tanh_sinh<Real>& q, F f, const Real& a, const Real& b, const Real& tol) {
  const Real w = b - a;
  auto g = [&](const Real& s) { return Real(f(a + w * s)); };
  return w * q.integrate(g, Real(0), Real(1), tol);
}

template <class F>
big integrate_y(tanh_sinh<big>& q, F f, const big& eps) {
  // Split at y = ε (inside the disk only for ε < 1): the inner integral has a
  // log singularity there, which tanh_sinh handles best at an endpoint.
  if (eps < 1)
    return integrate(q, f, big(-1), eps, tolerance) + integrate(q, f, eps, big(1), tolerance);
  return integrate(q, f, big(-1), big(1), tolerance);
}

values disk_integrals(tanh_sinh<big>& q, const big& eps) {
  using std::sqrt;
  const big& pi = boost::math::constants::pi<big>();
  auto parts = [eps](const big& y, big& X, big& S, big& c, big& L) {
    X = sqrt((1 - y) * (1 + y));
    c = y - eps;
    S = sqrt(X * X + c * c);
    L = c == 0 ? big(0) : big(boost::math::asinh(X / abs(c)));
  };
  auto f_force = [&](const big& y) {
    big X, S, c, L;
    parts(y, X, S, c, L);
    return big(-2 * c * L);
  };
  auto f_torque = [&](const big& y) {
    big X, S, c, L;
    parts(y, X, S, c, L);
    return big(X * S + c * (y + eps) * L);
  };
  auto f_force_derivative = [&](const big& y) {
    big X, S, c, L;
    parts(y, X, S, c, L);
    if (c == 0) return big(0);  // measure zero; L → ∞ only logarithmically
    return big(2 * (L - X / S));
  };
  values v;
  v.force = integrate_y(q, f_force, eps) / pi;
  v.torque = integrate_y(q, f_torque, eps) / pi;
  v.force_derivative = integrate_y(q, f_force_derivative, eps) / pi;
  v.torque_derivative = -eps * v.force_derivative;
  return v;
}

// Nested 2-D quadrature of the raw area integrands, in 50 digits.
void check_2d(double eps_d) {
  using mid = boost::multiprecision::cpp_bin_float_50;
  const mid eps = eps_d;
  const mid& pi = boost::math::constants::pi<mid>();
  tanh_sinh<mid> outer, inner;
  const mid tol("1e-30");
  auto area = [&](auto integrand) {
    auto over_x = [&](const mid& y) {
      const mid X = sqrt((1 - y) * (1 + y));
      if (X == 0) return mid(0);
      auto g = [&](const mid& x) { return integrand(x, y); };
      // Both integrands are even in x; x = 0 is where ρ is smallest.
      return mid(2 * integrate(inner, g, mid(0), X, tol));
    };
    mid r = eps < 1 ? mid(integrate(outer, over_x, mid(-1), eps, tol) +
                          integrate(outer, over_x, eps, mid(1), tol))
                    : mid(integrate(outer, over_x, mid(-1), mid(1), tol));
    return mid(r / pi);
  };
  auto rho = [&](const mid& x, const mid& y) { return sqrt(x * x + (y - eps) * (y - eps)); };
  const mid F2 = area([&](const mid& x, const mid& y) {
    const mid r = rho(x, y);
    return r == 0 ? mid(0) : mid((eps - y) / r);
  });
  const mid T2 = area([&](const mid& x, const mid& y) {
    const mid r = rho(x, y);
    return r == 0 ? mid(0) : mid((x * x + y * y - eps * y) / r);
  });
  tanh_sinh<big> q;
  const values v = disk_integrals(q, big(eps_d));
  // Central difference of the 𝓣 integral checks 𝓣' = −ε𝓕' (error ~ h²).
  const big h("1e-25");
  const big dT =
      (disk_integrals(q, big(eps_d) + h).torque - disk_integrals(q, big(eps_d) - h).torque) /
      (2 * h);
  const double dF = static_cast<double>(abs((mid(v.force) - F2) / F2));
  const double dT2 = static_cast<double>(abs((mid(v.torque) - T2) / T2));
  const double dD = static_cast<double>(abs((dT - v.torque_derivative) / v.torque_derivative));
  std::fprintf(stderr, "check-2d eps=%-10g |dF/F|=%.1e |dT/T|=%.1e |dT'/T'|(difference)=%.1e\n",
               eps_d, dF, dT2, dD);
  if (dF > 1e-25 || dT2 > 1e-25 || dD > 1e-30) {
    std::fprintf(stderr, "check-2d FAILED at eps=%g\n", eps_d);
    std::exit(1);
  }
}

// The table's ε, all exactly representable in double; `float_exact` marks
// those that are also floats.  Clustered near 1, where K diverges.
struct point {
  double eps;
  bool float_exact;
};

std::vector<point> table_points() {
  std::vector<point> p;
  auto add = [&](double e) {
    const bool fe = static_cast<double>(static_cast<float>(e)) == e;
    p.push_back({e, fe});
  };
  auto add_float = [&](double e) { add(static_cast<double>(static_cast<float>(e))); };
  for (int i = 0; i <= 160; ++i) add_float(std::pow(10.0, -8.0 + i / 10.0));  // 1e-8 … 1e8
  for (int i = 0; i <= 80; ++i) add_float(0.25 * std::pow(16.0, i / 80.0));   // 0.25 … 4
  for (int j = 1; j <= 53; ++j) {
    if (j <= 52) add(1 + std::ldexp(1.0, -j));
    add(1 - std::ldexp(1.0, -j));
  }
  for (int j = 1; j <= 15; ++j) {
    add(1 + std::pow(10.0, -j));
    add(1 - std::pow(10.0, -j));
  }
  for (double e : {0.5, 0.653, 1.0, 2.0, 3.0, 10.0, 0.1, 0.2, 5.0, 1e-3, 1e3}) add(e);
  std::sort(p.begin(), p.end(), [](const point& a, const point& b) { return a.eps < b.eps; });
  p.erase(std::unique(p.begin(), p.end(),
                      [](const point& a, const point& b) { return a.eps == b.eps; }),
          p.end());
  return p;
}

std::string fmt(const big& x) {
  std::ostringstream os;
  os.precision(64);
  os << std::scientific << x;
  return os.str();
}

std::string row(const point& pt, const values& v) {
  char head[128];
  std::snprintf(head, sizeof head, "%a,%.17g,%d", pt.eps, pt.eps, pt.float_exact ? 1 : 0);
  return std::string(head) + "," + fmt(v.force) + "," + fmt(v.torque) + "," +
         fmt(v.force_derivative) + "," + fmt(v.torque_derivative);
}

std::vector<values> compute(const std::vector<point>& pts) {
  std::vector<values> out(pts.size());
  const unsigned n_threads = std::max(1u, std::min(2u, std::thread::hardware_concurrency()));
  std::vector<std::thread> workers;
  for (unsigned t = 0; t < n_threads; ++t) {
    workers.emplace_back([&, t] {
      tanh_sinh<big> q;  // one per thread: the abscissa tables grow lazily
      for (std::size_t i = t; i < pts.size(); i += n_threads) {
        out[i] = disk_integrals(q, big(pts[i].eps));
        if (t == 0) std::fprintf(stderr, "\r%zu / %zu rows", i + 1, pts.size());
      }
    });
  }
  for (auto& w : workers) w.join();
  std::fprintf(stderr, "\n");
  return out;
}

int compare(const char* file) {
  std::vector<std::vector<std::string>> table;
  if (!spinslide_reference::read_csv_rows(file, "eps_hex", table)) return 2;
  std::vector<std::pair<point, values>> rows;
  for (std::size_t n = 0; n < table.size(); n += 25) {
    const std::vector<std::string>& f = table[n];
    point pt{std::strtod(f.at(0).c_str(), nullptr), f.at(2) == "1"};
    rows.push_back({pt, {big(f.at(3)), big(f.at(4)), big(f.at(5)), big(f.at(6))}});
  }
  tanh_sinh<big> q;
  double worst = 0;
  for (const auto& r : rows) {
    const values v = disk_integrals(q, big(r.first.eps));
    for (auto [a, b] : {std::pair<big, big>{v.force, r.second.force},
                        {v.torque, r.second.torque},
                        {v.force_derivative, r.second.force_derivative},
                        {v.torque_derivative, r.second.torque_derivative}}) {
      if (b != 0) worst = std::max(worst, static_cast<double>(abs((a - b) / b)));
    }
  }
  std::printf("compared %zu rows: largest relative difference %.2e\n", rows.size(), worst);
  return worst > 1e-45 ? 1 : 0;
}

int terminal_ratio() {
  tanh_sinh<big> q;
  auto f = [&](const big& e) {
    const values v = disk_integrals(q, e);
    return big(e - v.force / (2 * v.torque));
  };
  boost::uintmax_t iterations = 100;
  // 60 digits: far beyond what the tests need, short of the quadrature's ~64.
  const auto r = boost::math::tools::toms748_solve(
      f, big("0.6"), big("0.7"), boost::math::tools::eps_tolerance<big>(200), iterations);
  std::printf("# the paper's terminal ratio eps0: zero of eps - F/(2T) for the uniform disk,\n");
  std::printf(
      "# F and T from the defining area integrals (generate_disk_reference --terminal-ratio)\n");
  std::printf("%s\n", fmt((r.first + r.second) / 2).c_str());
  std::fprintf(stderr, "toms748: %d iterations, bracket width %s\n", static_cast<int>(iterations),
               fmt(r.second - r.first).c_str());
  return 0;
}

int run(int argc, char** argv) {
  bool do_check = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--check-2d") {
      do_check = true;
    } else if (a == "--terminal-ratio") {
      return terminal_ratio();
    } else if (a == "--compare" && i + 1 < argc) {
      return compare(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: %s [--check-2d] [--compare FILE]\n", argv[0]);
      return 2;
    }
  }
  if (do_check) {
    for (double e : {1e-3, 0.2, 0.653, 0.999, 1.0, 1.001, 3.0, 100.0}) check_2d(e);
  }
  const std::vector<point> pts = table_points();
  const std::vector<values> vals = compute(pts);
  std::printf("# spinslide reference: uniformly pressed disk, from the defining area integrals\n");
  std::printf(
      "# generated by tests/reference/generate_disk_reference.cpp (cpp_bin_float_100, tanh_sinh, "
      "tol 1e-80)\n");
  std::printf(
      "# columns: eps as hex float (exact), eps decimal, float_exact, F, T, dF/deps, dT/deps\n");
  std::printf("eps_hex,eps,float_exact,force,torque,force_derivative,torque_derivative\n");
  for (std::size_t i = 0; i < pts.size(); ++i) std::printf("%s\n", row(pts[i], vals[i]).c_str());
  return 0;
}

}  // namespace

// An exception (a row of the --compare FILE that does not parse, a failed
// quadrature or root finding) is reported with the program's name, and the
// exit status is 2, as for a file that cannot be read.
int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "generate_disk_reference: %s\n", e.what());
    return 2;
  }
}
