//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file erased_profile.hpp
/// Any friction profile behind a small virtual interface: the fallback
/// alternative of the run-time handle contact_profile (contact_profile.hpp),
/// for the profiles it does not name (weighted sums, radial and scaled
/// profiles, a profile of one's own, the Python package's run-time
/// profiles).  It models the profile concept (profile_concept.hpp) itself,
/// so every algorithm takes it; what it erases is the wrapped type's
/// compile-time fast paths (a call costs one indirect call more, and the
/// projections take secants where the wrapped profile had a closed-form
/// 𝓕′).

#ifndef SPINSLIDE_VALUES_ERASED_PROFILE_HPP
#define SPINSLIDE_VALUES_ERASED_PROFILE_HPP

#include <spinslide/values/detail/singular_ratios.hpp>
#include <spinslide/values/force_torque_result.hpp>
#include <spinslide/values/profile_concept.hpp>

#include <boost/math/policies/policy.hpp>

#include <memory>
#include <type_traits>
#include <utility>

namespace spinslide {

/// A friction profile of value_type `Real` behind a virtual interface,
/// shared and immutable: copies are cheap and thread-safe, as the library's
/// algorithms need (they copy profiles into systems and laws, from any
/// thread).  The wrapped profile obeys maximum dissipation with a smooth
/// curve (as the erased type then claims); it reports a bad ε through its
/// own policy;
/// `policy_type` is the default policy, for the arguments the algorithms
/// check themselves.
template <class Real = double>
class erased_profile {
 public:
  using value_type = Real;                              ///< the floating type
  using policy_type = boost::math::policies::policy<>;  ///< the default policy

  /// Wraps `profile` (a copy), which must model the profile concept with
  /// value_type `Real`.
  template <class Profile,
            class = std::enable_if_t<!std::is_same<std::decay_t<Profile>, erased_profile>::value>>
  explicit erased_profile(Profile profile)
      : self_(std::make_shared<const model<Profile>>(std::move(profile))) {
    static_assert(detail::requires_profile<Profile>());
    static_assert(std::is_same<typename Profile::value_type, Real>::value,
                  "spinslide::erased_profile<Real>: the profile's value_type must be Real");
    // What the erased type claims by default (profile_concept.hpp), which
    // erasing must not make true of a profile that it is not true of.
    static_assert(obeys_maximum_dissipation<Profile>::value && !has_box_limit_set<Profile>::value,
                  "spinslide::erased_profile: only a profile that obeys maximum dissipation with "
                  "a smooth curve (not the Pade approximants, not the uncoupled caps) is erased");
  }

  /// 𝓕(ε) and 𝓣(ε), the wrapped profile's.
  force_torque_result<Real> force_torque(Real eps) const { return self_->force_torque(eps); }
  /// 𝓕(ε).
  Real force(Real eps) const { return self_->force_torque(eps).force; }
  /// 𝓣(ε).
  Real torque(Real eps) const { return self_->force_torque(eps).torque; }
  /// ⟨r⟩.
  Real mean_radius() const { return self_->mean_radius(); }
  /// ⟨1/r⟩.
  Real mean_inverse_radius() const { return self_->mean_inverse_radius(); }
  /// ⟨r²⟩.
  Real mean_square_radius() const { return self_->mean_square_radius(); }
  /// The ratios where 𝓕 and 𝓣 are singular (detail/singular_ratios.hpp).
  detail::ratio_list<Real> singular_ratios() const { return self_->singular_ratios(); }

 private:
  struct interface {
    interface() = default;
    interface(const interface&) = delete;
    interface& operator=(const interface&) = delete;
    virtual ~interface() = default;
    virtual force_torque_result<Real> force_torque(Real eps) const = 0;
    virtual Real mean_radius() const = 0;
    virtual Real mean_inverse_radius() const = 0;
    virtual Real mean_square_radius() const = 0;
    virtual detail::ratio_list<Real> singular_ratios() const = 0;
  };
  template <class Profile>
  struct model final : interface {
    explicit model(Profile p) : profile(std::move(p)) {}
    force_torque_result<Real> force_torque(Real eps) const override {
      return profile.force_torque(eps);
    }
    Real mean_radius() const override { return profile.mean_radius(); }
    Real mean_inverse_radius() const override { return profile.mean_inverse_radius(); }
    Real mean_square_radius() const override { return profile.mean_square_radius(); }
    detail::ratio_list<Real> singular_ratios() const override {
      return detail::singular_ratios(profile);
    }
    Profile profile;
  };
  std::shared_ptr<const interface> self_;
};

}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_ERASED_PROFILE_HPP
