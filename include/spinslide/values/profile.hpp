//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file profile.hpp
/// Axisymmetric pressure profiles on the unit disk and their friction force
/// 𝓕(ε) and torque 𝓣(ε), by the ring kernel of docs/theory.md §6.
///
/// A profile is a load distribution p(r) on 0 ≤ r ≤ 1 (the contact radius
/// scaled to 1), normalised to unit total load.  Every profile has
///   force(eps), torque(eps), force_torque(eps),
///   mean_radius() ⟨r⟩, mean_inverse_radius() ⟨1/r⟩, mean_square_radius() ⟨r²⟩,
/// where ⟨·⟩ is the load-weighted mean.  𝓕 is in units of μN, 𝓣 of μNa.

#ifndef SPINSLIDE_VALUES_PROFILE_HPP
#define SPINSLIDE_VALUES_PROFILE_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/values/detail/elastic_closed_forms.hpp>
#include <spinslide/values/detail/force_slope.hpp>
#include <spinslide/values/detail/ring_kernel.hpp>
#include <spinslide/values/detail/singular_ratios.hpp>
#include <spinslide/values/disk.hpp>
#include <spinslide/values/profile_base.hpp>
#include <spinslide/values/profile_concept.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>

namespace spinslide {

/// The paper's uniformly pressed disk, p = const on r ≤ 1: the closed forms of
/// disk.hpp.  ⟨r⟩ = 2/3, ⟨1/r⟩ = 2, ⟨r²⟩ = 1/2.
template <class Real = double, class Policy = boost::math::policies::policy<>>
class uniform_disk : public profile_base<uniform_disk<Real, Policy>, Real, Policy> {
 public:
  /// ⟨r⟩ = 2/3 = 𝓣(0).
  Real mean_radius() const { return Real(2) / 3; }
  /// ⟨1/r⟩ = 2 (𝓕′(0) = ⟨1/r⟩/2 = 1).
  Real mean_inverse_radius() const { return Real(2); }
  /// ⟨r²⟩ = 1/2 (ε𝓣(ε) → ⟨r²⟩/2 = 1/4 as ε → ∞).
  Real mean_square_radius() const { return Real(1) / 2; }

 private:
  friend class profile_base<uniform_disk, Real, Policy>;
  static constexpr const char* name = "spinslide::uniform_disk<%1%>";
  force_torque_result<Real> general(Real eps) const {
    return detail::disk_at_valid_ratio(eps, detail::disk_pair(), "spinslide::uniform_disk<%1%>",
                                       Policy());
  }
};

namespace detail {
// The disk's 𝓕, 𝓣, 𝓕′ and 𝓕″ in one call, in float and double: its fast
// table's polynomials and their derivatives (disk_fast_slope; 𝓕″ NaN near
// ε = 1, where it diverges).  Other types take secants.
template <class Real, class Policy>
struct fused_value_slope<uniform_disk<Real, Policy>>
    : std::integral_constant<bool, has_fast_disk<Real>::value> {
  static constexpr bool bounded_curvature = has_fast_disk<Real>::value;
  template <bool Curvature = true, class P>
  static value_slope<Real> at(const P&, Real eps) {
    const disk_fast_derivatives d = disk_fast_slope<Real, Curvature>(eps);
    return {{static_cast<Real>(d.force), static_cast<Real>(d.torque)},
            static_cast<Real>(d.slope),
            static_cast<Real>(d.curvature)};
  }
};
}  // namespace detail

/// All the load on the rim r = 1 (theory (R3)):
///   ε < 1: 𝓕 = (2/π)(E − yK)/ε, 𝓣 = (2/π) E;  ε > 1: 𝓕 = (2/π) E, 𝓣 = (2/π) ε (E − yK),
/// with modulus min(ε, 1/ε); 𝓕(ε) = 𝓣(1/ε).  ⟨r⟩ = ⟨1/r⟩ = ⟨r²⟩ = 1.
template <class Real = double, class Policy = boost::math::policies::policy<>>
class ring : public profile_base<ring<Real, Policy>, Real, Policy> {
 public:
  /// ⟨r⟩ = 1.
  Real mean_radius() const { return 1; }
  /// ⟨1/r⟩ = 1.
  Real mean_inverse_radius() const { return 1; }
  /// ⟨r²⟩ = 1.
  Real mean_square_radius() const { return 1; }

