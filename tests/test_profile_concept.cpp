//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The friction profile concept (profile_concept.hpp): every profile of the
// library models it, types that break one requirement do not, and the
// archetype — the smallest model — goes through every generic entry point,
// which proves that they ask for nothing beyond the concept.  Where the
// archetype's law (𝓕 = ε/(1 + ε), 𝓣 = 1/(1 + ε)) gives an answer in closed
// form, the entry point is run and checked against it.

#include <spinslide/base/friction_result.hpp>
#include <spinslide/base/named_inputs.hpp>
#include <spinslide/contact/contact_inputs.hpp>
#include <spinslide/contact/contact_law.hpp>
#include <spinslide/contact/planar_metric.hpp>
#include <spinslide/contact/spring_friction.hpp>
#include <spinslide/contact/trial_cap.hpp>
#include <spinslide/motion/batch_throws.hpp>
#include <spinslide/motion/dynamics.hpp>
#include <spinslide/motion/equations_of_motion.hpp>
#include <spinslide/motion/motion_types.hpp>
#include <spinslide/motion/tabulated_throw.hpp>
#include <spinslide/motion/terminal.hpp>
#include <spinslide/motion/terminal_state.hpp>
#include <spinslide/motion/throw_inputs.hpp>
#include <spinslide/values/approximations.hpp>
#include <spinslide/values/coupling.hpp>
#include <spinslide/values/cylinder.hpp>
#include <spinslide/values/force_torque_result.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/profile_concept.hpp>
#include <spinslide/values/radial_profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <type_traits>
#include <utility>

