//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Prints the largest error of every disk function, in units of epsilon of
// each type, per range of ε, against the reference table.  This is the table
// in docs/accuracy.md:
//   ./build/release/tests/disk_accuracy_report [path/to/disk_reference.csv]
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cstdio>

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

}  // namespace

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : SPINSLIDE_DISK_REFERENCE;
  const auto rows = spinslide_test::load_disk_reference(path);
  std::printf("Largest error in units of epsilon of each type (boost::math::epsilon_difference)\n");
  std::printf("against %zu reference points from the defining area integrals.\n", rows.size());
  std::printf("float uses only the rows whose eps is exactly a float.\n");
  report<float>("float", rows);
  report<double>("double", rows);
  report<long double>("long double", rows);
  report<boost::multiprecision::cpp_bin_float_50>("cpp_bin_float_50", rows);
  return 0;
}
