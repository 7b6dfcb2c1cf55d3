//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The Python profiles (docs/python.md).  A Python profile object holds a
// profile_handle: one of the library's own profile classes, held by value so
// that every algorithm runs on the concrete type (the same instantiation,
// and so the same numbers, as C++ code gets), or, for the profiles that are
// built at run time (a weighted sum of a Python list, a pressure given as a
// Python callable, a table of either), an erased_profile.
#ifndef SPINSLIDE_PYTHON_PROFILE_HANDLE_HPP
#define SPINSLIDE_PYTHON_PROFILE_HANDLE_HPP

#include <spinslide/spinslide.hpp>

#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace spinslide_python {

using spinslide::force_torque_result;
using ratio_list = spinslide::detail::ratio_list<double>;

// A friction profile (profile_concept.hpp) behind a virtual interface, shared
// and immutable: copies are cheap and thread-safe, as the library's
// algorithms need (they copy profiles into systems and laws, from any
// thread).  It forwards 𝓕′ only where the profile has it in closed form.
class erased_profile {
 public:
  using value_type = double;
  using policy_type = boost::math::policies::policy<>;

  template <class Profile>
  explicit erased_profile(Profile p) : self_(std::make_shared<model<Profile>>(std::move(p))) {}

  force_torque_result<double> force_torque(double eps) const { return self_->force_torque(eps); }
  double force(double eps) const { return self_->force_torque(eps).force; }
  double torque(double eps) const { return self_->force_torque(eps).torque; }
  double mean_radius() const { return self_->mean_radius(); }
  double mean_inverse_radius() const { return self_->mean_inverse_radius(); }
  double mean_square_radius() const { return self_->mean_square_radius(); }
  ratio_list singular_ratios() const { return self_->singular_ratios(); }

 private:
  struct interface {
    virtual ~interface() = default;
    virtual force_torque_result<double> force_torque(double eps) const = 0;
    virtual double mean_radius() const = 0;
    virtual double mean_inverse_radius() const = 0;
    virtual double mean_square_radius() const = 0;
    virtual ratio_list singular_ratios() const = 0;
  };
  template <class Profile>
  struct model final : interface {
    explicit model(Profile p) : profile(std::move(p)) {}
    force_torque_result<double> force_torque(double eps) const override {
      return profile.force_torque(eps);
    }
    double mean_radius() const override { return profile.mean_radius(); }
    double mean_inverse_radius() const override { return profile.mean_inverse_radius(); }
    double mean_square_radius() const override { return profile.mean_square_radius(); }
    ratio_list singular_ratios() const override {
      return spinslide::detail::singular_ratios(profile);
    }
    Profile profile;
  };
  std::shared_ptr<const interface> self_;
};

// The profiles a Python object may hold.
using profile_variant = std::variant<spinslide::uniform_disk<>, spinslide::annulus<>,
                                     spinslide::ring<>, spinslide::hertz<>, spinslide::boussinesq<>,
                                     spinslide::tabulated_profile<>, erased_profile>;

// What a Python profile object holds: the profile and how Python spells it.
struct profile_handle {
  profile_variant profile;
  std::string repr;
};

// f(profile) on the concrete profile.
template <class F>
decltype(auto) visit(const profile_handle& p, F&& f) {
  return std::visit(std::forward<F>(f), p.profile);
}

// The profile as an erased_profile (for parts of sums and tables).
inline erased_profile erase(const profile_handle& p) {
  return std::visit(
      [](const auto& q) -> erased_profile {
        using Q = std::decay_t<decltype(q)>;
        if constexpr (std::is_same<Q, erased_profile>::value)
          return q;
        else
          return erased_profile(q);
      },
      p.profile);
}

}  // namespace spinslide_python

#endif  // SPINSLIDE_PYTHON_PROFILE_HANDLE_HPP
