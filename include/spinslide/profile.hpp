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

#ifndef SPINSLIDE_PROFILE_HPP
#define SPINSLIDE_PROFILE_HPP

#include <spinslide/disk.hpp>

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>

namespace spinslide {

namespace detail {

// The policy the profiles evaluate their elliptic integrals with: the
// caller's, without promotion (a quadrature sums many kernel values, so a
// wider type buys nothing but time).
template <class Policy>
using kernel_policy =
    typename boost::math::policies::normalise<Policy, boost::math::policies::promote_float<false>,
                                              boost::math::policies::promote_double<false>>::type;

/// The ring kernel (theory (R1)–(R2)): force and torque, per unit load, of a
/// thin ring of radius r, at ratio ε.  `distance` is |r − ε|, computed by the
/// caller without cancellation (quadrature nodes near r = ε know it exactly).
/// With c = min(r, ε)/max(r, ε), y = 1 − c², K = R_F(0, y, 1) and
/// B̃ = (y/3) R_D(0, 1, y) = (E − yK)/c² (DLMF 19.25.1):
///   r < ε:  f_F = (2/π) E(c) = (2/π)(yK + c²B̃),   f_T = (2/π) r c B̃,
///   r > ε:  f_F = (2/π) c B̃,                      f_T = (2/π) r (yK + c²B̃).
/// Every term is non-negative; as r → ε (y → 0) yK → 0 and B̃ → 1.
template <class T, class Policy>
force_torque_result<T> ring_kernel(T r, T eps, T distance, const Policy& pol) {
  using boost::math::constants::two_div_pi;
  const bool inside = r < eps;  // the ring lies inside the circle through P
  const T big = inside ? eps : r;
  const T c = inside ? T(r / eps) : T(eps / r);
  const T y = (distance / big) * ((r + eps) / big);  // big² could overflow
  // For a subnormal y (a quadrature node within about the smallest normal
  // number of r = ε), Boost's R_F and R_D return NaN; the limits yK = 0 and
  // B̃ = 1 are then exact to far below an ulp (the corrections are O(y ln y)).
  T yK = 0, Bt = 1;
  if (y >= boost::math::tools::min_value<T>()) {
    yK = y * boost::math::ellint_rf(T(0), y, T(1), pol);
    Bt = y / 3 * boost::math::ellint_rd(T(0), T(1), y, pol);
  }
  if (inside) return {two_div_pi<T>() * (yK + c * c * Bt), two_div_pi<T>() * r * c * Bt};
  return {two_div_pi<T>() * c * Bt, two_div_pi<T>() * r * (yK + c * c * Bt)};
}

template <class T>
struct ring_node {
  T r;            // the radius
  T one_minus_r;  // 1 − r, exact near r = 1
};

// ∫ w(r) (f_F, f_T)(r, ε) dr over [inner, 1], split at r = ε where the kernel's
// derivative has its logarithmic singularity.  w(node) is the load per unit
// radius; Boost's tanh_sinh handles integrable endpoint singularities of w
// (such as Boussinesq's 1/√(1−r)) given the exact complement 1 − r.
template <class T, class Weight, class Policy>
force_torque_result<T> ring_integral(const Weight& w, T inner, T eps, const Policy& pol) {
  BOOST_MATH_STD_USING
  // One integrator per thread and type: tanh_sinh extends its abscissa
  // tables lazily, which must not race.
  static thread_local boost::math::quadrature::tanh_sinh<T, Policy> q;
  // tanh_sinh stops when two levels agree to `tol`; its error is then about
  // tol², except where a feature of width ε sits at an endpoint (ε → 0),
  // which the default root_epsilon misjudged by 1e-12 at ε = 1e-6.
  static const T tol = pow(boost::math::tools::epsilon<T>(), T(0.75));
  force_torque_result<T> total{0, 0};
  auto segment = [&](T a, T b) {
    // tanh_sinh passes x and xc: xc < 0 is a − x, xc > 0 is b − x.
    auto node = [&](T x, T xc) {
      const T from_a = xc < 0 ? T(-xc) : T(x - a);
      const T to_b = xc > 0 ? xc : T(b - x);
      const T one_minus_r = b == 1 ? to_b : T(1 - x);
      const T distance = a == eps ? from_a : (b == eps ? to_b : T(abs(x - eps)));
      return std::make_pair(ring_node<T>{x, one_minus_r}, distance);
    };
    auto force = [&](T x, T xc) {
      const auto n = node(x, xc);
      return T(w(n.first) * ring_kernel(x, eps, n.second, pol).force);
    };
    auto torque = [&](T x, T xc) {
      const auto n = node(x, xc);
      return T(w(n.first) * ring_kernel(x, eps, n.second, pol).torque);
    };
    total.force += q.integrate(force, a, b, tol);
    total.torque += q.integrate(torque, a, b, tol);
  };
  if (inner < eps && eps < 1) {
    segment(inner, eps);
    segment(eps, T(1));
  } else {
    segment(inner, T(1));
  }
  return total;
}

template <class T, class Policy>
bool profile_domain_error(T eps, const char* function, force_torque_result<T>& result,
                          const Policy& pol) {
  if ((boost::math::isnan)(eps) || eps < 0) {
    const T nan = boost::math::policies::raise_domain_error<T>(
        function, "Got eps = %1%, but the ratio eps = v/(R omega) must be >= 0.", eps, pol);
    result = {nan, nan};
    return true;
  }
  return false;
}

template <class T>
T checked_parameter(T value, T lo, T hi, bool hi_open, const char* function, const char* message) {
  if (!(value >= lo) || (hi_open ? !(value < hi) : !(value <= hi)))
    return boost::math::policies::raise_domain_error<T>(function, message, value,
                                                        boost::math::policies::policy<>());
  return value;
}

/// The common part of every profile: force() and torque() from
/// force_torque(), the limits ε = 0 and ε = ∞, and the domain check.
/// Derived supplies `general(eps)` for 0 < ε < ∞ and the three moments.
template <class Derived, class Real, class Policy>
class profile_base {
 public:
  using value_type = Real;
  using policy_type = Policy;

