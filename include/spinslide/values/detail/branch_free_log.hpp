//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// ln y for finite y ≥ 0 without branches or library calls, so that a loop
// calling it vectorizes (std::log does not, without -ffast-math and a vector
// math library).  Used by the vectorized batch of disk_fast.hpp.
#ifndef SPINSLIDE_VALUES_DETAIL_BRANCH_FREE_LOG_HPP
#define SPINSLIDE_VALUES_DETAIL_BRANCH_FREE_LOG_HPP

#include <cstdint>
#include <cstring>

namespace spinslide {
namespace detail {

// y = 2^e m with m ∈ [√½, √2), ln y = e ln 2 + 2 atanh(z), z = (m − 1)/(m + 1),
// |z| ≤ 0.1716, and 2 atanh z = 2z Σ z^(2j)/(2j + 1) to j = 11 (the next term
// is below 2^−60 relative).  ln 2 is split so that e ln 2 is exact to 2^−80.
// Measured: ≤ 1.8 eps relative on (0, 1] (tests/test_disk_fast.cpp).  Not for
// subnormal y, whose exponent field is 0: ln 0 returns −1023.5 ln 2 ≈ −709.4,
// finite, which is what y² ln y = 0 at y = 0 needs.
inline double branch_free_log(double y) {
  std::uint64_t bits;
  std::memcpy(&bits, &y, sizeof y);
  // The biased exponent as a double without an integer conversion (which
  // SSE2 lacks for 64-bit integers): 2^52 + e_biased has e_biased as its
  // low mantissa bits.
  const std::uint64_t exponent_bits = (bits >> 52) | 0x4330000000000000ull;
  double biased;
  std::memcpy(&biased, &exponent_bits, sizeof biased);
  const std::uint64_t mantissa = (bits & 0x000FFFFFFFFFFFFFull) | 0x3FF0000000000000ull;
  double m;
  std::memcpy(&m, &mantissa, sizeof m);
  const bool high = m > 1.4142135623730951;
  m = high ? m * 0.5 : m;
  const double exponent = (biased - (4503599627370496.0 + 1023)) + (high ? 1.0 : 0.0);
  const double z = (m - 1) / (m + 1), z2 = z * z;
  double s = 1.0 / 23;
  for (int j = 10; j >= 0; --j) s = s * z2 + 1.0 / (2 * j + 1);
  const double ln2_hi = 0.693147180369123816490, ln2_lo = 1.90821492927058770002e-10;
  return exponent * ln2_hi + (2 * z * s + exponent * ln2_lo);
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DETAIL_BRANCH_FREE_LOG_HPP
