//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// "No heap allocation for up to 8 points" (contact/contact_patch.hpp): this
// binary replaces the global operator new and counts every call while
// contact patches are built from 1 to 8 engine points (a point, a line, a
// face with a centre inside its kern and one beyond it, repeated points), in
// float and double.  Ten points may allocate, and do (the count below proves
// the counter counts).
#include <gtest/gtest.h>

#include <spinslide/contact/contact_patch.hpp>

#include <array>
#include <cmath>

#include "counting_allocator.hpp"

namespace {

template <class Real, std::size_t N>
Real build_all() {
  using spinslide::contact_point;
  Real sum = 0;
  for (int kind = 0; kind < 4; ++kind) {
    std::array<contact_point<Real>, N> p{};
    for (std::size_t k = 0; k < N; ++k) {
      const double a = 6.283185307179586 * static_cast<double>(k) / static_cast<double>(N);
      const double x = kind == 1 ? 0.2 * static_cast<double>(k) : 0.11 * std::cos(a);
      const double y = kind == 1 ? 0.05 : 0.05 * std::sin(a);
      const double load = kind == 2 ? (k == 0 ? 100.0 : 1.0) : 1.0 + static_cast<double>(k);
      p[k] = {{static_cast<Real>(kind == 3 ? 0.01 : x), static_cast<Real>(kind == 3 ? 0.02 : y)},
              static_cast<Real>(load)};
    }
    const auto patch = spinslide::contact_patch(p);
    sum += patch.centre()[0] + patch.centre()[1];
  }
  return sum;
}

template <class Real>
Real all_sizes() {
  return build_all<Real, 1>() + build_all<Real, 2>() + build_all<Real, 3>() + build_all<Real, 4>() +
         build_all<Real, 5>() + build_all<Real, 6>() + build_all<Real, 7>() + build_all<Real, 8>();
}

TEST(NoAllocation, ContactPatchesOfUpTo8PointsNeverAllocate) {
  double s = 0, ten = 0;
  EXPECT_EQ(allocations_of(
                [] { return static_cast<double>(all_sizes<float>()) + all_sizes<double>(); }, s),
            0);
  EXPECT_TRUE(std::isfinite(s));
  // Beyond the inline storage the vertices go to the heap.
  EXPECT_GT(allocations_of([] { return build_all<double, 10>(); }, ten), 0);
  EXPECT_TRUE(std::isfinite(ten));
}

}  // namespace
