//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file equations_of_motion.hpp
/// The equations of motion of a body sliding and spinning on a flat contact,
/// in the paper's dimensionless units and in SI, as odeint systems
/// (sys(x, dxdt, t)), for any profile and inertia ratio γ = I/(mR²).
///
/// Dimensionless units (the paper's): v* = v/(μ√(gR)), ω* = ω√(R/g)/μ,
/// t* = t√(g/R); then distance s = μR s* and angle θ = μ θ*.

#ifndef SPINSLIDE_MOTION_EQUATIONS_OF_MOTION_HPP
#define SPINSLIDE_MOTION_EQUATIONS_OF_MOTION_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/values/profile_concept.hpp>

#include <array>
#include <cmath>
#include <utility>

namespace spinslide {

/// The state the systems below integrate: {v, ω, s, θ} (speed, spin, distance
/// slid, angle turned), dimensionless or SI according to the system.
template <class Real>
using motion_state = std::array<Real, 4>;

/// The paper's equations in dimensionless form, generalised to any profile
/// and γ:  dv*/dt* = −𝓕(ε), dω*/dt* = −𝓣(ε)/γ, ds*/dt* = v*, dθ*/dt* = ω*,
/// ε = v*/ω*.  An odeint system: sys(x, dxdt, t).  Pure sliding (ω* = 0) and
/// pure spinning (v* = 0) are handled exactly; at rest, or if a stepper
/// overshoots below zero, the friction vanishes (the body stays at rest).
/// odeint copies the system it is given on every step; for a profile that
/// holds tables (tabulated_profile, weighted sums of them) pass std::ref(sys),
/// which odeint unwraps (the copy cost bench_dynamics' baseline 100 ms per throw).
template <class Profile>
class dimensionless_motion {
  static_assert(detail::requires_profile<Profile>());
  using Real = typename Profile::value_type;

 public:
  /// The profile's floating-point type.
  using value_type = Real;

  /// The system for `profile` and γ = `inertia_ratio` (finite and > 0,
  /// otherwise std::domain_error).
  dimensionless_motion(Profile profile, Real inertia_ratio)
      : profile_(std::move(profile)),
        gamma_(detail::checked_constructor_argument<typename Profile::policy_type>(
            "spinslide::dimensionless_motion<%1%>::dimensionless_motion(profile, %1%)",
            "inertia_ratio", inertia_ratio, detail::argument_rule::finite_positive)) {}

  /// odeint's system call: x = {v*, ω*, s*, θ*} → dx/dt* =
  /// {−𝓕(ε), −𝓣(ε)/γ, v*, ω*}, ε = v*/ω*; a speed that overshot below 0
  /// counts as 0 (then no friction on it).  Never throws for finite x.
  template <class State, class Time>
  void operator()(const State& x, State& dxdt, Time /*t*/) const {
    const Real v = x[0] > 0 ? Real(x[0]) : Real(0);
    const Real w = x[1] > 0 ? Real(x[1]) : Real(0);
    Real F = 0, T = 0;
    if (v > 0 && w > 0) {
      const auto ft = profile_.force_torque(v / w);
      F = ft.force;
      T = ft.torque;
    } else if (v > 0) {
      F = 1;  // pure sliding
    } else if (w > 0) {
      T = profile_.mean_radius();  // pure spinning
    }
    dxdt[0] = -F;
    dxdt[1] = -T / gamma_;
    dxdt[2] = v;
    dxdt[3] = w;
  }

  /// The profile.
  const Profile& profile() const { return profile_; }
  /// γ.
  Real inertia_ratio() const { return gamma_; }

 private:
  Profile profile_;
  Real gamma_;
};

/// The paper's units for a body of radius R [m] with friction coefficient μ
/// under gravity g [m/s²]: the factors from dimensionless to SI values.
template <class Real>
struct si_units {
  using value_type = Real;    ///< the floating type
  Real radius;                ///< R [m]
  Real friction_coefficient;  ///< μ
  Real gravity;               ///< g [m/s²]

  /// μ√(gR) [m/s per unit v*].
  Real velocity_unit() const { return friction_coefficient * root(gravity * radius); }
  /// μ√(g/R) [rad/s per unit ω*].
  Real spin_unit() const { return friction_coefficient * root(gravity / radius); }
  /// √(R/g) [s per unit t*].
  Real time_unit() const { return root(radius / gravity); }
  /// μR [m per unit s*].
  Real distance_unit() const { return friction_coefficient * radius; }
  /// μ [rad per unit θ*].
  Real angle_unit() const { return friction_coefficient; }

 private:
  static Real root(Real x) {
    BOOST_MATH_STD_USING
    return sqrt(x);
  }
};

/// The same in SI units: dv/dt = −μg𝓕, dω/dt = −μg𝓣/(γR), ds/dt = v, dθ/dt = ω;
/// v in m/s, ω in rad/s, s in m, θ in rad, t in s.  No mass is needed.
template <class Profile>
class si_motion {
  using Real = typename Profile::value_type;

 public:
  /// The profile's floating-point type.
  using value_type = Real;

  /// radius R [m], friction coefficient μ, gravity g [m/s²] (each finite and
  /// > 0), γ = I/(mR²) (as for dimensionless_motion); otherwise std::domain_error.
  si_motion(Profile profile, Real radius, Real friction_coefficient, Real gravity,
            Real inertia_ratio)
      : scaled_(std::move(profile), inertia_ratio),
        units_{positive("radius", radius), positive("friction_coefficient", friction_coefficient),
               positive("gravity", gravity)} {}

  /// odeint's system call: x = {v, ω, s, θ} (SI) → dx/dt =
  /// {−μg𝓕(ε), −μg𝓣(ε)/(γR), v, ω}, ε = v/(Rω).  Never throws for finite x.
  template <class State, class Time>
  void operator()(const State& x, State& dxdt, Time t) const {
    State xs = x;
    xs[0] = x[0] / velocity_unit();
    xs[1] = x[1] / spin_unit();
    State d = dxdt;
    scaled_(xs, d, t);
    const Real mu = units_.friction_coefficient, g = units_.gravity;
    dxdt[0] = d[0] * mu * g;
    dxdt[1] = d[1] * mu * g / units_.radius;
    dxdt[2] = x[0];
    dxdt[3] = x[1];
  }

  /// The units: v = v*·μ√(gR), ω = ω*·μ√(g/R), t = t*·√(R/g), s = s*·μR, θ = θ*·μ.
  const si_units<Real>& units() const { return units_; }
  /// μ√(gR) [m/s per unit v*].
  Real velocity_unit() const { return units_.velocity_unit(); }
  /// μ√(g/R) [rad/s per unit ω*].
  Real spin_unit() const { return units_.spin_unit(); }
  /// √(R/g) [s per unit t*].
  Real time_unit() const { return units_.time_unit(); }
  /// μR [m per unit s*].
  Real distance_unit() const { return units_.distance_unit(); }
  /// μ [rad per unit θ*].
  Real angle_unit() const { return units_.angle_unit(); }
  /// The same motion in the paper's units.
  const dimensionless_motion<Profile>& dimensionless() const { return scaled_; }

 private:
  static Real positive(const char* name, Real x) {
    return detail::checked_constructor_argument<typename Profile::policy_type>(
        "spinslide::si_motion<%1%>::si_motion(profile, %1%, %1%, %1%, %1%)", name, x,
        detail::argument_rule::finite_positive);
  }
  dimensionless_motion<Profile> scaled_;
  si_units<Real> units_;
};

}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_EQUATIONS_OF_MOTION_HPP
