//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The projection onto a flat patch's limit set (contact/patch_limit_set.hpp)
// and its inverse map: the answer lies on the set (it is the friction
// wrench of its own slip), it is optimal (the slip is M times the
// displacement: the nearest point's condition), no sampled point of the set
// is nearer, points inside stick, a 256-gon agrees with the round disk's
// projection, and a point patch agrees with a brute-force search of its disk.
#include <gtest/gtest.h>

#include <spinslide/contact/limit_set.hpp>
#include <spinslide/contact/patch_limit_set.hpp>
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
using spinslide::planar_metric;
using spinslide::planar_twist;
using spinslide::planar_wrench;
using spinslide::polygon_patch;
using point = std::array<double, 2>;
using matrix = std::array<std::array<double, 3>, 3>;

// The patches of the issue: a square, a sole, a triangle, a hexagon, a thin
// strip; uniform, linear and no-tension pressures; a line patch.
std::vector<polygon_patch<double>> patches() {
  const std::vector<point> square{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const std::vector<point> sole{{-0.1, -0.04}, {0.12, -0.04}, {0.12, 0.06}, {-0.1, 0.06}};
  const std::vector<point> triangle{{0, 0}, {2, 0.3}, {0.5, 1.5}};
  std::vector<point> hexagon = spinslide_test::regular_polygon(6);
  for (auto& v : hexagon) v = {v[0] + 0.3, v[1] - 0.2};
  const std::vector<point> strip{{-1, -0.01}, {1, -0.01}, {1, 0.01}, {-1, 0.01}};
  return {polygon_patch<double>(square),
          polygon_patch<double>(square, centre_of_pressure<double>{{0.2, -0.1}}),
          polygon_patch<double>(square, centre_of_pressure<double>{{0.8, 0.7}}),
          polygon_patch<double>(sole),
          polygon_patch<double>(sole, centre_of_pressure<double>{{0.09, 0.03}}),
          polygon_patch<double>(triangle),
          polygon_patch<double>(hexagon, centre_of_pressure<double>{{0.5, 0.1}}),
          polygon_patch<double>(strip),
          polygon_patch<double>::segment({-0.5, 0.2}, {0.7, -0.1},
                                         centre_of_pressure<double>{{0.3, 0.0}})};
}

using spinslide_test::times;

// A random symmetric positive definite metric (condition up to about 1e4).
matrix random_metric(std::mt19937_64& rng) { return spinslide_test::random_spd(rng, 0.01, 0); }

double distance2(const matrix& m, const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const std::array<double, 3> d{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  const auto md = times(m, d);
  return d[0] * md[0] + d[1] * md[1] + d[2] * md[2];
}

// The point of the set with outward normal along the twist w's slip, in
// the limit set's units: friction_wrench(patch, w) with the torque over ℓ.
std::array<double, 3> set_point(const polygon_patch<double>& p, const planar_twist<double>& w) {
  const auto f = spinslide::friction_wrench(p, w);
  const double l = p.radius();
  return {f.force[0], f.force[1], f.torque / l};
}

struct checked_projection {
  std::array<double, 3> z, p;
  bool sticking;
};

// A slipping answer's two defining conditions: p is the friction wrench of
// its slip (on the set), and the slip in the limit set's units, −(v, ℓω),
// is M(z − p) (optimal).
void expect_on_set_and_optimal(const polygon_patch<double>& patch, const matrix& m,
                               const std::array<double, 3>& z, const std::array<double, 3>& p,
                               const planar_twist<double>& slip) {
  const double l = patch.radius();
  const auto q = set_point(patch, slip);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(p[i], q[i], 1e-12) << "component " << i;
  const std::array<double, 3> s{-slip.velocity[0], -slip.velocity[1], -l * slip.omega};
  const auto target = times(m, {z[0] - p[0], z[1] - p[1], z[2] - p[2]});
  const double size = std::fabs(target[0]) + std::fabs(target[1]) + std::fabs(target[2]);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(s[i], target[i], 1e-9 * (size + 1e-3));
}

// Projects z and checks the answer's two defining conditions.
checked_projection project_and_check(const polygon_patch<double>& patch, const matrix& m,
                                     const std::array<double, 3>& z,
                                     const planar_twist<double>& start = {{0, 0}, 0}) {
  const planar_metric<double> metric(m);
  const auto r = spinslide::project_to_limit_set(patch, planar_wrench<double>{{z[0], z[1]}, z[2]},
                                                 metric, start);
  const std::array<double, 3> p{r.force[0], r.force[1], r.torque};
  if (r.sticking) {
    EXPECT_EQ(p, z);
    EXPECT_EQ(r.slip.velocity[0], 0.0);
    EXPECT_EQ(r.slip.omega, 0.0);
    return {z, p, true};
  }
  expect_on_set_and_optimal(patch, m, z, p, r.slip);
  return {z, p, false};
}

TEST(PatchProjection, OnTheSetAndOptimalForRandomMetricsAndPoints) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int slipping = 0, sticking = 0;
  for (const auto& patch : patches()) {
    for (int k = 0; k < 40; ++k) {
      const matrix m = random_metric(rng);
      const checked_projection c = project_and_check(patch, m, {u(rng), u(rng), u(rng)});
      (c.sticking ? sticking : slipping) += 1;
      if (c.sticking) continue;
      // No sampled point of the set is nearer to z.
      const double best = distance2(m, c.p, c.z);
      for (int j = 0; j < 200; ++j) {
        const auto q = set_point(patch, {{u(rng), u(rng)}, u(rng) / patch.radius()});
        EXPECT_GE(distance2(m, q, c.z), best * (1 - 1e-12));
      }
    }
  }
  EXPECT_GT(slipping, 100);
  EXPECT_GT(sticking, 10);
}

TEST(PatchProjection, PointsInsideStickAndJustOutsideSlip) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const auto& patch : patches()) {
    for (int k = 0; k < 30; ++k) {
      // A convex combination of boundary points lies in the set.
      std::array<double, 3> inside{};
      for (int j = 0; j < 3; ++j) {
        const auto q = set_point(patch, {{u(rng), u(rng)}, u(rng) / patch.radius()});
        for (std::size_t i = 0; i < 3; ++i) inside[i] += q[i] / 3;
      }
      const matrix m = random_metric(rng);
      EXPECT_TRUE(project_and_check(patch, m, inside).sticking);
      // A boundary point moved outward along its normal slips back to it.
      const planar_twist<double> w{{u(rng), u(rng)}, u(rng) / patch.radius()};
      const auto b = set_point(patch, w);
      const double l = patch.radius();
      const std::array<double, 3> normal{-w.velocity[0], -w.velocity[1], -l * w.omega};
      // In the metric M the displacement M⁻¹n is the normal's: z = b + 0.1 M⁻¹n.
      const planar_metric<double> metric(m);
      const auto dz = times(metric.inverse(), normal);
      const std::array<double, 3> z{b[0] + 0.1 * dz[0], b[1] + 0.1 * dz[1], b[2] + 0.1 * dz[2]};
      const checked_projection c = project_and_check(patch, m, z);
      EXPECT_FALSE(c.sticking);
      for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(c.p[i], b[i], 1e-9);
    }
  }
}

