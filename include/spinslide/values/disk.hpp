//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file disk.hpp
/// The uniformly pressed disk of Farkas, Bartels, Unger & Wolf (2003):
/// dimensionless friction force 𝓕(ε), friction torque 𝓣(ε) and their
/// derivatives, as functions of the ratio ε = v/(Rω).
///
/// Every branch below is derived in docs/theory.md; "theory (n)" in a comment
/// names the equation there.

#ifndef SPINSLIDE_VALUES_DISK_HPP
#define SPINSLIDE_VALUES_DISK_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/values/detail/disk_fast.hpp>
#include <spinslide/values/force_torque_result.hpp>

#include <boost/cstdint.hpp>
#include <boost/math/constants/constants.hpp>
#include <boost/math/policies/error_handling.hpp>
#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/tools/precision.hpp>
#include <boost/math/tools/promotion.hpp>
#include <boost/math/tools/series.hpp>
#include <cstddef>
#if __cplusplus >= 202002L && __has_include(<span>)
#include <span>
#endif

namespace spinslide {

namespace detail {

// Keeps an output pointer out of template deduction, so that nullptr works.
template <class T>
struct non_deduced {
  using type = T;
};

// The state shared by 𝓕, 𝓣 and 𝓕' at one ε (theory, "Evaluation").
//
// With k = min(ε, 1/ε), m = k² and y = 1 − m, the complete elliptic
// integrals enter only through Carlson's symmetric forms (DLMF 19.25.1):
//   K = R_F(0, y, 1),
//   D = R_D(0, y, 1)            = 3 (K − E) / m,
//   B = (m y / 3) R_D(0, 1, y)  = E − y K.
// Each closed form is written with whichever of D or B makes it a sum of
// like-signed terms, so that the log(1/k') divergence of K never cancels.
template <class T>
struct disk_state {
  T eps{};           // ε ≥ 0, finite
  T k{};             // min(ε, 1/ε)
  T m{};             // k²
  bool above_one{};  // ε > 1, so k = 1/ε
  bool series{};     // ε > 1 and m small: the series in 1/ε², no elliptic integrals
  bool uses_b{};     // the pair (K, B); otherwise (K, D)
  T K{};             // R_F(0, y, 1); unused by the series
  T yK{};            // y·K, exactly 0 at ε = 1 where K diverges
  T aux{};           // B or D, according to uses_b
};

// Where the series in m = 1/ε² takes over above ε = 1.  The closed forms of
// 𝓣 and 𝓕' there lose about log2(1/m) bits to cancellation (theory, "Where
// the closed forms cancel").  When the evaluation type carries at least 8
// guard bits over the result type (double evaluated in long double, float in
// double) that loss is invisible down to m = 1/8; otherwise the closed forms
// are kept only for m > 1/2, where the loss is under 2 bits.
template <class Result, class T>
T series_threshold() {
  return boost::math::tools::digits<T>() >= boost::math::tools::digits<Result>() + 8 ? T(0.125)
                                                                                     : T(0.5);
}

template <class T, class Policy>
disk_state<T> make_disk_state(T eps, T series_below, const Policy& pol) {
  disk_state<T> s;
  s.eps = eps;
  s.above_one = eps > 1;
  s.k = s.above_one ? T(1 / eps) : eps;
  s.m = s.k * s.k;
  s.series = s.above_one && s.m <= series_below;
  s.uses_b = s.above_one || s.m > T(0.5);
  if (s.series) return s;
  // 1 − k² as a product keeps its full relative accuracy as k → 1.
  const T y = (1 - s.k) * (1 + s.k);
  if (y == 0) {
    // ε = 1: K = ∞, but y·K → 0 and B → E(1) = 1 (DLMF 19.6.1).
    s.uses_b = true;
    s.aux = 1;
    return s;
  }
  s.K = boost::math::ellint_rf(T(0), y, T(1), pol);
  s.yK = y * s.K;
  s.aux = s.uses_b ? T(s.m * y / 3 * boost::math::ellint_rd(T(0), T(1), y, pol))
                   : T(boost::math::ellint_rd(T(0), y, T(1), pol));
  return s;
}

// a_n m^n with a_n = ((1/2)_n / n!)², the coefficients of K = (π/2) Σ a_n m^n
// (DLMF 19.5.1); every series below is a_n m^n times a rational in n.
template <class T>
struct elliptic_coefficients {
  explicit elliptic_coefficients(T m) : m_(m) {}
  // Returns a_n m^n for n = 0, 1, 2, ... on successive calls, and n.
  T next() {
    if (n_ > 0) {
      const T r = T(2 * n_ - 1) / T(2 * n_);
      c_ *= m_ * r * r;
    }
    ++n_;
    return c_;
  }
  int n() const { return n_ - 1; }

