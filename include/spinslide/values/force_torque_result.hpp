//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file force_torque_result.hpp
/// What every profile's force_torque(ε) returns: 𝓕(ε) and 𝓣(ε) together.
/// Its own header (issue 28), so that the projections and kernels that only
/// pass it along need not include the disk's closed forms (disk.hpp).

#ifndef SPINSLIDE_VALUES_FORCE_TORQUE_RESULT_HPP
#define SPINSLIDE_VALUES_FORCE_TORQUE_RESULT_HPP

namespace spinslide {

/// 𝓕(ε) and 𝓣(ε) at one ε, as returned by force_torque().
/// `force` is in units of μF_n, `torque` in units of μF_n R.
template <class Real>
struct force_torque_result {
  using value_type = Real;  ///< the floating type
  Real force;               ///< 𝓕(ε), in units of μF_n
  Real torque;              ///< 𝓣(ε), in units of μF_n R
};

}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_FORCE_TORQUE_RESULT_HPP