TEST(PatchProjection, WarmStartsGiveTheColdAnswer) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-2, 2);
  for (const auto& patch : patches()) {
    for (int k = 0; k < 20; ++k) {
      const matrix m = random_metric(rng);
      const std::array<double, 3> z{u(rng), u(rng), u(rng)};
      const planar_metric<double> metric(m);
      const planar_wrench<double> w{{z[0], z[1]}, z[2]};
      const auto cold = spinslide::project_to_limit_set(patch, w, metric);
      // From the answer's own slip, from a poor one, from the opposite one.
      for (const planar_twist<double>& start :
           {cold.slip, planar_twist<double>{{1, 0}, 0}, planar_twist<double>{{-0.3, 0.2}, -5.0}}) {
        const auto warm = spinslide::project_to_limit_set(patch, w, metric, start);
        EXPECT_EQ(warm.sticking, cold.sticking);
        EXPECT_NEAR(warm.force[0], cold.force[0], 1e-11);
        EXPECT_NEAR(warm.force[1], cold.force[1], 1e-11);
        EXPECT_NEAR(warm.torque, cold.torque, 1e-11);
      }
    }
  }
}

// A 256-gon under uniform pressure is the disk to 1e-4 (its 𝓕, 𝓣 differ by
// about (π/n)²/6 relatively): the projections agree to that.
TEST(PatchProjection, ManyGonAgreesWithTheRoundDisksProjection) {
  const polygon_patch<double> patch(spinslide_test::regular_polygon(256));
  const auto disk = spinslide::uniform_disk<>();
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int k = 0; k < 40; ++k) {
    const matrix m = random_metric(rng);
    const planar_metric<double> metric(m);
    const std::array<double, 3> z{u(rng), u(rng), u(rng)};
    const auto round = spinslide::project_to_limit_set(
        disk, spinslide::tangent_wrench<double>{z[0], z[1], z[2]}, metric);
    const auto flat =
        spinslide::project_to_limit_set(patch, planar_wrench<double>{{z[0], z[1]}, z[2]}, metric);
    if (round.sticking != flat.sticking) {
      // Only within the polygon's distance from the disk of the boundary.
      EXPECT_LT(std::fabs(round.force[0] - z[0]) + std::fabs(round.torque - z[2]), 1e-3);
      continue;
    }
    EXPECT_NEAR(flat.force[0], round.force[0], 2e-4);
    EXPECT_NEAR(flat.force[1], round.force[1], 2e-4);
    EXPECT_NEAR(flat.torque, round.torque, 2e-4);
  }
}

