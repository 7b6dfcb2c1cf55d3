//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The input checks (base/detail/checks.hpp): every entry point names itself and
// the bad argument in its message; every constructor throws std::domain_error
// with every policy (it has no NaN to return in place of an object); every
// function reports through its policy (NaN with errno_on_error and
// ignore_error; test_policies.cpp has the rest of those).

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/base/named_inputs.hpp>
#include <spinslide/contact/contact_inputs.hpp>
#include <spinslide/contact/contact_law.hpp>
#include <spinslide/motion/dynamics.hpp>
#include <spinslide/motion/equations_of_motion.hpp>
#include <spinslide/motion/tabulated_throw.hpp>
#include <spinslide/motion/terminal.hpp>
#include <spinslide/motion/throw_inputs.hpp>
#include <spinslide/values/approximations.hpp>
#include <spinslide/values/coupling.hpp>
#include <spinslide/values/cylinder.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/radial_profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace spinslide;

// The named inputs (a, N, μ) of a contact, from plain numbers in this order.
spinslide::force_contact<double> contact_of(double radius, double normal, double mu) {
  return {spinslide::patch_radius<double>{radius}, spinslide::normal_force<double>{normal},
          spinslide::friction_coefficient<double>{mu}};
}
using boost::math::policies::domain_error;
using boost::math::policies::errno_on_error;
using boost::math::policies::ignore_error;
using boost::math::policies::policy;
using errno_policy = policy<domain_error<errno_on_error>>;
using ignore_policy = policy<domain_error<ignore_error>>;
const double nan = std::numeric_limits<double>::quiet_NaN();

// f() must throw std::domain_error whose message contains every one of `parts`.
template <class F>
void expect_domain_error(F f, std::initializer_list<const char*> parts) {
  try {
    f();
    ADD_FAILURE() << "no std::domain_error; expected one naming " << *parts.begin();
  } catch (const std::domain_error& e) {
    const std::string what = e.what();
    for (const char* part : parts) EXPECT_NE(what.find(part), std::string::npos) << what;
  }
}

// ---------------------------------------------------------------- the rules

TEST(Checks, RulesAcceptAndRejectTheirEdges) {
  using detail::argument_rule;
  using detail::satisfies;
  const double inf = HUGE_VAL, min = std::numeric_limits<double>::min();
  const double sub = std::numeric_limits<double>::denorm_min();
  const double big = std::numeric_limits<double>::max() * std::numeric_limits<double>::epsilon();
  const double pi = boost::math::constants::pi<double>();
  struct row {
    argument_rule rule;
    std::vector<double> yes, no;
  };
  const row rows[] = {
      {argument_rule::finite, {-1.0, 0.0, 1e308}, {inf, -inf, nan}},
      {argument_rule::non_negative, {0.0, -0.0, sub, inf}, {-sub, -inf, nan}},
      {argument_rule::finite_non_negative, {0.0, sub, 1e308}, {-sub, inf, nan}},
      {argument_rule::finite_positive, {sub, 1e308}, {0.0, -1.0, inf, nan}},
      {argument_rule::normal_positive, {min, 1e308}, {sub, 0.0, inf, nan}},
      {argument_rule::inner_ratio, {0.0, std::nextafter(1.0, 0.0)}, {1.0, -sub, nan}},
      {argument_rule::shrink_radius,
       {std::sqrt(min), 1.0},
       {std::nextafter(std::sqrt(min), 0.0), min, sub, -0.5, -1.0, -inf, std::nextafter(1.0, 2.0),
        nan}},
      {argument_rule::throw_inertia_ratio, {min, big}, {sub, std::nextafter(big, inf), nan}},
      {argument_rule::contact_half_angle,
       {sub, pi},
       {0.0, -sub, std::nextafter(pi, 4.0), inf, nan}},
  };
  for (const row& r : rows) {
    for (double x : r.yes) EXPECT_TRUE(satisfies(x, r.rule)) << x << " rule " << int(r.rule);
    for (double x : r.no) EXPECT_FALSE(satisfies(x, r.rule)) << x << " rule " << int(r.rule);
  }
}