  force_torque_result<Real> force_torque(Real eps) const {
    force_torque_result<Real> r{Real(0), Real(0)};  // set by profile_domain_error on failure
    if (profile_domain_error(eps, "spinslide::profile::force_torque<%1%>(%1%)", r, Policy()))
      return r;
    if (eps == 0) return {Real(0), self().mean_radius()};      // pure spinning
    if ((boost::math::isinf)(eps)) return {Real(1), Real(0)};  // pure sliding
    r = self().general(eps);
    // 𝓕 ≤ 1 as documented: a quadrature or a difference of closed forms can
    // round an ulp above it where 𝓕 → 1 (an annulus with b = 0.64 gave
    // 1 + 2⁻⁵² at ε = 2e87, and μN𝓕 overflowed in the contact law for
    // μN = DBL_MAX; found by fuzz_contact).
    if (r.force > 1) r.force = 1;
    return r;
  }
  Real force(Real eps) const { return force_torque(eps).force; }
  Real torque(Real eps) const { return force_torque(eps).torque; }

 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

}  // namespace detail

/// The paper's uniformly pressed disk, p = const on r ≤ 1: the closed forms of
/// disk.hpp.  ⟨r⟩ = 2/3, ⟨1/r⟩ = 2, ⟨r²⟩ = 1/2.
template <class Real = double, class Policy = boost::math::policies::policy<>>
class uniform_disk {
 public:
  /// The floating-point type.
  using value_type = Real;
  /// The Boost.Math policy for errors (domain errors throw by default).
  using policy_type = Policy;
  /// 𝓕(ε) of disk.hpp; ε ≥ 0, +∞ allowed; NaN or ε < 0 is a domain error.
  Real force(Real eps) const { return spinslide::force(eps, Policy()); }
  /// 𝓣(ε) of disk.hpp; domain and errors as force().
  Real torque(Real eps) const { return spinslide::torque(eps, Policy()); }
  /// 𝓕(ε) and 𝓣(ε) from one evaluation; domain and errors as force().
  force_torque_result<Real> force_torque(Real eps) const {
    return spinslide::force_torque(eps, Policy());
  }
  /// ⟨r⟩ = 2/3 = 𝓣(0).
  Real mean_radius() const { return Real(2) / 3; }
  /// ⟨1/r⟩ = 2 (𝓕′(0) = ⟨1/r⟩/2 = 1).
  Real mean_inverse_radius() const { return Real(2); }
  /// ⟨r²⟩ = 1/2 (ε𝓣(ε) → ⟨r²⟩/2 = 1/4 as ε → ∞).
  Real mean_square_radius() const { return Real(1) / 2; }
};

/// All the load on the rim r = 1 (theory (R3)):
///   ε < 1: 𝓕 = (2/π)(E − yK)/ε, 𝓣 = (2/π) E;  ε > 1: 𝓕 = (2/π) E, 𝓣 = (2/π) ε (E − yK),
/// with modulus min(ε, 1/ε); 𝓕(ε) = 𝓣(1/ε).  ⟨r⟩ = ⟨1/r⟩ = ⟨r²⟩ = 1.
template <class Real = double, class Policy = boost::math::policies::policy<>>
class ring : public detail::profile_base<ring<Real, Policy>, Real, Policy> {
 public:
  /// ⟨r⟩ = 1.
  Real mean_radius() const { return 1; }
  /// ⟨1/r⟩ = 1.
  Real mean_inverse_radius() const { return 1; }
  /// ⟨r²⟩ = 1.
  Real mean_square_radius() const { return 1; }
  /// 𝓕 and 𝓣 for 0 < ε < ∞: the hook that profile_base::force_torque() calls after
  /// its domain check and the limits ε = 0 (𝓕 = 0, 𝓣 = ⟨r⟩) and ε = ∞ (𝓕 = 1, 𝓣 = 0);
  /// call force_torque() instead.
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
class annulus : public detail::profile_base<annulus<Real, Policy>, Real, Policy> {
 public:
  /// The annulus b ≤ r ≤ 1 with b = inner_ratio ∈ [0, 1); b outside it (or
  /// NaN) is a domain error (std::domain_error).
  explicit annulus(Real inner_ratio)
      : b_(detail::checked_parameter<Real>(inner_ratio, Real(0), Real(1), true,
                                           "spinslide::annulus<%1%>::annulus(%1%)",
                                           "Got inner_ratio = %1%, but it must be in [0, 1).")) {}
  /// b.
  Real inner_ratio() const { return b_; }
  /// ⟨r⟩ = 2(1 + b + b²)/(3(1 + b)) = 𝓣(0).
  Real mean_radius() const { return 2 * (1 + b_ + b_ * b_) / (3 * (1 + b_)); }
  /// ⟨1/r⟩ = 2/(1 + b).
  Real mean_inverse_radius() const { return 2 / (1 + b_); }
  /// ⟨r²⟩ = (1 + b²)/2.
  Real mean_square_radius() const { return (1 + b_ * b_) / 2; }
  /// 𝓕 and 𝓣 for 0 < ε < ∞: the hook that profile_base::force_torque() calls after
  /// its domain check and the limits ε = 0 (𝓕 = 0, 𝓣 = ⟨r⟩) and ε = ∞ (𝓕 = 1, 𝓣 = 0);
  /// call force_torque() instead.
  force_torque_result<Real> general(Real eps) const {
    if (b_ == 0) return spinslide::force_torque(eps, Policy());
    if (b_ <= Real(0.5)) {
      const auto outer = spinslide::force_torque(eps, Policy());
      const auto hole = spinslide::force_torque(eps / b_, Policy());
      const Real area = (1 - b_) * (1 + b_);
      return {(outer.force - b_ * b_ * hole.force) / area,
              (outer.torque - b_ * b_ * b_ * hole.torque) / area};
    }
    const Real area = (1 - b_) * (1 + b_);
    auto w = [area](const detail::ring_node<Real>& n) { return 2 * n.r / area; };
    return detail::ring_integral(w, b_, eps, detail::kernel_policy<Policy>());
  }

