//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file dynamics.hpp
/// spinslide's own integration of a throw through the singular stop, with the
/// exact stop time, distance and rotation (docs/theory.md §9).  The equations
/// of motion are in equations_of_motion.hpp, the precomputed throws in
/// tabulated_throw.hpp.
///
/// Dimensionless units (the paper's): v* = v/(μ√(gR)), ω* = ω√(R/g)/μ,
/// t* = t√(g/R); then distance s = μR s* and angle θ = μ θ*.  γ = I/(mR²).

#ifndef SPINSLIDE_MOTION_DYNAMICS_HPP
#define SPINSLIDE_MOTION_DYNAMICS_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/motion/detail/stop_integrator.hpp>
#include <spinslide/motion/equations_of_motion.hpp>
#include <spinslide/motion/motion_types.hpp>
#include <spinslide/motion/terminal.hpp>
#include <spinslide/motion/throw_inputs.hpp>
#include <spinslide/values/profile_concept.hpp>

#include <limits>
#include <vector>

namespace spinslide {

namespace detail {

// A throw's checks (named after the entry point `function`), then its integration.
template <class Profile, class Real, class Observer>
stop_result<Real> checked_throw_to_stop(const char* function, const Profile& profile,
                                        Real inertia_ratio, Real v0, Real omega0,
                                        Observer observer) {
  static_assert(requires_profile<Profile>());
  const auto in = check_throw(function, inertia_ratio, v0, omega0, typename Profile::policy_type());
  if (!in.valid()) {
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    return {nan, nan, nan, {terminal_regime::sliding_and_spinning, nan}};
  }
  const std::vector<Real> none;
  std::vector<motion_sample<Real>> unused;
  return stop_integrator<Profile, Observer>(profile, in, observer, {function, none, unused}).run();
}

}  // namespace detail

/// The throw of a body with `profile` and inertia ratio γ from dimensionless
/// speed v0* and spin ω0* (both ≥ 0): the exact stop time, distance, angle and
/// terminal regime.  `observer(motion_sample)` is called at every adaptive
/// step (dimensionless), and at the stop.  Bad input is a domain error: γ not
/// in [min_value, max_value·epsilon] (2e-308 to 4e292 for double), or a speed
/// that is negative or not finite.
template <class Profile, class Real, class Observer>
stop_result<Real> simulate_throw(const Profile& profile, Real inertia_ratio, Real v0, Real omega0,
                                 Observer observer) {
  return detail::checked_throw_to_stop("spinslide::simulate_throw<%1%>(profile, %1%, %1%, %1%)",
                                       profile, inertia_ratio, v0, omega0, observer);
}

/// The trajectory of a throw sampled at the given times (dimensionless,
/// sorted ascending, ≥ 0); samples at or after the stop are the rest state.
template <class Profile, class Real>
std::vector<motion_sample<Real>> trajectory(const Profile& profile, Real inertia_ratio, Real v0,
                                            Real omega0, const std::vector<Real>& times) {
  static_assert(detail::requires_profile<Profile>());
  using Policy = typename Profile::policy_type;
  static const char* function = "spinslide::trajectory<%1%>(profile, %1%, %1%, %1%, times)";
  const auto in = detail::check_throw(function, inertia_ratio, v0, omega0, Policy());
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!(times[i] >= 0) || (i > 0 && times[i] < times[i - 1]))
      detail::raise_argument_error(function, "a time", ">= 0 and not below the time before it",
                                   times[i], Policy());
  }
  std::vector<motion_sample<Real>> samples;
  if (!in.valid()) {
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    samples.assign(times.size(), motion_sample<Real>{nan, nan, nan, nan, nan, nan});
    return samples;
  }
  samples.reserve(times.size());
  auto ignore = [](const motion_sample<Real>&) {};
  detail::stop_integrator<Profile, decltype(ignore)>(profile, in, ignore,
                                                     {function, times, samples})
      .run();
  return samples;
}

/// simulate_throw without an observer.
template <class Profile, class Real>
stop_result<Real> simulate_throw(const Profile& profile, Real inertia_ratio, Real v0, Real omega0) {
  return simulate_throw(profile, inertia_ratio, v0, omega0, [](const motion_sample<Real>&) {});
}

/// A throw in SI units, its inputs named (throw_inputs.hpp): the disk's
/// radius R [m], friction coefficient μ, gravity g [m/s²], γ = I/(mR²), speed
/// v0 [m/s] and spin ω0 [rad/s] (both ≥ 0).
/// Returns the stop time [s], distance [m] and angle [rad].  Bad input
/// (R, μ, g not finite and > 0, γ as for simulate_throw, negative or NaN
/// speeds) is a domain error.
template <class Profile, class Real>
stop_result<Real> simulate_throw_si(const Profile& profile, disk_radius<Real> radius,
                                    friction_coefficient<Real> mu, gravity<Real> g,
                                    Real inertia_ratio, initial_speed<Real> v0,
                                    initial_spin<Real> omega0) {
  using Policy = typename Profile::policy_type;
  using detail::argument_rule;
  static const char* function =
      "spinslide::simulate_throw_si<%1%>(profile, radius, friction_coefficient, gravity, %1%, "
      "v0, omega0)";
  const si_units<Real> units{
      detail::checked(function, "radius", radius.value, argument_rule::finite_positive, Policy()),
      detail::checked(function, "friction_coefficient", mu.value, argument_rule::finite_positive,
                      Policy()),
      detail::checked(function, "gravity", g.value, argument_rule::finite_positive, Policy())};
  const auto in = detail::check_throw(function, inertia_ratio, v0.value, omega0.value, Policy());
  if (detail::any_reported(units.radius, units.friction_coefficient, units.gravity) ||
      !in.valid()) {
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    return {nan, nan, nan, {terminal_regime::sliding_and_spinning, nan}};
  }
  stop_result<Real> r = simulate_throw(profile, in.gamma, in.v0 / units.velocity_unit(),
                                       in.omega0 / units.spin_unit());
  r.time *= units.time_unit();
  r.distance *= units.distance_unit();
  r.angle *= units.angle_unit();
  return r;
}

/// Dimensionless stop time t* of a throw (v0*, ω0*) for any profile and γ.
template <class Profile, class Real>
Real stop_time(const Profile& profile, Real inertia_ratio, Real v0, Real omega0) {
  return detail::checked_throw_to_stop("spinslide::stop_time<%1%>(profile, %1%, %1%, %1%)", profile,
                                       inertia_ratio, v0, omega0, [](const motion_sample<Real>&) {})
      .time;
}

}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_DYNAMICS_HPP
