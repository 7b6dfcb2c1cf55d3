//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file coupling.hpp
/// The force–torque coupling curve of any profile: the exact limit curve
/// 𝓣(𝓕) of the contact, and the inverses ε(𝓕) and ε(𝓣).
///
/// Both 𝓕 and 𝓣 are strictly monotonic in ε for every profile (docs/theory.md,
/// (I2): 𝓕′ > 0 and 𝓣′ = −ε𝓕′), so each inverse is a single root, found by
/// Boost's toms748_solve to full precision.

#ifndef SPINSLIDE_VALUES_COUPLING_HPP
#define SPINSLIDE_VALUES_COUPLING_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/values/profile_concept.hpp>

#include <boost/math/tools/roots.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <utility>

namespace spinslide {

namespace detail {

// A bracket [lo, hi] of the ratio where `below` (g short of its target)
// turns false, grown geometrically from ε = 1 (at most ~1100 steps, the
// exponent range of the type; [0, ε] below the normal numbers).  Where the
// target lies beyond the largest ratio, both ends are still `below`.
template <class Real, class Below>
std::pair<Real, Real> bracket_from_one(Below below) {
  const Real big = boost::math::tools::max_value<Real>() / 8;
  const Real tiny = boost::math::tools::min_value<Real>() * 8;
  Real lo = 1, hi = 1;
  if (below(Real(1))) {
    while (below(hi) && hi < big) hi *= 4;
    return {hi / 4, hi};
  }
  while (!below(lo) && lo > tiny) lo /= 4;
  if (!below(lo)) return {Real(0), lo};  // a root among the subnormal ratios: g(0) brackets it
  return {lo, lo * 4};
}

// For a target that g never crosses: if it is within 4 ulp of g at the far
// end `end` (a quadrature profile's 𝓕 may level off an ulp below 1; found
// by fuzz_coupling: a thin annulus, 𝓕 ≤ 1 − 2⁻⁵² where the target was
// 1 − 2⁻⁵³), the ratio where g first reaches that level, by bisection in
// ln ε between 1 (short of it) and `end`; otherwise a domain error.
template <class Real, class G, class Policy>
Real first_ratio_at_level(G g, Real target, Real end, const char* function, const Policy& pol) {
  BOOST_MATH_STD_USING
  const Real level = g(end), tolerance = 4 * boost::math::tools::epsilon<Real>();
  if (!(fabs(level - target) <= tolerance * fabs(target)) || g(Real(1)) == level)
    return raise_argument_error(
        function, "the target",
        "reached at a finite ratio of this type, which this profile does not", target, pol);
  Real a = 1, b = end;  // g(a) ≠ level, g(b) = level
  for (int i = 0; i < 200 && fabs(b / a - 1) > tolerance; ++i) {
    const Real m = exp((log(a) + log(b)) / 2);
    (g(m) == level ? b : a) = m;
  }
  return b;
}

// Solves g(ε) = target for a g that is monotonic on [0, ∞), given the
// direction: a bracket from bracket_from_one, refined by TOMS 748 to full
// precision.  A target not reached below max_value/2 is a domain error, and
// so is one that g jumps over at ε = 0 (`jumps_at_zero`: the uncoupled caps'
// 𝓕, whose ⟨1/r⟩ is infinite, goes from 0 to 1 there).
template <class Real, class G, class Policy>
Real invert_monotonic(G g, Real target, bool increasing, bool jumps_at_zero, const char* function,
                      const Policy& pol) {
  auto f = [&](Real e) { return g(e) - target; };
  // Sign of f moves from "below" to "above" as ε grows when increasing.
  auto below = [&](Real e) { return increasing ? f(e) < 0 : f(e) > 0; };
  const auto bracket = bracket_from_one<Real>(below);
  Real lo = bracket.first, hi = bracket.second;  // not const: returned (a class Real moves)
  const Real flo = f(lo), fhi = f(hi);
  if (flo == 0) return lo;
  if (fhi == 0) return hi;
  if ((flo < 0) == (fhi < 0))  // reached only beyond the largest ratio of the type, or never
    return first_ratio_at_level(g, target, (flo < 0) == increasing ? hi : lo, function, pol);
  boost::uintmax_t max_iter = boost::math::policies::get_max_root_iterations<Policy>();
  const auto r = boost::math::tools::toms748_solve(
      f, lo, hi, flo, fhi, boost::math::tools::eps_tolerance<Real>(), max_iter, pol);
  Real root = (r.first + r.second) / 2;  // not const: returned
  if (jumps_at_zero && root < boost::math::tools::min_value<Real>())
    return raise_argument_error(function, "the target",
                                "reached at some ratio, but this profile jumps over it at 0",
                                target, pol);
  return root;
}

}  // namespace detail

/// ε(𝓕): the ratio at which `profile` has friction force F.
/// F = 0 gives 0; F outside [0, 1) or NaN is a domain error (by default
/// std::domain_error), and so is an F that the profile reaches only beyond the
/// type's largest ratio, or never (the uncoupled caps jump from 0 to 1).  Round trip:
/// profile.force(ratio_from_force(p, F)) = F.
template <class Profile, class Real>
Real ratio_from_force(const Profile& profile, Real F) {
  static_assert(detail::requires_profile<Profile>());
  using Policy = typename Profile::policy_type;
  static const char* function = "spinslide::ratio_from_force<%1%>(profile, %1%)";
  if (!(F >= 0 && F < 1))
    return detail::raise_argument_error(function, "F", "in [0, 1), where a profile's force lies", F,
                                        Policy());
  if (F == 0) return 0;
  const bool jumps = !(boost::math::isfinite)(profile.mean_inverse_radius());  // 𝓕′(0) = ⟨1/r⟩/2
  return detail::invert_monotonic<Real>([&](Real e) { return profile.force(e); }, F, true, jumps,
                                        function, Policy());
}

/// ε(𝓣): the ratio at which `profile` has friction torque T.
/// T = ⟨r⟩ gives 0; T outside (0, ⟨r⟩] or NaN is a domain error, and so is a
/// T that the profile reaches only beyond the type's largest ratio (T below
/// about ⟨r²⟩/max_value), or never.
template <class Profile, class Real>
Real ratio_from_torque(const Profile& profile, Real T) {
  static_assert(detail::requires_profile<Profile>());
  using Policy = typename Profile::policy_type;
  static const char* function = "spinslide::ratio_from_torque<%1%>(profile, %1%)";
  const Real top = profile.mean_radius();
  if (!(T > 0 && T <= top))
    return detail::raise_argument_error(
        function, "T", "in (0, <r>], where this profile's torque lies", T, Policy());
  if (T == top) return 0;
  return detail::invert_monotonic<Real>([&](Real e) { return profile.torque(e); }, T, false, false,
                                        function, Policy());
}

/// 𝓣(𝓕): the exact limit curve of the contact, the largest torque that can
/// act together with force F.  Domain as ratio_from_force; 𝓣(0) = ⟨r⟩.
template <class Profile, class Real>
Real torque_at_force(const Profile& profile, Real F) {
  return profile.torque(ratio_from_force(profile, F));
}

/// 𝓕(𝓣): the same curve read the other way.  Domain as ratio_from_torque.
template <class Profile, class Real>
Real force_at_torque(const Profile& profile, Real T) {
  return profile.force(ratio_from_torque(profile, T));
}

}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_COUPLING_HPP