TEST(Checks, MessageNamesFunctionArgumentValueAndRule) {
  expect_domain_error(
      [] {
        detail::checked("spinslide::f<%1%>(%1%)", "radius", -2.0,
                        detail::argument_rule::finite_positive, policy<>());
      },
      {"spinslide::f<double>(double)", "Got radius = -2", "finite and > 0"});
}

// ---------------------------------------------------------------- constructors

// Each constructor with a bad argument, built with the class's Policy: it
// throws, names the class and the argument, whatever the policy.
template <class Policy>
void constructors_throw() {
  using disk = uniform_disk<double, Policy>;
  expect_domain_error([] { annulus<double, Policy>(1.5); }, {"annulus<double>", "inner_ratio"});
  expect_domain_error([] { scaled<disk>(disk(), 0.0); }, {"scaled<double>", "radius = 0"});
  expect_domain_error(
      [] {
        weighted_sum({-1.0, 1.0}, disk(), disk());
      },
      {"weighted_sum<double>", "a weight = -1"});
  expect_domain_error(
      [] {
        weighted_sum({0.0, 0.0}, disk(), disk());
      },
      {"weighted_sum<double>", "the largest weight = 0"});
  expect_domain_error([] { radial_profile<double, double (*)(double), Policy>(nullptr, 1.0); },
                      {"radial_profile<double>", "inner_ratio = 1"});
  expect_domain_error(
      [] {
        auto p = [](double) { return -1.0; };
        radial_profile<double, decltype(p), Policy>{p};
      },
      {"radial_profile<double>", "the pressure p(r) = -1"});
  expect_domain_error(
      [] {
        auto p = [](double) { return 0.0; };
        radial_profile<double, decltype(p), Policy>{p};
      },
      {"radial_profile<double>", "the total load"});
  expect_domain_error([] { uncoupled_caps<double, Policy>(0.0); },
                      {"uncoupled_caps<double>", "torque_cap = 0"});
  expect_domain_error([] { elliptic_limit_surface<double, Policy>(-1.0); },
                      {"elliptic_limit_surface<double>", "torque_axis = -1"});
  expect_domain_error([] { pade_approximation<double, Policy>(0.5, nan, 0.5); },
                      {"pade_approximation<double>", "mean_inverse_radius = nan"});
  expect_domain_error([] { tabulated_profile<double, Policy>(disk(), -1.0); },
                      {"tabulated_profile<double>", "tolerance = -1"});
  expect_domain_error([] { contact_law<disk>(disk(), velocity_scale<double>{-1.0}); },
                      {"contact_law<double>", "velocity_scale = -1"});
  expect_domain_error([] { dimensionless_motion<disk>(disk(), -1.0); },
                      {"dimensionless_motion<double>", "inertia_ratio = -1"});
  expect_domain_error([] { si_motion<disk>(disk(), 0.06, 0.2, 0.0, 0.5); },
                      {"si_motion<double>", "gravity = 0"});
  expect_domain_error([] { tabulated_throw<disk>(disk(), 1e300); },
                      {"tabulated_throw<double>", "inertia_ratio = ", "overflow"});
}

TEST(Checks, ConstructorsThrowWithTheDefaultPolicy) { constructors_throw<policy<>>(); }
TEST(Checks, ConstructorsThrowWithErrnoOnError) { constructors_throw<errno_policy>(); }
TEST(Checks, ConstructorsThrowWithIgnoreError) { constructors_throw<ignore_policy>(); }

// ---------------------------------------------------------------- functions

