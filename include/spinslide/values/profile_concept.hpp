//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file profile_concept.hpp
/// The friction profile concept: what the coupling curve, the terminal
/// analysis, the dynamics, the contact law and the tables require of a
/// profile, written down and checked at compile time (Boost.Math's
/// concepts/distributions.hpp is the model).
///
/// A type P models a friction profile if, for `const P p` and `value_type e`:
///
/// | expression                 | type                                 | meaning |
/// | ---                        | ---                                  | --- |
/// | `P::value_type`            | a floating-point type (numeric_limits specialised, not integer) |
/// the type of ε, 𝓕 and 𝓣 | | `P::policy_type`           | a Boost.Math policy                  |
/// how a bad ε is reported | | `p.force_torque(e)`        | `force_torque_result<value_type>`    |
/// 𝓕(ε) and 𝓣(ε) for ε ∈ [0, ∞]: 𝓕 ∈ [0, 1] rising, 𝓣 ∈ [0, ⟨r⟩] falling; NaN or ε < 0 is a domain
/// error | | `p.force(e)`, `p.torque(e)` | `value_type`                        | the two halves of
/// force_torque | | `p.mean_radius()`          | `value_type`                         | ⟨r⟩ = 𝓣(0)
/// | | `p.mean_inverse_radius()`  | `value_type`                         | ⟨1/r⟩ = 2𝓕′(0) (may be
/// +∞) | | `p.mean_square_radius()`   | `value_type`                         | ⟨r²⟩ = 2 lim ε𝓣(ε)
/// as ε → ∞ (may be +∞) |
///
/// and P is copy constructible (laws and systems hold their profile by value).
/// Every profile of the library derives from profile_base, which supplies
/// force_torque, force and torque from a hook `general` (profile_base.hpp);
/// a profile of one's own may do the same, or implement the table directly.

#ifndef SPINSLIDE_VALUES_PROFILE_CONCEPT_HPP
#define SPINSLIDE_VALUES_PROFILE_CONCEPT_HPP

#include <spinslide/values/force_torque_result.hpp>

#include <boost/math/policies/policy.hpp>

#include <limits>
#include <type_traits>
#include <utility>

namespace spinslide {

namespace detail {

template <class P, class = void>
struct profile_expressions : std::false_type {};
template <class P>
struct profile_expressions<
    P, std::void_t<
           typename P::value_type, typename P::policy_type,
           decltype(std::declval<const P&>().force_torque(std::declval<typename P::value_type>())),
           decltype(std::declval<const P&>().force(std::declval<typename P::value_type>())),
           decltype(std::declval<const P&>().torque(std::declval<typename P::value_type>())),
           decltype(std::declval<const P&>().mean_radius()),
           decltype(std::declval<const P&>().mean_inverse_radius()),
           decltype(std::declval<const P&>().mean_square_radius())>> {
  using R = typename P::value_type;
  static constexpr bool floating =
      std::numeric_limits<R>::is_specialized && !std::numeric_limits<R>::is_integer;
  template <class E>
  static constexpr bool gives_value = std::is_same<std::decay_t<E>, R>::value;
  static constexpr bool value =
      floating &&
      std::is_same<decltype(std::declval<const P&>().force_torque(std::declval<R>())),
                   force_torque_result<R>>::value &&
      gives_value<decltype(std::declval<const P&>().force(std::declval<R>()))> &&
      gives_value<decltype(std::declval<const P&>().torque(std::declval<R>()))> &&
      gives_value<decltype(std::declval<const P&>().mean_radius())> &&
      gives_value<decltype(std::declval<const P&>().mean_inverse_radius())> &&
      gives_value<decltype(std::declval<const P&>().mean_square_radius())> &&
      std::is_copy_constructible<P>::value;
};

}  // namespace detail

/// True if `P` models the friction profile concept (the table above).
template <class P>
struct is_friction_profile
    : std::integral_constant<bool, detail::profile_expressions<std::decay_t<P>>::value> {};

/// True if `P`'s limit curve (𝓕(ε), 𝓣(ε)) has the outward normal (ε, 1) at
/// every ε, that is 𝓣′ = −ε𝓕′ (maximum dissipation: docs/theory.md §1).
/// Every pressure distribution obeys it, and so do the elliptic limit
/// surface and the uncoupled caps; the limit-set projections rely on it.  A
/// profile that does not (the Padé approximants) declares
/// `static constexpr bool maximum_dissipation = false;`, and the profiles
/// built from others (scaled, weighted_sum, tabulated_profile) pass it on.
template <class P, class = void>
struct obeys_maximum_dissipation : std::true_type {};
template <class P>
struct obeys_maximum_dissipation<P, std::void_t<decltype(std::decay_t<P>::maximum_dissipation)>>
    : std::integral_constant<bool, std::decay_t<P>::maximum_dissipation> {};

/// Whether the profile's limit set is a box (𝓕 and 𝓣 capped independently:
/// uncoupled_caps declares `static constexpr bool box_limit_set = true;`),
/// whose corners the 3-D projection's Newton cannot resolve (limit_set.hpp).
template <class P, class = void>
struct has_box_limit_set : std::false_type {};
template <class P>
struct has_box_limit_set<P, std::void_t<decltype(std::decay_t<P>::box_limit_set)>>
    : std::integral_constant<bool, std::decay_t<P>::box_limit_set> {};

#if defined(__cpp_concepts)
/// The friction profile concept (C++20): the same requirements as is_friction_profile.
template <class P>
concept friction_profile = is_friction_profile<P>::value;
#endif

namespace detail {

// Every generic entry point states its requirement through this, so that a
// wrong argument fails with one message instead of deep in the template.
template <class P>
constexpr bool requires_profile() {
  static_assert(is_friction_profile<P>::value,
                "spinslide: this argument must model the friction profile concept "
                "(profile_concept.hpp): value_type, policy_type, force_torque, force, torque, "
                "mean_radius, mean_inverse_radius and mean_square_radius.");
  return true;
}

}  // namespace detail

/// The smallest type that models the concept, and nothing more: a test
/// passes it to every generic entry point, which proves that they ask for
/// nothing beyond the concept.  Its law has the shape of one (𝓕 rising from 0
/// to 1, 𝓣 falling from ⟨r⟩ = 1 to 0, with ⟨1/r⟩ = 2 and ⟨r²⟩ = 2), so that
/// it may also be run, though no load on the unit disk gives it (⟨r²⟩ > 1).
template <class Real = double>
class friction_profile_archetype {
 public:
  /// The floating-point type.
  using value_type = Real;
  /// The default Boost.Math policy.
  using policy_type = boost::math::policies::policy<>;
  /// Not default constructible: a profile need not be.
  explicit friction_profile_archetype(int /*tag*/) {}
  /// 𝓕 = ε/(1 + ε), 𝓣 = 1/(1 + ε); no domain check (the archetype is minimal).
  force_torque_result<Real> force_torque(Real eps) const {
    if (eps > std::numeric_limits<Real>::max()) return {Real(1), Real(0)};
    return {eps / (1 + eps), 1 / (1 + eps)};
  }
  /// 𝓕(ε).
  Real force(Real eps) const { return force_torque(eps).force; }
  /// 𝓣(ε).
  Real torque(Real eps) const { return force_torque(eps).torque; }
  /// ⟨r⟩ = 1.
  Real mean_radius() const { return 1; }
  /// ⟨1/r⟩ = 2.
  Real mean_inverse_radius() const { return 2; }
  /// ⟨r²⟩ = 2.
  Real mean_square_radius() const { return 2; }
};

}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_PROFILE_CONCEPT_HPP
