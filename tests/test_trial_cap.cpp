//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The DEM trial-state cap (trial_cap.hpp), against what defines it: a
// sticking trial is kept exactly; a slipping one lands on μN times the
// limit curve, along the trial force's direction and the torque's sign,
// with the trial's excess normal to the curve in the springs' energy metric
// ((x − 𝓕) = w ε (y − 𝓣), w = a²k_t/k_θ, the optimality condition of the
// convex projection), and the springs it keeps give the cap back with the
// damping.  And against spring_history_friction, which it serves (without
// damping, bit for bit), and the 2-D form against the 3-D one.

#include <gtest/gtest.h>

#include <spinslide/base/friction_result.hpp>
#include <spinslide/contact/contact_inputs.hpp>
#include <spinslide/contact/spring_friction.hpp>
#include <spinslide/contact/trial_cap.hpp>
#include <spinslide/values/contact_profile.hpp>
#include <spinslide/values/coupling.hpp>
#include <spinslide/values/profile.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace {

using namespace spinslide;
using vec2 = std::array<double, 2>;
using vec3 = std::array<double, 3>;

force_contact<double> contact(double a, double n, double mu) {
  return {patch_radius<double>{a}, normal_force<double>{n}, friction_coefficient<double>{mu}};
}

spring_stiffness<double> springs(double kt, double a) {
  return mindlin_springs(tangential_stiffness<double>{kt}, patch_radius<double>{a});
}

struct random_trial {
  spring_trial<vec2, double> trial;
  double a, n, mu, kt, kw;
};

random_trial make_trial(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1), pos(0.2, 2);
  random_trial r{};
  r.a = 0.05 * pos(rng);
  r.n = 10 * pos(rng);
  r.mu = 0.5 * pos(rng);
  r.kt = 1000 * pos(rng);
  r.kw = r.kt * r.a * r.a * pos(rng);  // not Marshall's: any torque weight
  // From well inside the limit set to twice beyond it.
  const double scale =
      r.mu * r.n / r.kt * std::exp(std::uniform_real_distribution<double>(-2, 0.7)(rng));
  r.trial = {{scale * u(rng), scale * u(rng)},
             scale * r.a * r.kt / r.kw * u(rng),
             {0.3 * r.mu * r.n * u(rng), 0.3 * r.mu * r.n * u(rng)},
             0.3 * r.mu * r.n * r.a * u(rng)};
  return r;
}

TEST(TrialCap, StickingKeepsTheTrialAndSlippingLandsOnTheCurveAlongItsNormal) {
  std::mt19937_64 rng(11);
  const hertz<> profile;
  int slips = 0, sticks = 0;
  for (int k = 0; k < 2000; ++k) {
    const random_trial c = make_trial(rng);
    const spring_stiffness<double> k_springs{tangential_stiffness<double>{c.kt},
                                             twisting_stiffness<double>{c.kw}};
    const auto r = cap_trial_state(profile, c.trial, k_springs, contact(c.a, c.n, c.mu));
    const double fx = -c.kt * c.trial.displacement[0] + c.trial.damping_force[0];
    const double fy = -c.kt * c.trial.displacement[1] + c.trial.damping_force[1];
    const double t = -c.kw * c.trial.twist + c.trial.damping_torque;
    const double load = c.mu * c.n;
    if (r.sticking) {
      ++sticks;
      EXPECT_EQ(r.force[0], fx);
      EXPECT_EQ(r.force[1], fy);
      EXPECT_EQ(r.torque, t);
      EXPECT_EQ(r.displacement, c.trial.displacement) << "sticking keeps the springs";
      EXPECT_EQ(r.twist, c.trial.twist);
      // Inside: the curve's torque at the trial's force is not below the trial's.
      EXPECT_LE(std::hypot(fx, fy) / load, 1.0);
      EXPECT_LE(std::fabs(t) / (load * c.a),
                torque_at_force(profile, std::hypot(fx, fy) / load) * (1 + 1e-12));
      continue;
    }
    ++slips;
    const double f = std::hypot(r.force[0], r.force[1]);
    const auto ft = profile.force_torque(r.ratio);
    EXPECT_NEAR(f / load, ft.force, 4e-15) << k;
    EXPECT_NEAR(std::fabs(r.torque) / (load * c.a), ft.torque, 4e-15) << k;
    EXPECT_NEAR(r.force[0] * fy - r.force[1] * fx, 0, 1e-12 * load * load) << "direction kept";
    EXPECT_GE(r.force[0] * fx + r.force[1] * fy, 0);
    EXPECT_GE(r.torque * t, 0) << "the torque's sign kept";
    // Normal to the curve in the springs' metric: (x − 𝓕) = w ε (y − 𝓣).
    const double w = c.a * c.a * c.kt / c.kw;
    const double x = std::hypot(fx, fy) / load, y = std::fabs(t) / (load * c.a);
    if (std::isfinite(r.ratio)) {
      EXPECT_NEAR(x - ft.force, w * r.ratio * (y - ft.torque), 1e-11 * (1 + x + w * r.ratio * y))
          << k;
    }
    // The springs it keeps give the cap back with the damping.
    EXPECT_NEAR(-c.kt * r.displacement[0] + c.trial.damping_force[0], r.force[0], 1e-13 * load);
    EXPECT_NEAR(-c.kt * r.displacement[1] + c.trial.damping_force[1], r.force[1], 1e-13 * load);
    EXPECT_NEAR(-c.kw * r.twist + c.trial.damping_torque, r.torque, 1e-13 * load * c.a);
    EXPECT_EQ(r.curve().ratio, r.ratio);
  }
  EXPECT_GT(slips, 400);
  EXPECT_GT(sticks, 400);
}