 private:
  Real b_;
};

/// Hertz pressure p ∝ √(1 − r²): an elastic sphere pressed on a flat.
/// ⟨r⟩ = 3π/16, ⟨1/r⟩ = 3π/4, ⟨r²⟩ = 2/5.
template <class Real = double, class Policy = boost::math::policies::policy<>>
class hertz : public detail::profile_base<hertz<Real, Policy>, Real, Policy> {
 public:
  /// ⟨r⟩ = 3π/16.
  Real mean_radius() const { return 3 * boost::math::constants::pi<Real>() / 16; }
  /// ⟨1/r⟩ = 3π/4.
  Real mean_inverse_radius() const { return 3 * boost::math::constants::pi<Real>() / 4; }
  /// ⟨r²⟩ = 2/5.
  Real mean_square_radius() const { return Real(2) / 5; }
  /// 𝓕 and 𝓣 for 0 < ε < ∞: the hook that profile_base::force_torque() calls after
  /// its domain check and the limits ε = 0 (𝓕 = 0, 𝓣 = ⟨r⟩) and ε = ∞ (𝓕 = 1, 𝓣 = 0);
  /// call force_torque() instead.  Ring quadrature (theory §6), relative error ≲ 1e-13.
  force_torque_result<Real> general(Real eps) const {
    // Load per unit radius 3 r √(1 − r²), normalised: ∫₀¹ 3r√(1−r²) dr = 1.
    auto w = [](const detail::ring_node<Real>& n) {
      BOOST_MATH_STD_USING
      return 3 * n.r * sqrt(n.one_minus_r * (1 + n.r));
    };
    return detail::ring_integral(w, Real(0), eps, detail::kernel_policy<Policy>());
  }
};

/// Boussinesq pressure p ∝ 1/√(1 − r²): a rigid flat punch on an elastic
/// half-space, with an integrable singularity at the rim.
/// ⟨r⟩ = π/4, ⟨1/r⟩ = π/2, ⟨r²⟩ = 2/3.  For ε ≥ 1, 𝓕 = (asin k/k + √(1−k²))/2
/// with k = 1/ε (theory (B1)), which the tests use as a check.
template <class Real = double, class Policy = boost::math::policies::policy<>>
class boussinesq : public detail::profile_base<boussinesq<Real, Policy>, Real, Policy> {
 public:
  /// ⟨r⟩ = π/4.
  Real mean_radius() const { return boost::math::constants::pi<Real>() / 4; }
  /// ⟨1/r⟩ = π/2.
  Real mean_inverse_radius() const { return boost::math::constants::pi<Real>() / 2; }
  /// ⟨r²⟩ = 2/3.
  Real mean_square_radius() const { return Real(2) / 3; }
  /// 𝓕 and 𝓣 for 0 < ε < ∞: the hook that profile_base::force_torque() calls after
  /// its domain check and the limits ε = 0 (𝓕 = 0, 𝓣 = ⟨r⟩) and ε = ∞ (𝓕 = 1, 𝓣 = 0);
  /// call force_torque() instead.  Ring quadrature (theory §6), relative error ≲ 1e-13.
  force_torque_result<Real> general(Real eps) const {
    // Load per unit radius r/√(1 − r²), normalised.
    auto w = [](const detail::ring_node<Real>& n) {
      BOOST_MATH_STD_USING
      return n.r / sqrt(n.one_minus_r * (1 + n.r));
    };
    return detail::ring_integral(w, Real(0), eps, detail::kernel_policy<Policy>());
  }
};

/// A profile shrunk to the radius a ∈ (0, 1]: 𝓕_a(ε) = 𝓕(ε/a), 𝓣_a(ε) = a 𝓣(ε/a);
/// ⟨r⟩ → a⟨r⟩, ⟨1/r⟩ → ⟨1/r⟩/a, ⟨r²⟩ → a²⟨r²⟩.  With weighted_sum it builds
/// stepped profiles such as a two-tier disk.
template <class Profile>
class scaled : public detail::profile_base<scaled<Profile>, typename Profile::value_type,
                                           typename Profile::policy_type> {
 public:
  /// The floating-point type.
  using Real = typename Profile::value_type;
  /// `p` shrunk to radius a = `radius` ∈ (0, 1]; otherwise a domain error.
  scaled(Profile p, Real radius)
      : p_(std::move(p)),
        a_(detail::checked_parameter<Real>(radius, std::numeric_limits<Real>::min(), Real(1), false,
                                           "spinslide::scaled<%1%>::scaled",
                                           "Got radius = %1%, but it must be in (0, 1].")) {}
  /// a.
  Real radius() const { return a_; }
  /// ⟨r⟩ = a⟨r⟩_P.
  Real mean_radius() const { return a_ * p_.mean_radius(); }
  /// ⟨1/r⟩ = ⟨1/r⟩_P/a.
  Real mean_inverse_radius() const { return p_.mean_inverse_radius() / a_; }
  /// ⟨r²⟩ = a²⟨r²⟩_P.
  Real mean_square_radius() const { return a_ * a_ * p_.mean_square_radius(); }
  /// 𝓕 and 𝓣 for 0 < ε < ∞: the hook that profile_base::force_torque() calls after
  /// its domain check and the limits ε = 0 (𝓕 = 0, 𝓣 = ⟨r⟩) and ε = ∞ (𝓕 = 1, 𝓣 = 0);
  /// call force_torque() instead.  𝓕_P(ε/a) and a𝓣_P(ε/a).
  force_torque_result<Real> general(Real eps) const {
    const auto ft = p_.force_torque(eps / a_);
    return {ft.force, a_ * ft.torque};
  }

 private:
  Profile p_;
  Real a_;
};

/// A load-weighted sum of profiles: fraction w_i of the load is distributed
/// as profile i.  The weights are normalised; each must be ≥ 0 and finite and
/// their sum > 0.  Example, a two-tier disk carrying 60% of the load on
/// r < 1/2:  make_weighted_sum<double>({0.6, 0.4}, scaled(uniform_disk<>(), 0.5), annulus<>(0.5)).
template <class Real, class... Profiles>
class weighted_sum
    : public detail::profile_base<
          weighted_sum<Real, Profiles...>, Real,
          typename std::tuple_element<0, std::tuple<Profiles...>>::type::policy_type> {
 public:
  /// The number of parts.
  static constexpr std::size_t size = sizeof...(Profiles);
  /// Load fractions `weights` (normalised; each finite and ≥ 0, sum > 0,
  /// otherwise a domain error) of the `parts`.
  weighted_sum(const std::array<Real, size>& weights, Profiles... parts)
      : parts_(std::move(parts)...), w_(normalised(weights)) {}

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
  /// 𝓕 and 𝓣 for 0 < ε < ∞: the hook that profile_base::force_torque() calls after
  /// its domain check and the limits ε = 0 (𝓕 = 0, 𝓣 = ⟨r⟩) and ε = ∞ (𝓕 = 1, 𝓣 = 0);
  /// call force_torque() instead.  Σ wᵢ𝓕ᵢ(ε) and Σ wᵢ𝓣ᵢ(ε).
  force_torque_result<Real> general(Real eps) const {
    return {sum([eps](const auto& p) { return p.force(eps); }),
            sum([eps](const auto& p) { return p.torque(eps); })};
  }

 private:
  static std::array<Real, size> normalised(std::array<Real, size> w) {
    static const char* function = "spinslide::weighted_sum<%1%>::weighted_sum";
    Real largest = 0;
    for (Real& x : w) {
      if (!(x >= 0) || !(boost::math::isfinite)(x)) {
        x = boost::math::policies::raise_domain_error<Real>(
            function, "Got weight %1%, but every weight must be finite and >= 0.", x,
            boost::math::policies::policy<>());
      }
      if (x > largest) largest = x;
    }
    if (!(largest > 0))
      largest = boost::math::policies::raise_domain_error<Real>(
          function, "Got total weight %1%, but it must be > 0.", largest,
          boost::math::policies::policy<>());
    // Divided by the largest first, so that the sum cannot overflow.
    Real total = 0;
    for (Real& x : w) {
      x /= largest;
      total += x;
    }
    for (Real& x : w) x /= total;
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

/// Builds a weighted_sum; the weights are load fractions (normalised).
template <class Real, class... Profiles>
weighted_sum<Real, Profiles...> make_weighted_sum(const std::array<Real, sizeof...(Profiles)>& w,
                                                  Profiles... parts) {
  return weighted_sum<Real, Profiles...>(w, std::move(parts)...);
}

/// Any pressure p(r) ≥ 0 on inner ≤ r ≤ 1, given as a callable Real(Real).
/// The library normalises it by ∫ p(r) r dr (quadrature); a negative or
/// non-finite pressure met at any quadrature node, or a total that is zero
/// or overflows the type (relative to p at the middle of the support), is a
/// domain error.  Moments by quadrature at construction.  p may have
/// integrable singularities at the ends of [inner, 1].
template <class Real, class Pressure, class Policy = boost::math::policies::policy<>>
class radial_profile
    : public detail::profile_base<radial_profile<Real, Pressure, Policy>, Real, Policy> {
 public:
  /// p is called as p(r), or as p(r, 1 − r) if it accepts two arguments: then
  /// 1 − r is exact near the rim, which a pressure singular there needs for
  /// full accuracy (with p(r) alone, 1 − r is only known to ~1e-16 absolute,
  /// and a 1/√(1 − r) singularity then costs ~1e-8 relative).
  explicit radial_profile(Pressure p, Real inner = 0)
      : p_(std::move(p)),
        inner_(detail::checked_parameter<Real>(inner, Real(0), Real(1), true,
                                               "spinslide::radial_profile<%1%>::radial_profile",
                                               "Got inner = %1%, but it must be in [0, 1).")) {
    static const char* function = "spinslide::radial_profile<%1%>::radial_profile";
    boost::math::quadrature::tanh_sinh<Real, Policy> q;
    const Real tol = pow(boost::math::tools::epsilon<Real>(), Real(0.75));
    // p and λp are the same profile: p is divided by its value at the middle
    // of the support, so that a pressure of any size the type holds is
    // integrated without overflow.
    const Real half_width = (1 - inner_) / 2;  // 1 − middle, exact even where middle rounds to 1
    const Real p_middle = pressure(1 - half_width, half_width);
    if (p_middle > 0 && (boost::math::isfinite)(p_middle)) scale_ = p_middle;
    // ∫ p(r) r^{power+1} dr / scale over [inner, 1]: the load (power 0) and the
    // numerators of ⟨r^power⟩.  tanh_sinh's xc > 0 is 1 − r near the rim.
    // A sum that overflows even so (p spanning the type's whole range) is
    // reported as a load that is not finite.
    auto moment = [&](int power) {
      auto f = [&](Real r, Real xc) {
        const Real pr = pressure(r, xc > 0 ? xc : Real(1 - r)) / scale_;
        Real rp = r;
        for (int i = 0; i < power; ++i) rp *= r;
        return power == -1 ? pr : Real(rp * pr);
      };
      try {
        return q.integrate(f, inner_, Real(1), tol);
      } catch (const boost::math::evaluation_error&) {
        return std::numeric_limits<Real>::infinity();
      }
    };
    total_ = moment(0);
    if (!(total_ > 0) || !(boost::math::isfinite)(total_))
      total_ = boost::math::policies::raise_domain_error<Real>(
          function,
          "Got a total load of %1% (relative to p at the middle of the support), but the "
          "pressure must have a positive, finite total.",
          total_, Policy());
    mean_inverse_ = moment(-1) / total_;
    mean_ = moment(1) / total_;
    mean_square_ = moment(2) / total_;
  }

  /// The inner radius of the support.
  Real inner_radius() const { return inner_; }
  /// ⟨r⟩, by quadrature at construction.
  Real mean_radius() const { return mean_; }
  /// ⟨1/r⟩, by quadrature at construction.
  Real mean_inverse_radius() const { return mean_inverse_; }
  /// ⟨r²⟩, by quadrature at construction.
  Real mean_square_radius() const { return mean_square_; }
  /// The load per unit radius, r p(r) / ∫ r p dr (integrates to 1 over [inner, 1]).
  Real load_density(Real r) const { return r * (pressure(r, 1 - r) / scale_) / total_; }

  /// 𝓕 and 𝓣 for 0 < ε < ∞: the hook that profile_base::force_torque() calls after
  /// its domain check and the limits ε = 0 (𝓕 = 0, 𝓣 = ⟨r⟩) and ε = ∞ (𝓕 = 1, 𝓣 = 0);
  /// call force_torque() instead.  Ring quadrature of the normalised load.
  force_torque_result<Real> general(Real eps) const {
    auto w = [this](const detail::ring_node<Real>& n) {
      return n.r * (pressure(n.r, n.one_minus_r) / scale_) / total_;
    };
    return detail::ring_integral(w, inner_, eps, detail::kernel_policy<Policy>());
  }

 private:
  Real pressure(Real r, Real one_minus_r) const {
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
    if (!(p >= 0) || !(boost::math::isfinite)(p))
      return boost::math::policies::raise_domain_error<Real>(
          "spinslide::radial_profile<%1%>",
          "Got pressure %1%, but the pressure must be finite and >= 0 everywhere.", p, Policy());
    return p;
  }

  Pressure p_;
  Real inner_;
  Real scale_ = 1;  // p at the middle of the support (1 if that is 0)
  Real total_ = 0, mean_ = 0, mean_inverse_ = 0, mean_square_ = 0;
};

/// Builds a radial_profile from a callable p(r).
template <class Real = double, class Pressure>
radial_profile<Real, Pressure> make_radial_profile(Pressure p, Real inner = 0) {
  return radial_profile<Real, Pressure>(std::move(p), inner);
}

}  // namespace spinslide

#endif  // SPINSLIDE_PROFILE_HPP
