//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The friction wrench of flat patches against tests/reference/patch_reference.csv
// (generate_patch_reference.cpp: the defining area integral by polar
// quadrature in cpp_bin_float_50, its own no-tension solve): squares, a sole,
// a triangle, a hexagon, a 200:1 strip; uniform, linear and no-tension
// pressures; instantaneous centres inside, on an edge, on a vertex, outside,
// at 10 to 2e7 sizes and ω = 0; both spin senses.  The error is
// max(|ΔF_x|, |ΔF_y|, |Δτ|/ℓ), ℓ the largest distance of a vertex from the
// origin; bounds: double 1e-13, float 1e-5, long double 1e-16 (64-bit
// mantissa: 1.1e-19 ulp), cpp_bin_float_50 1e-39 on the rows it runs.
#include <gtest/gtest.h>

#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "reference/csv.hpp"
#include "reference/patch_cases.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {

using big = boost::multiprecision::cpp_bin_float_50;

struct row {
  std::string shape, pressure, where;
  double cx, cy, vx, vy, omega;
  big fx, fy, tau;
};

const std::vector<row>& table() {
  static const std::vector<row> rows = [] {
    std::vector<row> out;
    for (const auto& c : spinslide_reference::read_csv_rows(SPINSLIDE_PATCH_REFERENCE, "shape"))
      out.push_back({c[0], c[1], c[4], std::stod(c[2]), std::stod(c[3]), std::stod(c[5]),
                     std::stod(c[6]), std::stod(c[7]), big(c[8]), big(c[9]), big(c[10])});
    return out;
  }();
  return rows;
}

template <class Real>
spinslide::polygon_patch<Real> make_patch(const row& r) {
  std::vector<std::array<Real, 2>> v;
  for (const auto& p : patch_cases::outline(r.shape)) v.push_back({Real(p[0]), Real(p[1])});
  if (r.pressure == "uniform") return spinslide::polygon_patch<Real>(v);
  return spinslide::polygon_patch<Real>(
      v, spinslide::centre_of_pressure<Real>{{Real(r.cx), Real(r.cy)}});
}

/// max(|ΔF_x|, |ΔF_y|, |Δτ|/ℓ) of Real's wrench against the reference.
template <class Real>
big wrench_error(const row& r) {
  const auto patch = make_patch<Real>(r);
  const spinslide::planar_twist<Real> twist{{Real(r.vx), Real(r.vy)}, Real(r.omega)};
  const auto w = spinslide::friction_wrench(patch, twist);
  const big l = big(patch_cases::size(patch_cases::outline(r.shape)));
  const big ex = abs(big(w.force[0]) - r.fx), ey = abs(big(w.force[1]) - r.fy);
  const big et = abs(big(w.torque) - r.tau) / l;
  const big e = std::max(ex, std::max(ey, et));
  return (boost::multiprecision::isfinite)(e) ? e : big(1);
}

/// The worst error of each family (pressure, where) and the worst overall.
template <class Real>
big worst_error(const char* type, double bound) {
  std::map<std::string, big> worst;
  big overall = 0;
  for (const row& r : table()) {
    const big e = wrench_error<Real>(r);
    big& w = worst[r.pressure + "/" + r.where];
    w = std::max(w, e);
    overall = std::max(overall, e);
    EXPECT_LE(e, big(bound)) << type << ' ' << r.shape << ' ' << r.pressure << ' ' << r.where
                             << " omega " << r.omega;
  }
  for (const auto& f : worst)
    std::printf("%-12s %-28s %.2e\n", type, f.first.c_str(), static_cast<double>(f.second));
  return overall;
}

TEST(PatchReference, TableCoversEveryFamily) {
  ASSERT_EQ(table().size(), patch_cases::inputs().size());
  std::map<std::string, int> count;
  for (const row& r : table()) ++count[r.shape + r.pressure];
  EXPECT_EQ(count.size(), 15u);
}

TEST(PatchReference, DoubleWithin1e13) {
  EXPECT_LE(worst_error<double>("double", 1e-13), big(1e-13));
}

TEST(PatchReference, FloatWithin1e5) { EXPECT_LE(worst_error<float>("float", 1e-5), big(1e-5)); }

TEST(PatchReference, LongDoubleWithin1e16) {
  EXPECT_LE(worst_error<long double>("long double", 1e-16), big(1e-16));
}

// cpp_bin_float_50 on a few rows of each kind (the expansion runs to order 85
// near the crossover and a strip is 100 slabs, so not all): the reference's
// 40 digits, to 1e-39.
TEST(PatchReference, BinFloat50OnAFewRows) {
  int n = 0;
  for (const row& r : table()) {
    const bool pick = (r.shape == "square" || r.shape == "triangle" || r.shape == "strip") &&
                      (r.where == "inside" || r.where == "edge" || r.where == "vertex" ||
                       r.where == "rho_4.001" || r.where == "far_1000" ||
                       r.where == "far_20000000" || r.where == "slide") &&
                      r.omega >= 0;
    if (!pick) continue;
    ++n;
    const big e = wrench_error<big>(r);
    EXPECT_LE(e, big(1e-39)) << r.shape << ' ' << r.pressure << ' ' << r.where;
    std::printf("bin_float_50 %-8s %-10s %-12s %.2e\n", r.shape.c_str(), r.pressure.c_str(),
                r.where.c_str(), static_cast<double>(e));
  }
  EXPECT_EQ(n, 63);
}

}  // namespace