TEST(Checks, FunctionsNameThemselvesAndTheArgument) {
  expect_domain_error([] { hertz<>().force_torque(-1.0); },
                      {"spinslide::hertz<double>::force_torque(double)", "eps = -1"});
  expect_domain_error([] { uniform_disk<float>().torque(-1.0f); },
                      {"spinslide::uniform_disk<float>::torque(float)", "eps = -1"});
  expect_domain_error([] { tabulated_profile<>(ring<>()).force(nan); },
                      {"spinslide::tabulated_profile<double>", "eps = nan"});
  expect_domain_error([] { ratio_from_force(hertz<>(), 1.0); },
                      {"ratio_from_force<double>", "F = 1", "[0, 1)"});
  expect_domain_error([] { ratio_from_torque(annulus<>(0.5), 0.875); },
                      {"ratio_from_torque<double>", "T = 0.875"});
  expect_domain_error([] { ratio_flow(ring<>(), HUGE_VAL, 0.5); }, {"ratio_flow<double>", "eps"});
  expect_domain_error([] { terminal_motion(ring<>(), 0.5, -1.0); },
                      {"terminal_motion<double>", "initial_ratio = -1"});
  expect_domain_error([] { simulate_throw(ring<>(), 0.5, -1.0, 1.0); },
                      {"simulate_throw<double>", "v0 = -1"});
  expect_domain_error([] { stop_time(ring<>(), 0.0, 1.0, 1.0); },
                      {"spinslide::stop_time<double>(profile,", "inertia_ratio = 0"});
  expect_domain_error([] { stop_time(-1.0f, 1.0f); },
                      {"spinslide::stop_time<float>(profile,", "v0 = -1"});
  expect_domain_error([] { stop_time(1.0, -1.0); },
                      {"spinslide::stop_time<double>(double, double)", "omega0 = -1"});
  expect_domain_error([] { hertz<>().force(-2.0); },
                      {"spinslide::hertz<double>::force(double)", "eps = -2"});
  expect_domain_error(
      [] {
        simulate_throw_si(ring<>(), disk_radius{0.06}, friction_coefficient{0.2}, gravity{9.81},
                          0.5, initial_speed{1.0}, initial_spin{nan});
      },
      {"simulate_throw_si<double>", "omega0 = nan"});
  expect_domain_error(
      [] {
        simulate_throw_si(ring<>(), disk_radius{0.06}, friction_coefficient{-0.25}, gravity{9.81},
                          0.5, initial_speed{1.0}, initial_spin{1.0});
      },
      {"simulate_throw_si<double>", "friction_coefficient = -0.25"});
  expect_domain_error(
      [] {
        trajectory(ring<>(), 0.5, 1.0, 1.0, std::vector<double>{1.0, 0.5});
      },
      {"trajectory<double>", "a time = 0.5"});
  expect_domain_error(
      [] {
        const contact_law<> law(uniform_disk<>(), velocity_scale<double>{1e-6});
        law(std::array<double, 2>{1.0, 0.0}, 1.0, contact_of(0.05, -1.0, 0.3));
      },
      {"contact_law<double>::operator()", "contact.normal = -1"});
  expect_domain_error(
      [] {
        const contact_law<> law(uniform_disk<>(), velocity_scale<double>{1e-6});
        law(std::array<double, 2>{1.0, 0.0}, nan, contact_of(0.05, 1.0, 0.3));
      },
      {"contact_law<double>::operator()", "the spin = nan"});
  expect_domain_error([] { tilted_cylinder_friction(0.5, 0.05, 0.06, -0.25); },
                      {"tilted_cylinder_friction<double>", "friction_coefficient = -0.25"});
  expect_domain_error([] { tilted_cylinder_friction(0.5, 0.05, 0.0, 0.2); },
                      {"tilted_cylinder_friction<double>", "radius = 0"});
  expect_domain_error([] { truncated_pressure_friction(0.5, 4.0, 0.0); },
                      {"truncated_pressure_friction<double>", "contact_angle = 4", "(0, pi]"});
  expect_domain_error([] { truncated_pressure_friction(0.5, 1.0, nan); },
                      {"truncated_pressure_friction<double>", "direction = nan"});
  expect_domain_error([] { tilted_pressure_integrals(-0.5); },
                      {"tilted_pressure_integrals<double>", "eps = -0.5"});
}