// Without damping, spring_history_friction is the cap on the stretched
// springs: the same numbers, bit for bit, and the same history.
TEST(TrialCap, IsWhatTheSpringHistoryLawCalls) {
  std::mt19937_64 rng(5);
  const uniform_disk<> profile;
  for (int k = 0; k < 500; ++k) {
    const random_trial c = make_trial(rng);
    const auto s = springs(c.kt, c.a);
    spring_history<vec2, double> history{{0, 0}, 0, {}};
    const auto law = spring_history_friction(profile, history, c.trial.displacement, c.trial.twist,
                                             s, contact(c.a, c.n, c.mu));
    const auto cap = cap_trial_state(
        profile, spring_trial<vec2, double>{c.trial.displacement, c.trial.twist, {}, 0}, s,
        contact(c.a, c.n, c.mu));
    EXPECT_EQ(law.sticking, cap.sticking);
    EXPECT_EQ(law.force, cap.force);
    EXPECT_EQ(law.torque, cap.torque);
    EXPECT_EQ(history.displacement, cap.displacement);
    EXPECT_EQ(history.twist, cap.twist);
    if (!cap.sticking) {
      EXPECT_EQ(history.curve.ratio, cap.curve().ratio);
    }
  }
}

// The same cap with world-frame 3-vectors in a tilted tangent plane: the
// 2-D answer rotated into it (the metric is isotropic in the plane).
TEST(TrialCap, ThreeComponentVectorsInATiltedPlane) {
  std::mt19937_64 rng(8);
  const hertz<> profile;
  const vec3 e1{0.6, 0.0, 0.8}, e2{0.0, 1.0, 0.0};  // orthonormal, normal (−0.8, 0, 0.6)
  auto lift = [&](const vec2& v) {
    return vec3{v[0] * e1[0] + v[1] * e2[0], v[0] * e1[1] + v[1] * e2[1],
                v[0] * e1[2] + v[1] * e2[2]};
  };
  for (int k = 0; k < 500; ++k) {
    const random_trial c = make_trial(rng);
    const auto s = springs(c.kt, c.a);
    const auto flat = cap_trial_state(profile, c.trial, s, contact(c.a, c.n, c.mu));
    const spring_trial<vec3, double> tilted{lift(c.trial.displacement), c.trial.twist,
                                            lift(c.trial.damping_force), c.trial.damping_torque};
    const auto r = cap_trial_state(profile, tilted, s, contact(c.a, c.n, c.mu));
    ASSERT_EQ(r.sticking, flat.sticking) << k;
    const vec3 expected = lift(flat.force), springs3 = lift(flat.displacement);
    const double load = c.mu * c.n;
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_NEAR(r.force[i], expected[i], 1e-14 * load) << k;
      EXPECT_NEAR(r.displacement[i], springs3[i], 1e-14 * load / c.kt) << k;
    }
    EXPECT_NEAR(r.torque, flat.torque, 1e-14 * load * c.a);
  }
}