namespace {

using namespace spinslide;

// The named inputs (a, N, μ) of a contact, from plain numbers in this order.
spinslide::force_contact<double> contact_of(double radius, double normal, double mu) {
  return {spinslide::patch_radius<double>{radius}, spinslide::normal_force<double>{normal},
          spinslide::friction_coefficient<double>{mu}};
}
using archetype = friction_profile_archetype<double>;

// Every profile of the library.
static_assert(is_friction_profile<uniform_disk<>>::value);
static_assert(is_friction_profile<uniform_disk<float>>::value);
static_assert(is_friction_profile<uniform_disk<long double>>::value);
static_assert(is_friction_profile<annulus<>>::value);
static_assert(is_friction_profile<ring<>>::value);
static_assert(is_friction_profile<hertz<>>::value);
static_assert(is_friction_profile<boussinesq<>>::value);
static_assert(is_friction_profile<scaled<hertz<>>>::value);
static_assert(is_friction_profile<weighted_sum<double, uniform_disk<>, ring<>>>::value);
static_assert(is_friction_profile<tabulated_profile<>>::value);
static_assert(is_friction_profile<uncoupled_caps<>>::value);
static_assert(is_friction_profile<elliptic_limit_surface<>>::value);
static_assert(is_friction_profile<pade_approximation<>>::value);
static_assert(is_friction_profile<archetype>::value);
static_assert(is_friction_profile<const hertz<>&>::value, "references decay");
static_assert(is_friction_profile<radial_profile<double, double (*)(double)>>::value);

// Types that break one requirement each.
static_assert(!is_friction_profile<int>::value);
static_assert(!is_friction_profile<double>::value);
static_assert(!is_friction_profile<contact_law<>>::value);

// A complete profile but for the one thing its name says.
struct base_profile {
  using value_type = double;
  using policy_type = boost::math::policies::policy<>;
  force_torque_result<double> force_torque(double) const { return {0, 0}; }
  double force(double) const { return 0; }
  double torque(double) const { return 0; }
  double mean_radius() const { return 1; }
  double mean_inverse_radius() const { return 1; }
  double mean_square_radius() const { return 1; }
};
static_assert(is_friction_profile<base_profile>::value, "the control case models the concept");

struct without_square_radius {
  using value_type = double;
  using policy_type = boost::math::policies::policy<>;
  force_torque_result<double> force_torque(double) const { return {0, 0}; }
  double force(double) const { return 0; }
  double torque(double) const { return 0; }
  double mean_radius() const { return 1; }
  double mean_inverse_radius() const { return 1; }
};
static_assert(!is_friction_profile<without_square_radius>::value);

struct pair_instead_of_result : base_profile {
  std::pair<double, double> force_torque(double) const { return {0, 0}; }
};
static_assert(!is_friction_profile<pair_instead_of_result>::value);

struct float_moments_for_double : base_profile {
  float mean_radius() const { return 1; }
};
static_assert(!is_friction_profile<float_moments_for_double>::value);

struct integer_value_type : base_profile {
  using value_type = int;
};
static_assert(!is_friction_profile<integer_value_type>::value);

struct without_policy {
  using value_type = double;
  force_torque_result<double> force_torque(double) const { return {0, 0}; }
  double force(double) const { return 0; }
  double torque(double) const { return 0; }
  double mean_radius() const { return 1; }
  double mean_inverse_radius() const { return 1; }
  double mean_square_radius() const { return 1; }
};
static_assert(!is_friction_profile<without_policy>::value);

struct not_copyable : base_profile {
  not_copyable() = default;
  not_copyable(const not_copyable&) = delete;
};
static_assert(!is_friction_profile<not_copyable>::value);

struct force_torque_not_const : base_profile {
  force_torque_result<double> force_torque(double) { return {0, 0}; }
};
static_assert(!is_friction_profile<force_torque_not_const>::value);

#if defined(__cpp_concepts)
// The C++20 concept is the same predicate.
static_assert(friction_profile<hertz<>>);
static_assert(friction_profile<archetype>);
static_assert(!friction_profile<without_square_radius>);
static_assert(!friction_profile<pair_instead_of_result>);
template <friction_profile P>
constexpr bool constrained(const P&) {
  return true;
}
static_assert(constrained(uniform_disk<>()));
#endif

// The archetype's own values, against its closed form.
TEST(ProfileConcept, ArchetypeLaw) {
  const archetype p(0);
  EXPECT_EQ(p.force(1.0), 0.5);
  EXPECT_EQ(p.torque(3.0), 0.25);
  EXPECT_EQ(p.force_torque(HUGE_VAL).force, 1.0);
}

// The coupling inverses: 𝓕 = ε/(1 + ε) gives ε = F/(1 − F), 𝓣 = 1/(1 + ε)
// gives ε = 1/T − 1; the curve is 𝓣 = 1 − 𝓕.
TEST(ProfileConcept, ArchetypeThroughTheCoupling) {
  const archetype p(0);
  EXPECT_NEAR(ratio_from_force(p, 0.75), 3.0, 1e-14);
  EXPECT_NEAR(ratio_from_torque(p, 0.2), 4.0, 1e-14);
  EXPECT_NEAR(torque_at_force(p, 0.3), 0.7, 1e-15);
  EXPECT_NEAR(force_at_torque(p, 0.4), 0.6, 1e-15);
}

// The flow: f(ε) = ε − γ𝓕/𝓣 = ε(1 − γ), so g = 1 − γ has one sign for all
// ε: ε → ∞ (pure sliding) for γ < 1, ε → 0 (pure spinning) for γ > 1; the
// window ⟨r²⟩/2 < γ < 2⟨r⟩/⟨1/r⟩ is (1, 1), empty.
TEST(ProfileConcept, ArchetypeThroughTheTerminalAnalysis) {
  const archetype p(0);
  EXPECT_NEAR(ratio_flow(p, 2.0, 0.25), 1.5, 1e-15);
  EXPECT_EQ(terminal_motion(p, 0.5).regime, terminal_regime::pure_sliding);
  EXPECT_EQ(terminal_motion(p, 2.0).regime, terminal_regime::pure_spinning);
  EXPECT_EQ(terminal_motion(p, 0.5, 3.0).regime, terminal_regime::pure_sliding);
  const auto w = terminal_window(p);
  EXPECT_EQ(w.lower, 1.0);
  EXPECT_EQ(w.upper, 1.0);
}

// The systems, the contact law and the tables accept it; values where they
// are exact: pure sliding at ε = ∞ and a throw with ω0 = 0 (t* = v0).
TEST(ProfileConcept, ArchetypeThroughTheDynamicsTheLawAndTheTables) {
  const archetype p(0);
  const dimensionless_motion<archetype> sys(p, 0.5);
  motion_state<double> x{2.0, 0.0, 0.0, 0.0}, dxdt{};
  sys(x, dxdt, 0.0);
  EXPECT_EQ(dxdt[0], -1.0);  // pure sliding: 𝓕 = 1
  EXPECT_EQ(dxdt[1], 0.0);
  const si_motion<archetype> si(p, 0.05, 0.3, 9.81, 0.5);
  si(x, dxdt, 0.0);
  EXPECT_NEAR(dxdt[0], -0.3 * 9.81, 1e-15);
  EXPECT_EQ(stop_time(p, 0.5, 1.5, 0.0), 1.5);
  const contact_law<archetype> law(p, velocity_scale<double>{0.0});
  // ε = |v|/(a|ω|) = 1: |F| = μN/2, |T| = μNa/2.
  const auto f = law(std::array<double, 2>{0.3, 0.4}, 10.0, contact_of(0.05, 2.0, 0.5));
  EXPECT_NEAR(std::hypot(f.force[0], f.force[1]), 0.5, 1e-15);
  EXPECT_NEAR(f.torque, -0.025, 1e-16);
  const tabulated_profile<> table(p);
  EXPECT_NEAR(table.force(1.0), 0.5, 1e-14);
  const scaled<archetype> half(p, 0.5);
  EXPECT_NEAR(half.force(1.0), 2.0 / 3, 1e-15);  // 𝓕(ε/a) at ε/a = 2
  const auto sum = weighted_sum({1.0, 1.0}, p, p);
  EXPECT_NEAR(sum.torque(1.0), 0.5, 1e-15);
  EXPECT_EQ(pade_approximation<>::matching(p).mean_square_radius(), 2.0);
  const tabulated_throw<archetype> throws(p, 0.5);
  EXPECT_EQ(throws.stop_time(1.5, 0.0), 1.5);  // pure sliding: exact
}

// Issue 28: one name per thing (docs/architecture.md, rule 4): every public
// class template over a floating type names it value_type, the results and
// the named inputs as the profiles, systems, laws and tables do.
template <template <class> class C>
constexpr bool names_float() {
  return std::is_same<typename C<float>::value_type, float>::value &&
         std::is_same<typename C<long double>::value_type, long double>::value;
}
template <template <class, class> class C>
constexpr bool names_float_with_vector() {
  return std::is_same<typename C<std::array<float, 2>, float>::value_type, float>::value;
}
static_assert(names_float<force_torque_result>() && names_float<motion_sample>() &&
              names_float<stop_result>() && names_float<terminal_state>() &&
              names_float<inertia_window>() && names_float<ratio_flow_zero>() &&
              names_float<throw_start>() && names_float<tabulated_stop>() &&
              names_float<si_units>() && names_float<tangent_wrench>() &&
              names_float<curve_point>() && names_float<cylinder_friction>() &&
              names_float<segment_friction>() && names_float<tilt_integrals>());
static_assert(names_float<patch_radius>() && names_float<normal_impulse>() &&
              names_float<normal_force>() && names_float<tangential_stiffness>() &&
              names_float<twisting_stiffness>() && names_float<velocity_scale>() &&
              names_float<friction_coefficient>() && names_float<impulse_contact>() &&
              names_float<force_contact>() && names_float<spring_stiffness>() &&
              names_float<disk_radius>() && names_float<gravity>() &&
              names_float<initial_speed>() && names_float<initial_spin>());
// The one result family (issue 40): scalars, 2-vectors and 3-vectors.
template <class Real>
using scalar_result = friction_result<Real, Real>;
template <class Real>
using spatial_result = friction_result<std::array<Real, 3>, std::array<Real, 3>>;
template <class Real>
using impulse_of = impulse_result<std::array<Real, 2>, Real>;
static_assert(names_float<scalar_result>() && names_float<spatial_result>() &&
              names_float<impulse_of>());
static_assert(std::is_same<impulse_of<double>::quantity, impulse_quantity>::value &&
              std::is_same<scalar_result<double>::quantity, force_quantity>::value);
// (friction_result's third parameter has a default, which clang 14 does not
// let a two-parameter template template argument ignore.)
template <class Vec, class Real>
using planar_result = friction_result<Vec, Real>;
static_assert(names_float_with_vector<planar_result>() &&
              names_float_with_vector<spring_history>() &&
              names_float_with_vector<spring_trial>() &&
              names_float_with_vector<capped_friction>());

}  // namespace
