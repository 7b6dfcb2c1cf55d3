//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The batch API (disk.hpp): pointer and count, and std::span under C++20.
// Built twice by CMake: as C++17 and as C++20 (test_batch_cxx20).
#include <gtest/gtest.h>

#include <spinslide/values/disk.hpp>

#include <cmath>
#include <limits>
#include <vector>

namespace {

std::vector<double> ratios() {
  std::vector<double> e = {0.0, 1e-300, 1e-3, 0.653,
                           1.0, 2.0,    1e8,  std::numeric_limits<double>::infinity()};
  for (double x = 1e-6; x < 1e6; x *= 1.7) e.push_back(x);
  return e;
}

// The batch gives the scalar calls' values; on AVX-512 targets it takes the
// vectorized form (detail::disk_fast_vector), which rounds differently, both
// within 4 ulp of the exact values (test_disk_fast.cpp): so within 8 eps.
template <class Real>
bool close(Real batch, Real scalar) {
  return std::fabs(batch - scalar) <= 8 * std::numeric_limits<Real>::epsilon() * scalar;
}

TEST(Batch, PointerAndCountEqualTheScalarCalls) {
  const auto e = ratios();
  std::vector<double> f(e.size()), t(e.size());
  spinslide::force_torque_batch(e.data(), e.size(), f.data(), t.data());
  for (std::size_t i = 0; i < e.size(); ++i) {
    EXPECT_PRED2(close<double>, f[i], spinslide::force(e[i])) << e[i];
    EXPECT_PRED2(close<double>, t[i], spinslide::torque(e[i])) << e[i];
  }
  std::vector<double> only(e.size());
  spinslide::force_torque_batch(e.data(), e.size(), nullptr, only.data());
  EXPECT_EQ(only, t);
}

TEST(Batch, FloatAndErrors) {
  const std::vector<float> e = {0.1f, 1.0f, 10.0f};
  std::vector<float> f(3), t(3);
  spinslide::force_torque_batch(e.data(), e.size(), f.data(), t.data());
  for (std::size_t i = 0; i < e.size(); ++i)
    EXPECT_PRED2(close<float>, f[i], spinslide::force(e[i]));
  const std::vector<double> bad = {0.5, -1.0};
  std::vector<double> fb(2), tb(2);
  EXPECT_THROW(spinslide::force_torque_batch(bad.data(), bad.size(), fb.data(), tb.data()),
               std::domain_error);
  EXPECT_EQ(fb[0], spinslide::force(0.5));  // written before the bad element
}

#if defined(__cpp_lib_span)
TEST(Batch, SpansUnderCxx20) {
  const auto e = ratios();
  std::vector<double> f(e.size()), t(e.size());
  spinslide::force_torque_batch(std::span<const double>(e), std::span<double>(f),
                                std::span<double>(t));
  for (std::size_t i = 0; i < e.size(); ++i)
    EXPECT_PRED2(close<double>, f[i], spinslide::force(e[i]));
  std::vector<double> short_out(1);
  EXPECT_THROW(spinslide::force_torque_batch(std::span<const double>(e),
                                             std::span<double>(short_out), std::span<double>(t)),
               std::domain_error);
}
#endif

}  // namespace
