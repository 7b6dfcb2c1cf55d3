//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file throw_inputs.hpp
/// Named inputs of a throw in SI units (simulate_throw_si, dynamics.hpp): the
/// disk's radius, the gravity and the initial speed and spin each have their
/// own type, as the contact laws' inputs do (with the shared
/// friction_coefficient of base/named_inputs.hpp), so that a call cannot swap them:
///
///     spinslide::simulate_throw_si(spinslide::annulus<>(0.125), spinslide::disk_radius{0.06},
///                                  spinslide::friction_coefficient{0.2},
///                                  spinslide::gravity{9.81}, 0.5,
///                                  spinslide::initial_speed{1.0},
///                                  spinslide::initial_spin{20.0});

#ifndef SPINSLIDE_MOTION_THROW_INPUTS_HPP
#define SPINSLIDE_MOTION_THROW_INPUTS_HPP

#include <spinslide/base/named_inputs.hpp>

namespace spinslide {

/// The radius R of the thrown disk's contact (m, > 0).
template <class Real>
struct disk_radius : named_input<disk_radius<Real>, Real> {
  using named_input<disk_radius<Real>, Real>::named_input;
};
/// disk_radius{x} is a disk_radius<double> for a double x.
template <class Real>
disk_radius(Real) -> disk_radius<Real>;
/// The initial speed v0 of a throw (m/s, ≥ 0).
template <class Real>
struct initial_speed : named_input<initial_speed<Real>, Real> {
  using named_input<initial_speed<Real>, Real>::named_input;
};
/// initial_speed{x} is a initial_speed<double> for a double x.
template <class Real>
initial_speed(Real) -> initial_speed<Real>;
/// The initial spin ω0 of a throw (rad/s, ≥ 0).
template <class Real>
struct initial_spin : named_input<initial_spin<Real>, Real> {
  using named_input<initial_spin<Real>, Real>::named_input;
};
/// initial_spin{x} is a initial_spin<double> for a double x.
template <class Real>
initial_spin(Real) -> initial_spin<Real>;

/// The radius of gyration k = √(I/m) of a thrown plate about its vertical
/// axis through the centre of mass (a length in the patch's unit, > 0).
template <class Real>
struct gyration_radius : named_input<gyration_radius<Real>, Real> {
  using named_input<gyration_radius<Real>, Real>::named_input;
};
/// gyration_radius{x} is a gyration_radius<double> for a double x.
template <class Real>
gyration_radius(Real) -> gyration_radius<Real>;

}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_THROW_INPUTS_HPP
