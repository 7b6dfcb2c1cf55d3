//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Every disk function, in every supported type, against the 64-digit table
// computed from the paper's defining area integrals.
#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <string>
#include <type_traits>

#include "reference_table.hpp"

namespace {

using spinslide_test::all_quantities;
using spinslide_test::all_ranges;
using spinslide_test::quantity;

const std::vector<spinslide_test::reference_row>& rows() {
  static const auto table = spinslide_test::load_disk_reference(SPINSLIDE_DISK_REFERENCE);
  return table;
}

bool is_derivative(quantity q) {
  return q == quantity::force_derivative || q == quantity::torque_derivative;
}

// The budgets: double (and float) 4 ulp for 𝓕, 𝓣 and 16 for the
// derivatives; long double and cpp_bin_float_50 16 ulp for everything.
template <class Real>
double budget(quantity q) {
  if (std::numeric_limits<Real>::digits <= 53) return is_derivative(q) ? 16 : 4;
  return 16;
}

template <class Real>
class DiskReference : public ::testing::Test {};

using Types = ::testing::Types<float, double, long double, boost::multiprecision::cpp_bin_float_50>;
struct TypeNames {
  template <class T>
  static std::string GetName(int) {
    if (std::is_same<T, float>::value) return "float";
    if (std::is_same<T, double>::value) return "double";
    if (std::is_same<T, long double>::value) return "long_double";
    return "cpp_bin_float_50";
  }
};
TYPED_TEST_SUITE(DiskReference, Types, TypeNames);

TYPED_TEST(DiskReference, TableCoversTheRequiredRange) {
  const auto& t = rows();
  ASSERT_GE(t.size(), 300u);
  EXPECT_LE(t.front().eps, 1e-8);
  EXPECT_GE(t.back().eps, 1e8);
  std::size_t near_one = 0;
  for (const auto& r : t) near_one += std::fabs(r.eps - 1) < 1e-3;
  EXPECT_GE(near_one, 60u) << "the table must cluster near eps = 1";
}

TYPED_TEST(DiskReference, EveryFunctionWithinBudgetInEveryRange) {
  using Real = TypeParam;
  for (quantity q : all_quantities) {
    for (auto rg : all_ranges) {
      const auto w = spinslide_test::measure<Real>(rows(), q, rg);
      ASSERT_GT(w.points, 0) << name(q) << " " << name(rg);
      EXPECT_LE(w.error, budget<Real>(q))
          << name(q) << " in " << name(rg) << ": worst " << w.error << " eps at eps = " << w.eps;
      ::testing::Test::RecordProperty(std::string(name(q)) + " " + name(rg),
                                      std::to_string(w.error));
    }
  }
}

}  // namespace