// tilted_cylinder_friction, truncated_pressure_friction and
// tilted_pressure_integrals (cylinder.hpp): NaN for a bad argument; tipping
// over is an outcome, not an error: NaN numbers and `tipped` whatever the
// policy.
template <class Policy>
void cylinder_functions_return_nan() {
  const Policy pol;
  const auto c = tilted_cylinder_friction(0.5, -1.0, 0.06, 0.2, pol);
  EXPECT_TRUE(std::isnan(c.force[0]) && std::isnan(c.force[1]) && std::isnan(c.torque) &&
              std::isnan(c.centre[0]) && std::isnan(c.centre[1]) && std::isnan(c.contact_angle));
  const auto tips = tilted_cylinder_friction(2.0, 10.0, 0.06, 0.9, pol);
  EXPECT_EQ(tips.contact, cylinder_contact::tipped);
  EXPECT_TRUE(std::isnan(tips.force[0]) && std::isnan(tips.centre[1]));
  const auto s = truncated_pressure_friction(0.5, 0.0, 0.0, pol);
  EXPECT_TRUE(std::isnan(s.force[0]) && std::isnan(s.torque) && std::isnan(s.centre));
  const auto i = tilted_pressure_integrals(nan, pol);
  EXPECT_TRUE(std::isnan(i.A) && std::isnan(i.B) && std::isnan(i.C));
}

// simulate_throw_si and tabulated_throw, through the profile's policy.
template <class Policy>
void throw_functions_return_nan() {
  using disk = uniform_disk<double, Policy>;
  const auto r = simulate_throw_si(disk(), disk_radius{0.06}, friction_coefficient{0.2},
                                   gravity{-9.81}, 0.5, initial_speed{1.0}, initial_spin{1.0});
  EXPECT_TRUE(std::isnan(r.time) && std::isnan(r.distance) && std::isnan(r.angle));
  const tabulated_throw<disk> table(disk(), 0.5);
  EXPECT_TRUE(std::isnan(table.distance(-1.0, 1.0)));
  EXPECT_TRUE(std::isnan(table.stop_time(1.0, nan)));
}

// The functions that had no policy before the checks were gathered
// (cylinder.hpp) and the entry points not in test_policies.cpp: NaN through
// a policy that does not throw, errno EDOM with errno_on_error.
template <class Policy>
void functions_return_nan() {
  errno = 0;
  cylinder_functions_return_nan<Policy>();
  throw_functions_return_nan<Policy>();
  EXPECT_EQ(errno, (std::is_same<Policy, errno_policy>::value ? EDOM : 0));
}

TEST(Checks, FunctionsReturnNanWithErrnoOnError) { functions_return_nan<errno_policy>(); }
TEST(Checks, FunctionsReturnNanWithIgnoreError) { functions_return_nan<ignore_policy>(); }

}  // namespace

// issue 27 - the engine adapters' errors, one convention (checks.hpp): a
// missing object and a wrong one are std::invalid_argument naming the
// entry point, an index beyond those coupled is std::out_of_range naming
// the index and the count.
TEST(Checks, AdapterErrorsFollowOneConvention) {
  const char* function = "spinslide::some_adapter::couple";
  int object = 0;
  EXPECT_EQ(detail::required(function, "the body", &object), &object);
  try {
    detail::required(function, "the body", static_cast<int*>(nullptr));
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "spinslide::some_adapter::couple: the body is null");
  }
  EXPECT_THROW(detail::refuse(function, "a == b"), std::invalid_argument);
  EXPECT_EQ(detail::checked_index(function, "pair", 1, 2), 1u);
  try {
    detail::checked_index(function, "pair", 5, 2);
    ADD_FAILURE();
  } catch (const std::out_of_range& e) {
    EXPECT_EQ(std::string(e.what()), "spinslide::some_adapter::couple: pair 5, but 2 are coupled");
  }
}
