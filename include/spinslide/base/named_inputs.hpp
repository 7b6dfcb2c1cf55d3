//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file named_inputs.hpp
/// The one template of every named input, `named_input`, and the named
/// inputs that the values, the motion and the contact share: the friction
/// coefficient μ (a throw's and every contact law's) and the gravity g (a
/// throw's, and the Box2D adapter's table).  Each named input is its own
/// type, so that a swapped call does not compile; the others are declared
/// beside the functions that take them (contact/contact_inputs.hpp,
/// motion/throw_inputs.hpp), each the same three lines:
///
///     template <class Real>
///     struct patch_radius : named_input<patch_radius<Real>, Real> {
///       using named_input<patch_radius<Real>, Real>::named_input;
///     };
///     template <class Real> patch_radius(Real) -> patch_radius<Real>;

#ifndef SPINSLIDE_BASE_NAMED_INPUTS_HPP
#define SPINSLIDE_BASE_NAMED_INPUTS_HPP

namespace spinslide {

/// A number (or vector) `Value` named by the type `Name` that derives from
/// it.  Explicit, and not an aggregate: a plain number does not convert, not
/// even by brace elision inside a struct of named inputs (impulse_contact).
/// The deduction guide beside each name keeps `patch_radius{0.06}`.
template <class Name, class Value>
struct named_input {
  using value_type = Value;  ///< the floating type (contact_normal: the vector type)
  /// The value, named.
  explicit constexpr named_input(Value v) : value(v) {}
  Value value;  ///< the value
};

/// The Coulomb friction coefficient μ (≥ 0).
template <class Real>
struct friction_coefficient : named_input<friction_coefficient<Real>, Real> {
  using named_input<friction_coefficient<Real>, Real>::named_input;
};
/// friction_coefficient{0.2} is a friction_coefficient<double>.
template <class Real>
friction_coefficient(Real) -> friction_coefficient<Real>;

/// The gravitational acceleration g (m/s², > 0).
template <class Real>
struct gravity : named_input<gravity<Real>, Real> {
  using named_input<gravity<Real>, Real>::named_input;
};
/// gravity{9.81} is a gravity<double>.
template <class Real>
gravity(Real) -> gravity<Real>;

}  // namespace spinslide

#endif  // SPINSLIDE_BASE_NAMED_INPUTS_HPP
