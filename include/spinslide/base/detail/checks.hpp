//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file checks.hpp
/// Every input check of the library (docs/architecture.md, "Input checks").
///
/// A check names the entry point that was called (`function`, Boost.Math's
/// format: "spinslide::annulus<%1%>::annulus(%1%)") and the argument that was
/// bad (`name`), and states the rule the argument breaks.  The rules are the
/// `argument_rule`s below; each is used wherever its kind of argument appears.
///
/// Two ways to report, one for functions and one for constructors:
///  - a function reports through its policy (`check`, `checked`): by default
///    std::domain_error; with errno_on_error or ignore_error the caller gets
///    NaN back and returns it (and computes nothing more, so that no second
///    error follows the first);
///  - a constructor throws std::domain_error whatever the class's policy
///    (`checked_constructor_argument`): it has no NaN to return in place of
///    an object, and an object built from a bad argument would answer every
///    later call wrongly.
#ifndef SPINSLIDE_BASE_DETAIL_CHECKS_HPP
#define SPINSLIDE_BASE_DETAIL_CHECKS_HPP

#include <boost/config.hpp>
#include <boost/math/constants/constants.hpp>
#include <boost/math/policies/error_handling.hpp>
#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/tools/precision.hpp>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace spinslide {
namespace detail {

/// The rules an argument can be held to.
enum class argument_rule {
  finite,               ///< x finite (a signed rate such as a spin)
  non_negative,         ///< x ≥ 0; +∞ allowed (a ratio ε: +∞ is pure sliding)
  finite_non_negative,  ///< 0 ≤ x < ∞ (speeds, forces, coefficients, weights)
  finite_positive,      ///< 0 < x < ∞ (lengths, gravity, γ for the flow and the systems)
  normal_positive,      ///< min_value ≤ x ≤ max_value (model parameters that are divided by)
  inner_ratio,          ///< 0 ≤ x < 1 (an inner radius in units of the contact radius)
  shrink_radius,        ///< min_value ≤ x² and x ≤ 1 (a radius a profile is shrunk to)
  throw_inertia_ratio,  ///< min_value ≤ γ ≤ max_value·epsilon (a throw integrated to its stop)
  contact_half_angle,   ///< 0 < x ≤ π (the half-angle of a contact segment of the unit disk)
  normal_load           ///< x ≥ min_value, +∞ allowed (a custom pressure's load per unit width)
};

template <class T>
bool satisfies(T x, argument_rule rule) {
  using boost::math::tools::epsilon;
  using boost::math::tools::max_value;
  using boost::math::tools::min_value;
  const bool finite = (boost::math::isfinite)(x);
  switch (rule) {
    case argument_rule::finite:
      return finite;
    case argument_rule::non_negative:
      return x >= 0;  // false for NaN
    case argument_rule::finite_non_negative:
      return x >= 0 && finite;
    case argument_rule::finite_positive:
      return x > 0 && finite;
    case argument_rule::normal_positive:
      return x >= min_value<T>() && finite;
    case argument_rule::inner_ratio:
      return x >= 0 && x < 1;
    case argument_rule::shrink_radius:
      return x > 0 && x <= 1 && x * x >= min_value<T>();
    case argument_rule::throw_inertia_ratio:
      // The integration to the stop runs in double (motion/detail/stop_flow.hpp): a
      // type wider than double keeps double's range.
      return x >= min_value<T>() && x <= max_value<T>() * epsilon<T>() &&
             x >= T(min_value<double>()) && x <= T(max_value<double>() * epsilon<double>());
    case argument_rule::contact_half_angle:
      return x > 0 && x <= boost::math::constants::pi<T>();
    case argument_rule::normal_load:
      return x >= min_value<T>();
  }
  return false;
}

inline const char* requirement(argument_rule rule) {
  switch (rule) {
    case argument_rule::finite:
      return "finite";
    case argument_rule::non_negative:
      return ">= 0";
    case argument_rule::finite_non_negative:
      return "finite and >= 0";
    case argument_rule::finite_positive:
      return "finite and > 0";
    case argument_rule::normal_positive:
      return "finite and at least the smallest normal number (it is divided by)";
    case argument_rule::inner_ratio:
      return "in [0, 1)";
    case argument_rule::shrink_radius:
      // a²⟨r²⟩ must not underflow (found by fuzz_profiles).
      return "in [sqrt(min_value), 1] (1.5e-154 to 1 for double): below it the mean square "
             "radius a^2<r^2> of the shrunk profile underflows";
    case argument_rule::throw_inertia_ratio:
      // Why the throws narrow γ's domain (found by fuzz_stop_time).
      return "in [min_value, max_value*epsilon] of its type, and of double for a wider type "
             "(2.2e-308 to 4.0e292 for double and long double): above it the rates gamma*F/T and "
             "gamma/T of the integration to the stop overflow, below it gamma has too few digits";
    case argument_rule::contact_half_angle:
      return "in (0, pi]";
    case argument_rule::normal_load:
      // A subnormal pressure is a staircase of multiples of the smallest
      // subnormal: its moments miss by up to 1 % (found by fuzz_profiles).
      return "at least the smallest normal number (2.2e-308 for double): a subnormal pressure has "
             "too few digits for its moments; scale it (p and any multiple of p are the same "
             "profile)";
  }
  return "";
}

/// Reports `value` of argument `name` through `pol`: "Got name = value, but
/// it must be requirement."  Returns what the policy returns (NaN unless it
/// throws).
template <class T, class Policy>
T raise_argument_error(const char* function, const char* name, const char* requirement, T value,
                       const Policy& pol) {
  // Built only on the error path: Boost formats the message into a string anyway.
  const std::string message =
      std::string("Got ") + name + " = %1%, but it must be " + requirement + ".";
  return boost::math::policies::raise_domain_error<T>(function, message.c_str(), value, pol);
}

/// True if `x` satisfies `rule`; otherwise reports it through `pol`, stores
/// the policy's result (NaN) in `*result` and returns false.
template <class T, class Policy>
bool check(const char* function, const char* name, T x, argument_rule rule, T* result,
           const Policy& pol) {
  if (satisfies(x, rule)) return true;
  *result = raise_argument_error(function, name, requirement(rule), x, pol);
  return false;
}

/// `x` if it satisfies `rule`, otherwise what `pol` returns for the error (NaN).
template <class T, class Policy>
T checked(const char* function, const char* name, T x, argument_rule rule, const Policy& pol) {
  T result = x;
  check(function, name, x, rule, &result, pol);
  return result;
}

/// `Policy` with domain errors that throw: constructors report through it.
template <class Policy>
using constructor_policy = typename boost::math::policies::normalise<
    Policy, boost::math::policies::domain_error<boost::math::policies::throw_on_error>>::type;

/// `x` if it satisfies `rule`; otherwise std::domain_error, whatever `Policy`
/// says (the constructor rule above).
template <class Policy = boost::math::policies::policy<>, class T>
T checked_constructor_argument(const char* function, const char* name, T x, argument_rule rule) {
  return checked(function, name, x, rule, constructor_policy<Policy>());
}

/// Refuses a constructor's argument that breaks a rule no `argument_rule`
/// states (the shape of a flat patch: too few vertices, a repeated vertex, a
/// non-convex outline): std::domain_error "Error in function <function>: Got
/// <name> = <value>, but it must be <requirement>.", whatever `Policy` says.
template <class Policy = boost::math::policies::policy<>, class T>
[[noreturn]] void refuse_constructor_argument(const char* function, const char* name,
                                              const char* requirement, T value) {
  raise_argument_error(function, name, requirement, value, constructor_policy<Policy>());
  throw std::domain_error(function);  // not reached: the policy throws
}

/// True if every one of `xs` is finite: x − x is 0 for a finite x and NaN
/// for ±∞ or NaN, so one comparison tests them all (the entry points' test
/// of good arguments, before any check one by one).
template <class... T>
bool all_finite(T... xs) {
  return ((xs - xs) + ...) == 0;
}

/// True once any of `xs` is NaN: an earlier check reported an error through a
/// policy that does not throw, and the entry point returns NaN rather than
/// compute on (and report a second, different error).
template <class... T>
bool any_reported(T... xs) {
  return ((boost::math::isnan)(xs) || ...);
}

/// A contact's radius a, normal load (force or impulse) and μ, checked.
template <class Real>
struct patch_values {
  Real radius;    ///< a > 0 (≥ 0 for the impulse law), finite
  Real normal;    ///< N or Λ ≥ 0, finite
  Real friction;  ///< μ ≥ 0, finite
};

/// The named inputs of a contact (force_contact or impulse_contact:
/// members radius, normal, friction, each with a `value`), checked; a
/// reported error leaves its value NaN.  The radius by `radius_rule`
/// (finite_non_negative for a law that takes a patch from nothing).
/// Always inlined: through contact_profile every law is instantiated for
/// each profile, so g++ stops inlining it (several callers), and the call
/// with its run-time rules cost a sticking impulse 24 instructions, 10 %
/// (tools/path_instructions.py, impulse_handle; inlined: within 3 % either way).
template <class Contact, class Policy>
BOOST_FORCEINLINE auto checked_patch(const char* function, const Contact& c, const Policy& pol,
                                     argument_rule radius_rule = argument_rule::finite_positive) {
  using Real = std::decay_t<decltype(c.radius.value)>;
  return patch_values<Real>{
      checked(function, "contact.radius", c.radius.value, radius_rule, pol),
      checked(function, "contact.normal", c.normal.value, argument_rule::finite_non_negative, pol),
      checked(function, "contact.friction", c.friction.value, argument_rule::finite_non_negative,
              pol)};
}

/// The initial conditions of a throw, checked (check_throw).
template <class Real>
struct throw_input {
  Real gamma;   ///< γ = I/(mR²)
  Real v0;      ///< the initial speed
  Real omega0;  ///< the initial spin
  /// False once a check reported an error through a policy that does not throw.
  bool valid() const { return !any_reported(gamma, v0, omega0); }
};

/// The checks of every entry point that integrates a throw to its stop: γ in
/// [min_value, max_value·epsilon], v0 and ω0 finite and ≥ 0.  A bad one is
/// reported through `pol` and comes back as NaN (throw_input::valid).
template <class Real, class Policy>
throw_input<Real> check_throw(const char* function, Real inertia_ratio, Real v0, Real omega0,
                              const Policy& pol) {
  return {
      checked(function, "inertia_ratio", inertia_ratio, argument_rule::throw_inertia_ratio, pol),
      checked(function, "v0", v0, argument_rule::finite_non_negative, pol),
      checked(function, "omega0", omega0, argument_rule::finite_non_negative, pol)};
}

/// The engine adapters' errors, one convention for all of them
/// (docs/engines.md, "Errors"): a number outside its domain is
/// std::domain_error naming the value (checked_constructor_argument, also
/// for a function's argument, such as a time step: an adapter has no NaN to
/// give back); a missing or wrong object (a null pointer, a pair of a body
/// with itself, an unknown name, an engine setting the adapter cannot work
/// with) is std::invalid_argument (`refuse`); an index or a pair that was
/// not coupled is std::out_of_range (`checked_index`).
[[noreturn]] inline void refuse(const char* function, const std::string& why) {
  throw std::invalid_argument(std::string(function) + ": " + why);
}

/// `pointer`, or std::invalid_argument "function: `what` is null".
template <class T>
T* required(const char* function, const char* what, T* pointer) {
  if (pointer == nullptr) refuse(function, std::string(what) + " is null");
  return pointer;
}

/// `index` if below `count`; otherwise std::out_of_range naming both
/// ("pair 5, but 2 pairs are coupled").
inline std::size_t checked_index(const char* function, const char* what, std::size_t index,
                                 std::size_t count) {
  if (index >= count)
    throw std::out_of_range(std::string(function) + ": " + what + " " + std::to_string(index) +
                            ", but " + std::to_string(count) + " are coupled");
  return index;
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_BASE_DETAIL_CHECKS_HPP