// A point patch's set is the disk {(f, x × f/ℓ) : |f| ≤ 1}: against a
// brute-force search over a fine polar grid of f.
TEST(PatchProjection, PointPatchAgreesWithABruteForceSearch) {
  int inside = 0, rim = 0;
  const point x{0.3, -0.4};
  const auto patch = polygon_patch<double>::point(x);
  const double l = patch.radius();
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int k = 0; k < 30; ++k) {
    const matrix m = random_metric(rng);
    const std::array<double, 3> z{u(rng), u(rng), u(rng)};
    const auto r = spinslide::project_to_limit_set(patch, planar_wrench<double>{{z[0], z[1]}, z[2]},
                                                   planar_metric<double>(m));
    const std::array<double, 3> p{r.force[0], r.force[1], r.torque};
    EXPECT_LE(std::hypot(p[0], p[1]), 1 + 1e-14);
    // On the rim the slip moves x along −f (its friction is f); inside, x
    // holds and the slip turns the body about it.
    const double ux = r.slip.velocity[0] - r.slip.omega * x[1],
                 uy = r.slip.velocity[1] + r.slip.omega * x[0];
    if (std::hypot(p[0], p[1]) < 1 - 1e-9) {
      EXPECT_NEAR(std::hypot(ux, uy), 0.0, 1e-12 * (std::fabs(r.slip.omega) + 1e-300));
      ++inside;
    } else if (!r.sticking) {
      const auto w = spinslide::friction_wrench(patch, r.slip);
      EXPECT_NEAR(w.force[0], p[0], 1e-12);
      EXPECT_NEAR(w.force[1], p[1], 1e-12);
      ++rim;
    }
    EXPECT_NEAR(p[2], (x[0] * p[1] - x[1] * p[0]) / l, 1e-15);
    const double best = distance2(m, p, z);
    for (int i = 0; i <= 400; ++i)
      for (int j = 0; j < 400; ++j) {
        const double rho = i / 400.0, phi = 2 * M_PI * j / 400;
        const std::array<double, 3> q{
            rho * std::cos(phi), rho * std::sin(phi),
            (x[0] * rho * std::sin(phi) - x[1] * rho * std::cos(phi)) / l};
        EXPECT_GE(distance2(m, q, z), best * (1 - 1e-12)) << i << " " << j;
      }
  }
  EXPECT_GT(inside, 3);
  EXPECT_GT(rim, 3);
}

TEST(PatchProjection, InverseMapRecoversTheTwist) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const auto& patch : patches()) {
    const double l = patch.radius();
    for (int k = 0; k < 30; ++k) {
      const planar_twist<double> w{{u(rng), u(rng)}, u(rng) / l};
      const auto b = spinslide::friction_wrench(patch, w);
      const auto t = spinslide::limit_surface_twist(patch, b);
      EXPECT_NEAR(t.gauge, 1.0, 1e-12);
      // The same direction as w, with |v|² + (ℓω)² = 1.
      const double size = std::sqrt(w.velocity[0] * w.velocity[0] + w.velocity[1] * w.velocity[1] +
                                    l * l * w.omega * w.omega);
      EXPECT_NEAR(t.twist.velocity[0], w.velocity[0] / size, 1e-6);
      EXPECT_NEAR(t.twist.velocity[1], w.velocity[1] / size, 1e-6);
      EXPECT_NEAR(l * t.twist.omega, l * w.omega / size, 1e-6);
      // Half the wrench has gauge 1/2, and the same twist.
      const auto h = spinslide::limit_surface_twist(
          patch, planar_wrench<double>{{b.force[0] / 2, b.force[1] / 2}, b.torque / 2});
      EXPECT_NEAR(h.gauge, 0.5, 1e-12);
    }
  }
}