 private:
  T m_;
  T c_ = 1;
  int n_ = 0;
};

// 𝓕(ε) − 1 for ε > 1: Σ_{n≥1} a_n m^n / ((n+1)(1−2n)), m = 1/ε² (theory (S3)).
template <class T>
struct force_series {
  using result_type = T;
  explicit force_series(T m) : c(m) { c.next(); }
  T operator()() {
    const T cn = c.next();
    const int n = c.n();
    return cn / T((n + 1) * (1 - 2 * n));
  }
  elliptic_coefficients<T> c;
};

// 𝓣(ε) / k for ε > 1: Σ_{n≥0} a_n m^n / (2(n+1)(n+2)) (theory (S4)).
template <class T>
struct torque_series {
  using result_type = T;
  explicit torque_series(T m) : c(m) {}
  T operator()() {
    const T cn = c.next();
    const int n = c.n();
    return cn / T(2 * (n + 1) * (n + 2));
  }
  elliptic_coefficients<T> c;
};

// 𝓕'(ε) / k = −𝓣'(ε) for ε > 1: Σ_{n≥1} 2n a_n m^n / ((n+1)(2n−1)) (theory (S5)).
template <class T>
struct force_derivative_series {
  using result_type = T;
  explicit force_derivative_series(T m) : c(m) { c.next(); }
  T operator()() {
    const T cn = c.next();
    const int n = c.n();
    return cn * T(2 * n) / T((n + 1) * (2 * n - 1));
  }
  elliptic_coefficients<T> c;
};

template <class Series, class T, class Policy>
T sum(Series series, T init, const char* function, const Policy& pol) {
  boost::uintmax_t max_terms = boost::math::policies::get_max_series_iterations<Policy>();
  T result = boost::math::tools::sum_series(  // not const: returned by move (cpp_bin_float)
      series, boost::math::policies::get_epsilon<T, Policy>(), max_terms, init);
  boost::math::policies::check_series_iterations<T>(function, max_terms, pol);
  return result;
}

template <class T, class Policy>
T force_imp(const disk_state<T>& s, const char* function, const Policy& pol) {
  using boost::math::constants::pi;
  const T m = s.m;
  if (s.series) return sum(force_series<T>(m), T(1), function, pol);
  if (s.above_one)  // theory (C1b)
    return 4 * (m * s.yK + (1 + m) * s.aux) / (3 * pi<T>() * m);
  if (s.uses_b)  // theory (C1a)
    return 4 * (m * s.yK + (1 + m) * s.aux) / (3 * pi<T>() * s.k);
  return 4 * s.k * (2 * s.K - (1 + m) * s.aux / 3) / (3 * pi<T>());  // theory (C1d)
}

template <class T, class Policy>
T torque_imp(const disk_state<T>& s, const char* function, const Policy& pol) {
  using boost::math::constants::pi;
  const T m = s.m;
  if (s.series) return s.k * sum(torque_series<T>(m), T(0), function, pol);
  if (s.above_one)  // theory (C2b), the corrected form
    return 4 * (m * s.yK + (4 * m - 2) * s.aux) / (9 * pi<T>() * s.k * m);
  if (s.uses_b)  // theory (C2a)
    return 4 * ((3 - 2 * m) * s.yK + (4 - 2 * m) * s.aux) / (9 * pi<T>());
  return 4 * ((3 - m) * s.K - (4 - 2 * m) * m * s.aux / 3) / (9 * pi<T>());  // theory (C2d)
}

// 𝓕'(ε) and, from the identity 𝓣'(ε) = −ε 𝓕'(ε) (theory (I2)), 𝓣'(ε).
// For ε > 1 the common factor is kept apart so that 𝓣' = −(𝓕' core)/k² needs
// no multiplication by a rounded ε.
template <class T, class Policy>
T force_derivative_imp(const disk_state<T>& s, bool torque, const char* function,
                       const Policy& pol) {
  using boost::math::constants::pi;
  const T m = s.m;
  if (s.above_one) {
    // 𝓕' = k · core and 𝓣' = −core, with core the series (S5) or (C3b).
    T core;
    if (s.series) {
      core = sum(force_derivative_series<T>(m), T(0), function, pol);
    } else {
      core = 4 * ((2 - m) * s.aux - m * s.yK) / (3 * pi<T>() * m);
    }
    return torque ? T(-core) : T(s.k * core);
  }
  T fd;
  if (s.uses_b)  // theory (C3a)
    fd = 4 * (2 * m * s.yK + (2 * m - 1) * s.aux) / (3 * pi<T>() * m);
  else  // theory (C3d)
    fd = 4 * (s.K + (1 - 2 * m) * s.aux / 3) / (3 * pi<T>());
  return torque ? T(-s.eps * fd) : fd;
}

// What a public disk function returns: one quantity, or 𝓕 and 𝓣 together.
enum class disk_quantity { force, torque, force_derivative, torque_derivative };
struct disk_pair {};

// Pure spinning (ε = 0, including −0.0) and pure sliding (ε = +∞).
template <class T>
T disk_limit(T eps, disk_quantity q) {
  if (eps == 0) {
    switch (q) {
      case disk_quantity::force:
      case disk_quantity::torque_derivative:
        return 0;
      case disk_quantity::torque:
        return T(2) / 3;
      case disk_quantity::force_derivative:
        return 1;
    }
  }
  return q == disk_quantity::force ? T(1) : T(0);  // ε = +∞
}
template <class T>
force_torque_result<T> disk_limit(T eps, disk_pair) {
  return {disk_limit(eps, disk_quantity::force), disk_limit(eps, disk_quantity::torque)};
}

template <class T, class Policy>
T disk_evaluate(const disk_state<T>& s, disk_quantity q, const char* function, const Policy& pol) {
  switch (q) {
    case disk_quantity::force:
      return force_imp(s, function, pol);
    case disk_quantity::torque:
      return torque_imp(s, function, pol);
    case disk_quantity::force_derivative:
      return force_derivative_imp(s, false, function, pol);
    case disk_quantity::torque_derivative:
      return force_derivative_imp(s, true, function, pol);
  }
  return 0;  // unreachable
}
template <class T, class Policy>
force_torque_result<T> disk_evaluate(const disk_state<T>& s, disk_pair, const char* function,
                                     const Policy& pol) {
  return {force_imp(s, function, pol), torque_imp(s, function, pol)};
}

// The fast path (values/detail/disk_fast.hpp) serves 𝓕, 𝓣 and the pair.
inline bool disk_fast_serves(disk_quantity q) {
  return q == disk_quantity::force || q == disk_quantity::torque;
}
inline bool disk_fast_serves(disk_pair) { return true; }
template <class R>
R disk_fast_value(R eps, disk_quantity q) {
  R f, t;
  disk_fast(eps, f, t);
  return q == disk_quantity::force ? f : t;
}
template <class R>
force_torque_result<R> disk_fast_value(R eps, disk_pair) {
  force_torque_result<R> r;
  disk_fast(eps, r.force, r.torque);
  return r;
}

// The Boost.Math calling convention: promote the argument, evaluate in the
// policy's evaluation type (double → long double by default), narrow back.
template <class T, class Policy>
struct disk_types {
  using result_type = typename boost::math::tools::promote_args<T>::type;
  using value_type = typename boost::math::policies::evaluation<result_type, Policy>::type;
  using forwarding_policy =
      typename boost::math::policies::normalise<Policy, boost::math::policies::promote_float<false>,
                                                boost::math::policies::promote_double<false>,
                                                boost::math::policies::discrete_quantile<>,
                                                boost::math::policies::assert_undefined<>>::type;
};

template <class R, class Policy, class V>
R disk_narrow(V v, const char* function) {
  return boost::math::policies::checked_narrowing_cast<R, Policy>(v, function);
}
template <class R, class Policy, class V>
force_torque_result<R> disk_narrow(const force_torque_result<V>& v, const char* function) {
  return {disk_narrow<R, Policy>(v.force, function), disk_narrow<R, Policy>(v.torque, function)};
}

// A disk function at a checked ratio ε ≥ 0 (or +∞) of the result type R:
// the fast path where it serves, else the limits, the Carlson forms and the
// series in the evaluation type.  `Quantity` is a disk_quantity or disk_pair.
template <class R, class Policy, class Quantity>
auto disk_at_valid_ratio(R eps, Quantity q, const char* function, const Policy&) {
  using types = disk_types<R, Policy>;
  using value_type = typename types::value_type;
  using forwarding_policy = typename types::forwarding_policy;
  if constexpr (has_fast_disk<R>::value) {
    if (disk_fast_serves(q)) return disk_fast_value(eps, q);
  }
  const forwarding_policy pol;
  const value_type e = static_cast<value_type>(eps);
  if (e == 0 || (boost::math::isinf)(e))
    return disk_narrow<R, forwarding_policy>(disk_limit(e, q), function);
  const disk_state<value_type> s = make_disk_state(e, series_threshold<R, value_type>(), pol);
  return disk_narrow<R, forwarding_policy>(disk_evaluate(s, q, function, pol), function);
}

template <class R>
R disk_invalid(R nan, disk_quantity) {
  return nan;
}
template <class R>
force_torque_result<R> disk_invalid(R nan, disk_pair) {
  return {nan, nan};
}

// Every public disk function: the check of ε in the caller's own type (so
// that the message names that type), then disk_at_valid_ratio.
template <class T, class Policy, class Quantity>
auto disk_public(T eps, Quantity q, const char* function, const Policy& pol) {
  using types = disk_types<T, Policy>;
  using result_type = typename types::result_type;
  const auto e = static_cast<result_type>(eps);
  result_type invalid = 0;
  if (!check(function, "eps", e, argument_rule::non_negative, &invalid,
             typename types::forwarding_policy()))
    return disk_invalid(invalid, q);
  return disk_at_valid_ratio(e, q, function, pol);
}

}  // namespace detail

/// 𝓕(ε): the friction force on a uniformly pressed disk, in units of μF_n,
/// directed against the velocity.  𝓕(0) = 0, 𝓕(1) = 8/(3π), 𝓕(∞) = 1.
///
/// \param eps the ratio ε = v/(Rω) ≥ 0; +∞ is pure sliding.
/// \param pol a Boost.Math policy; NaN or ε < 0 is a domain error through it
///            (by default `std::domain_error`).
/// Integer arguments are computed in double.  Accuracy: see docs/accuracy.md.
template <class T, class Policy>
typename boost::math::tools::promote_args<T>::type force(T eps, const Policy& pol) {
  return detail::disk_public(eps, detail::disk_quantity::force, "spinslide::force<%1%>(%1%)", pol);
}
/// 𝓕(ε) with the default policy.
template <class T>
typename boost::math::tools::promote_args<T>::type force(T eps) {
  return force(eps, boost::math::policies::policy<>());
}

/// 𝓣(ε): the friction torque on a uniformly pressed disk, in units of μF_n R,
/// directed against the spin.  𝓣(0) = 2/3, 𝓣(1) = 8/(9π), 𝓣(ε) ~ 1/(4ε) as ε → ∞.
/// Parameters and errors as for force().
template <class T, class Policy>
typename boost::math::tools::promote_args<T>::type torque(T eps, const Policy& pol) {
  return detail::disk_public(eps, detail::disk_quantity::torque, "spinslide::torque<%1%>(%1%)",
                             pol);
}
/// 𝓣(ε) with the default policy.
template <class T>
typename boost::math::tools::promote_args<T>::type torque(T eps) {
  return torque(eps, boost::math::policies::policy<>());
}

/// d𝓕/dε.  𝓕'(0) = 1, 𝓕'(1) = 4/(3π), 𝓕'(ε) ~ 1/(4ε³) as ε → ∞.
/// Parameters and errors as for force().
template <class T, class Policy>
typename boost::math::tools::promote_args<T>::type force_derivative(T eps, const Policy& pol) {
  return detail::disk_public(eps, detail::disk_quantity::force_derivative,
                             "spinslide::force_derivative<%1%>(%1%)", pol);
}
/// d𝓕/dε with the default policy.
template <class T>
typename boost::math::tools::promote_args<T>::type force_derivative(T eps) {
  return force_derivative(eps, boost::math::policies::policy<>());
}

/// d𝓣/dε = −ε d𝓕/dε.  𝓣'(0) = 0, 𝓣'(1) = −4/(3π), 𝓣'(ε) ~ −1/(4ε²) as ε → ∞.
/// Parameters and errors as for force().
template <class T, class Policy>
typename boost::math::tools::promote_args<T>::type torque_derivative(T eps, const Policy& pol) {
  return detail::disk_public(eps, detail::disk_quantity::torque_derivative,
                             "spinslide::torque_derivative<%1%>(%1%)", pol);
}
/// d𝓣/dε with the default policy.
template <class T>
typename boost::math::tools::promote_args<T>::type torque_derivative(T eps) {
  return torque_derivative(eps, boost::math::policies::policy<>());
}

/// 𝓕(ε) and 𝓣(ε) together: one evaluation of the elliptic integrals serves
/// both.  Parameters and errors as for force(); the error names force_torque.
template <class T, class Policy>
force_torque_result<typename boost::math::tools::promote_args<T>::type> force_torque(
    T eps, const Policy& pol) {
  return detail::disk_public(eps, detail::disk_pair(), "spinslide::force_torque<%1%>(%1%)", pol);
}
/// 𝓕(ε) and 𝓣(ε) together, with the default policy.
template <class T>
force_torque_result<typename boost::math::tools::promote_args<T>::type> force_torque(T eps) {
  return force_torque(eps, boost::math::policies::policy<>());
}
/// 𝓕 and 𝓣 for `count` ratios at once, for simulators: force[i] and
/// torque[i] receive 𝓕(eps[i]) and 𝓣(eps[i]), the same values as
/// force_torque(eps[i]).  Either output pointer may be null to skip it.
/// Errors as for force_torque(), element by element; with the default policy
/// the first bad ratio throws and earlier outputs are already written.
/// For float and double on targets with AVX-512 (e.g. -march=native on a
/// machine that has it), or with AVX2 and FMA (-mavx2 -mfma), a vectorized
/// form of the same accuracy (≤ 4 ulp; about 2× faster than the loop on
/// AVX-512, 1.6× on AVX2); elsewhere a loop of force_torque() calls
/// (docs/performance.md).
template <class Real, class Policy>
void force_torque_batch(const Real* eps, std::size_t count,
                        typename detail::non_deduced<Real>::type* force,
                        typename detail::non_deduced<Real>::type* torque, const Policy& pol) {
#if defined(__AVX512F__) || (defined(__AVX2__) && defined(__FMA__))
  if constexpr (detail::has_fast_disk<Real>::value) {
    // Targets with AVX-512 or AVX2: the vectorized form (one pass for the
    // check, one for the values); a bad ratio falls through to the loop
    // below, which reports it through the policy at the right element.
    int invalid = 0;
    for (std::size_t i = 0; i < count; ++i) invalid |= !(eps[i] >= 0);  // NaN or < 0
    if (!invalid) {
      detail::disk_fast_batch(eps, count, force, torque);
      return;
    }
  }
#endif
  for (std::size_t i = 0; i < count; ++i) {
    const auto ft = spinslide::force_torque(eps[i], pol);
    if (force) force[i] = ft.force;
    if (torque) torque[i] = ft.torque;
  }
}
/// force_torque_batch with the default policy.
template <class Real>
void force_torque_batch(const Real* eps, std::size_t count,
                        typename detail::non_deduced<Real>::type* force,
                        typename detail::non_deduced<Real>::type* torque) {
  force_torque_batch(eps, count, force, torque, boost::math::policies::policy<>());
}

#if defined(__cpp_lib_span)
/// force_torque_batch over spans (C++20); `force` and `torque` must be at
/// least as long as `eps` (otherwise a domain error through the policy).
template <class Real, class Policy = boost::math::policies::policy<>>
void force_torque_batch(std::span<const Real> eps, std::span<Real> force, std::span<Real> torque,
                        const Policy& pol = Policy()) {
  if (force.size() < eps.size() || torque.size() < eps.size()) {
    detail::raise_argument_error<Real>("spinslide::force_torque_batch<%1%>(span)", "eps.size()",
                                       "at most force.size() and torque.size()",
                                       static_cast<Real>(eps.size()), pol);
    return;
  }
  force_torque_batch(eps.data(), eps.size(), force.data(), torque.data(), pol);
}
#endif

}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DISK_HPP
