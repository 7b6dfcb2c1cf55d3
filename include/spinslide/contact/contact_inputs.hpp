//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file contact_inputs.hpp
/// Named inputs of the contact laws: the patch radius, the normal load, the
/// friction coefficient, the springs' stiffnesses and the 3-D contact normal
/// each have their own type, so that a call
/// cannot swap them (a radius where a force goes does not compile) and reads plainly:
///
///     spinslide::impulse_contact<double> c{spinslide::patch_radius<double>{0.06},
///                                          spinslide::normal_impulse<double>{p_n},
///                                          spinslide::friction_coefficient<double>{0.2}};
///
/// (Class template argument deduction also allows spinslide::patch_radius{0.06}.)

#ifndef SPINSLIDE_CONTACT_CONTACT_INPUTS_HPP
#define SPINSLIDE_CONTACT_CONTACT_INPUTS_HPP

#include <spinslide/base/named_inputs.hpp>

namespace spinslide {

/// The contact patch's radius a (a length, > 0).
template <class Real>
struct patch_radius : named_input<patch_radius<Real>, Real> {
  using named_input<patch_radius<Real>, Real>::named_input;
};
/// patch_radius{x} is a patch_radius<double> for a double x.
template <class Real>
patch_radius(Real) -> patch_radius<Real>;
/// The normal impulse over the step, Λ = ∫N dt (≥ 0), for the impulse law.
template <class Real>
struct normal_impulse : named_input<normal_impulse<Real>, Real> {
  using named_input<normal_impulse<Real>, Real>::named_input;
};
/// normal_impulse{x} is a normal_impulse<double> for a double x.
template <class Real>
normal_impulse(Real) -> normal_impulse<Real>;
/// The normal force N (≥ 0), for the force-level laws.
template <class Real>
struct normal_force : named_input<normal_force<Real>, Real> {
  using named_input<normal_force<Real>, Real>::named_input;
};
/// normal_force{x} is a normal_force<double> for a double x.
template <class Real>
normal_force(Real) -> normal_force<Real>;
/// The tangential spring's stiffness k_t (force per length, > 0).
template <class Real>
struct tangential_stiffness : named_input<tangential_stiffness<Real>, Real> {
  using named_input<tangential_stiffness<Real>, Real>::named_input;
};
/// tangential_stiffness{x} is a tangential_stiffness<double> for a double x.
template <class Real>
tangential_stiffness(Real) -> tangential_stiffness<Real>;
/// The twisting spring's stiffness k_θ (torque per radian, > 0).
template <class Real>
struct twisting_stiffness : named_input<twisting_stiffness<Real>, Real> {
  using named_input<twisting_stiffness<Real>, Real>::named_input;
};
/// twisting_stiffness{x} is a twisting_stiffness<double> for a double x.
template <class Real>
twisting_stiffness(Real) -> twisting_stiffness<Real>;
/// The regularized contact law's velocity scale v_s (≥ 0, in the caller's
/// velocity unit; about 2μgΔt for a time step Δt): below it the law is
/// scaled down linearly to 0 at rest.
template <class Real>
struct velocity_scale : named_input<velocity_scale<Real>, Real> {
  using named_input<velocity_scale<Real>, Real>::named_input;
};
/// velocity_scale{x} is a velocity_scale<double> for a double x.
template <class Real>
velocity_scale(Real) -> velocity_scale<Real>;

/// The unit contact normal n of the 3-D contact law: a 3-component vector
/// class (operator[] or members x, y, z), of length 1 (the law does not
/// normalize it).  Its own type, so that a call cannot pass the normal where
/// a velocity goes: law(v, w, contact_normal{n}, contact).
template <class Vec3>
struct contact_normal : named_input<contact_normal<Vec3>, Vec3> {
  using named_input<contact_normal<Vec3>, Vec3>::named_input;
};
/// contact_normal{n} is a contact_normal of n's vector type.
template <class Vec3>
contact_normal(Vec3) -> contact_normal<Vec3>;

/// One contact over one time step, for the impulse law (impulse_friction.hpp).
template <class Real>
struct impulse_contact {
  using value_type = Real;              ///< the floating type
  patch_radius<Real> radius;            ///< a
  normal_impulse<Real> normal;          ///< Λ
  friction_coefficient<Real> friction;  ///< μ
};

/// One flat patch's contact over one time step, for its impulse law
/// (patch_impulse.hpp): the patch itself gives the size, so no radius.
template <class Real>
struct patch_impulse_contact {
  using value_type = Real;              ///< the floating type
  normal_impulse<Real> normal;          ///< Λ
  friction_coefficient<Real> friction;  ///< μ
};

/// One flat patch's contact under a normal force, for its trial cap
/// (patch_trial_cap.hpp): the patch itself gives the size, so no radius.
template <class Real>
struct patch_force_contact {
  using value_type = Real;              ///< the floating type
  normal_force<Real> normal;            ///< N
  friction_coefficient<Real> friction;  ///< μ
};

/// One contact under a normal force, for the force-level laws
/// (spring_friction.hpp).
template <class Real>
struct force_contact {
  using value_type = Real;              ///< the floating type
  patch_radius<Real> radius;            ///< a
  normal_force<Real> normal;            ///< N
  friction_coefficient<Real> friction;  ///< μ
};

/// force_contact{patch_radius{a}, normal_force{n}, friction_coefficient{mu}}.
template <class Real>
force_contact(patch_radius<Real>, normal_force<Real>, friction_coefficient<Real>)
    -> force_contact<Real>;

/// The two springs of a spring-history contact.
template <class Real>
struct spring_stiffness {
  using value_type = Real;                ///< the floating type
  tangential_stiffness<Real> tangential;  ///< k_t
  twisting_stiffness<Real> twisting;      ///< k_θ
};

/// spring_stiffness{tangential_stiffness{kt}, twisting_stiffness{kw}}.
template <class Real>
spring_stiffness(tangential_stiffness<Real>, twisting_stiffness<Real>) -> spring_stiffness<Real>;

/// impulse_contact{patch_radius{a}, normal_impulse{p}, friction_coefficient{mu}}.
template <class Real>
impulse_contact(patch_radius<Real>, normal_impulse<Real>, friction_coefficient<Real>)
    -> impulse_contact<Real>;

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_CONTACT_INPUTS_HPP