// A start (the last slip's curve point) changes only how the search begins.
TEST(TrialCap, AStartChangesNothingButTheSearch) {
  std::mt19937_64 rng(3);
  const hertz<> profile;
  int slips = 0;
  for (int k = 0; k < 300; ++k) {
    const random_trial c = make_trial(rng);
    const auto s = springs(c.kt, c.a);
    const auto cold = cap_trial_state(profile, c.trial, s, contact(c.a, c.n, c.mu));
    if (cold.sticking || !std::isfinite(cold.ratio) || cold.ratio == 0) continue;
    ++slips;
    const auto near_point = profile.force_torque(cold.ratio * 1.01);
    const curve_point<double> starts[] = {
        cold.curve(),
        {cold.ratio * 1.01, near_point.force, near_point.torque,
         std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()},
        {0.3, 0.9, 0.1, 5.0, -1.0}};  // a wrong point: only a worse start
    for (const auto& start : starts) {
      const auto warm = cap_trial_state(profile, c.trial, s, contact(c.a, c.n, c.mu), start);
      EXPECT_FALSE(warm.sticking);
      EXPECT_NEAR(warm.force[0], cold.force[0], 1e-12 * c.mu * c.n) << k;
      EXPECT_NEAR(warm.torque, cold.torque, 1e-12 * c.mu * c.n * c.a) << k;
    }
  }
  EXPECT_GT(slips, 50);
}

// No load (a contact coming apart, or a load so small that the trial is
// beyond 2^1024 of it): no friction, the springs hold only the damping, and
// nothing is raised.
TEST(TrialCap, NoLoadNoFriction) {
  const hertz<> profile;
  const spring_trial<vec2, double> trial{{1e-3, -2e-3}, 0.5, {0.1, 0.2}, 0.01};
  for (double n : {0.0, 1e-320}) {
    const auto r = cap_trial_state(profile, trial, springs(1e3, 0.05), contact(0.05, n, 0.5));
    EXPECT_FALSE(r.sticking);
    EXPECT_EQ(r.force[0], 0);
    EXPECT_EQ(r.force[1], 0);
    EXPECT_EQ(r.torque, 0);
    EXPECT_DOUBLE_EQ(r.displacement[0], 0.1 / 1e3);
    EXPECT_DOUBLE_EQ(r.displacement[1], 0.2 / 1e3);
  }
}

TEST(TrialCap, BadArgumentsAreDomainErrors) {
  const hertz<> profile;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const spring_trial<vec2, double> good{{1e-3, 0}, 0, {0, 0}, 0};
  const spring_trial<vec2, double> bad{{nan, 0}, 0, {0, 0}, 0};
  const spring_trial<vec2, double> bad_damping{{0, 0}, 0, {0, 0}, nan};
  EXPECT_THROW(cap_trial_state(profile, bad, springs(1e3, 0.05), contact(0.05, 1, 0.5)),
               std::domain_error);
  EXPECT_THROW(cap_trial_state(profile, bad_damping, springs(1e3, 0.05), contact(0.05, 1, 0.5)),
               std::domain_error);
  EXPECT_THROW(cap_trial_state(profile, good, springs(1e3, 0.05), contact(-0.05, 1, 0.5)),
               std::domain_error);
  EXPECT_THROW(cap_trial_state(profile, good, springs(1e3, 0.05), contact(0.05, 1, 0.5),
                               curve_point<double>{-1, 0, 0, 0, 0}),
               std::domain_error);
  EXPECT_NO_THROW(cap_trial_state(profile, good, springs(1e3, 0.05), contact(0.05, 1, 0.5)));
}

