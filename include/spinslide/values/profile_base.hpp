//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file profile_base.hpp
/// profile_base: the part every profile shares — the check of ε, the limits
/// ε = 0 and ε = ∞, the bound 𝓕 ≤ 1, and force() and torque() from
/// force_torque().  A profile derives from it and supplies only its law for
/// 0 < ε < ∞ and its moments (docs/architecture.md, "A new profile").

#ifndef SPINSLIDE_VALUES_PROFILE_BASE_HPP
#define SPINSLIDE_VALUES_PROFILE_BASE_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/values/force_torque_result.hpp>

#include <string>

namespace spinslide {

/// The base of every profile (the curiously recurring template pattern).
/// `Derived` supplies, besides the three moments of the friction profile
/// concept (profile_concept.hpp):
///  - `force_torque_result<Real> general(Real eps) const` for 0 < ε < ∞,
///    which may be private with `friend class profile_base` (no check of ε
///    is needed there);
///  - `static constexpr const char* name`, Boost.Math's format of the
///    class's name (`"spinslide::hertz<%1%>"`), which error messages name.
template <class Derived, class Real, class Policy>
class profile_base {
 public:
  /// The floating-point type.
  using value_type = Real;
  /// The Boost.Math policy for a bad ε (by default std::domain_error).
  using policy_type = Policy;

  /// 𝓕(ε) in units of μN and 𝓣(ε) in units of μNa, from one evaluation.
  /// ε ∈ [0, ∞]: ε = 0 is pure spinning (𝓕 = 0, 𝓣 = ⟨r⟩) and ε = +∞ pure
  /// sliding (𝓕 = 1, 𝓣 = 0).  NaN or ε < 0 is a domain error through
  /// policy_type, naming the profile.
  force_torque_result<Real> force_torque(Real eps) const { return at(eps, "force_torque"); }
  /// 𝓕(ε); as force_torque().
  Real force(Real eps) const { return at(eps, "force").force; }
  /// 𝓣(ε); as force_torque().
  Real torque(Real eps) const { return at(eps, "torque").torque; }

 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
  // `member` is the entry point that was called, for the message.
  force_torque_result<Real> at(Real eps, const char* member) const {
    if (!detail::satisfies(eps, detail::argument_rule::non_negative)) return invalid(eps, member);
    if (eps == 0) return {Real(0), self().mean_radius()};      // pure spinning
    if ((boost::math::isinf)(eps)) return {Real(1), Real(0)};  // pure sliding
    force_torque_result<Real> r = self().general(eps);
    // 𝓕 ≤ 1 as documented: a quadrature or a difference of closed forms can
    // round an ulp above it where 𝓕 → 1 (an annulus with b = 0.64 gave
    // 1 + 2⁻⁵² at ε = 2e87, and μN𝓕 overflowed in the contact law for
    // μN = DBL_MAX; found by fuzz_contact).
    if (r.force > 1) r.force = 1;
    return r;
  }
  static force_torque_result<Real> invalid(Real eps, const char* member) {
    // The entry point's name is built only here, on the error path.
    const std::string function = std::string(Derived::name) + "::" + member + "(%1%)";
    const Real nan = detail::raise_argument_error(
        function.c_str(), "eps", detail::requirement(detail::argument_rule::non_negative), eps,
        Policy());
    return {nan, nan};
  }
};

}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_PROFILE_BASE_HPP
