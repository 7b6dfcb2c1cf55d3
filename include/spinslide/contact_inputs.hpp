//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file contact_inputs.hpp
/// Named inputs of the contact laws: the patch radius, the normal load and
/// the friction coefficient each have their own type, so that a call cannot
/// swap them (a radius where a force goes does not compile) and reads plainly:
///
///     spinslide::impulse_contact<double> c{spinslide::patch_radius<double>{0.06},
///                                          spinslide::normal_impulse<double>{p_n},
///                                          spinslide::friction_coefficient<double>{0.2}};
///
/// (Class template argument deduction also allows spinslide::patch_radius{0.06}.)

#ifndef SPINSLIDE_CONTACT_INPUTS_HPP
#define SPINSLIDE_CONTACT_INPUTS_HPP

namespace spinslide {

/// The contact patch's radius a (a length, > 0).
template <class Real>
struct patch_radius {
  /// Explicit, and not an aggregate: a plain number does not convert, not
  /// even by brace elision inside impulse_contact.
  explicit constexpr patch_radius(Real v) : value(v) {}
  Real value;  ///< a
};
/// The normal impulse over the step, Λ = ∫N dt (≥ 0), for the impulse law.
template <class Real>
struct normal_impulse {
  /// Explicit, and not an aggregate: a plain number does not convert, not
  /// even by brace elision inside impulse_contact.
  explicit constexpr normal_impulse(Real v) : value(v) {}
  Real value;  ///< Λ
};
/// The Coulomb friction coefficient μ (≥ 0).
template <class Real>
struct friction_coefficient {
  /// Explicit, and not an aggregate: a plain number does not convert, not
  /// even by brace elision inside impulse_contact.
  explicit constexpr friction_coefficient(Real v) : value(v) {}
  Real value;  ///< μ
};

/// One contact over one time step, for the impulse law (impulse_friction.hpp).
template <class Real>
struct impulse_contact {
  patch_radius<Real> radius;            ///< a
  normal_impulse<Real> normal;          ///< Λ
  friction_coefficient<Real> friction;  ///< μ
};

/// impulse_contact{patch_radius{a}, normal_impulse{p}, friction_coefficient{mu}}.
template <class Real>
impulse_contact(patch_radius<Real>, normal_impulse<Real>, friction_coefficient<Real>)
    -> impulse_contact<Real>;

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_INPUTS_HPP