// The one test of good arguments reads the trial's magnitudes, not each
// component: an infinite or NaN component of any input still fails it, the
// error names that input, and a trial that overflows from finite inputs is
// reported as such (not taken for a bad argument, nor capped).
std::string domain_error_of(const spring_trial<vec2, double>& t, const spring_stiffness<double>& k,
                            const force_contact<double>& c) {
  try {
    cap_trial_state(hertz<>(), t, k, c);
  } catch (const std::domain_error& e) {
    return e.what();
  }
  return "";
}
TEST(TrialCap, AnErrorNamesItsInputAndAnOverflowedTrialIsReported) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto k = springs(1e3, 0.05);
  const auto c = contact(0.05, 1, 0.5);
  using t = spring_trial<vec2, double>;
  EXPECT_NE(domain_error_of(t{{0, inf}, 0, {0, 0}, 0}, k, c).find("trial.displacement"),
            std::string::npos);
  // +∞ spring and +∞ damping: −k_t·∞ + ∞ is NaN, still caught.
  EXPECT_NE(domain_error_of(t{{inf, 0}, 0, {inf, 0}, 0}, k, c).find("trial.displacement"),
            std::string::npos);
  EXPECT_NE(domain_error_of(t{{0, 0}, 0, {0, -inf}, 0}, k, c).find("trial.damping_force"),
            std::string::npos);
  EXPECT_NE(domain_error_of(t{{0, 0}, nan, {0, 0}, 0}, k, c).find("trial.twist"),
            std::string::npos);
  const spring_stiffness<double> infinite{tangential_stiffness<double>{inf},
                                          twisting_stiffness<double>{1}};
  EXPECT_NE(domain_error_of(t{{1, 0}, 0, {0, 0}, 0}, infinite, c).find("springs.tangential"),
            std::string::npos);
  EXPECT_NE(domain_error_of(t{{1e-3, 0}, 0, {0, 0}, 0}, k, contact(0.05, inf, 0.5))
                .find("contact.normal"),
            std::string::npos);
  EXPECT_NE(domain_error_of(t{{1e-3, 0}, 0, {0, 0}, 0}, k, contact(0.05, 1, nan))
                .find("contact.friction"),
            std::string::npos);
  // Finite inputs whose trial force −k_t ξ overflows.
  const spring_stiffness<double> stiff{tangential_stiffness<double>{1e300},
                                       twisting_stiffness<double>{1}};
  EXPECT_NE(domain_error_of(t{{1e300, 0}, 0, {0, 0}, 0}, stiff, c).find("the trial force"),
            std::string::npos);
  EXPECT_EQ(domain_error_of(t{{1e-3, 0}, 0, {0, 0}, 0}, k, c), "");
}

// surely_sticks is the inner triangle |F|/(μN) + |T|/(μNa⟨r⟩) ≤ 1 of the
// trial (computed here in long double, away from its edge), and where it
// holds cap_trial_state sticks and keeps the trial bit for bit; between the
// triangle and the curve it decides nothing (false) while the cap sticks.
// cap_trial_state on a profile, or on the one a contact_profile holds.
template <class Profile, class... Args>
auto cap_on(const Profile& profile, const Args&... args) {
  return cap_trial_state(profile, args...);
}
template <class... Args>
auto cap_on(const contact_profile<double>& handle, const Args&... args) {
  return handle.visit([&](const auto& p) { return cap_trial_state(p, args...); });
}

// The trial's |F|/(μN) + |T|/(μNa⟨r⟩), in long double.
long double triangle_side(const random_trial& c, long double mean_radius) {
  const long double fx = -(long double)c.kt * c.trial.displacement[0] + c.trial.damping_force[0];
  const long double fy = -(long double)c.kt * c.trial.displacement[1] + c.trial.damping_force[1];
  const long double t = -(long double)c.kw * c.trial.twist + c.trial.damping_torque;
  const long double load = (long double)c.mu * c.n;
  return std::sqrt(fx * fx + fy * fy) / load + std::fabs(t) / (load * c.a * mean_radius);
}

// A sticking cap that kept the trial bit for bit: its force and torque, and
// the springs as they were.
template <class Result>
void expect_the_trial_kept(const Result& r, const random_trial& c, int k) {
  ASSERT_TRUE(r.sticking) << k;
  EXPECT_EQ(r.force[0], -c.kt * c.trial.displacement[0] + c.trial.damping_force[0]) << k;
  EXPECT_EQ(r.force[1], -c.kt * c.trial.displacement[1] + c.trial.damping_force[1]) << k;
  EXPECT_EQ(r.torque, -c.kw * c.trial.twist + c.trial.damping_torque) << k;
  EXPECT_EQ(r.displacement[0], c.trial.displacement[0]) << k;
  EXPECT_EQ(r.twist, c.trial.twist) << k;
}

template <class Profile>
void expect_surely_sticks_is_the_triangle(const Profile& profile, long double mean_radius) {
  std::mt19937_64 rng(12);
  int sure = 0, left_to_the_cap = 0;
  for (int k = 0; k < 3000; ++k) {
    const random_trial c = make_trial(rng);
    const spring_stiffness<double> kk{springs(c.kt, c.a).tangential,
                                      twisting_stiffness<double>{c.kw}};
    const auto law = contact(c.a, c.n, c.mu);
    const bool quick = surely_sticks(profile, c.trial, kk, law);
    const long double side = triangle_side(c, mean_radius);
    if (std::fabs(side - 1) > 1e-12L) {
      EXPECT_EQ(quick, side < 1) << k;
    }
    const auto r = cap_on(profile, c.trial, kk, law);
    sure += quick;
    left_to_the_cap += !quick && r.sticking;
    if (quick) {
      expect_the_trial_kept(r, c, k);
    }
  }
  EXPECT_GT(sure, 300);
  EXPECT_GT(left_to_the_cap, 30);
}

