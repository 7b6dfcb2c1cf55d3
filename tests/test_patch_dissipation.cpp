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

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <array>
#include <cmath>
#include <random>
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
  const std::vector<planar_twist<double>> twists{{{-0.01, 0.02}, 1.0},
                                                 {{0.3, -0.05}, -1.0},
                                                 {{-0.1, 0.3}, 1.0},
                                                 {{-0.04, -0.2}, 1.0},
                                                 {{0.8, -0.3}, 0.0},
                                                 {{5, 1}, -0.1},
                                                 // just beyond the crossover (4.3 loaded
                                                 // radii), 20 and 10⁴ radii away
                                                 {{0.33, 0.4}, 1.0},
                                                 {{-2.0, 1.5}, -1.0},
                                                 {{900.0, -700.0}, 1.0}};
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

// The closed-form far Hessian (detail/patch_far_hessian.hpp) in cpp_bin_float_50
// against central differences of its own exact wrench (step 1e-17: the
// differences err by ~1e-34), and the double one against it: the uniform,
// linear and lifted sole at 4.3 to 10⁹ loaded radii, both spin senses.
TEST(PatchDissipation, FarHessianMatchesDifferencesAt50Digits) {
  using big = boost::multiprecision::cpp_bin_float_50;
  auto make = [](auto zero, int kind) {
    using R = decltype(zero);
    const std::vector<std::array<R, 2>> sole{
        {R(-0.1), R(-0.04)}, {R(0.12), R(-0.04)}, {R(0.12), R(0.06)}, {R(-0.1), R(0.06)}};
    if (kind == 0) return polygon_patch<R>(sole);
    return polygon_patch<R>(
        sole, centre_of_pressure<R>{{R(kind == 1 ? 0.03 : 0.09), R(kind == 1 ? 0.0 : 0.03)}});
  };
  const double twists[][3] = {
      {0.33, 0.4, 1.0}, {-2.0, 1.5, -1.0}, {900.0, -700.0, 1.0}, {5, 1, -0.1}, {1e6, 3, 1e-3}};
  for (int kind = 0; kind < 3; ++kind) {
    const auto pb = make(big(0), kind);
    const auto pd = make(0.0, kind);
    for (const auto& t : twists) {
      const planar_twist<big> w{{big(t[0]), big(t[1])}, big(t[2])};
      const auto H = spinslide::friction_dissipation(pb, w).hessian;
      const auto Hd =
          spinslide::friction_dissipation(pd, planar_twist<double>{{t[0], t[1]}, t[2]}).hessian;
      const big scale = abs(H[0][0]) + abs(H[1][1]) + abs(H[2][2]);
      const big h = big(1e-17) * (abs(w.velocity[0]) + abs(w.velocity[1]) + abs(w.omega));
      for (std::size_t k = 0; k < 3; ++k) {
        const auto a = spinslide::friction_wrench(pb, spinslide::detail::shifted_twist(w, k, h));
        const auto b =
            spinslide::friction_wrench(pb, spinslide::detail::shifted_twist(w, k, big(-h)));
        const std::array<big, 3> column{-(a.force[0] - b.force[0]) / (2 * h),
                                        -(a.force[1] - b.force[1]) / (2 * h),
                                        -(a.torque - b.torque) / (2 * h)};
        for (std::size_t i = 0; i < 3; ++i) {
          EXPECT_LE(abs(H[i][k] - column[i]), big(1e-30) * scale) << kind << ' ' << t[0] << i << k;
          EXPECT_LE(std::fabs(Hd[i][k] - static_cast<double>(H[i][k])),
                    1e-14 * static_cast<double>(scale))
              << kind << ' ' << t[0] << i << k;
        }
      }
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

namespace {

// Random convex patches (3 to 8 points on ellipses of aspect 1 to 100,
// random centres of pressure inside) and random twists (centres from inside
// to 1e8 sizes away, ω = 0 among them): the wrench is finite, |F| ≤ 1,
// |τ| ≤ ℓ, and D is homogeneous of degree 1, so F·v + τω = −D (Euler).
TEST(PatchDissipation, RandomPatchesObeyEuler) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0, 1);
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const std::size_t n = 3 + static_cast<std::size_t>(u(rng) * 6);
    // Points at increasing angles on an ellipse: convex.
    std::vector<double> steps(n);
    double total = 0;
    for (auto& st : steps) total += st = 0.3 + u(rng);
    std::vector<point> v;
    double angle = 6.283185307179586 * u(rng);
    const double cx = u(rng) - 0.5, cy = u(rng) - 0.5, stretch = std::pow(10.0, 2 * u(rng));
    for (double st : steps) {
      v.push_back({cx + stretch * 0.3 * std::cos(angle), cy + 0.3 * std::sin(angle)});
      angle += st / total * 6.283185307179586;
    }
    // The centre of pressure: between the vertex mean and a vertex.
    point m{0, 0};
    for (const auto& x : v)
      m = {m[0] + x[0] / static_cast<double>(n), m[1] + x[1] / static_cast<double>(n)};
    const double t = 0.98 * u(rng);
    const point e{m[0] + t * (v[0][0] - m[0]), m[1] + t * (v[0][1] - m[1])};
    const polygon_patch<double> p(v, centre_of_pressure<double>{e});
    double l = 0;
    for (const auto& x : v) l = std::fmax(l, std::hypot(x[0], x[1]));
    for (int k = 0; k < 5; ++k) {
      const double r = std::pow(10.0, 8 * u(rng) - 2), a = 6.283185307179586 * u(rng);
      const double omega = k == 0 ? 0.0 : (u(rng) < 0.5 ? -1.0 : 1.0) / std::fmax(1.0, r);
      const point c{m[0] + r * std::cos(a), m[1] + r * std::sin(a)};
      const planar_twist<double> w{
          k == 0 ? point{std::cos(a), std::sin(a)} : point{omega * c[1], -omega * c[0]}, omega};
      const auto f = spinslide::friction_wrench(p, w);
      const auto d = spinslide::friction_dissipation(p, w);
      ASSERT_TRUE(std::isfinite(f.force[0]) && std::isfinite(f.force[1]) &&
                  std::isfinite(f.torque));
      EXPECT_LE(std::hypot(f.force[0], f.force[1]) - 1, 1e-13)
          << "trial " << trial << " k " << k << " n " << n << " stretch " << stretch;
      EXPECT_LE(std::fabs(f.torque), l * (1 + 1e-14));
      const double power =
          f.force[0] * w.velocity[0] + f.force[1] * w.velocity[1] + f.torque * w.omega;
      const double scale = std::hypot(w.velocity[0], w.velocity[1]) + std::fabs(w.omega) * l;
      EXPECT_NEAR(power, -d.value, 1e-13 * scale) << "trial " << trial << " k " << k;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2000);
}

}  // namespace
