//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file planar_metric.hpp
/// A contact's friction state in its tangent plane, (F_x, F_y, T) with T the
/// torque about the normal, and a symmetric positive-definite 3×3 metric over
/// it: the engine's effective mass (Delassus operator) for impulse laws, the
/// springs' compliance for spring-history laws (docs/theory.md §11).

#ifndef SPINSLIDE_CONTACT_PLANAR_METRIC_HPP
#define SPINSLIDE_CONTACT_PLANAR_METRIC_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/contact/detail/matrix3.hpp>

#include <boost/math/policies/policy.hpp>

#include <cmath>
#include <cstddef>
#include <limits>

namespace spinslide {

/// A force (force_x, force_y) in the tangent plane and a torque about the
/// normal (positive counter-clockwise seen from the normal's tip).  In the
/// limit set's units, force = F/(μN) and torque = T/(μNa).
template <class Real>
struct tangent_wrench {
  using value_type = Real;  ///< the floating type
  Real force_x;             ///< the force along the tangent plane's first axis
  Real force_y;             ///< the force along its second axis
  Real torque;              ///< the torque about the normal
};

/// A symmetric positive-definite 3×3 matrix over (force_x, force_y, torque),
/// checked and factored once.
template <class Real>
class planar_metric {
 public:
  /// The floating type of the entries.
  using value_type = Real;
  /// The 3×3 matrix type: std::array of three rows.
  using matrix = detail::matrix3<Real>;

  /// The metric with entries `m` (row-major; m[2][2] weighs the torque).  It
  /// must be finite, symmetric (to 8 ulp of its largest entry; it is then
  /// symmetrized), positive definite, and conditioned within 1/√ε_mach
  /// (‖M‖_F‖M⁻¹‖_F ≤ 6.7e7 in double); otherwise std::domain_error.
  explicit planar_metric(const matrix& m) : m_(m) {
    static const char* function = "spinslide::planar_metric<%1%>::planar_metric(matrix)";
    using std::fabs;
    Real largest = 0;
    for (const auto& row : m)
      for (const Real& x : row) {
        detail::checked_constructor_argument(function, "an entry", x,
                                             detail::argument_rule::finite);
        largest = fabs(x) > largest ? fabs(x) : largest;
      }
    const Real slack = 8 * std::numeric_limits<Real>::epsilon() * largest;
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < i; ++j) {
        if (!(fabs(m[i][j] - m[j][i]) <= slack))
          detail::raise_argument_error(function, "m[i][j] - m[j][i]", "0 (a symmetric matrix)",
                                       Real(m[i][j] - m[j][i]), throwing());
        m_[i][j] = m_[j][i] = (m[i][j] + m[j][i]) / 2;
      }
    if (!detail::cholesky(m_, factor_))
      detail::raise_argument_error(function, "m[0][0]",
                                   "the first entry of a positive-definite matrix", m[0][0],
                                   throwing());
    inverse_ = detail::cholesky_inverse(factor_);
    kappa_ = detail::frobenius(m_) * detail::frobenius(inverse_);
    if (!detail::well_conditioned(m_, inverse_))
      detail::raise_argument_error(function, "the condition number (Frobenius) of the matrix",
                                   "at most 1/sqrt(epsilon) (6.7e7 in double)",
                                   Real(detail::frobenius(m_) * detail::frobenius(inverse_)),
                                   throwing());
  }

  /// The matrix (symmetrized).
  const matrix& entries() const { return m_; }
  /// Its inverse.
  const matrix& inverse() const { return inverse_; }
  /// ‖M‖_F‖M⁻¹‖_F, which bounds the condition number from above.
  Real condition_bound() const { return kappa_; }
  /// Its lower Cholesky factor L, m = L Lᵀ.
  const matrix& cholesky_factor() const { return factor_; }

 private:
  using throwing = detail::constructor_policy<boost::math::policies::policy<>>;
  matrix m_;
  matrix factor_{};
  matrix inverse_{};
  Real kappa_ = 1;
};

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_PLANAR_METRIC_HPP
