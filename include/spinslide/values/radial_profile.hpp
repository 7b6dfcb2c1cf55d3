//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file radial_profile.hpp
/// The profile of any axisymmetric pressure p(r), its moments by quadrature
/// at construction (`radial_profile`); included by
/// profile.hpp with the other profiles.
#ifndef SPINSLIDE_VALUES_RADIAL_PROFILE_HPP
#define SPINSLIDE_VALUES_RADIAL_PROFILE_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/values/detail/ring_kernel.hpp>
#include <spinslide/values/detail/singular_ratios.hpp>
#include <spinslide/values/disk.hpp>
#include <spinslide/values/profile_base.hpp>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include <limits>
#include <type_traits>
#include <utility>

namespace spinslide {

/// Any pressure p(r) ≥ 0 on b ≤ r ≤ 1 (b = inner_ratio), given as a callable
/// Real(Real).  The library normalises it by ∫ p(r) r dr (quadrature); a
/// negative or non-finite pressure met at any quadrature node, or a total
/// that is zero or overflows the type (relative to p at the middle of the
/// support), is a domain error (std::domain_error in the constructor, through
/// the policy in force_torque).  Moments by quadrature at construction.  p
/// may have integrable singularities at the ends of [b, 1].
template <class Real, class Pressure, class Policy = boost::math::policies::policy<>>
class radial_profile : public profile_base<radial_profile<Real, Pressure, Policy>, Real, Policy> {
 public:
  /// p is called as p(r), or as p(r, 1 − r) if it accepts two arguments: then
  /// 1 − r is exact near the rim, which a pressure singular there needs for
  /// full accuracy (with p(r) alone, 1 − r is only known to ~1e-16 absolute,
  /// and a 1/√(1 − r) singularity then costs ~1e-8 relative).  `inner_ratio`
  /// b ∈ [0, 1), otherwise std::domain_error.
  explicit radial_profile(Pressure p, Real inner_ratio = 0)
      : p_(std::move(p)),
        inner_(detail::checked_constructor_argument<Policy>(constructor, "inner_ratio", inner_ratio,
                                                            detail::argument_rule::inner_ratio)) {
    // p and λp are the same profile: p is divided by its value at the middle
    // of the support, so that a pressure of any size the type holds is
    // integrated without overflow.
    const Real half_width = (1 - inner_) / 2;  // 1 − middle, exact even where middle rounds to 1
    const Real p_middle = pressure(1 - half_width, half_width, construction_policy());
    if (p_middle > 0 && (boost::math::isfinite)(p_middle)) scale_ = p_middle;
    total_ = detail::checked_constructor_argument<Policy>(
        constructor, "the total load (relative to p at the middle of the support)", moment(0),
        detail::argument_rule::finite_positive);
    // Subnormal values round to multiples of the smallest subnormal, which
    // costs the integral at most that over the support's width: relative ε
    // once the load per unit width is normal.
    detail::checked_constructor_argument<Policy>(
        constructor, "the load per unit width of the support, (integral of r p(r) dr)/(1 - b)",
        Real(total_ * scale_ / (1 - inner_)), detail::argument_rule::normal_load);
    mean_inverse_ = moment(-1) / total_;
    mean_ = moment(1) / total_;
    mean_square_ = moment(2) / total_;
  }

  /// b, the inner radius of the support in units of the contact radius.
  Real inner_ratio() const { return inner_; }
  /// The ratios where 𝓕″ and 𝓣″ are singular, b (if > 0) and 1, the edges of
  /// the support: breakpoints for the stop integrator.
  detail::ratio_list<Real> singular_ratios() const {
    detail::ratio_list<Real> r(Real(1));
    r.add(inner_);
    return r;
  }
  /// ⟨r⟩, by quadrature at construction.
  Real mean_radius() const { return mean_; }
  /// ⟨1/r⟩, by quadrature at construction.
  Real mean_inverse_radius() const { return mean_inverse_; }
  /// ⟨r²⟩, by quadrature at construction.
  Real mean_square_radius() const { return mean_square_; }
  /// The load per unit radius, r p(r) / ∫ r p dr (integrates to 1 over [b, 1]).
  Real load_density(Real r) const { return r * (pressure(r, 1 - r, Policy()) / scale_) / total_; }

 private:
  friend class profile_base<radial_profile, Real, Policy>;
  static constexpr const char* name = "spinslide::radial_profile<%1%>";
  static constexpr const char* constructor =
      "spinslide::radial_profile<%1%>::radial_profile(pressure, %1%)";
  using construction_policy = detail::constructor_policy<Policy>;

  // Ring quadrature of the normalised load.
  force_torque_result<Real> general(Real eps) const {
    auto w = [this](const detail::ring_node<Real>& n) {
      return n.r * (pressure(n.r, n.one_minus_r, Policy()) / scale_) / total_;
    };
    return detail::ring_integral(w, inner_, eps, detail::kernel_policy<Policy>());
  }

  // ∫ p(r) r^{power+1} dr / scale over [b, 1]: the load (power 0) and the
  // numerators of ⟨r^power⟩.  tanh_sinh's xc > 0 is 1 − r near the rim.  A
  // sum that overflows even so (p spanning the type's whole range) is
  // reported as a load that is not finite.
  Real moment(int power) const {
    BOOST_MATH_STD_USING
    boost::math::quadrature::tanh_sinh<Real, Policy> q;
    const Real tol = pow(boost::math::tools::epsilon<Real>(), Real(0.75));
    auto f = [&](Real r, Real xc) {
      const Real pr = pressure(r, xc > 0 ? xc : Real(1 - r), construction_policy()) / scale_;
      Real rp = r;
      for (int i = 0; i < power; ++i) rp *= r;
      return power == -1 ? pr : Real(rp * pr);
    };
    try {
      return q.integrate(f, inner_, Real(1), tol);
    } catch (const boost::math::evaluation_error&) {
      return std::numeric_limits<Real>::infinity();
    }
  }

  template <class ReportPolicy>
  Real pressure(Real r, Real one_minus_r, const ReportPolicy& pol) const {
    Real p;
    if constexpr (std::is_invocable<const Pressure&, Real, Real>::value) {
      p = p_(r, one_minus_r);
    } else {
      // A quadrature node within 1e-16 of the rim rounds to r = 1, where a
      // one-argument p singular at the rim is infinite: such a sliver is
      // below the resolution of r anyway, so it carries no load.
      if (r == 1 && one_minus_r > 0) return 0;
      p = p_(r);
    }
    return detail::checked(name, "the pressure p(r)", p, detail::argument_rule::finite_non_negative,
                           pol);
  }

  Pressure p_;
  Real inner_;
  Real scale_ = 1;  // p at the middle of the support (1 if that is 0)
  Real total_ = 0, mean_ = 0, mean_inverse_ = 0, mean_square_ = 0;
};

/// Deduces radial_profile's floating type: double from p(r) alone, else the
/// inner ratio's (an integer inner ratio counts as double):
/// radial_profile([](double r) { return 1 - r * r; }) or radial_profile(p, 0.125f).
template <class Pressure>
radial_profile(Pressure) -> radial_profile<double, Pressure>;
/// As above, with an inner ratio.
template <class Pressure, class Inner>
radial_profile(Pressure, Inner)
    -> radial_profile<std::conditional_t<std::is_integral<Inner>::value, double, Inner>, Pressure>;

}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_RADIAL_PROFILE_HPP
