//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// "No heap allocation for up to 8 vertices": this binary replaces the global
// operator new and counts every call while flat patches of 3 to 8 vertices
// are built (uniform, linear, no-tension: the clip adds a ninth vertex) and
// their wrenches and dissipations computed (centre inside, outside, far,
// ω = 0), in float and double.  A patch of 10 vertices may allocate, and does
// (the count below proves the counter counts).
#include <gtest/gtest.h>

#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/patch_dissipation.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <array>
#include <cmath>

#include "counting_allocator.hpp"

namespace {

template <class Real, std::size_t N>
std::array<std::array<Real, 2>, N> regular() {
  std::array<std::array<Real, 2>, N> v{};
  for (std::size_t k = 0; k < N; ++k) {
    const double a = 6.283185307179586 * static_cast<double>(k) / static_cast<double>(N);
    v[k] = {static_cast<Real>(0.1 + 0.3 * std::cos(a)), static_cast<Real>(0.2 * std::sin(a))};
  }
  return v;
}

template <class Real, std::size_t N>
Real sweep() {
  using spinslide::centre_of_pressure;
  using spinslide::planar_twist;
  const auto v = regular<Real, N>();
  Real sum = 0;
  for (const auto& centre :
       {std::array<Real, 2>{Real(0.12), Real(0.01)}, std::array<Real, 2>{Real(0.3), Real(0.01)}}) {
    const spinslide::polygon_patch<Real> uniform(v), loaded(v, centre_of_pressure<Real>{centre});
    for (const auto* p : {&uniform, &loaded}) {
      for (const auto& w : {planar_twist<Real>{{Real(0.01), Real(0.02)}, Real(1)},
                            planar_twist<Real>{{Real(0.5), Real(0.1)}, Real(-1)},
                            planar_twist<Real>{{Real(3), Real(0.1)}, Real(0.01)},
                            planar_twist<Real>{{Real(1), Real(0.3)}, Real(0)}}) {
        const auto f = spinslide::friction_wrench(*p, w);
        sum += f.force[0] + f.force[1] + f.torque + spinslide::friction_dissipation(*p, w).value;
      }
    }
  }
  return sum;
}

template <class Real>
Real all_sizes() {
  return sweep<Real, 3>() + sweep<Real, 4>() + sweep<Real, 5>() + sweep<Real, 6>() +
         sweep<Real, 7>() + sweep<Real, 8>();
}

TEST(NoAllocation, PatchesOfUpTo8VerticesNeverAllocate) {
  double s = 0, ten = 0;
  EXPECT_EQ(allocations_of(
                [] { return static_cast<double>(all_sizes<float>()) + all_sizes<double>(); }, s),
            0);
  EXPECT_TRUE(std::isfinite(s));
  // Beyond the inline storage the vertices go to the heap.
  EXPECT_GT(allocations_of([] { return sweep<double, 10>(); }, ten), 0);
  EXPECT_TRUE(std::isfinite(ten));
}

}  // namespace