// Float: the same answers as double to float's precision, on the set and
// optimal to it.
TEST(PatchProjection, FloatAgreesWithDouble) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int compared = 0;
  for (const auto& patch : patches()) {
    std::vector<std::array<float, 2>> vf;
    for (const auto& v : patch.loaded_vertices()) vf.push_back({float(v[0]), float(v[1])});
    if (patch.shape() != spinslide::patch_shape::area) continue;
    const polygon_patch<float> single(vf);
    const polygon_patch<double> twin(
        std::vector<point>(patch.loaded_vertices().begin(), patch.loaded_vertices().end()));
    for (int k = 0; k < 30; ++k) {
      const matrix m = random_metric(rng);
      std::array<std::array<float, 3>, 3> mf{};
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) mf[i][j] = float(m[i][j]);
      const std::array<double, 3> z{float(u(rng)), float(u(rng)), float(u(rng))};
      const auto rd = spinslide::project_to_limit_set(
          twin, planar_wrench<double>{{z[0], z[1]}, z[2]}, planar_metric<double>(m));
      const auto rf = spinslide::project_to_limit_set(
          single, planar_wrench<float>{{float(z[0]), float(z[1])}, float(z[2])},
          planar_metric<float>(mf));
      if (rd.sticking != rf.sticking) continue;  // within float's rounding of the boundary
      EXPECT_NEAR(rf.force[0], rd.force[0], 2e-5);
      EXPECT_NEAR(rf.force[1], rd.force[1], 2e-5);
      EXPECT_NEAR(rf.torque, rd.torque, 2e-5);
      if (rf.sticking) continue;
      ++compared;
      const auto q = spinslide::friction_wrench(single, rf.slip);
      EXPECT_NEAR(q.force[0], rf.force[0], 1e-5);
      EXPECT_NEAR(q.torque / single.radius(), rf.torque, 1e-5);
    }
  }
  EXPECT_GT(compared, 100);
}

// Metrics of condition up to 1e7 and of any size, points from 1e-12 to
// 1e12 away: always an answer, finite, on the set (to 1e-12) and optimal
// (to the metric's condition times the rounding).
TEST(PatchProjection, ExtremeMetricsAndPointsAlwaysAnswer) {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(-1, 1), e(-12, 12), c(0, 7), g(-20, 20);
  int slipping = 0;
  for (const auto& patch : patches()) {
    for (int k = 0; k < 60; ++k) {
      matrix m = spinslide_test::random_spd_with_condition(rng, std::pow(10.0, c(rng)));
      const double size = std::pow(10.0, g(rng));
      for (auto& row : m)
        for (double& x : row) x *= size;
      const double reach = std::pow(10.0, e(rng));
      const std::array<double, 3> z{reach * u(rng), reach * u(rng), reach * u(rng)};
      const auto r = spinslide::project_to_limit_set(
          patch, planar_wrench<double>{{z[0], z[1]}, z[2]}, planar_metric<double>(m));
      ASSERT_TRUE(std::isfinite(r.force[0]) && std::isfinite(r.force[1]) &&
                  std::isfinite(r.torque));
      if (r.sticking) {
        EXPECT_LT(std::fabs(z[0]) + std::fabs(z[1]) + std::fabs(z[2]), 6.0);
        continue;
      }
      ++slipping;
      const auto p = set_point(patch, r.slip);
      EXPECT_NEAR(p[0], r.force[0], 1e-12);
      EXPECT_NEAR(p[1], r.force[1], 1e-12);
      EXPECT_NEAR(p[2], r.torque, 1e-12);
    }
  }
  EXPECT_GT(slipping, 200);
}

TEST(PatchProjection, BadArgumentsAreDomainErrors) {
  const polygon_patch<double> patch({{0, 0}, {1, 0}, {0, 1}});
  const planar_metric<double> metric(matrix{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}});
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(spinslide::project_to_limit_set(patch, planar_wrench<double>{{inf, 0}, 0}, metric),
               std::domain_error);
  EXPECT_THROW(spinslide::project_to_limit_set(patch, planar_wrench<double>{{1, 0}, 0}, metric,
                                               planar_twist<double>{{NAN, 0}, 0}),
               std::domain_error);
  EXPECT_THROW(spinslide::limit_surface_twist(patch, planar_wrench<double>{{0, 0}, 0}),
               std::domain_error);
  EXPECT_THROW(spinslide::limit_surface_twist(polygon_patch<double>::point({1, 0}),
                                              planar_wrench<double>{{1, 0}, 0.5}),
               std::domain_error);
}

}  // namespace
