//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// horner_pair: two polynomials with interleaved coefficients evaluated in one
// loop, the evaluation kernel of the disk's fast path (values/detail/disk_fast.hpp)
// and of the runtime tables (values/detail/piecewise_chebyshev.hpp).
#ifndef SPINSLIDE_VALUES_DETAIL_HORNER_HPP
#define SPINSLIDE_VALUES_DETAIL_HORNER_HPP

#include <cstddef>

namespace spinslide {
namespace detail {

// Σ_k c[a + k·stride] x^k and Σ_k c[b + k·stride] x^k, k = 0..Degree: two
// independent Horner chains in one loop, so that their latencies overlap.
// Offsets rather than pointers, so that a loop over many x with a different
// piece each vectorizes (as gathers).  (Estrin's scheme was measured too: no
// faster here, and up to 1.6× the rounding error.)
template <std::size_t Degree, class Real>
inline void horner_pair(const Real* c, std::ptrdiff_t a, std::ptrdiff_t b, std::ptrdiff_t stride,
                        Real x, Real& sa, Real& sb) {
  sa = c[a + std::ptrdiff_t(Degree) * stride];
  sb = c[b + std::ptrdiff_t(Degree) * stride];
  for (std::ptrdiff_t k = std::ptrdiff_t(Degree); k-- > 0;) {
    sa = sa * x + c[a + k * stride];
    sb = sb * x + c[b + k * stride];
  }
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DETAIL_HORNER_HPP