 private:
  friend class profile_base<ring, Real, Policy>;
  static constexpr const char* name = "spinslide::ring<%1%>";
  force_torque_result<Real> general(Real eps) const {
    BOOST_MATH_STD_USING
    return detail::ring_kernel(Real(1), eps, Real(abs(eps - 1)), detail::kernel_policy<Policy>());
  }
};

/// Uniform pressure on the annulus b ≤ r ≤ 1, 0 ≤ b < 1 (the paper's CD:
/// b = 0.125).  ⟨r⟩ = 2(1−b³)/(3(1−b²)), ⟨1/r⟩ = 2/(1+b), ⟨r²⟩ = (1+b²)/2.
/// For b ≤ 1/2 it is the full disk minus the disk of radius b, by the
/// closed forms (theory (A1)); for thinner annuli, where that difference
/// cancels, the ring integral.
template <class Real = double, class Policy = boost::math::policies::policy<>>
class annulus : public profile_base<annulus<Real, Policy>, Real, Policy> {
 public:
  /// The annulus b ≤ r ≤ 1 with b = inner_ratio ∈ [0, 1); b outside it (or
  /// NaN) is a domain error (std::domain_error).
  explicit annulus(Real inner_ratio)
      : b_(detail::checked_constructor_argument<Policy>("spinslide::annulus<%1%>::annulus(%1%)",
                                                        "inner_ratio", inner_ratio,
                                                        detail::argument_rule::inner_ratio)) {}
  /// b.
  Real inner_ratio() const { return b_; }
  /// ⟨r⟩ = 2(1 + b + b²)/(3(1 + b)) = 𝓣(0).
  Real mean_radius() const { return 2 * (1 + b_ + b_ * b_) / (3 * (1 + b_)); }
  /// ⟨1/r⟩ = 2/(1 + b).
  Real mean_inverse_radius() const { return 2 / (1 + b_); }
  /// ⟨r²⟩ = (1 + b²)/2.
  Real mean_square_radius() const { return (1 + b_ * b_) / 2; }
  /// The ratios where 𝓕″ and 𝓣″ are singular, b (if > 0) and 1, the edges of
  /// the support: breakpoints for the stop integrator.
  detail::ratio_list<Real> singular_ratios() const {
    detail::ratio_list<Real> r(Real(1));
    r.add(b_);
    return r;
  }

 private:
  friend class profile_base<annulus, Real, Policy>;
  static constexpr const char* name = "spinslide::annulus<%1%>";
  static force_torque_result<Real> disk(Real eps) {
    return detail::disk_at_valid_ratio(eps, detail::disk_pair(), name, Policy());
  }
  force_torque_result<Real> general(Real eps) const {
    if (b_ == 0) return disk(eps);
    if (b_ <= Real(0.5)) {
      const auto outer = disk(eps);
      const auto hole = disk(eps / b_);
      const Real area = (1 - b_) * (1 + b_);
      return {(outer.force - b_ * b_ * hole.force) / area,
              (outer.torque - b_ * b_ * b_ * hole.torque) / area};
    }
    const Real area = (1 - b_) * (1 + b_);
    auto w = [area](const detail::ring_node<Real>& n) { return 2 * n.r / area; };
    return detail::ring_integral(w, b_, eps, detail::kernel_policy<Policy>());
  }

  Real b_;
};

namespace detail {
// What Hertz's and Boussinesq's profiles share but their moments and name:
// 𝓕 and 𝓣 from the closed forms of values/detail/elastic_closed_forms.hpp for the
// load `Load`, and 𝓕′, 𝓣′ checked (issue 28: the two were written twice).
template <class Self, class Load, class Real, class Policy>
class elastic_profile : public profile_base<Self, Real, Policy> {
 public:
  /// 𝓕′(ε) for ε ∈ [0, ∞] (𝓕′(∞) = 0); NaN or ε < 0 is a domain error
  /// through the policy.
  Real force_derivative(Real eps) const {
    return checked_elastic_derivatives<Load>(eps, Self::force_derivative_name, Policy()).force;
  }
  /// 𝓣′(ε) = −ε𝓕′(ε) for ε ∈ [0, ∞) (0 at both ends); as force_derivative().
  Real torque_derivative(Real eps) const {
    return checked_elastic_derivatives<Load>(eps, Self::torque_derivative_name, Policy()).torque;
  }

