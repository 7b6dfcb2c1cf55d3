//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// A profile's limit curve with its torque axis in other units: 𝓕_k(ε) =
// 𝓕(ε/k), 𝓣_k(ε) = k𝓣(ε/k), for any k > 0 (the public `scaled`, a profile
// shrunk to a radius k ≤ 1, is the same curve).  The impulse law projects
// in it when a patch radius a is far from the length scale of the inverse
// mass W (a grazing contact, a = 1e-8 m under a body of radius of gyration
// 0.1 m): the torque in units of c (W's own scale), and the curve's in units
// of a, give k = a/c, and the metric diag(1, 1, c) W diag(1, 1, c) stays as
// well conditioned as W, where diag(1, 1, a) W diag(1, 1, a) would not be
// (docs/theory.md §11, "A patch that starts at zero").
//
// The slopes follow: 𝓕′_k(ε) = 𝓕′(ε/k)/k, 𝓕″_k(ε) = 𝓕″(ε/k)/k², and the
// moments: k⟨r⟩, ⟨1/r⟩/k, k²⟨r²⟩; Hertz's and Boussinesq's fused values
// and slopes (fused_value_slope) and closed-form 𝓕′ (force_slope) pass
// through.
#ifndef SPINSLIDE_CONTACT_DETAIL_TORQUE_SCALED_HPP
#define SPINSLIDE_CONTACT_DETAIL_TORQUE_SCALED_HPP

#include <spinslide/values/detail/force_slope.hpp>
#include <spinslide/values/force_torque_result.hpp>
#include <spinslide/values/profile_concept.hpp>

#include <limits>
#include <type_traits>

namespace spinslide {
namespace detail {

template <class Profile>
class torque_scaled {
 public:
  using value_type = typename Profile::value_type;
  using policy_type = typename Profile::policy_type;
  static constexpr bool maximum_dissipation = obeys_maximum_dissipation<Profile>::value;

  // k > 0 with k² a normal number (checked by the caller); `profile` must
  // outlive this object.
  torque_scaled(const Profile& profile, value_type k) : p_(profile), k_(k) {}

  const Profile& unscaled() const { return p_; }
  value_type factor() const { return k_; }

  force_torque_result<value_type> force_torque(value_type eps) const {
    const auto ft = p_.force_torque(eps / k_);
    return {ft.force, k_ * ft.torque};
  }
  value_type force(value_type eps) const { return p_.force(eps / k_); }
  value_type torque(value_type eps) const { return k_ * p_.torque(eps / k_); }
  value_type mean_radius() const { return k_ * p_.mean_radius(); }
  value_type mean_inverse_radius() const { return p_.mean_inverse_radius() / k_; }
  value_type mean_square_radius() const { return k_ * (k_ * p_.mean_square_radius()); }

  // 𝓕′_k, where P has a closed form (has_force_slope).
  template <class P = Profile, std::enable_if_t<has_force_slope<P>(), int> = 0>
  value_type force_derivative(value_type eps) const {
    const value_type x = eps / k_;
    return x < std::numeric_limits<value_type>::infinity() ? force_slope(p_, x) / k_
                                                           : value_type(0);
  }

 private:
  const Profile& p_;
  value_type k_;
};

// Hertz's and Boussinesq's 𝓕, 𝓣, 𝓕′ and 𝓕″ from one call, in the new units
// (ε/k beyond the largest value: the curve's end, 𝓕 = 1, 𝓣 = 𝓕′ = 𝓕″ = 0).
template <class Profile>
struct fused_value_slope<torque_scaled<Profile>> : fused_value_slope<Profile> {
  template <bool Curvature = true>
  static auto at(const torque_scaled<Profile>& p, typename Profile::value_type eps) {
    using Real = typename Profile::value_type;
    const Real k = p.factor(), x = eps / k;
    if (!(x < std::numeric_limits<Real>::infinity())) {
      decltype(fused_value_slope<Profile>::template at<Curvature>(p.unscaled(), Real(1))) end{};
      end.value = p.unscaled().force_torque(x);
      end.value.torque *= k;
      return end;
    }
    auto r = fused_value_slope<Profile>::template at<Curvature>(p.unscaled(), x);
    r.value.torque *= k;
    r.slope /= k;
    r.curvature /= k * k;
    return r;
  }
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_TORQUE_SCALED_HPP
