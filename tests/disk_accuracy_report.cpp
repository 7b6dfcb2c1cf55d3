//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Prints the largest error of every disk function, in units of epsilon of
// each type, per range of ε, against the reference table.  This is the table
// in docs/accuracy.md:
//   ./build/release/tests/disk_accuracy_report [path/to/disk_reference.csv]
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cstdio>
#include <exception>

#include "reference_table.hpp"

namespace {

template <class Real>
void report(const char* type, const std::vector<spinslide_test::reference_row>& rows) {
  std::printf("\n%s\n\n| function | ", type);
  for (auto rg : spinslide_test::all_ranges) std::printf("%s | ", spinslide_test::name(rg));
  std::printf("\n| --- |");
  for (std::size_t i = 0; i < spinslide_test::all_ranges.size(); ++i) std::printf(" ---: |");
  std::printf("\n");
  for (auto q : spinslide_test::all_quantities) {
    std::printf("| %s |", spinslide_test::name(q));
    for (auto rg : spinslide_test::all_ranges) {
      const auto w = spinslide_test::measure<Real>(rows, q, rg);
      std::printf(" %.2f |", w.error);
    }
    std::printf("\n");
  }
}

// For comparison: the closed forms of docs/theory.md §2 evaluated literally
// in double with Boost's K(k) and E(k) (the ε ≥ 1 torque corrected by ε²).
double literal(spinslide_test::quantity q, double e) {
  using boost::math::ellint_1;
  using boost::math::ellint_2;
  const double pi = boost::math::constants::pi<double>();
  const double k = e <= 1 ? e : 1 / e, m = k * k, K = ellint_1(k), E = ellint_2(k);
  switch (q) {
    case spinslide_test::quantity::force:
      return e <= 1 ? 4 * ((1 + m) * E - (1 - m) * K) / (3 * pi * k)
                    : 4 * ((1 + m) * E - (1 - m) * K) / (3 * pi * m);
    case spinslide_test::quantity::torque:
      return e <= 1 ? 4 * ((4 - 2 * m) * E - (1 - m) * K) / (9 * pi)
                    : 4 * ((4 * m - 2) * E + (1 - m) * (2 - 3 * m) * K) / (9 * pi * k * m);
    case spinslide_test::quantity::force_derivative:
      return e <= 1 ? 4 * ((1 - m) * K - (1 - 2 * m) * E) / (3 * pi * m)
                    : 4 * ((2 - m) * E - 2 * (1 - m) * K) / (3 * pi * k);
    default:
      return 0;
  }
}

void report_literal(const std::vector<spinslide_test::reference_row>& rows) {
  using spinslide_test::quantity;
  std::printf(
      "\nFor comparison, the literal closed forms in double (Boost ellint_1/ellint_2):\n\n");
  std::printf("| function | ");
  for (auto rg : spinslide_test::all_ranges) std::printf("%s | ", spinslide_test::name(rg));
  std::printf("\n| --- |");
  for (std::size_t i = 0; i < spinslide_test::all_ranges.size(); ++i) std::printf(" ---: |");
  std::printf("\n");
  for (quantity q : {quantity::force, quantity::torque, quantity::force_derivative}) {
    std::printf("| %s |", spinslide_test::name(q));
    for (auto rg : spinslide_test::all_ranges) {
      double worst = 0;
      for (const auto& row : rows) {
        if (!spinslide_test::in_range(rg, row.eps) || row.eps == 1) continue;
        const double want =
            spinslide_test::from_string<double>(spinslide_test::reference_value(row, q));
        const double got = literal(q, row.eps);
        worst = std::max(worst, static_cast<double>(boost::math::epsilon_difference(got, want)));
      }
      std::printf(" %.3g |", worst);
    }
    std::printf("\n");
  }
}

int run(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : SPINSLIDE_DISK_REFERENCE;
  const auto rows = spinslide_test::load_disk_reference(path);
  std::printf("Largest error in units of epsilon of each type (boost::math::epsilon_difference)\n");
  std::printf("against %zu reference points from the defining area integrals.\n", rows.size());
  std::printf("float uses only the rows whose eps is exactly a float.\n");
  report<float>("float", rows);
  report<double>("double", rows);
  report<long double>("long double", rows);
  report<boost::multiprecision::cpp_bin_float_50>("cpp_bin_float_50", rows);
  report_literal(rows);
  std::printf(
      "\n(1.8e+308 is epsilon_difference saturating: the literal value has the wrong sign.)\n");
  std::printf("\nliteral torque at eps = 1e6: %.17g (exact: 2.5000000000002083e-07)\n",
              literal(spinslide_test::quantity::torque, 1e6));
  return 0;
}

}  // namespace

// An exception (the table cannot be read, a row does not parse) is reported
// with the program's name, and the exit status is 1.
int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "disk_accuracy_report: %s\n", e.what());
    return 1;
  }
}
