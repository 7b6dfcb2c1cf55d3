//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file contact_profile.hpp
/// The run-time handle of a contact's pressure profile (docs/architecture.md,
/// "Three shared decisions", 1): what pair_friction, every engine adapter and
/// the Python package hold, so that every profile reaches every engine.
///
/// A `std::variant` of the models the library names (the uniform disk, the
/// annulus, the ring, Hertz, Boussinesq and the tabulated profile, each with
/// the default policy), dispatched by visit() to code compiled for the
/// concrete type, so that each keeps its compile-time fast path (the disk's
/// and Hertz's tables, Hertz's and Boussinesq's fused 𝓕′); any other model
/// of the concept (a weighted sum, a radial or scaled profile, a profile of
/// one's own) is held as an erased_profile, behind a virtual interface.

#ifndef SPINSLIDE_VALUES_CONTACT_PROFILE_HPP
#define SPINSLIDE_VALUES_CONTACT_PROFILE_HPP

#include <spinslide/values/erased_profile.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/profile_concept.hpp>
#include <spinslide/values/tabulated.hpp>

#include <cstddef>
#include <type_traits>
#include <utility>
#include <variant>

namespace spinslide {

/// Any friction profile of value_type `Real` (float, double, long double)
/// whose limit curve a contact can slide on: one that obeys maximum
/// dissipation (every pressure distribution) with a smooth curve (not the
/// uncoupled caps' box).  Copies are cheap (a tabulated or erased profile
/// shares its table or model).
template <class Real = double>
class contact_profile {
 public:
  using value_type = Real;  ///< the floating type
  /// What the handle holds: a named model, or any other as an erased_profile.
  using alternatives =
      std::variant<uniform_disk<Real>, annulus<Real>, ring<Real>, hertz<Real>, boussinesq<Real>,
                   tabulated_profile<Real>, erased_profile<Real>>;

  /// The handle of `profile` (implicit: a profile passes where a
  /// contact_profile goes).  A named model is held as itself, any other
  /// as an erased_profile.  Its value_type must be `Real`, and it must obey
  /// maximum dissipation with a smooth curve; otherwise this does not compile.
  template <class Profile, class = std::enable_if_t<is_friction_profile<Profile>::value &&
                                                    !std::is_same<Profile, contact_profile>::value>>
  contact_profile(Profile profile)  // implicit by design
      : profile_(hold(std::move(profile))) {}

  /// f(profile) on the concrete profile held (an erased_profile for the
  /// others): f is compiled for each alternative, and must return one type
  /// for all.  A chain of index tests, each call inlinable where f is
  /// (std::visit's table of function pointers is not: it cost a sticking
  /// impulse 13 % more instructions; tools/path_instructions.py).
  template <class F>
  decltype(auto) visit(F&& f) const {
    return visit_from<0>(f);
  }

  /// ⟨r⟩ of the profile held (profile_concept.hpp).
  Real mean_radius() const {
    return visit([](const auto& p) { return p.mean_radius(); });
  }

  /// True if the profile is held behind the virtual interface (no fast path).
  bool erased() const { return std::holds_alternative<erased_profile<Real>>(profile_); }

 private:
  // True if Profile is one of the alternatives (read from the variant's list).
  template <class Profile, class Variant = alternatives>
  struct named;
  template <class Profile, class... Held>
  struct named<Profile, std::variant<Held...>>
      : std::integral_constant<bool, (std::is_same<Profile, Held>::value || ...)> {};

  template <std::size_t I, class F>
  decltype(auto) visit_from(F& f) const {
    if constexpr (I + 1 == std::variant_size<alternatives>::value) {
      return f(*std::get_if<I>(&profile_));
    } else {
      if (profile_.index() == I) return f(*std::get_if<I>(&profile_));
      return visit_from<I + 1>(f);
    }
  }

  template <class Profile>
  static alternatives hold(Profile profile) {
    static_assert(std::is_same<typename Profile::value_type, Real>::value,
                  "spinslide::contact_profile<Real>: the profile's value_type must be Real");
    static_assert(obeys_maximum_dissipation<Profile>::value,
                  "spinslide::contact_profile: this profile's curve does not obey T' = -eps F' "
                  "(the Pade approximants): no contact law applies to it");
    static_assert(!has_box_limit_set<Profile>::value,
                  "spinslide::contact_profile: the uncoupled caps' limit set is a box, whose "
                  "corners the contact laws' 3-D projection cannot resolve");
    if constexpr (named<Profile>::value) {
      return alternatives(std::in_place_type<Profile>, std::move(profile));
    } else {
      return alternatives(std::in_place_type<erased_profile<Real>>, std::move(profile));
    }
  }

  alternatives profile_;
};

}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_CONTACT_PROFILE_HPP
