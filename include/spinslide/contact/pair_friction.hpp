//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)

/// \file pair_friction.hpp
/// One coupled pair of bodies, engine-independent (docs/engines.md): its
/// friction settings (the patch's pressure profile, any profile through the
/// run-time handle contact_profile; how its radius is found; μ), or the
/// contact's own flat patch (own_patch: the adapter builds it every step
/// from the engine's points, contact_patch.hpp), and the impulse over one
/// step, with where the last step left the limit set kept to start the
/// next step's search.  An engine adapter (under engines/) gathers
/// what its engine knows (the relative motion before friction, the
/// effective inverse mass, the normal impulse, the penetration), applies the
/// impulse this returns and reports it as a pair_report (pair_report.hpp).
/// In the core: built and tested without any engine, in float as in double.
#ifndef SPINSLIDE_CONTACT_PAIR_FRICTION_HPP
#define SPINSLIDE_CONTACT_PAIR_FRICTION_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/base/friction_result.hpp>
#include <spinslide/contact/contact_inputs.hpp>
#include <spinslide/contact/impulse_friction.hpp>
#include <spinslide/contact/patch_impulse.hpp>
#include <spinslide/contact/planar_metric.hpp>
#include <spinslide/values/contact_profile.hpp>
#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <array>
#include <cmath>
#include <limits>

namespace spinslide {

/// The patch radius of a curved contact from the engine's penetration depth δ:
/// Hertz's a = √(R*δ), with R* = R₁R₂/(R₁ + R₂) the effective radius (a
/// sphere on a plane: R* = R), and never below a minimum (by default 0: a
/// grazing contact, δ → 0, is point friction, to which the law tends as the
/// patch grows from nothing).  δ is the engine's, set by its contact
/// softness (MuJoCo's solref/solimp: δ = 0.37 mm for a resting billiard
/// ball) or by its solver's residual overlap (Bullet: about 1e-11 m), not by
/// the materials' elasticity.  Where δ means little, set the minimum to the
/// material's Hertz radius (3NR*/(4E*))^(1/3), or give a fixed patch_radius.
template <class Real = double>
struct hertz_radius {
  using value_type = Real;  ///< the floating type
  /// R* [m] (finite, > 0; checked by pair_friction), no minimum radius.
  explicit constexpr hertz_radius(Real effective_radius) : value(effective_radius), minimum(0) {}
  /// R* [m], and the smallest radius `least` (finite, ≥ 0).
  constexpr hertz_radius(Real effective_radius, patch_radius<Real> least)
      : value(effective_radius), minimum(least.value) {}
  Real value;    ///< R*
  Real minimum;  ///< the smallest a
};

/// Selects a pair whose patch is the contact's own: the convex hull of the
/// engine's contact points of the pair in each step under the linear
/// (no-tension) pressure of their normal forces (contact_patch.hpp), in
/// place of a round profile: pair_friction(own_patch{}, friction_coefficient{mu}).
struct own_patch {};

/// One coupled pair's friction: the patch profile (any profile, held by a
/// contact_profile), its radius (fixed, or from the penetration by
/// hertz_radius) and μ, in the floating type `Real`.  It keeps where the
/// last step left the limit curve, to start the next step's search.
template <class Real = double>
class pair_friction {
 public:
  using value_type = Real;  ///< the floating type

  /// A patch of fixed radius a: `profile` scaled to a, with friction
  /// coefficient μ.  a finite and ≥ 0 (0: point friction), μ finite and ≥
  /// 0; otherwise std::domain_error.
  pair_friction(const contact_profile<Real>& profile, patch_radius<Real> radius,
                friction_coefficient<Real> friction)
      : profile_(profile),
        fixed_radius_(check(radius.value, "patch radius", rule::finite_non_negative)),
        friction_(check(friction.value, "friction coefficient", rule::finite_non_negative)) {}

  /// A patch whose radius follows the penetration (hertz_radius): a curved
  /// body.  R* finite and > 0, the minimum finite and ≥ 0, μ finite and ≥ 0;
  /// otherwise std::domain_error naming the value passed.
  pair_friction(const contact_profile<Real>& profile, hertz_radius<Real> rule_of_radius,
                friction_coefficient<Real> friction)
      : profile_(profile),
        fixed_radius_(check(rule_of_radius.minimum, "minimum radius", rule::finite_non_negative)),
        effective_radius_(check(rule_of_radius.value, "effective radius", rule::finite_positive)),
        friction_(check(friction.value, "friction coefficient", rule::finite_non_negative)) {}

  /// The contact's own patch (an adapter builds it every step from the
  /// engine's points, contact_patch.hpp, and passes it to impulse()), with
  /// friction coefficient μ (finite and ≥ 0; otherwise std::domain_error).
  pair_friction(own_patch, friction_coefficient<Real> friction)
      : profile_(uniform_disk<Real>()),
        fixed_radius_(0),
        friction_(check(friction.value, "friction coefficient", rule::finite_non_negative)),
        own_patch_(true) {}

