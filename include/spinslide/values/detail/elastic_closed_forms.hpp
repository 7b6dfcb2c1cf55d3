//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The closed forms of the Boussinesq and Hertz profiles (docs/theory.md §6,
// "Hertz and Boussinesq in closed form"): 𝓕, 𝓣 and their derivatives.  With
// k = 1/ε, w = √(ε² − 1) and A = asin(k) = atan2(1, w):
//
//   ε ≤ 1 (polynomials):            Boussinesq 𝓕 = πε/4,          𝓣 = (π/8)(2 − ε²)
//                                   Hertz      𝓕 = (3π/32)ε(4 − ε²), 𝓣 = (3π/128)(8 − 8ε² + 3ε⁴)
//   1 < ε < 3/2 (elementary, (E2), (B1)): Boussinesq 𝓕 = (εA + w k)/2,    𝓣 = ((1 − w²)A + w)/4
//                                   Hertz 𝓕 = (3/16)[ε(4 − ε²)A + w(w² + 3)k],
//                                         𝓣 = (3/64)[(3w⁴ − 2w² + 3)A + 3w(1 − w²)]
//   ε ≥ 3/2 (series in z = k², (E3)): 𝓕 = 1 − Σ_{j≥1} a_j z^j,   ε𝓣 = Σ_{j≥0} b_j z^j,
//
// and everywhere 𝓕′ = U − 𝓕/ε, 𝓣′ = −ε𝓕′.  The curvature 𝓕″ (for the
// limit-set projection's Halley steps) is, for ε > 1,
//   Hertz 𝓕″ = (3/8)[3wk + 2wk³ − 3εA],  Boussinesq 𝓕″ = −k³/w,
// (the derivative of 𝓕′ below with dA/dε = −k/w, dw/dε = ε/w), and in the
// series −z Σ 2j(2j + 1) a_j z^j.  Each branch is used where it is
// a sum of like-signed terms or nearly so: the elementary forms cancel as
// ε → ∞ (𝓣 by a factor of about ε⁴), the series converge slowly as ε → 1.
// float is evaluated in double; every other type in its own arithmetic.
// Hertz in double and float takes a fixed-cost table from ε = 13/10 on
// instead (hertz_fast.hpp): elastic_at and elastic_value_and_slope choose,
// elastic_forms_at and elastic_forms_value_and_slope are the forms alone.
#ifndef SPINSLIDE_VALUES_DETAIL_ELASTIC_CLOSED_FORMS_HPP
#define SPINSLIDE_VALUES_DETAIL_ELASTIC_CLOSED_FORMS_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/values/detail/force_slope.hpp>
#include <spinslide/values/detail/hertz_fast.hpp>
#include <spinslide/values/disk.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/precision.hpp>

