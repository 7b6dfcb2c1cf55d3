//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file named_inputs.hpp
/// The named inputs that the values, the motion and the contact share: the
/// friction coefficient μ (a throw's and every contact law's) and the
/// gravity g (a throw's, and the Box2D adapter's table).  Each named input
/// is its own type, so that a swapped call does not compile.

#ifndef SPINSLIDE_BASE_NAMED_INPUTS_HPP
#define SPINSLIDE_BASE_NAMED_INPUTS_HPP

namespace spinslide {

/// The Coulomb friction coefficient μ (≥ 0).
template <class Real>
struct friction_coefficient {
  using value_type = Real;  ///< the floating type
  /// Explicit, and not an aggregate: a plain number does not convert, not
  /// even by brace elision inside impulse_contact.
  explicit constexpr friction_coefficient(Real v) : value(v) {}
  Real value;  ///< μ
};
/// The gravitational acceleration g (m/s², > 0).
template <class Real>
struct gravity {
  using value_type = Real;  ///< the floating type
  /// Explicit, and not an aggregate: a plain number does not convert.
  explicit constexpr gravity(Real v) : value(v) {}
  Real value;  ///< g
};

}  // namespace spinslide

#endif  // SPINSLIDE_BASE_NAMED_INPUTS_HPP