  /// True for a pair whose patch is the contact's own (own_patch).
  bool uses_own_patch() const { return own_patch_; }

  /// The patch radius at penetration δ (a negative δ counts as 0): the
  /// fixed radius, or √(R*δ) but not below hertz_radius's minimum; 0 for an
  /// own patch (its size is the patch's radius(), ℓ).
  Real radius(Real penetration) const {
    using std::fmax;
    using std::sqrt;
    if (effective_radius_ <= 0) return fixed_radius_;
    const Real depth = penetration > 0 ? penetration : Real(0);
    return fmax(sqrt(effective_radius_ * depth), fixed_radius_);
  }

  /// True for a curved contact, whose radius follows the penetration
  /// (hertz_radius): its normal force's moment rolls the body, where a flat
  /// face's only shifts its pressure.
  bool curved() const { return effective_radius_ > 0; }

  /// μ.
  Real friction() const { return friction_; }

  /// The profile.
  const contact_profile<Real>& profile() const { return profile_; }

  /// The friction impulse over one step on the body whose relative motion is
  /// given (impulse_friction.hpp): `velocity` and `spin` the relative sliding
  /// velocity (tangent-plane axes) and spin about the normal before friction,
  /// `inverse_mass` the pair's effective inverse mass over them, `normal` the
  /// normal impulse of the step and `penetration` the depth δ for the radius.
  /// Starts from where the pair's last slip left the limit curve and keeps
  /// the result's curve() (a stick keeps the last slip's point).  An
  /// own_patch pair takes its patch this step, `own` (the tangent-plane axes
  /// of the motion, about the point the motion is given at; point friction
  /// there if null), by the patch's impulse law (patch_impulse.hpp), started
  /// from its last slip; a round pair ignores `own`.
  impulse_result<std::array<Real, 2>, Real> impulse(const std::array<Real, 2>& velocity, Real spin,
                                                    const planar_metric<Real>& inverse_mass,
                                                    normal_impulse<Real> normal, Real penetration,
                                                    const polygon_patch<Real>* own = nullptr) {
    if (own_patch_) return patch_impulse(own, velocity, spin, inverse_mass, normal);
    const impulse_contact<Real> contact{patch_radius<Real>{radius(penetration)}, normal,
                                        friction_coefficient<Real>{friction_}};
    const auto out = profile_.visit([&](const auto& profile) {
      return impulse_friction(profile, velocity, spin, inverse_mass, contact, last_);
    });
    last_ = out.curve();  // a stick keeps the last slip's point
    return out;
  }

  /// Drops the kept curve point and slip (the pair lost contact).
  void forget() {
    last_ = {};
    last_slip_ = {};
  }

 private:
  // The patch's impulse law (patch_impulse.hpp), started from the last
  // slip, as the impulse_result the joint solve takes (no curve point: a
  // patch has none; its ratio is the slip's |v|/(ℓ|ω|)).
  impulse_result<std::array<Real, 2>, Real> patch_impulse(const polygon_patch<Real>* own,
                                                          const std::array<Real, 2>& velocity,
                                                          Real spin,
                                                          const planar_metric<Real>& inverse_mass,
                                                          normal_impulse<Real> normal) {
    if (!own) {  // no patch given: point friction at the origin
      const polygon_patch<Real> origin = polygon_patch<Real>::point({Real(0), Real(0)});
      return patch_impulse(&origin, velocity, spin, inverse_mass, normal);
    }
    const auto out = impulse_friction(
        *own, velocity, spin, inverse_mass,
        patch_impulse_contact<Real>{normal, friction_coefficient<Real>{friction_}}, last_slip_);
    if (!out.sticking) last_slip_ = out.slip;  // a stick keeps the last slip
    return {{out.force[0], out.force[1]}, out.torque, out.sticking, out.ratio, last_};
  }

  using rule = detail::argument_rule;
  static Real check(Real value, const char* name, rule r) {
    return detail::checked_constructor_argument(
        "spinslide::pair_friction<%1%>(profile, radius, friction)", name, value, r);
  }

  contact_profile<Real> profile_;
  Real fixed_radius_;          // a, or the least a of a hertz_radius
  Real effective_radius_ = 0;  // R* (0: a fixed radius)
  Real friction_;
  curve_point<Real> last_;  // where the last slip left the curve ({}: none)
  bool own_patch_ = false;
  planar_twist<Real> last_slip_{};  // the own patch's last slip ({}: none)
};

/// pair_friction(profile, patch_radius{a}, friction_coefficient{mu}): the
/// floating type of the named inputs.
template <class Profile, class Real>
pair_friction(Profile, patch_radius<Real>, friction_coefficient<Real>) -> pair_friction<Real>;
/// pair_friction(profile, hertz_radius{r}, friction_coefficient{mu}).
template <class Profile, class Real>
pair_friction(Profile, hertz_radius<Real>, friction_coefficient<Real>) -> pair_friction<Real>;

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_PAIR_FRICTION_HPP