#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace spinslide {
namespace detail {

// The series (E3) start at ε = 3/2 for the values and at ε = 13/10 for the
// derivatives, whose elementary forms cancel sooner (by 6.7× at ε = 3/2).
template <class Real>
Real elastic_series_start() {
  return Real(3) / 2;
}
template <class Real>
Real elastic_derivative_series_start() {
  return Real(13) / 10;
}

// The arithmetic a result type is evaluated in: float in double.
template <class Real>
using elastic_arithmetic =
    typename std::conditional<std::is_same<Real, float>::value, double, Real>::type;

// The coefficients of (E3), c_j = C(2j, j)/4ʲ times a rational in j that
// depends on the load, long enough for the slowest case (the derivatives at
// their series start), built once per type (in long double for double);
// with them the derivatives' coefficients and the term counts' thresholds.
template <class Real>
struct elastic_coefficients {
  std::vector<Real> force;      // a_j (a_0 = 0)
  std::vector<Real> torque;     // b_j
  std::vector<Real> slope;      // 2j a_j: 𝓕′ = k Σ 2j a_j z^j
  std::vector<Real> curvature;  // 2j(2j + 1) a_j: 𝓕″ = −z Σ 2j(2j + 1) a_j z^j
  // elastic_series_terms: n terms suffice below z = threshold[n] (n ≥ 2)
  std::vector<Real> threshold;
};

template <class Load, class Real>
const elastic_coefficients<Real>& elastic_series_coefficients() {
  using Wide =
      typename std::conditional<std::is_same<Real, double>::value, long double, Real>::type;
  static const elastic_coefficients<Real> table = [] {
    const Wide z =
        1 / (elastic_derivative_series_start<Wide>() * elastic_derivative_series_start<Wide>());
    const Wide tol = boost::math::tools::epsilon<Real>() / 64;
    elastic_coefficients<Real> t;
    Wide c = 1, zj = 1;  // C(2j, j)/4ʲ and zʲ
    for (int j = 0;; ++j) {
      if (j > 0) c *= Wide(2 * j - 1) / Wide(2 * j);
      const Wide a = j == 0 ? Wide(0) : Load::force_coefficient(c, Wide(j));
      t.force.push_back(Real(a));
      t.torque.push_back(Real(Load::torque_coefficient(c, Wide(j))));
      t.slope.push_back(Real(2 * j * a));
      t.curvature.push_back(Real(Wide(2 * j) * Wide(2 * j + 1) * a));
      // As elastic_series_terms: j a_j z^(j−1) against a₁ (zj = z^j here).
      if (j > 1 && Wide(j) * a * zj < tol * Wide(t.force[1]) * z) break;
      zj *= z;
    }
    // n a_n z^(n−1) ≥ ε_mach a₁/64 (a term that still counts) where z ≥ the
    // n-th threshold: (ε_mach a₁/(64 n a_n))^(1/(n−1)).
    using std::pow;
    t.threshold.assign(t.force.size(), Real(0));
    for (std::size_t n = 2; n < t.force.size(); ++n)
      t.threshold[n] =
          Real(pow(tol * Wide(t.force[1]) / (Wide(n) * Wide(t.force[n])), 1 / Wide(n - 1)));
    return t;
  }();
  return table;
}

// The number of terms of (E3) that z = k² needs: the first n with
// n a_n z^(n−1) below ε_mach a₁/64 (the derivative's terms 2n a_n z^n
// relative to its first, 2a₁z; the values need fewer, but share the count),
// by the thresholds in z of that condition (comparisons only).
template <class Real>
std::size_t elastic_series_terms(const elastic_coefficients<Real>& c, Real z) {
  std::size_t n = 2;
  while (n + 1 < c.force.size() && z >= c.threshold[n]) ++n;
  return n;
}

// (E3): 𝓕 and 𝓣, or (derivative) 𝓕′ and 𝓣′, from the series in z = k²,
// summed by Horner from the smallest term.
template <class Load, class Real>
force_torque_result<Real> elastic_series(Real eps, bool derivative) {
  const auto& c = elastic_series_coefficients<Load, Real>();
  const Real k = 1 / eps, z = k * k;
  const std::size_t n = elastic_series_terms(c, z);
  Real f = 0, t = 0;
  if (derivative) {
    for (std::size_t j = n; j >= 1; --j) f = f * z + c.slope[j];
    f *= z;              // −ε𝓣′ = Σ 2j a_j z^j
    return {f * k, -f};  // 𝓕′ = k Σ 2j a_j z^j
  }
  for (std::size_t j = n; j >= 1; --j) {
    f = f * z + c.force[j];
    t = t * z + c.torque[j];
  }
  return {1 - f * z, (t * z + c.torque[0]) * k};
}

// The elementary pieces shared by the forms for 1 < ε: w² = ε² − 1 (exact
// as ε → 1), w, A = asin(1/ε) = atan2(1, w) (accurate as ε → 1, where asin
// of a rounded 1/ε is not) and k = 1/ε.
template <class Real>
struct elastic_outside {
  Real eps, w2, w, a, k;
  explicit elastic_outside(Real e) : eps(e), w2((e - 1) * (e + 1)), w(0), a(0), k(1 / e) {
    BOOST_MATH_STD_USING
    w = sqrt(w2);
    a = atan2(Real(1), w);
  }
};

// p ∝ 1/√(1 − r²): the rigid flat punch.  U = π/2 inside, asin(1/s) outside.
struct boussinesq_load {
  template <class Real>
  static Real force_coefficient(Real c, Real j) {
    return c / ((2 * j - 1) * (2 * j + 1));
  }
  template <class Real>
  static Real torque_coefficient(Real c, Real j) {
    return c / ((2 * j + 1) * (2 * j + 3));
  }
  template <class Real>
  static force_torque_result<Real> inside(Real e) {
    using boost::math::constants::pi;
    return {pi<Real>() / 4 * e, pi<Real>() / 8 * ((1 - e) * (1 + e) + 1)};
  }
  template <class Real>
  static force_torque_result<Real> inside_derivative(Real e) {
    using boost::math::constants::pi;
    return {pi<Real>() / 4, -(pi<Real>() / 4) * e};
  }
  template <class Real>
  static force_torque_result<Real> outside(const elastic_outside<Real>& o) {
    return {(o.eps * o.a + o.w * o.k) / 2, ((1 - o.w2) * o.a + o.w) / 4};
  }
  // 𝓕′ = (A − w k²)/2.
  template <class Real>
  static Real outside_force_derivative(const elastic_outside<Real>& o) {
    return (o.a - o.w * o.k * o.k) / 2;
  }
  // 𝓕″ = 0 inside; −k³/w outside, unbounded as ε → 1⁺.
  template <class Real>
  static Real inside_curvature(Real) {
    return 0;
  }
  template <class Real>
  static Real outside_curvature(const elastic_outside<Real>& o) {
    return -(o.k * o.k * o.k) / o.w;
  }
};

// p ∝ √(1 − r²): Hertz.  U = (3π/8)(2 − s²) inside, (3/4)[(2 − s²)asin(1/s) + √(s² − 1)] outside.
struct hertz_load {
  template <class Real>
  static Real force_coefficient(Real c, Real j) {
    return 3 * c / ((2 * j - 1) * (2 * j + 1) * (2 * j + 3));
  }
  template <class Real>
  static Real torque_coefficient(Real c, Real j) {
    return 3 * c / ((2 * j + 1) * (2 * j + 3) * (2 * j + 5));
  }
  template <class Real>
  static force_torque_result<Real> inside(Real e) {
    using boost::math::constants::pi;
    const Real e2 = e * e;
    // 8 − 8ε² + 3ε⁴ as 8(1 − ε)(1 + ε) + 3ε⁴: like-signed for ε ≤ 1.
    return {3 * pi<Real>() / 32 * e * (4 - e2),
            3 * pi<Real>() / 128 * (8 * ((1 - e) * (1 + e)) + 3 * e2 * e2)};
  }
  template <class Real>
  static force_torque_result<Real> inside_derivative(Real e) {
    using boost::math::constants::pi;
    const Real d = 3 * pi<Real>() / 32 * (4 - 3 * e * e);
    return {d, -e * d};
  }
  template <class Real>
  static force_torque_result<Real> outside(const elastic_outside<Real>& o) {
    const Real e = o.eps, w2 = o.w2;
    return {Real(3) / 16 * (e * ((2 - e) * (2 + e)) * o.a + o.w * (w2 + 3) * o.k),
            Real(3) / 64 * (((3 * w2 - 2) * w2 + 3) * o.a + 3 * o.w * (1 - w2))};
  }
  // 𝓕′ = (3/16)[(1 − 3w²)A + w(1 + 3w²)k²].
  template <class Real>
  static Real outside_force_derivative(const elastic_outside<Real>& o) {
    return Real(3) / 16 * ((1 - 3 * o.w2) * o.a + o.w * (1 + 3 * o.w2) * o.k * o.k);
  }
  // 𝓕″ = −(9π/16)ε inside; (3/8)[3wk + 2wk³ − 3εA] outside, continuous at
  // ε = 1 (where 𝓕‴ is unbounded, like √(ε − 1)).
  template <class Real>
  static Real inside_curvature(Real e) {
    using boost::math::constants::pi;
    return -9 * pi<Real>() / 16 * e;
  }
  template <class Real>
  static Real outside_curvature(const elastic_outside<Real>& o) {
    return Real(3) / 8 * (o.w * o.k * (3 + 2 * o.k * o.k) - 3 * o.eps * o.a);
  }
};

// Hertz in double (and so float) takes the fast path from ε = 13/10 on
// (hertz_fast.hpp), in place of the series and of the elementary forms
// between 13/10 and 3/2.
template <class Load, class W>
constexpr bool has_fast_elastic() {
  return std::is_same<Load, hertz_load>::value && std::is_same<W, double>::value;
}

// 𝓕 and 𝓣, or (derivative) 𝓕′ and 𝓣′ = −ε𝓕′, of the load at 0 < ε < ∞,
// in Real's evaluation arithmetic, by the closed forms and the series alone.
template <class Load, class Real>
force_torque_result<Real> elastic_forms_at(Real eps, bool derivative) {
  using W = elastic_arithmetic<Real>;
  const W& e = eps;  // float: a double temporary; otherwise eps itself
  const W series_start =
      derivative ? elastic_derivative_series_start<W>() : elastic_series_start<W>();
  force_torque_result<W> r;
  if (e <= 1) {
    r = derivative ? Load::inside_derivative(e) : Load::inside(e);
  } else if (e < series_start) {
    const elastic_outside<W> o(e);
    if (derivative) {
      const W d = Load::outside_force_derivative(o);
      r = {d, -e * d};
    } else {
      r = Load::outside(o);
    }
  } else {
    r = elastic_series<Load>(e, derivative);
  }
  return {Real(r.force), Real(r.torque)};
}

// The same, by Hertz's fast path where it applies.
template <class Load, class Real>
force_torque_result<Real> elastic_at(Real eps, bool derivative) {
  using W = elastic_arithmetic<Real>;
  if constexpr (has_fast_elastic<Load, W>()) {
    const W& e = eps;
    if (e >= hertz_fast_start()) {
      if (derivative) {
        const W d = hertz_fast<false, true, false>(e).slope;
        return {Real(d), Real(-e * d)};
      }
      const auto v = hertz_fast<true, false, false>(e);
      return {Real(v.force), Real(v.torque)};
    }
  }
  return elastic_forms_at<Load>(eps, derivative);
}

// (E3) for the values and the derivatives together: the same sums as
// elastic_series(ε, false) and elastic_series(ε, true), term for term, from
// one z and one count (the count depends on z only), and 𝓕″ if asked for
// (otherwise 0).
template <class Load, bool Curvature, class Real>
value_slope<Real> elastic_series_value_slope(Real eps) {
  const auto& c = elastic_series_coefficients<Load, Real>();
  const Real k = 1 / eps, z = k * k;
  const std::size_t n = elastic_series_terms(c, z);
  Real f = 0, t = 0, d = 0, dd = 0;
  for (std::size_t j = n; j >= 1; --j) {
    f = f * z + c.force[j];
    t = t * z + c.torque[j];
    d = d * z + c.slope[j];
    if constexpr (Curvature) dd = dd * z + c.curvature[j];
  }
  return {{1 - f * z, (t * z + c.torque[0]) * k}, d * z * k, -(dd * z * z)};
}

// 𝓕′ and, if Curvature, 𝓕″ (otherwise 0) from (E3) in one loop, between
// the derivative's series start and the values': 𝓕′ the same sum as
// elastic_series(ε, true), term for term.
template <class Load, bool Curvature, class Real>
value_slope<Real> elastic_series_slope(Real eps) {
  const auto& c = elastic_series_coefficients<Load, Real>();
  const Real k = 1 / eps, z = k * k;
  const std::size_t n = elastic_series_terms(c, z);
  Real d = 0, dd = 0;
  for (std::size_t j = n; j >= 1; --j) {
    d = d * z + c.slope[j];
    if constexpr (Curvature) dd = dd * z + c.curvature[j];
  }
  return {{Real(0), Real(0)}, d * z * k, -(dd * z * z)};
}

// 𝓕, 𝓣 and 𝓕′ of the load at 0 < ε < ∞, each exactly as elastic_forms_at
// gives it (the same branch and the same operations), sharing what the branches
// share: √(ε² − 1) and asin(1/ε) below the series, z and the term count in
// them; and 𝓕″ if Curvature (otherwise 0: the projection's safeguarded
// search does without it, and the series' fourth sum would cost it 11 %).
template <class Load, bool Curvature, class Real>
value_slope<Real> elastic_forms_value_and_slope(Real eps) {
  using W = elastic_arithmetic<Real>;
  const W& e = eps;
  value_slope<W> r;
  if (e <= 1) {
    r = {Load::inside(e), Load::inside_derivative(e).force,
         Curvature ? Load::inside_curvature(e) : W(0)};
  } else if (e >= elastic_series_start<W>()) {
    r = elastic_series_value_slope<Load, Curvature>(e);
  } else {
    // 𝓕″'s elementary form cancels too, as 𝓕′'s does: the same switch.
    const elastic_outside<W> o(e);
    if (e >= elastic_derivative_series_start<W>()) {
      r = elastic_series_slope<Load, Curvature>(e);
    } else {
      r.slope = Load::outside_force_derivative(o);
      r.curvature = Curvature ? Load::outside_curvature(o) : W(0);
    }
    r.value = Load::outside(o);
  }
  return {{Real(r.value.force), Real(r.value.torque)}, Real(r.slope), Real(r.curvature)};
}

// The same, by Hertz's fast path where it applies (elastic_at's branch).
template <class Load, bool Curvature, class Real>
value_slope<Real> elastic_value_and_slope(Real eps) {
  using W = elastic_arithmetic<Real>;
  if constexpr (has_fast_elastic<Load, W>()) {
    const W& e = eps;
    if (e >= hertz_fast_start()) {
      const auto v = hertz_fast<true, true, Curvature>(e);
      return {{Real(v.force), Real(v.torque)}, Real(v.slope), Real(v.curvature)};
    }
  }
  return elastic_forms_value_and_slope<Load, Curvature>(eps);
}

// The derivatives at any ε ≥ 0 (𝓕′ = 0 and 𝓣′ = −0 at ε = ∞, where the
// series has z = 0), after the one check of ε; `function` names the member.
template <class Load, class Real, class Policy>
force_torque_result<Real> checked_elastic_derivatives(Real eps, const char* function,
                                                      const Policy& pol) {
  Real nan = 0;
  if (!check(function, "eps", eps, argument_rule::non_negative, &nan, pol)) return {nan, nan};
  if ((boost::math::isinf)(eps)) return {Real(0), Real(0)};
  return elastic_at<Load>(eps, true);
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DETAIL_ELASTIC_CLOSED_FORMS_HPP
