//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// generate_throw_reference --validate: both routes on synthetic flows with
// exact answers, and the closed forms of throw_reference_loads.cpp against
// the quadrature tables of 𝓕 and 𝓣.
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "csv.hpp"
#include "throw_reference.hpp"

namespace throw_reference {

namespace {

// The closed forms (throw_reference_loads.cpp) against the quadrature tables
// of 𝓕 and 𝓣 beside this file (the disk's area integrals, 64 digits; Hertz's
// and Boussinesq's ring kernel, 40 digits), for 1e-3 ≤ ε ≤ 1e3: the number of
// failures.
int closed_forms_against_tables() {
  std::vector<std::vector<std::string>> disk_rows, elastic_rows;
  if (!spinslide_reference::read_csv_rows(SPINSLIDE_DISK_REFERENCE, "eps_hex", disk_rows) ||
      !spinslide_reference::read_csv_rows(SPINSLIDE_ELASTIC_REFERENCE, "", elastic_rows))
    return 1;
  big worst_disk = 0, worst_elastic = 0;
  auto note = [](big& worst, const ft& v, const std::string& f, const std::string& t) {
    const big d = std::max(abs(v.force / big(f) - 1), abs(v.torque / big(t) - 1));
    if (d > worst) worst = d;
  };
  const double lo = 1e-3, hi = 1e3;
  for (const auto& c : disk_rows) {
    const double e = std::strtod(c.at(0).c_str(), nullptr);
    if (e >= lo && e <= hi) note(worst_disk, disk(big(e)), c.at(3), c.at(4));
  }
  for (const auto& c : elastic_rows) {
    const double e = std::strtod(c.at(1).c_str(), nullptr);
    if (e < lo || e > hi) continue;
    note(worst_elastic, c.at(0) == "hertz" ? hertz(big(e)) : boussinesq(big(e)), c.at(2), c.at(3));
  }
  std::printf("closed forms against disk_reference.csv: largest relative difference %s\n",
              worst_disk.str(3, std::ios_base::scientific).c_str());
  std::printf("closed forms against elastic_reference.csv: largest relative difference %s\n",
              worst_elastic.str(3, std::ios_base::scientific).c_str());
  return (worst_disk < big("1e-45") ? 0 : 1) + (worst_elastic < big("1e-38") ? 0 : 1);
}

}  // namespace

// Synthetic flows with exact answers, both routes.
int validate() {
  int failures = 0;
  auto check = [&](const char* what, const big& got, const big& exact) {
    const big e = rel(got, exact);
    const bool ok = e < big("1e-38");
    failures += ok ? 0 : 1;
    std::printf("%-40s rel. error %s %s\n", what, e.str(3, std::ios_base::scientific).c_str(),
                ok ? "" : "FAIL");
  };
  const big gamma = big(1) / 2, T = synthetic_torque;
  for (const route* r : {&route_a, &route_b}) {
    const char* name = r == &route_b ? "B" : "A";
    std::printf("route %s\n", name);
    for (const char* start : {"0.05", "3", "0.81"}) {
      const big ei(start);
      const result lin = unit_throw(flow{load::linear, gamma}, *r, ei);
      std::printf(" linear flow, eps0 = 4/5, eps_i = %s:\n", start);
      check("  time", lin.time, gamma / T);
      check("  angle", lin.angle, gamma / (2 * T));
      check("  distance", lin.distance,
            gamma / T * (linear_zero / 2 + (ei - linear_zero) / (linear_rate + 2)));
      check("  eps_final", lin.end, linear_zero);
    }
    for (const char* start : {"0.05", "3"}) {
      // 1/𝓣 = Σ (−q)^n e^{−nλx}/T with q = T₁(ε_i − ε₀)/T, integrated term by term.
      const big ei(start), delta = ei - linear_zero, q = -torque_slope * delta / T;
      big t = 0, s = 0, th = 0, term = 1;
      for (int n = 0; abs(term) > big("1e-110"); ++n, term *= q) {
        t += term / (1 + n * linear_rate);
        th += term / (2 + n * linear_rate);
        s += term * (linear_zero / (2 + n * linear_rate) + delta / (2 + (n + 1) * linear_rate));
      }
      const result v = unit_throw(flow{load::linear_torque, gamma}, *r, ei);
      std::printf(" linear flow, torque 7/10 + (eps - 4/5)/10, eps_i = %s:\n", start);
      check("  time", v.time, gamma * t / T);
      check("  angle", v.angle, gamma * th / T);
      check("  distance", v.distance, gamma * s / T);
    }
    for (const char* start : {"0.05", "3", "0.81"}) {
      const big ei(start);
      const result q = unit_throw(flow{load::quadratic, gamma}, *r, ei);
      std::printf(" quadratic flow, eps0 = 4/5, eps_i = %s:\n", start);
      check("  time", q.time, gamma / T);
      check("  angle", q.angle, gamma / (2 * T));
    }
    for (const char* start : {"0.01", "1", "100"}) {
      const big ei(start);
      const result z = unit_throw(flow{load::spin_linear, gamma}, *r, ei);
      std::printf(" flow to pure spinning, kappa = 1/2, eps_i = %s:\n", start);
      check("  time", z.time, gamma / T);
      check("  angle", z.angle, gamma / (2 * T));
      check("  distance", z.distance, gamma / T * ei / (2 + big(1) / 2));
    }
  }
  failures += closed_forms_against_tables();
  std::printf("%d failures\n", failures);
  return failures == 0 ? 0 : 1;
}

}  // namespace throw_reference
