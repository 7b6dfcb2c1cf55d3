//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)

/// \file pair_friction.hpp
/// One coupled pair of bodies, engine-independent (docs/engines.md): its
/// friction settings (the patch's pressure profile, how its radius is found,
/// μ) and the impulse over one step, with the last step's curve point kept
/// to start the next step's search.  An engine adapter
/// (engines/mujoco.hpp, engines/bullet.hpp, engines/box2d.hpp) gathers what
/// its engine knows (the relative motion before friction, the effective
/// inverse mass, the normal impulse, the penetration), applies the impulse
/// this returns and reports it as a pair_report (pair_report.hpp).  In the
/// core: built and tested without any engine.
#ifndef SPINSLIDE_CONTACT_PAIR_FRICTION_HPP
#define SPINSLIDE_CONTACT_PAIR_FRICTION_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/contact/contact_inputs.hpp>
#include <spinslide/contact/impulse_friction.hpp>
#include <spinslide/contact/planar_metric.hpp>
#include <spinslide/values/profile.hpp>

#include <array>
#include <cmath>
#include <variant>

namespace spinslide {

/// The pressure profiles an adapter's pair can have: a flat face on a flat
/// face (uniform pressure), a sphere (Hertz), a rim (an annulus; its inner
/// radius ratio is the profile's).
using patch_profile = std::variant<uniform_disk<double>, hertz<double>, annulus<double>>;

/// The patch radius of a curved contact from the engine's penetration depth δ:
/// Hertz's a = √(R*δ), with R* = R₁R₂/(R₁ + R₂) the effective radius (a
/// sphere on a plane: R* = R), and never below a minimum (by default 0: a
/// grazing contact, δ → 0, is point friction, to which the law tends as the
/// patch grows from nothing).  δ is the engine's, set by its contact
/// softness (MuJoCo's solref/solimp: δ = 0.37 mm for a resting billiard
/// ball) or by its solver's residual overlap (Bullet: about 1e-11 m), not by
/// the materials' elasticity.  Where δ means little, set the minimum to the
/// material's Hertz radius (3NR*/(4E*))^(1/3), or give a fixed patch_radius.
struct hertz_radius {
  /// R* [m] (finite, > 0; checked by pair_friction), no minimum radius.
  explicit constexpr hertz_radius(double effective_radius) : value(effective_radius), minimum(0) {}
  /// R* [m], and the smallest radius `least` (finite, ≥ 0).
  constexpr hertz_radius(double effective_radius, patch_radius<double> least)
      : value(effective_radius), minimum(least.value) {}
  double value;    ///< R*
  double minimum;  ///< the smallest a
};

/// One coupled pair's friction: the patch profile, its radius (fixed, or from
/// the penetration by hertz_radius) and μ.  It keeps the pair's ratio ε from
/// the last step to start the next step's search.
class pair_friction {
 public:
  /// A patch of fixed radius a: `profile` scaled to a, with friction
  /// coefficient μ.  a finite and ≥ 0 (0: point friction), μ finite and ≥
  /// 0; otherwise std::domain_error.
  pair_friction(const patch_profile& profile, patch_radius<double> radius,
                friction_coefficient<double> friction)
      : profile_(profile),
        fixed_radius_(check(radius.value, "patch radius", rule::finite_non_negative)),
        friction_(check(friction.value, "friction coefficient", rule::finite_non_negative)) {}

  /// A patch whose radius follows the penetration (hertz_radius).  R*
  /// finite and > 0, the minimum finite and ≥ 0, μ finite and ≥ 0;
  /// otherwise std::domain_error naming the value passed.
  pair_friction(const patch_profile& profile, hertz_radius rule_of_radius,
                friction_coefficient<double> friction)
      : profile_(profile),
        fixed_radius_(check(rule_of_radius.minimum, "minimum radius", rule::finite_non_negative)),
        effective_radius_(check(rule_of_radius.value, "effective radius", rule::finite_positive)),
        friction_(check(friction.value, "friction coefficient", rule::finite_non_negative)) {}

  /// The patch radius at penetration δ (a negative δ counts as 0): the
  /// fixed radius, or √(R*δ) but not below hertz_radius's minimum.
  double radius(double penetration) const {
    if (effective_radius_ <= 0) return fixed_radius_;
    const double depth = penetration > 0 ? penetration : 0.0;
    return std::fmax(std::sqrt(effective_radius_ * depth), fixed_radius_);
  }

  /// True for a curved contact (the Hertz profile): its normal force's
  /// moment rolls the body, where a flat face's only shifts its pressure.
  bool curved() const { return std::holds_alternative<hertz<double>>(profile_); }

  /// μ.
  double friction() const { return friction_; }

  /// The friction impulse over one step on the body whose relative motion is
  /// given (impulse_friction.hpp): `velocity` and `spin` the relative sliding
  /// velocity (tangent-plane axes) and spin about the normal before friction,
  /// `inverse_mass` the pair's effective inverse mass over them, `normal` the
  /// normal impulse of the step and `penetration` the depth δ for the radius.
  /// Starts from where the pair's last slip left the limit curve and keeps
  /// the result's curve() (a stick keeps the last slip's point).
  impulse_result<std::array<double, 2>, double> impulse(const std::array<double, 2>& velocity,
                                                        double spin,
                                                        const planar_metric<double>& inverse_mass,
                                                        normal_impulse<double> normal,
                                                        double penetration) {
    const impulse_contact<double> contact{patch_radius<double>{radius(penetration)}, normal,
                                          friction_coefficient<double>{friction_}};
    const auto out = std::visit(
        [&](const auto& profile) {
          return impulse_friction(profile, velocity, spin, inverse_mass, contact, last_);
        },
        profile_);
    last_ = out.curve();  // a stick keeps the last slip's point
    return out;
  }

  /// Drops the kept curve point (the pair lost contact).
  void forget() { last_ = {}; }

 private:
  using rule = detail::argument_rule;
  static double check(double value, const char* name, rule r) {
    return detail::checked_constructor_argument(
        "spinslide::pair_friction(profile, radius, friction)", name, value, r);
  }

  patch_profile profile_;
  double fixed_radius_;          // a, or the least a of a hertz_radius
  double effective_radius_ = 0;  // R* (0: a fixed radius)
  double friction_;
  curve_point<double> last_;  // where the last slip left the curve ({}: none)
};

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_PAIR_FRICTION_HPP
