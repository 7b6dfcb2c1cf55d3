//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The Hessian of the dissipation function D(s) = |s_f|𝓕(ε) + |s_t|𝓣(ε),
// ε = |s_f|/|s_t|, at a slip s, for the metric projection's Newton steps
// (metric_projector.hpp; docs/theory.md §11), and the slope 𝓕′ it needs.
#ifndef SPINSLIDE_CONTACT_DETAIL_DISSIPATION_HESSIAN_HPP
#define SPINSLIDE_CONTACT_DETAIL_DISSIPATION_HESSIAN_HPP

#include <spinslide/contact/detail/matrix3.hpp>
#include <spinslide/values/detail/force_slope.hpp>
#include <spinslide/values/force_torque_result.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

#include <cmath>
#include <cstddef>
#include <limits>

namespace spinslide {
namespace detail {

// A slip s of the metric projection, the curve point ∇D(s) it gives, Ψ
// there, and what the Hessian needs.
template <class Real>
struct slip_point {
  using vec = vector3<Real>;
  vec s;
  Real along = 0, across = 0;  // |s_f| and |s_t|
  Real eps = 0;
  force_torque_result<Real> ft{0, 0};
  vec grad_d{};  // ∇D(s): the point of the curve
  Real psi = 0;
  Real psi_scale = 0;  // the sum of |Ψ|'s terms: its rounding is a few ulp of it
  vec ms{};            // M⁻¹s
  Real slope = 0;  // 𝓕′(ε), where the profile gives it with the values (fused_value_slope)
};

template <class Profile>
class dissipation_hessian {
  using Real = typename Profile::value_type;

 public:
  explicit dissipation_hessian(const Profile& profile) : p_(profile) {}

  // The Hessian of D, rank two: (𝓕′ε/|s_f|) u uᵀ + (𝓕/|s_f|)(I − ddᵀ) on the
  // force block, u = (d, −ε sign s_t); in 1/|s_t| form where ε ≤ 1 (finite
  // at ε = 0: ⟨1/r⟩/2 I), and its ε = ∞ limit (⟨r²⟩/2 for the torque).
  matrix3<Real> operator()(const slip_point<Real>& d, const slip_point<Real>* previous) const {
    matrix3<Real> h{};
    const Real sign = d.s[2] < 0 ? Real(-1) : Real(1);
    const Real dx = d.along > 0 ? Real(d.s[0] / d.along) : Real(1);
    const Real dy = d.along > 0 ? Real(d.s[1] / d.along) : Real(0);
    Real a = 0, b = 0, c = 0, q = 0, scale = 1;  // u uᵀ weights, and the (I − ddᵀ) weight
    if (d.eps == 0) {
      a = q = p_.mean_inverse_radius() / 2;  // 𝓕′(0) = 𝓕/ε at 0
      scale = 1 / d.across;
    } else if (!(d.eps < std::numeric_limits<Real>::infinity())) {
      q = 1;
      c = p_.mean_square_radius() / 2;  // ε³𝓕′ → ⟨r²⟩/2
      scale = 1 / d.along;
    } else {
      const Real fp = slope(d, previous);
      const bool small = d.eps <= 1;
      // 1/|s_t| form: 𝓕′ ddᵀ + (𝓕/ε)(I − ddᵀ), −𝓕′ε σd, 𝓕′ε²; 1/|s_f| form: times ε.
      a = small ? fp : fp * d.eps;
      b = small ? fp * d.eps : fp * d.eps * d.eps;
      c = small ? fp * d.eps * d.eps : fp * d.eps * d.eps * d.eps;
      q = small ? Real(d.ft.force / d.eps) : d.ft.force;
      scale = small ? 1 / d.across : 1 / d.along;
    }
    if (!(boost::math::isfinite)(a)) a = 0;  // ⟨1/r⟩ = ∞: left to the line search
    const Real dd[2] = {dx, dy};
    for (std::size_t i = 0; i < 2; ++i) {
      for (std::size_t j = 0; j < 2; ++j)
        h[i][j] = scale * ((a - q) * dd[i] * dd[j] + (i == j ? q : Real(0)));
      h[i][2] = h[2][i] = -scale * b * sign * dd[i];
    }
    h[2][2] = scale * c;
    return h;
  }

 private:
  // 𝓕′(ε), closed form where the profile has one, else the secant through
  // the previous iterate where it is within 10 % in ε (as Newton's steps
  // are near the answer), else a forward difference (one more evaluation);
  // each in 𝓣 through 𝓣′ = −ε𝓕′ where 𝓕 > 1/2, where 𝓕's differences round
  // away.  Newton needs only an approximate Hessian: the gradient is exact.
  Real slope(const slip_point<Real>& d, const slip_point<Real>* previous) const {
    if constexpr (fused_value_slope<Profile>::value) {
      return d.slope;
    } else if constexpr (has_force_slope<Profile>()) {
      return force_slope(p_, d.eps);
    } else {
      using std::fabs;
      if (previous && previous->eps > 0 && previous->eps < std::numeric_limits<Real>::infinity()) {
        const Real gap = fabs(d.eps - previous->eps);
        Real secant = difference_slope(d, previous->eps, previous->ft);
        if (gap > 0 && gap <= d.eps / 10 && secant > 0 && (boost::math::isfinite)(secant))
          return secant;
      }
      using std::sqrt;
      static const Real relative = sqrt(std::numeric_limits<Real>::epsilon());
      const Real next = d.eps * (1 + relative);
      return difference_slope(d, next, p_.force_torque(next));
    }
  }
  // The slope of the chord from d to the curve point (e, c).
  static Real difference_slope(const slip_point<Real>& d, Real e,
                               const force_torque_result<Real>& c) {
    return d.ft.force <= Real(0.5)
               ? Real((c.force - d.ft.force) / (e - d.eps))
               : Real((d.ft.torque - c.torque) / ((e - d.eps) * ((e + d.eps) / 2)));
  }

  const Profile& p_;
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_DISSIPATION_HESSIAN_HPP
