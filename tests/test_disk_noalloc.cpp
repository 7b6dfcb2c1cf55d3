//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// "No allocation and no exception on valid input": this binary replaces the
// global operator new and counts every call while the disk functions run
// over ε from 1e-300 to 1e300 (every branch: Carlson forms on both sides of
// 1/2 and of 1, the large-ε series) in float, double and long double.
#include <gtest/gtest.h>

#include <spinslide/values/disk.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include "counting_allocator.hpp"

namespace {

template <class Real>
Real sweep() {
  Real sum = 0;
  for (double e = 1e-300; e < 1e300; e *= 1.37) {
    const Real x = static_cast<Real>(e);
    sum += spinslide::force(x) + spinslide::torque(x) + spinslide::force_derivative(x) +
           spinslide::torque_derivative(x) + spinslide::force_torque(x).force;
  }
  for (double e = 0.5; e < 2; e += 1.0 / 64)
    sum += spinslide::force_torque(static_cast<Real>(e)).torque;
  return sum;
}

TEST(NoAllocation, DiskFunctionsNeverAllocate) {
  // Warm up anything lazily initialised (Boost constants) outside the count.
  sweep<float>();
  sweep<double>();
  sweep<long double>();
  const long before = allocations.load();
  const double s = static_cast<double>(sweep<float>()) + sweep<double>() +
                   static_cast<double>(sweep<long double>());
  EXPECT_EQ(allocations.load() - before, 0);
  EXPECT_TRUE(std::isfinite(s));
}

// A tabulated profile allocates when it is built, never when it is called.
TEST(NoAllocation, TabulatedProfileCallsNeverAllocate) {
  const spinslide::tabulated_profile<> tab{spinslide::hertz<>()};
  double sum = tab.force(0.5);
  const long before = allocations.load();
  for (double e = 1e-300; e < 1e300; e *= 1.37) sum += tab.force_torque(e).force + tab.torque(e);
  EXPECT_EQ(allocations.load() - before, 0);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
