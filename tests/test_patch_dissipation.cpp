//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The Hessian of a flat patch's dissipation (values/patch_dissipation.hpp)
// against central differences of its wrench (∇²D = −∂(F, τ)/∂w); symmetric,
// positive semi-definite, homogeneous of degree −1; +∞ where a line patch
// pivots about one of its points.
#include <gtest/gtest.h>

#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/patch_dissipation.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <array>
#include <cmath>
#include <vector>

namespace {

using spinslide::centre_of_pressure;
using spinslide::planar_twist;
using spinslide::polygon_patch;
using point = std::array<double, 2>;
using matrix = std::array<std::array<double, 3>, 3>;

matrix wrench_differences(const polygon_patch<double>& p, const planar_twist<double>& w) {
  matrix m{};
  const double h = 1e-6;
  for (std::size_t k = 0; k < 3; ++k) {
    const auto a = spinslide::friction_wrench(p, spinslide::detail::shifted_twist(w, k, h));
    const auto b = spinslide::friction_wrench(p, spinslide::detail::shifted_twist(w, k, -h));
    m[0][k] = -(a.force[0] - b.force[0]) / (2 * h);
    m[1][k] = -(a.force[1] - b.force[1]) / (2 * h);
    m[2][k] = -(a.torque - b.torque) / (2 * h);
  }
  return m;
}

TEST(PatchDissipation, HessianMatchesDifferencesOfTheWrench) {
  const std::vector<point> sole{{-0.1, -0.04}, {0.12, -0.04}, {0.12, 0.06}, {-0.1, 0.06}};
  const polygon_patch<double> uniform(sole), linear(sole, centre_of_pressure<double>{{0.03, 0.0}}),
      lifted(sole, centre_of_pressure<double>{{0.09, 0.03}}),
      line = polygon_patch<double>::segment({-0.1, -0.04}, {0.12, -0.04},
                                            centre_of_pressure<double>{{0.05, -0.04}});
  // Centres inside, on the sole's edge line beside the segment, outside, far; ω = 0.
  const std::vector<planar_twist<double>> twists{{{-0.01, 0.02}, 1.0}, {{0.3, -0.05}, -1.0},
                                                 {{-0.1, 0.3}, 1.0},   {{-0.04, -0.2}, 1.0},
                                                 {{0.8, -0.3}, 0.0},   {{5, 1}, -0.1}};
  for (const auto* p : {&uniform, &linear, &lifted, &line}) {
    for (const auto& w : twists) {
      const auto d = spinslide::friction_dissipation(*p, w);
      const matrix fd = wrench_differences(*p, w);
      const double scale =
          std::fabs(d.hessian[0][0]) + std::fabs(d.hessian[1][1]) + std::fabs(d.hessian[2][2]);
      for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t j = 0; j < 3; ++j) {
          EXPECT_NEAR(d.hessian[i][j], fd[i][j], 1e-6 * scale) << i << j << " omega " << w.omega;
          EXPECT_EQ(d.hessian[i][j], d.hessian[j][i]);
        }
      }
      // Positive semi-definite: the leading minors (D is convex).
      const auto& H = d.hessian;
      EXPECT_GE(H[0][0], -1e-12 * scale);
      EXPECT_GE(H[0][0] * H[1][1] - H[0][1] * H[1][0], -1e-10 * scale * scale);
      // Homogeneous of degree −1.
      const auto d2 = spinslide::friction_dissipation(
          *p, planar_twist<double>{{2 * w.velocity[0], 2 * w.velocity[1]}, 2 * w.omega});
      EXPECT_NEAR(d2.hessian[2][2], H[2][2] / 2, 1e-6 * scale);
      EXPECT_NEAR(d2.value, 2 * d.value, 1e-14);
    }
  }
}

// A line patch pivoting about a point of it: ∫ q/|r| diverges, every entry +∞;
// an area patch pivoting about a point inside stays finite.
TEST(PatchDissipation, PivotingLinePatchHasInfiniteHessian) {
  const auto line = polygon_patch<double>::segment({-0.1, 0.0}, {0.12, 0.0});
  const auto d = spinslide::friction_dissipation(line, planar_twist<double>{{0.0, -0.02}, 1.0});
  for (const auto& row : d.hessian)
    for (double x : row) EXPECT_EQ(x, HUGE_VAL);
  EXPECT_TRUE(std::isfinite(d.value) && std::isfinite(d.gradient[2]));
  const auto pivot = spinslide::friction_dissipation(polygon_patch<double>::point({0.1, 0.2}),
                                                     planar_twist<double>{{0.2, -0.1}, 1.0});
  EXPECT_EQ(pivot.hessian[1][1], HUGE_VAL);
  const polygon_patch<double> area{{-0.1, -0.05}, {0.1, -0.05}, {0.1, 0.05}, {-0.1, 0.05}};
  const auto a = spinslide::friction_dissipation(area, planar_twist<double>{{0.0, 0.0}, 1.0});
  for (const auto& row : a.hessian)
    for (double x : row) EXPECT_TRUE(std::isfinite(x));
}

}  // namespace
