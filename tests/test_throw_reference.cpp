//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// simulate_throw, stop_time and trajectory against tests/reference/throw_reference.csv:
// stop time, distance and angle of throws of the uniform disk, Hertz,
// Boussinesq and a two-attractor load (3/4 on the rim, 1/4 a disk of radius
// 1/8 at the centre), computed by nested quadrature in the ratio at 100 digits
// (tests/reference/generate_throw_reference.cpp, which links nothing of
// spinslide; docs/accuracy.md).  The bound, 1e-12 relative, is the accuracy
// issue 16 asks of the integrator; the largest errors are printed.
#include <gtest/gtest.h>

#include <spinslide/motion/dynamics.hpp>
#include <spinslide/motion/tabulated_throw.hpp>
#include <spinslide/motion/terminal_state.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "reference/csv.hpp"

#ifndef SPINSLIDE_THROW_REFERENCE
#error "SPINSLIDE_THROW_REFERENCE must name tests/reference/throw_reference.csv"
#endif

namespace {

using namespace spinslide;
using big = boost::multiprecision::cpp_bin_float_50;

struct throw_row {
  std::string profile;
  double gamma, v0, omega0;
  big eps_final, time, distance, angle;
};

const std::vector<throw_row>& throw_reference() {
  static const std::vector<throw_row> rows = [] {
    std::vector<throw_row> r;
    for (const auto& c : spinslide_reference::read_csv_rows(SPINSLIDE_THROW_REFERENCE, "profile"))
      r.push_back({c.at(0), std::strtod(c.at(1).c_str(), nullptr),
                   std::strtod(c.at(2).c_str(), nullptr), std::strtod(c.at(3).c_str(), nullptr),
                   big(c.at(5)), big(c.at(6)), big(c.at(7)), big(c.at(8))});
    return r;
  }();
  return rows;
}

double relative_error(double computed, const big& exact) {
  return exact == 0 ? std::fabs(computed) : static_cast<double>(abs(big(computed) / exact - 1));
}

struct worst {
  double time = 0, distance = 0, angle = 0, ratio = 0, stop_time = 0, at_rest = 0;
  std::string where;  // the row of the largest error of any quantity
  double largest = 0;
  void note(double& slot, double e, const throw_row& row) {
    slot = std::max(slot, e);
    if (e > largest) {
      largest = e;
      char buf[160];
      std::snprintf(buf, sizeof buf, "%s gamma=%g eps_i=%.17g", row.profile.c_str(), row.gamma,
                    row.v0 / row.omega0);
      where = buf;
    }
  }
};

// The library's profile of a row, passed to `use`.
template <class Real, class Use>
void with_profile(const std::string& name, Use use) {
  if (name == "uniform_disk") return use(uniform_disk<Real>());
  if (name == "hertz") return use(hertz<Real>());
  if (name == "boussinesq") return use(boussinesq<Real>());
  if (name == "cd_annulus") return use(annulus<Real>(Real(1) / 8));
  ASSERT_EQ(name, "ring_and_core");
  use(weighted_sum({Real(0.75), Real(0.25)}, ring<Real>(),
                   scaled<uniform_disk<Real>>(uniform_disk<Real>(), Real(0.125))));
}

// The largest errors over the table and for each (profile, γ).
struct measured {
  worst all;
  std::map<std::string, worst> by_family;
};

// One row's errors, noted in each of `into`.
template <class Real, class Profile>
void measure_row(const Profile& p, const throw_row& row, const std::string& family,
                 const std::vector<worst*>& into) {
  const Real g = row.gamma, v0 = row.v0, w0 = row.omega0;
  const auto r = simulate_throw(p, g, v0, w0);
  const double t = relative_error(static_cast<double>(r.time), row.time);
  const double s = relative_error(static_cast<double>(r.distance), row.distance);
  const double a = relative_error(static_cast<double>(r.angle), row.angle);
  const double st = relative_error(static_cast<double>(stop_time(p, g, v0, w0)), row.time);
  // The trajectory's rest state, sampled after the stop.
  const std::vector<Real> after{static_cast<Real>(2 * row.time)};
  const auto m = trajectory(p, g, v0, w0, after).at(0);
  EXPECT_EQ(m.speed, 0) << family;
  EXPECT_EQ(m.spin, 0) << family;
  const double rest = std::max(relative_error(static_cast<double>(m.distance), row.distance),
                               relative_error(static_cast<double>(m.angle), row.angle));
  const bool spinning = row.eps_final == 0;
  EXPECT_EQ(r.terminal.regime,
            spinning ? terminal_regime::pure_spinning : terminal_regime::sliding_and_spinning)
      << family;
  const double ratio =
      spinning ? 0 : relative_error(static_cast<double>(r.terminal.ratio), row.eps_final);
  for (worst* w : into) {
    w->note(w->time, t, row);
    w->note(w->distance, s, row);
    w->note(w->angle, a, row);
    w->note(w->stop_time, st, row);
    w->note(w->at_rest, rest, row);
    w->ratio = std::max(w->ratio, ratio);
  }
}

template <class Real>
measured measure(bool closed_forms_only = false) {
  measured out;
  const auto& rows = throw_reference();
  EXPECT_GE(rows.size(), 80U);
  for (const throw_row& row : rows) {
    if (closed_forms_only && (row.profile == "ring_and_core" || row.profile == "cd_annulus"))
      continue;
    char family[80];
    std::snprintf(family, sizeof family, "%s gamma=%g", row.profile.c_str(), row.gamma);
    const std::vector<worst*> into{&out.all, &out.by_family[family]};
    with_profile<Real>(row.profile,
                       [&](const auto& p) { measure_row<Real>(p, row, family, into); });
  }
  return out;
}

void report(const char* type, const measured& m) {
  const worst& w = m.all;
  std::printf(
      "%s, largest relative errors against throw_reference.csv: time %.2e, distance %.2e, "
      "angle %.2e, stop_time %.2e, trajectory at rest %.2e, terminal ratio %.2e (largest at %s)\n",
      type, w.time, w.distance, w.angle, w.stop_time, w.at_rest, w.ratio, w.where.c_str());
  for (const auto& [family, f] : m.by_family)
    std::printf("  %-28s time %.2e, distance %.2e, angle %.2e\n", family.c_str(), f.time,
                f.distance, f.angle);
}

void expect_within(const measured& m, double bound) {
  const worst& w = m.all;
  EXPECT_LE(w.time, bound);
  EXPECT_LE(w.distance, bound);
  EXPECT_LE(w.angle, bound);
  EXPECT_LE(w.stop_time, bound);
  EXPECT_LE(w.at_rest, bound);
  EXPECT_LE(w.ratio, 1e-14);  // terminal_motion, a root in the evaluation type
}

TEST(ThrowReference, TableReachesBothAttractors) {
  const auto& rows = throw_reference();
  std::size_t spinning = 0;
  for (const throw_row& row : rows) {
    ASSERT_GT(row.time, 0) << row.profile;
    ASSERT_GT(row.angle, 0) << row.profile;
    if (row.eps_final == 0) ++spinning;
  }
  EXPECT_GE(spinning, 1U) << "the two-attractor load reaches pure spinning from small ratios";
}

TEST(ThrowReference, DoubleWithin1e12) {
  const measured w = measure<double>();
  report("double", w);
  expect_within(w, 1e-12);
}

TEST(ThrowReference, LongDoubleWithin1e12) {
  const measured w = measure<long double>();
  report("long double", w);
  expect_within(w, 1e-12);
}

// A tabulated profile (the CD annulus, whose table is singular at ε = 1/8 and
// 1, the breakpoints it keeps from its source) against the annulus' rows: the
// table's own error (a few 1e-15) and the integration's.
TEST(ThrowReference, TabulatedAnnulusWithin1e12) {
  const tabulated_profile<> table{annulus<>(0.125)};
  measured m;
  std::size_t rows = 0;
  for (const throw_row& row : throw_reference()) {
    if (row.profile != "cd_annulus") continue;
    ++rows;
    const std::vector<worst*> into{&m.all, &m.by_family["tabulated cd_annulus"]};
    measure_row<double>(table, row, "tabulated cd_annulus", into);
  }
  report("tabulated CD annulus", m);
  EXPECT_GE(rows, 10U) << "the table's cd_annulus rows";
  expect_within(m, 1e-12);
}

// The integration runs in double whatever the profile's type (docs/theory.md
// §9), so a cpp_bin_float_50 profile gives double accuracy.  The rows of the
// closed-form profiles only: the ring's elliptic integrals at 50 digits would
// make this test take minutes.
TEST(ThrowReference, MultiprecisionWithin1e12) {
  const measured w = measure<big>(true);
  report("cpp_bin_float_50", w);
  expect_within(w, 1e-12);
}

}  // namespace