TEST(TrialCap, SurelySticksIsTheInnerTriangle) {
  expect_surely_sticks_is_the_triangle(hertz<>(), 3.0L * 3.14159265358979323846L / 16);
  expect_surely_sticks_is_the_triangle(uniform_disk<>(), 2.0L / 3);
  expect_surely_sticks_is_the_triangle(annulus<>(0.5), 14.0L / 18);
  expect_surely_sticks_is_the_triangle(contact_profile<double>(hertz<>()),
                                       3.0L * 3.14159265358979323846L / 16);
}

// It decides nothing for what cap_trial_state refuses (which says why).
TEST(TrialCap, SurelySticksDecidesNothingForBadArguments) {
  const hertz<> profile;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const spring_trial<vec2, double> good{{1e-6, 0}, 0, {0, 0}, 0};
  EXPECT_TRUE(surely_sticks(profile, good, springs(1e3, 0.05), contact(0.05, 1, 0.5)));
  EXPECT_FALSE(surely_sticks(profile, spring_trial<vec2, double>{{nan, 0}, 0, {0, 0}, 0},
                             springs(1e3, 0.05), contact(0.05, 1, 0.5)));
  EXPECT_FALSE(surely_sticks(profile, spring_trial<vec2, double>{{0, 0}, 0, {0, 0}, nan},
                             springs(1e3, 0.05), contact(0.05, 1, 0.5)));
  EXPECT_FALSE(surely_sticks(profile, good, springs(1e3, 0.05), contact(0.05, inf, 0.5)));
  EXPECT_FALSE(surely_sticks(profile, good, springs(1e3, 0.05), contact(0.05, 1, inf)));
  EXPECT_FALSE(surely_sticks(profile, good, springs(1e3, 0.05), contact(0.05, 0, 0.5)));
  EXPECT_FALSE(surely_sticks(profile, good, springs(1e3, 0.05), contact(0, 1, 0.5)));
  EXPECT_FALSE(surely_sticks(profile, good, springs(1e3, 0.05), contact(inf, 1, 0.5)));
  // A negative normal force and friction coefficient, whose product μN is
  // positive (it answered true until the cap's own first test shared it).
  EXPECT_FALSE(surely_sticks(profile, good, springs(1e3, 0.05), contact(0.05, -1, -0.5)));
  EXPECT_THROW(cap_trial_state(profile, good, springs(1e3, 0.05), contact(0.05, -1, -0.5)),
               std::domain_error);
  const spring_stiffness<double> soft{tangential_stiffness<double>{1e3},
                                      twisting_stiffness<double>{0}};
  EXPECT_FALSE(surely_sticks(profile, good, soft, contact(0.05, 1, 0.5)));
  const spring_stiffness<double> stiff{tangential_stiffness<double>{inf},
                                       twisting_stiffness<double>{1}};
  EXPECT_FALSE(surely_sticks(profile, good, stiff, contact(0.05, 1, 0.5)));
}

// float as double, to float's rounding.
TEST(TrialCap, FloatAgreesWithDouble) {
  std::mt19937_64 rng(9);
  for (int k = 0; k < 300; ++k) {
    const random_trial c = make_trial(rng);
    const auto d =
        cap_trial_state(hertz<double>(), c.trial, springs(c.kt, c.a), contact(c.a, c.n, c.mu));
    using vf = std::array<float, 2>;
    const spring_trial<vf, float> tf{
        {float(c.trial.displacement[0]), float(c.trial.displacement[1])},
        float(c.trial.twist),
        {float(c.trial.damping_force[0]), float(c.trial.damping_force[1])},
        float(c.trial.damping_torque)};
    const auto f = cap_trial_state(
        hertz<float>(), tf,
        mindlin_springs(tangential_stiffness<float>{float(c.kt)}, patch_radius<float>{float(c.a)}),
        force_contact<float>{patch_radius<float>{float(c.a)}, normal_force<float>{float(c.n)},
                             friction_coefficient<float>{float(c.mu)}});
    if (f.sticking != d.sticking) continue;  // on the boundary to float's rounding
    const double load = c.mu * c.n;
    EXPECT_NEAR(f.force[0], d.force[0], 2e-5 * load) << k;
    EXPECT_NEAR(f.torque, d.torque, 2e-5 * load * c.a) << k;
  }
}

}  // namespace
