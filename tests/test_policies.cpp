//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The Boost.Math error policies besides the default throw (issue 8, item 4):
// with domain_error<errno_on_error> a bad input returns NaN and sets errno to
// EDOM; with domain_error<ignore_error> it returns NaN and leaves errno alone
// (Boost.Math's documented behaviour for domain errors).  Checked for every
// entry point that takes a policy: the disk functions and the batch, the
// profiles (their class policy), the coupling inverses, the terminal
// analysis, the dynamics and the contact law.  Constructors (annulus(b),
// contact_law(..., v_s), ...) throw with every policy: an object is never
// built in a bad state.
#include <gtest/gtest.h>

#include <spinslide/contact/contact_inputs.hpp>
#include <spinslide/contact/contact_law.hpp>
#include <spinslide/motion/dynamics.hpp>
#include <spinslide/motion/terminal.hpp>
#include <spinslide/values/coupling.hpp>
#include <spinslide/values/disk.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include <array>
#include <cerrno>
#include <cmath>
#include <limits>

namespace {

// The named inputs (a, N, μ) of a contact, from plain numbers in this order.
spinslide::force_contact<double> contact_of(double radius, double normal, double mu) {
  return {spinslide::patch_radius<double>{radius}, spinslide::normal_force<double>{normal},
          spinslide::friction_coefficient<double>{mu}};
}

using namespace boost::math::policies;
using errno_policy = policy<domain_error<errno_on_error>>;
using ignore_policy = policy<domain_error<ignore_error>>;

// Runs f(), which must return NaN; with errno_on_error errno must become EDOM,
// with ignore_error stay 0.
template <class Policy, class F>
void expect_nan(F f, const char* what) {
  errno = 0;
  const double r = f();
  EXPECT_TRUE(std::isnan(r)) << what << " returned " << r;
  if (std::is_same<Policy, errno_policy>::value)
    EXPECT_EQ(errno, EDOM) << what;
  else
    EXPECT_EQ(errno, 0) << what;
}

template <class Policy>
void check_all() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_nan<Policy>([] { return spinslide::force(-1.0, Policy()); }, "force(-1)");
  expect_nan<Policy>([&] { return spinslide::torque(nan, Policy()); }, "torque(NaN)");
  expect_nan<Policy>([] { return spinslide::force_derivative(-2.0, Policy()); },
                     "force_derivative(-2)");
  expect_nan<Policy>([] { return spinslide::torque_derivative(-2.0, Policy()); },
                     "torque_derivative(-2)");
  expect_nan<Policy>([] { return spinslide::force_torque(-1.0, Policy()).torque; },
                     "force_torque(-1)");
  expect_nan<Policy>([] { return double(spinslide::force(-1.0f, Policy())); }, "force(-1.0f)");
  expect_nan<Policy>(
      [] {
        const double e[] = {0.5, -1.0};
        double f[2], t[2];
        spinslide::force_torque_batch(e, 2, f, t, Policy());
        return f[0] == spinslide::force(0.5) ? t[1] : 0.0;
      },
      "force_torque_batch with a bad element");

  const spinslide::uniform_disk<double, Policy> disk;
  const spinslide::annulus<double, Policy> cd(0.125);
  const spinslide::hertz<double, Policy> sphere;
  expect_nan<Policy>([&] { return disk.force(-1.0); }, "uniform_disk.force(-1)");
  expect_nan<Policy>([&] { return cd.torque(nan); }, "annulus.torque(NaN)");
  expect_nan<Policy>([&] { return sphere.force_torque(-3.0).force; }, "hertz.force_torque(-3)");
  const spinslide::tabulated_profile<double, Policy> tab{spinslide::uniform_disk<>()};
  expect_nan<Policy>([&] { return tab.force(-1.0); }, "tabulated_profile.force(-1)");

  expect_nan<Policy>([&] { return spinslide::ratio_from_force(cd, 1.5); }, "ratio_from_force(1.5)");
  expect_nan<Policy>([&] { return spinslide::ratio_from_torque(cd, 0.9); },
                     "ratio_from_torque(0.9 > <r>)");
  expect_nan<Policy>([&] { return spinslide::torque_at_force(disk, -0.1); },
                     "torque_at_force(-0.1)");

  expect_nan<Policy>([&] { return spinslide::ratio_flow(disk, -1.0, 0.5); }, "ratio_flow(eps < 0)");
  expect_nan<Policy>([&] { return spinslide::terminal_motion(disk, -0.5).ratio; },
                     "terminal_motion(gamma < 0)");
  expect_nan<Policy>([&] { return spinslide::stop_time(disk, 0.5, -1.0, 1.0); },
                     "stop_time(profile, v0 < 0)");
  expect_nan<Policy>([&] { return spinslide::simulate_throw(disk, nan, 1.0, 1.0).time; },
                     "simulate_throw(gamma NaN)");

  const spinslide::contact_law<spinslide::uniform_disk<double, Policy>> law(
      spinslide::uniform_disk<double, Policy>(), spinslide::velocity_scale<double>{1e-6});
  expect_nan<Policy>(
      [&] {
        return law(std::array<double, 2>{0.3, 0.4}, 1.0, contact_of(-0.05, 2.0, 0.5)).torque;
      },
      "contact_law(radius < 0)");
  expect_nan<Policy>(
      [&] {
        return law(std::array<double, 2>{nan, 0.4}, 1.0, contact_of(0.05, 2.0, 0.5)).force[0];
      },
      "contact_law(velocity NaN)");
}

TEST(Policies, ErrnoOnErrorReturnsNanAndSetsEdom) { check_all<errno_policy>(); }
TEST(Policies, IgnoreErrorReturnsNan) { check_all<ignore_policy>(); }

TEST(Policies, ConstructorsThrowWithEveryPolicy) {
  EXPECT_THROW((spinslide::annulus<double, ignore_policy>(1.5)), std::domain_error);
  EXPECT_THROW((spinslide::contact_law<spinslide::uniform_disk<double, ignore_policy>>(
                   spinslide::uniform_disk<double, ignore_policy>(),
                   spinslide::velocity_scale<double>{-1.0})),
               std::domain_error);
}

}  // namespace
