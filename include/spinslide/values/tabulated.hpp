//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file tabulated.hpp
/// A profile's 𝓕 and 𝓣 over all ε, precomputed once as a compact piecewise
/// Chebyshev approximation, for simulators that call the law per contact per
/// step (docs/theory.md §7).

#ifndef SPINSLIDE_VALUES_TABULATED_HPP
#define SPINSLIDE_VALUES_TABULATED_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/values/detail/force_slope.hpp>
#include <spinslide/values/detail/piecewise_chebyshev.hpp>
#include <spinslide/values/detail/singular_ratios.hpp>
#include <spinslide/values/profile_base.hpp>
#include <spinslide/values/profile_concept.hpp>

#include <boost/config.hpp>

#include <algorithm>
#include <limits>

namespace spinslide {

/// Any profile, tabulated.  With t = ε/(1+ε) ∈ [0, 1] it approximates the
/// bounded, nonvanishing functions
///   g_F(t) = 𝓕(ε)/t        (→ ⟨1/r⟩/2 at ε = 0, → 1 at ε = ∞),
///   g_T(t) = 𝓣(ε)/(1 − t)  (→ ⟨r⟩ at ε = 0,     → ⟨r²⟩/2 at ε = ∞),
/// so that an absolute error in g is a relative error in 𝓕 and 𝓣 at every ε,
/// including both ends.  Pieces are bisected until the trailing Chebyshev
/// coefficients fall below `tolerance` (default 1e-13); tests check the
/// result to 1e-10 relative against the profile itself.
///
/// Construction evaluates the profile a few thousand times (milliseconds to
/// a second for quadrature profiles) and allocates; force_torque() then
/// allocates nothing and touches only const data, so one object may be
/// shared by any number of threads.
///
/// The table keeps whether its curve obeys maximum dissipation
/// (obeys_maximum_dissipation), so that a projection onto the limit set of
/// a tabulated Padé approximant does not compile: the default table is of
/// a profile that obeys it, and tabulating one that does not (the Padé
/// approximants) takes `tabulated_profile<Real, Policy, false>`.
template <class Real = double, class Policy = boost::math::policies::policy<>,
          bool MaximumDissipation = true>
class tabulated_profile
    : public profile_base<tabulated_profile<Real, Policy, MaximumDissipation>, Real, Policy> {
 public:
  /// As tabulated (obeys_maximum_dissipation).
  static constexpr bool maximum_dissipation = MaximumDissipation;
  /// The degree of every piece.
  static constexpr std::size_t degree = 8;

  /// Tabulates `profile` (any friction profile; its errors propagate) to
  /// `tolerance` (relative trailing Chebyshev coefficients; finite and > 0,
  /// otherwise std::domain_error), bisecting at most `max_depth` levels.
  /// Allocates; milliseconds to a second.
  template <class Profile>
  explicit tabulated_profile(const Profile& profile, Real tolerance = Real(1e-13),
                             int max_depth = 40)
      : mean_(static_cast<Real>(profile.mean_radius())),
        mean_inverse_(static_cast<Real>(profile.mean_inverse_radius())),
        mean_square_(static_cast<Real>(profile.mean_square_radius())) {
    const auto edges = detail::singular_ratios(profile);
    for (std::size_t i = 0; i < edges.size(); ++i) singular_.add(static_cast<Real>(edges[i]));
    static_assert(detail::requires_profile<Profile>());
    static_assert(!MaximumDissipation || obeys_maximum_dissipation<Profile>::value,
                  "tabulated_profile: this profile's curve does not obey T' = -eps F' (the Pade "
                  "approximants), which tabulated_profile<Real, Policy> promises; tabulate it as "
                  "tabulated_profile<Real, Policy, false>, which the limit-set projections refuse");
    const Real tol = detail::checked_constructor_argument<Policy>(
        "spinslide::tabulated_profile<%1%>::tabulated_profile(profile, %1%, max_depth)",
        "tolerance", tolerance, detail::argument_rule::finite_positive);
    using P = typename Profile::value_type;
    auto g = [&](Real t) {
      const P eps = P(t) / (1 - P(t));
      const auto ft = profile.force_torque(eps);
      return std::make_pair(static_cast<Real>(ft.force * (1 + eps) / eps),
                            static_cast<Real>(ft.torque * (1 + eps)));
    };
    table_ = detail::piecewise_chebyshev_pair<Real, degree>(g, tol, max_depth);
  }

  /// ⟨r⟩ of the tabulated profile.
  Real mean_radius() const { return mean_; }
  /// ⟨1/r⟩ of the tabulated profile.
  Real mean_inverse_radius() const { return mean_inverse_; }
  /// ⟨r²⟩ of the tabulated profile.
  Real mean_square_radius() const { return mean_square_; }

  /// 𝓕′(ε) of the table, from the derivative of its piecewise polynomials,
  /// for ε ∈ [0, ∞] (0 at ∞); NaN or ε < 0 is a domain error.  With
  /// t = ε/(1+ε), s = 1 − t and dt/dε = s²: for ε ≤ 1, 𝓕 = t g_F gives
  /// 𝓕′ = (g_F + t g_F′) s²; for ε > 1, where that sum cancels down to
  /// O(1/ε), 𝓣 = s g_T and 𝓣′ = −ε𝓕′ (docs/theory.md (I2)) give
  /// 𝓕′ = (g_T − s g_T′) s²/ε, a sum of like terms.  Tests hold it to 1e-7 of
  /// the profile's own 𝓕′.  It lets project_to_limit_set take Newton steps
  /// on a tabulated profile (limit_set.hpp).
  Real force_derivative(Real eps) const {
    Real bad = 0;
    if (!detail::check("spinslide::tabulated_profile<%1%>::force_derivative(%1%)", "eps", eps,
                       detail::argument_rule::non_negative, &bad, Policy()))
      return bad;
    if ((boost::math::isinf)(eps)) return 0;
    const Real s = 1 / (1 + eps);
    const Real t = eps * s;
    return slope_of(eps, t, s, table_.with_slopes(t));
  }

  /// The singular ratios of the tabulated profile (its pieces are fine there,
  /// but the table is smooth only between them): breakpoints for the stop
  /// integrator.
  const detail::ratio_list<Real>& singular_ratios() const { return singular_; }

  /// The number of Chebyshev pieces.
  std::size_t pieces() const { return table_.size(); }
  /// The deepest bisection level used.
  int deepest_level() const { return table_.deepest(); }

 private:
  friend class profile_base<tabulated_profile, Real, Policy>;
  friend struct detail::fused_value_slope<tabulated_profile>;
  static constexpr const char* name = "spinslide::tabulated_profile<%1%>";
  using table_values = typename detail::piecewise_chebyshev_pair<Real, degree>::values_and_slopes;
  // 𝓕′ from g_F, g_F′ (ε ≤ 1) or g_T, g_T′ (ε > 1), as force_derivative says.
  static Real slope_of(Real eps, Real t, Real s, const table_values& g) {
    if (eps <= 1) return (g.value0 + t * g.slope0) * s * s;
    return (g.value1 - s * g.slope1) * s * s / eps;
  }
  // 𝓕, 𝓣 and 𝓕′ at 0 < ε < ∞ from one piece (fused_value_slope): general()'s
  // values and force_derivative's slope, bit for bit; 𝓕″ not given (NaN).
  // Always inlined: outlined, as g++ did once the impulse law's entry was
  // split, the 3-D Newton steps cost about 30 instructions a call more.
  BOOST_FORCEINLINE detail::value_slope<Real> value_and_slope(Real eps) const {
    const Real s = 1 / (1 + eps);
    const Real t = eps * s;
    const table_values g = table_.with_slopes(t);
    return {{(std::min)(t * g.value0, Real(1)), (std::min)(s * g.value1, mean_)},
            slope_of(eps, t, s, g),
            std::numeric_limits<Real>::quiet_NaN()};
  }
  // 𝓕 and 𝓣 from the table (≤ 1e-10 relative, tested; < 3e-15 measured).
  // No allocation; thread-safe.
  force_torque_result<Real> general(Real eps) const {
    const Real s = 1 / (1 + eps);  // 1 − t, exact for large ε where t rounds to 1
    const Real t = eps * s;
    const auto g = table_(t);
    // The table's error (a few ulp) must not push 𝓕 above 1 or 𝓣 above ⟨r⟩
    // (found by fuzz_coupling: 𝓕 = 1 + 2e-15 at ε = 4e11); clamping only
    // brings the value nearer the exact one.
    return {(std::min)(t * g.first, Real(1)), (std::min)(s * g.second, mean_)};
  }

  Real mean_, mean_inverse_, mean_square_;
  detail::ratio_list<Real> singular_;
  detail::piecewise_chebyshev_pair<Real, degree> table_;
};

namespace detail {
// A table's 𝓕, 𝓣 and 𝓕′ from one piece (force_slope.hpp): the projections
// take Newton's steps on it with one look-up a step.  No 𝓕″: the pieces'
// second derivatives are not held to any accuracy near the profile's
// singular ratios, where the table is bisected to its finest pieces.
template <class Real, class Policy>
struct fused_value_slope<tabulated_profile<Real, Policy, true>> : std::true_type {
  static constexpr bool bounded_curvature = false;
  template <bool Curvature = true, class P>
  static value_slope<Real> at(const P& p, Real eps) {
    return p.value_and_slope(eps);
  }
};
}  // namespace detail

}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_TABULATED_HPP
