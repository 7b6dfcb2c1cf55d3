//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The impulse law of a flat patch (contact/patch_impulse.hpp): the velocity
// after the step is the twist whose friction wrench is the impulse over μΛ
// (the exact law at the step's end), the kinetic energy falls, a stopping
// impulse inside the set sticks exactly, and a 256-gon agrees with the
// round disk's impulse law.
#include <gtest/gtest.h>

#include <spinslide/contact/contact_inputs.hpp>
#include <spinslide/contact/impulse_friction.hpp>
#include <spinslide/contact/patch_impulse.hpp>
#include <spinslide/contact/planar_metric.hpp>
#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/polygon_patch.hpp>
#include <spinslide/values/profile.hpp>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "random_metric.hpp"
#include "regular_polygon.hpp"

namespace {

using spinslide::centre_of_pressure;
using spinslide::friction_coefficient;
using spinslide::normal_impulse;
using spinslide::patch_impulse_contact;
using spinslide::planar_metric;
using spinslide::polygon_patch;
using point = std::array<double, 2>;
using matrix = std::array<std::array<double, 3>, 3>;

// The effective inverse mass of a box of mass m and yaw inertia I touching
// at the patch origin offset by r from its centre (a lever arm couples
// sliding and spin), plus a random positive semi-definite part.
matrix inverse_mass(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const double m = 2 + u(rng), inertia = 0.1 + 0.05 * u(rng);
  const point r{0.1 * u(rng), 0.1 * u(rng)};
  // v_origin = v_c + ω ẑ × r: the velocity change per impulse (P, L) at the origin.
  const std::array<double, 3> a{-r[1], r[0], 1};
  matrix w{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) w[i][j] = a[i] * a[j] / inertia;
  w[0][0] += 1 / m;
  w[1][1] += 1 / m;
  return w;
}

using spinslide_test::times;

double energy(const matrix& w_inverse, const std::array<double, 3>& v) {
  const auto y = times(w_inverse, v);
  return (v[0] * y[0] + v[1] * y[1] + v[2] * y[2]) / 2;
}

TEST(PatchImpulse, EndsOnTheExactLawAndLowersTheEnergy) {
  const std::vector<point> sole{{-0.1, -0.04}, {0.12, -0.04}, {0.12, 0.06}, {-0.1, 0.06}};
  const std::vector<polygon_patch<double>> patches{
      polygon_patch<double>(sole),
      polygon_patch<double>(sole, centre_of_pressure<double>{{0.1, 0.05}}),
      polygon_patch<double>::segment({-0.1, -0.04}, {0.12, -0.04})};
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(-1, 1);
  int slips = 0, sticks = 0;
  for (const auto& patch : patches) {
    for (int k = 0; k < 60; ++k) {
      const planar_metric<double> w(inverse_mass(rng));
      const std::array<double, 3> v{0.3 * u(rng), 0.3 * u(rng), 5 * u(rng)};
      const double lambda = k % 3 == 0 ? 20.0 : 0.5 * (1 + u(rng)), mu = 0.3;
      const auto r = spinslide::impulse_friction(
          patch, std::array<double, 2>{v[0], v[1]}, v[2], w,
          patch_impulse_contact<double>{normal_impulse<double>{lambda},
                                        friction_coefficient<double>{mu}});
      const std::array<double, 3> p{r.force[0], r.force[1], r.torque};
      const auto dv = times(w.entries(), p);
      const std::array<double, 3> after{v[0] + dv[0], v[1] + dv[1], v[2] + dv[2]};
      EXPECT_LE(energy(w.inverse(), after), energy(w.inverse(), v) * (1 + 1e-14));
      if (r.sticking) {
        ++sticks;
        for (double x : after) EXPECT_NEAR(x, 0.0, 1e-12);
        continue;
      }
      ++slips;
      // The slip is the velocity after, and the impulse its friction wrench times μΛ.
      const double speed = std::fabs(v[0]) + std::fabs(v[1]) + 0.1 * std::fabs(v[2]);
      EXPECT_NEAR(r.slip.velocity[0], after[0], 1e-10 * speed);
      EXPECT_NEAR(r.slip.velocity[1], after[1], 1e-10 * speed);
      EXPECT_NEAR(r.slip.omega, after[2], 1e-9 * speed);
      const auto f = spinslide::friction_wrench(patch, r.slip);
      EXPECT_NEAR(p[0], mu * lambda * f.force[0], 1e-12 * mu * lambda);
      EXPECT_NEAR(p[1], mu * lambda * f.force[1], 1e-12 * mu * lambda);
      EXPECT_NEAR(p[2], mu * lambda * f.torque, 1e-12 * mu * lambda * patch.radius());
    }
  }
  EXPECT_GT(slips, 50);
  EXPECT_GT(sticks, 10);
}

TEST(PatchImpulse, ManyGonAgreesWithTheRoundDisk) {
  const double a = 0.05;
  const polygon_patch<double> patch(spinslide_test::regular_polygon(256, a));
  const auto disk = spinslide::uniform_disk<>();
  std::mt19937 rng(37);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 60; ++k) {
    const planar_metric<double> w(inverse_mass(rng));
    const std::array<double, 3> v{0.2 * u(rng), 0.2 * u(rng), 8 * u(rng)};
    const double lambda = 0.02, mu = 0.4;
    const auto flat = spinslide::impulse_friction(
        patch, std::array<double, 2>{v[0], v[1]}, v[2], w,
        patch_impulse_contact<double>{normal_impulse<double>{lambda},
                                      friction_coefficient<double>{mu}});
    // The polygon's radius is a's: the disk of radius a (inscribed within (π/n)²/2).
    const auto round = spinslide::impulse_friction(
        disk, std::array<double, 2>{v[0], v[1]}, v[2], w,
        spinslide::impulse_contact<double>{spinslide::patch_radius<double>{a},
                                           normal_impulse<double>{lambda},
                                           friction_coefficient<double>{mu}});
    const double scale = mu * lambda;
    EXPECT_NEAR(flat.force[0], round.force[0], 2e-4 * scale);
    EXPECT_NEAR(flat.force[1], round.force[1], 2e-4 * scale);
    EXPECT_NEAR(flat.torque, round.torque, 2e-4 * scale * a);
  }
}

TEST(PatchImpulse, NoLoadNoImpulseAndBadArgumentsAreErrors) {
  const polygon_patch<double> patch({{0, 0}, {1, 0}, {0, 1}});
  const planar_metric<double> w(matrix{{{1, 0, 0}, {0, 1, 0}, {0, 0, 2}}});
  const auto none = spinslide::impulse_friction(
      patch, std::array<double, 2>{1, 2}, 3.0, w,
      patch_impulse_contact<double>{normal_impulse<double>{0}, friction_coefficient<double>{0.5}});
  EXPECT_EQ(none.force[0], 0.0);
  EXPECT_EQ(none.torque, 0.0);
  EXPECT_EQ(none.slip.omega, 3.0);
  EXPECT_THROW(
      spinslide::impulse_friction(patch, std::array<double, 2>{NAN, 0}, 0.0, w,
                                  patch_impulse_contact<double>{normal_impulse<double>{1},
                                                                friction_coefficient<double>{0.5}}),
      std::domain_error);
  EXPECT_THROW(
      spinslide::impulse_friction(patch, std::array<double, 2>{1, 0}, 0.0, w,
                                  patch_impulse_contact<double>{normal_impulse<double>{-1},
                                                                friction_coefficient<double>{0.5}}),
      std::domain_error);
}

}  // namespace