 private:
  friend class profile_base<Self, Real, Policy>;
  force_torque_result<Real> general(Real eps) const { return elastic_at<Load>(eps, false); }
};
}  // namespace detail

/// Hertz pressure p ∝ √(1 − r²): an elastic sphere pressed on a flat.
/// ⟨r⟩ = 3π/16, ⟨1/r⟩ = 3π/4, ⟨r²⟩ = 2/5.  Closed forms (docs/theory.md §6,
/// (E1)–(E3)): for ε ≤ 1, 𝓕 = (3π/32)ε(4 − ε²) and 𝓣 = (3π/128)(8 − 8ε² + 3ε⁴);
/// for ε > 1, elementary in asin(1/ε) and √(ε² − 1), and a series in 1/ε²
/// where those cancel.  Within 4 ulp in double, derivatives within 16.
template <class Real = double, class Policy = boost::math::policies::policy<>>
class hertz
    : public detail::elastic_profile<hertz<Real, Policy>, detail::hertz_load, Real, Policy> {
 public:
  /// ⟨r⟩ = 3π/16.
  Real mean_radius() const { return 3 * boost::math::constants::pi<Real>() / 16; }
  /// ⟨1/r⟩ = 3π/4.
  Real mean_inverse_radius() const { return 3 * boost::math::constants::pi<Real>() / 4; }
  /// ⟨r²⟩ = 2/5.
  Real mean_square_radius() const { return Real(2) / 5; }

 private:
  friend class profile_base<hertz, Real, Policy>;
  friend class detail::elastic_profile<hertz, detail::hertz_load, Real, Policy>;
  static constexpr const char* name = "spinslide::hertz<%1%>";
  static constexpr const char* force_derivative_name =
      "spinslide::hertz<%1%>::force_derivative(%1%)";
  static constexpr const char* torque_derivative_name =
      "spinslide::hertz<%1%>::torque_derivative(%1%)";
};

/// Boussinesq pressure p ∝ 1/√(1 − r²): a rigid flat punch on an elastic
/// half-space, with an integrable singularity at the rim.
/// ⟨r⟩ = π/4, ⟨1/r⟩ = π/2, ⟨r²⟩ = 2/3.  Closed forms (docs/theory.md §6,
/// (B1), (B2), (E3)): for ε ≤ 1, 𝓕 = πε/4 and 𝓣 = (π/8)(2 − ε²); for ε ≥ 1,
/// 𝓕 = (εA + √(ε²−1)/ε)/2 and 𝓣 = ((2 − ε²)A + √(ε²−1))/4 with A = asin(1/ε),
/// and a series in 1/ε² where those cancel.  Within 4 ulp in double,
/// derivatives within 16.
template <class Real = double, class Policy = boost::math::policies::policy<>>
class boussinesq : public detail::elastic_profile<boussinesq<Real, Policy>, detail::boussinesq_load,
                                                  Real, Policy> {
 public:
  /// ⟨r⟩ = π/4.
  Real mean_radius() const { return boost::math::constants::pi<Real>() / 4; }
  /// ⟨1/r⟩ = π/2.
  Real mean_inverse_radius() const { return boost::math::constants::pi<Real>() / 2; }
  /// ⟨r²⟩ = 2/3.
  Real mean_square_radius() const { return Real(2) / 3; }

 private:
  friend class profile_base<boussinesq, Real, Policy>;
  friend class detail::elastic_profile<boussinesq, detail::boussinesq_load, Real, Policy>;
  static constexpr const char* name = "spinslide::boussinesq<%1%>";
  static constexpr const char* force_derivative_name =
      "spinslide::boussinesq<%1%>::force_derivative(%1%)";
  static constexpr const char* torque_derivative_name =
      "spinslide::boussinesq<%1%>::torque_derivative(%1%)";
};

namespace detail {
// 𝓕 ≤ 1, as profile_base::force_torque caps it.
template <class Real>
value_slope<Real> capped(value_slope<Real> r) {
  if (r.value.force > 1) r.value.force = 1;
  return r;
}
// Hertz's and Boussinesq's 𝓕, 𝓣, 𝓕′ and 𝓕″ in one call (force_slope.hpp):
// the closed forms of the load `Load`, 𝓕″ bounded or not.
template <class Load, bool BoundedCurvature>
struct elastic_fused_value_slope : std::true_type {
  static constexpr bool bounded_curvature = BoundedCurvature;
  template <bool Curvature = true, class P>
  static value_slope<typename P::value_type> at(const P&, typename P::value_type eps) {
    return capped(elastic_value_and_slope<Load, Curvature>(eps));
  }
};
template <class Real, class Policy>
struct fused_value_slope<hertz<Real, Policy>> : elastic_fused_value_slope<hertz_load, true> {};
// (−k³/w as ε → 1⁺: unbounded.)
template <class Real, class Policy>
struct fused_value_slope<boussinesq<Real, Policy>>
    : elastic_fused_value_slope<boussinesq_load, false> {};
}  // namespace detail

/// A profile shrunk to the radius a ∈ (0, 1]: 𝓕_a(ε) = 𝓕(ε/a), 𝓣_a(ε) = a 𝓣(ε/a);
/// ⟨r⟩ → a⟨r⟩, ⟨1/r⟩ → ⟨1/r⟩/a, ⟨r²⟩ → a²⟨r²⟩.  With weighted_sum it builds
/// stepped profiles such as a two-tier disk.
template <class Profile>
class scaled : public profile_base<scaled<Profile>, typename Profile::value_type,
                                   typename Profile::policy_type> {
  static_assert(detail::requires_profile<Profile>());
  using Real = typename Profile::value_type;
  using Policy = typename Profile::policy_type;

 public:
  /// P's (obeys_maximum_dissipation): shrinking keeps the curve's normals.
  static constexpr bool maximum_dissipation = obeys_maximum_dissipation<Profile>::value;
  /// `p` shrunk to radius a = `radius` ∈ [√min_value, 1] (a² a normal number,
  /// so that a²⟨r²⟩ does not underflow); otherwise std::domain_error.
  scaled(Profile p, Real radius)
      : p_(std::move(p)),
        a_(detail::checked_constructor_argument<Policy>(
            "spinslide::scaled<%1%>::scaled(profile, %1%)", "radius", radius,
            detail::argument_rule::shrink_radius)) {}
  /// a.
  Real radius() const { return a_; }
  /// ⟨r⟩ = a⟨r⟩_P.
  Real mean_radius() const { return a_ * p_.mean_radius(); }
  /// ⟨1/r⟩ = ⟨1/r⟩_P/a.
  Real mean_inverse_radius() const { return p_.mean_inverse_radius() / a_; }
  /// ⟨r²⟩ = a²⟨r²⟩_P.
  Real mean_square_radius() const { return a_ * a_ * p_.mean_square_radius(); }
  /// The singular ratios of P times a (𝓕_a(ε) = 𝓕(ε/a)).
  detail::ratio_list<Real> singular_ratios() const {
    detail::ratio_list<Real> r;
    r.add_scaled(detail::singular_ratios(p_), a_);
    return r;
  }

 private:
  friend class profile_base<scaled, Real, Policy>;
  static constexpr const char* name = "spinslide::scaled<%1%>";
  // 𝓕_P(ε/a) and a𝓣_P(ε/a).
  force_torque_result<Real> general(Real eps) const {
    const auto ft = p_.force_torque(eps / a_);
    return {ft.force, a_ * ft.torque};
  }

  Profile p_;
  Real a_;
};

namespace detail {

/// Load fractions: checks `weights` (each finite and ≥ 0, the largest > 0;
/// otherwise std::domain_error naming `function`) and scales them in place
/// to sum 1.  Shared by weighted_sum and sums built at run time (the Python
/// package's WeightedSum).
template <class Policy, class Range>
void normalise_weights(Range& weights, const char* function) {
  using Real = std::decay_t<decltype(*std::begin(weights))>;
  Real largest = 0;
  for (Real& x : weights) {
    x = checked_constructor_argument<Policy>(function, "a weight", x,
                                             argument_rule::finite_non_negative);
    if (x > largest) largest = x;
  }
  largest = checked_constructor_argument<Policy>(function, "the largest weight", largest,
                                                 argument_rule::finite_positive);
  // Divided by the largest first, so that the sum cannot overflow.
  Real total = 0;
  for (Real& x : weights) {
    x /= largest;
    total += x;
  }
  for (Real& x : weights) x /= total;
}

}  // namespace detail

/// A load-weighted sum of profiles: fraction w_i of the load is distributed
/// as profile i.  The weights are normalised; each must be ≥ 0 and finite and
/// their sum > 0.  Example, a two-tier disk carrying 60% of the load on
/// r < 1/2:  weighted_sum({0.6, 0.4}, scaled(uniform_disk<>(), 0.5), annulus<>(0.5)).
template <class Real, class... Profiles>
class weighted_sum
    : public profile_base<
          weighted_sum<Real, Profiles...>, Real,
          typename std::tuple_element<0, std::tuple<Profiles...>>::type::policy_type> {
  static_assert((detail::requires_profile<Profiles>() && ...));
  using Policy = typename std::tuple_element<0, std::tuple<Profiles...>>::type::policy_type;

 public:
  /// The number of parts.
  static constexpr std::size_t size = sizeof...(Profiles);
  /// Every part's (obeys_maximum_dissipation): a sum of curves with normals
  /// (ε, 1) has them too, one with a part that has not, in general not.
  static constexpr bool maximum_dissipation = (obeys_maximum_dissipation<Profiles>::value && ...);
  /// Load fractions `weights` (normalised; each finite and ≥ 0, sum > 0,
  /// otherwise std::domain_error) of the `parts`.
  weighted_sum(const std::array<Real, size>& weights, Profiles... parts)
      : parts_(std::move(parts)...), w_(normalised(weights)) {}
  /// The same from a braced list of weights, which class template argument
  /// deduction reads the floating type from: weighted_sum({0.6, 0.4}, a, b).
  weighted_sum(const Real (&weights)[size], Profiles... parts)
      : weighted_sum(to_array(weights), std::move(parts)...) {}

  /// The normalised weights wᵢ.
  const std::array<Real, size>& weights() const { return w_; }
  /// ⟨r⟩ = Σ wᵢ⟨r⟩ᵢ.
  Real mean_radius() const {
    return sum([](const auto& p) { return p.mean_radius(); });
  }
  /// ⟨1/r⟩ = Σ wᵢ⟨1/r⟩ᵢ.
  Real mean_inverse_radius() const {
    return sum([](const auto& p) { return p.mean_inverse_radius(); });
  }
  /// ⟨r²⟩ = Σ wᵢ⟨r²⟩ᵢ.
  Real mean_square_radius() const {
    return sum([](const auto& p) { return p.mean_square_radius(); });
  }
  /// The singular ratios of every part with a weight > 0.
  detail::ratio_list<Real> singular_ratios() const {
    detail::ratio_list<Real> r;
    std::size_t i = 0;
    std::apply(
        [&](const auto&... part) {
          ((w_[i++] > 0 ? r.add_scaled(detail::singular_ratios(part), Real(1)) : void()), ...);
        },
        parts_);
    return r;
  }

 private:
  friend class profile_base<weighted_sum, Real, Policy>;
  static constexpr const char* name = "spinslide::weighted_sum<%1%>";
  // Σ wᵢ𝓕ᵢ(ε) and Σ wᵢ𝓣ᵢ(ε), each part evaluated once.
  force_torque_result<Real> general(Real eps) const {
    return general_impl(eps, std::make_index_sequence<size>());
  }
  template <std::size_t... I>
  force_torque_result<Real> general_impl(Real eps, std::index_sequence<I...>) const {
    const std::array<force_torque_result<Real>, size> parts = {
        std::get<I>(parts_).force_torque(eps)...};
    force_torque_result<Real> r{0, 0};
    for (std::size_t i = 0; i < size; ++i) r.force += w_[i] * parts[i].force;
    for (std::size_t i = 0; i < size; ++i) r.torque += w_[i] * parts[i].torque;
    return r;
  }

  static std::array<Real, size> to_array(const Real (&weights)[size]) {
    std::array<Real, size> w{};
    for (std::size_t i = 0; i < size; ++i) w[i] = weights[i];
    return w;
  }
  static std::array<Real, size> normalised(std::array<Real, size> w) {
    detail::normalise_weights<Policy>(
        w, "spinslide::weighted_sum<%1%>::weighted_sum(weights, parts...)");
    return w;
  }
  template <class F>
  Real sum(F f) const {
    return sum_impl(f, std::make_index_sequence<size>());
  }
  template <class F, std::size_t... I>
  Real sum_impl(F f, std::index_sequence<I...>) const {
    Real s = 0;
    ((s += w_[I] * f(std::get<I>(parts_))), ...);
    return s;
  }

  std::tuple<Profiles...> parts_;
  std::array<Real, size> w_;
};

/// Deduces weighted_sum's floating type from the weights, a braced list or a
/// std::array: weighted_sum({0.6, 0.4}, scaled(uniform_disk<>(), 0.5), annulus<>(0.5)).
template <class Real, std::size_t N, class... Profiles>
weighted_sum(const Real (&)[N], Profiles...) -> weighted_sum<Real, Profiles...>;
/// As above, from a std::array of weights.
template <class Real, std::size_t N, class... Profiles>
weighted_sum(const std::array<Real, N>&, Profiles...) -> weighted_sum<Real, Profiles...>;

}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_PROFILE_HPP

// Any pressure p(r): its own header, part of the profiles.
#include <spinslide/values/radial_profile.hpp>
