//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The flat patch's wrench in its limits, each against an independent
// reference:
//  - a regular n-gon inscribed in the unit circle tends to the uniform disk
//    (spinslide::force_torque, values/disk.hpp) with an error ~ 1/n²;
//  - with a centre of pressure beyond R/4 it tends to the tilted cylinder's
//    no-tension segment (tilted_cylinder_friction, values/cylinder.hpp);
//  - a thin strip tends to its segment (a line patch), which matches a 1-D
//    quadrature of its defining line integral;
//  - mirrored twists give mirrored wrenches on a symmetric patch;
//  - the wrench is minus the gradient of the dissipation D = ∬ p|u|
//    (central differences of a Gauss quadrature of D), and D matches it.
#include <gtest/gtest.h>

#include <spinslide/values/cylinder.hpp>
#include <spinslide/values/disk.hpp>
#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/patch_dissipation.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "patch_quadrature.hpp"

#include "regular_polygon.hpp"

namespace {

using spinslide::centre_of_pressure;
using spinslide::planar_twist;
using spinslide::polygon_patch;
using point = std::array<double, 2>;

using spinslide_test::regular_polygon;

// The disk of radius 1 sliding along x with speed ε and spinning with ω = 1:
// F = −𝓕(ε) x̂ (antiparallel to v by symmetry), τ = −𝓣(ε) (against the spin).
double disk_error(int n, double eps) {
  const polygon_patch<double> p(regular_polygon(n));
  const auto w = spinslide::friction_wrench(p, planar_twist<double>{{eps, 0}, 1});
  const auto ft = spinslide::force_torque(eps);
  return std::fmax(std::fabs(w.force[0] + ft.force),
                   std::fmax(std::fabs(w.force[1]), std::fabs(w.torque + ft.torque)));
}

TEST(PatchLimits, RegularPolygonTendsToTheDisk) {
  for (double eps : {0.0, 0.3, 1.0, 2.5, 40.0}) {
    double previous = 0;
    for (int n : {16, 32, 64, 128, 256}) {
      const double e = disk_error(n, eps);
      std::printf("disk eps %-5g n %4d error %.3e ratio %.2f\n", eps, n, e, previous / e);
      if (previous > 0 && e > 1e-12) {
        EXPECT_GT(previous / e, 3.6) << "eps " << eps << " n " << n;  // 1/n²: halving n → ×4
        EXPECT_LT(previous / e, 4.4) << "eps " << eps << " n " << n;
      }
      EXPECT_LT(e * n * n, 4.0) << "eps " << eps << " n " << n;
      previous = e;
    }
  }
}

// The cylinder's outputs: force = (along v, sideways along v × ω), torque per
// μNR about the normal, centre (forward, to the left of the motion for ω > 0).
// For v = (ε, 0) and ω = 1 on the unit face: F = (force[0], −force[1]),
// τ = torque, the centre of pressure (centre[0], centre[1]).
TEST(PatchLimits, RegularPolygonTendsToTheTiltedCylinder) {
  int lifted = 0;
  for (double lambda : {0.15, 0.4, 0.6}) {
    for (double eps : {0.5, 1.5}) {
      const auto cyl = spinslide::tilted_cylinder_friction(eps, lambda, 1.0, 1.0);
      ASSERT_NE(cyl.contact, spinslide::cylinder_contact::tipped);
      if (cyl.contact == spinslide::cylinder_contact::partial) ++lifted;
      double previous = 0;
      for (int n : {64, 128, 256}) {
        const polygon_patch<double> p(regular_polygon(n), centre_of_pressure<double>{cyl.centre});
        const auto w = spinslide::friction_wrench(p, planar_twist<double>{{eps, 0}, 1});
        const double e = std::fmax(
            std::fabs(w.force[0] - cyl.force[0]),
            std::fmax(std::fabs(w.force[1] + cyl.force[1]), std::fabs(w.torque - cyl.torque)));
        std::printf("cylinder lambda %.2f eps %.1f n %4d error %.3e ratio %.2f\n", lambda, eps, n,
                    e, previous / e);
        EXPECT_LT(e * n * n, 10.0) << "lambda " << lambda << " eps " << eps << " n " << n;
        if (previous > 0) {
          EXPECT_GT(previous / e, 3.0);
        }
        previous = e;
      }
    }
  }
  EXPECT_GE(lifted, 3);  // the rear lifts off: the no-tension pressure
}

// The segment's wrench from its line integral, by adaptive Gauss–Kronrod
// split at the foot of the instantaneous centre: q(s) = (q0 + (q1 − q0)s/L)/…
std::array<double, 3> segment_reference(const point& a, const point& b, double q0, double q1,
                                        const planar_twist<double>& w) {
  const double L = std::hypot(b[0] - a[0], b[1] - a[1]);
  auto f = [&](double t, int k) {
    const point x{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
    const double ux = w.velocity[0] - w.omega * x[1], uy = w.velocity[1] + w.omega * x[0];
    const double s = std::hypot(ux, uy), q = (q0 + (q1 - q0) * t) * L;
    if (k == 0) return -q * ux / s;
    if (k == 1) return -q * uy / s;
    return -q * (x[0] * uy - x[1] * ux) / s;
  };
  std::array<double, 3> out{};
  using gk = boost::math::quadrature::gauss_kronrod<double, 31>;
  for (int k = 0; k < 3; ++k) {
    auto g = [&](double t) { return f(t, k); };
    out[static_cast<std::size_t>(k)] =
        gk::integrate(g, 0.0, 0.37, 15, 1e-15) + gk::integrate(g, 0.37, 1.0, 15, 1e-15);
  }
  return out;
}

TEST(PatchLimits, StripTendsToItsSegment) {
  const point a{-0.7, 0.2}, b{0.9, 0.5};
  const auto seg = polygon_patch<double>::segment(a, b);
  const auto lin = polygon_patch<double>::segment(a, b, centre_of_pressure<double>{{0.3, 0.3875}});
  for (const auto& w : {planar_twist<double>{{0.3, -0.2}, 0.7}, planar_twist<double>{{1, 0.4}, 0},
                        planar_twist<double>{{0.2, 3}, -2}, planar_twist<double>{{50, 10}, 0.01}}) {
    // Against the line integral: uniform q = 1/L, and linear with the centre at 0.625 of it.
    const double L = std::hypot(b[0] - a[0], b[1] - a[1]);
    const auto f = spinslide::friction_wrench(seg, w);
    const auto r = segment_reference(a, b, 1 / L, 1 / L, w);
    EXPECT_NEAR(f.force[0], r[0], 1e-14);
    EXPECT_NEAR(f.force[1], r[1], 1e-14);
    EXPECT_NEAR(f.torque, r[2], 1e-14);
    const double t = 0.625;  // q ∝ (4 − 6t) + (12t − 6)s, the linear density with mean t
    const auto fl = spinslide::friction_wrench(lin, w);
    const auto rl = segment_reference(a, b, (4 - 6 * t) / L, (6 * t - 2) / L, w);
    EXPECT_NEAR(fl.force[0], rl[0], 1e-14);
    EXPECT_NEAR(fl.force[1], rl[1], 1e-14);
    EXPECT_NEAR(fl.torque, rl[2], 1e-14);
    // A strip of width h about the segment: error ~ h².
    const point n{-(b[1] - a[1]) / L, (b[0] - a[0]) / L};
    for (double h : {1e-2, 1e-3, 1e-4}) {
      const std::vector<point> strip{{a[0] - h / 2 * n[0], a[1] - h / 2 * n[1]},
                                     {b[0] - h / 2 * n[0], b[1] - h / 2 * n[1]},
                                     {b[0] + h / 2 * n[0], b[1] + h / 2 * n[1]},
                                     {a[0] + h / 2 * n[0], a[1] + h / 2 * n[1]}};
      const auto fs = spinslide::friction_wrench(polygon_patch<double>(strip), w);
      EXPECT_NEAR(fs.force[0], f.force[0], 10 * h * h);
      EXPECT_NEAR(fs.force[1], f.force[1], 10 * h * h);
      EXPECT_NEAR(fs.torque, f.torque, 10 * h * h);
    }
  }
}

// Mirroring the hexagon (symmetric about the x axis) in y: the twist
// (v_x, −v_y, −ω) has the wrench (F_x, −F_y, −τ).
TEST(PatchLimits, MirroredTwistMirroredWrench) {
  const polygon_patch<double> hex(regular_polygon(6));
  const polygon_patch<double> tilted(regular_polygon(6), centre_of_pressure<double>{{0.5, 0.0}});
  for (const auto* p : {&hex, &tilted}) {
    for (const auto& w :
         {planar_twist<double>{{0.3, -0.2}, 0.7}, planar_twist<double>{{1, 0.4}, 0},
          planar_twist<double>{{3e3, 2}, 1e-4}, planar_twist<double>{{0.4, 0.1}, 1}}) {
      const auto f = spinslide::friction_wrench(*p, w);
      const auto m = spinslide::friction_wrench(
          *p, planar_twist<double>{{w.velocity[0], -w.velocity[1]}, -w.omega});
      EXPECT_NEAR(m.force[0], f.force[0], 2e-15);
      EXPECT_NEAR(m.force[1], -f.force[1], 2e-15);
      EXPECT_NEAR(m.torque, -f.torque, 2e-15);
    }
  }
}

// D = ∬ p |u| by Gauss quadrature of the loaded triangles fanned from their
// first vertex (the instantaneous centre is outside the patch here, so |u|
// is analytic on it and 20 × 20 points per triangle are exact to rounding).
double dissipation_quadrature(const polygon_patch<double>& p, const planar_twist<double>& w) {
  return patch_quadrature::loaded_integral<20>(p, [&](const point& x) {
    return p.pressure(x) *
           std::hypot(w.velocity[0] - w.omega * x[1], w.velocity[1] + w.omega * x[0]);
  });
}

TEST(PatchLimits, WrenchIsMinusTheGradientOfTheDissipation) {
  const std::vector<point> sole{{-0.1, -0.04}, {0.12, -0.04}, {0.12, 0.06}, {-0.1, 0.06}};
  const polygon_patch<double> uniform(sole), linear(sole, centre_of_pressure<double>{{0.03, 0.0}}),
      lifted(sole, centre_of_pressure<double>{{0.09, 0.03}});
  // Centres outside the sole: at (0.3, 0.1), (−0.5, 2) and far, and ω = 0.
  for (const auto* p : {&uniform, &linear, &lifted}) {
    for (const auto& w :
         {planar_twist<double>{{-0.1, 0.3}, 1.0}, planar_twist<double>{{-2, -0.5}, 1.0},
          planar_twist<double>{{0.8, -0.3}, 0.0}, planar_twist<double>{{5, 1}, -0.1}}) {
      const auto d = spinslide::friction_dissipation(*p, w);
      const auto f = spinslide::friction_wrench(*p, w);
      EXPECT_NEAR(d.value, dissipation_quadrature(*p, w), 1e-14 * (1 + std::fabs(d.value)));
      EXPECT_EQ(d.gradient[0], -f.force[0]);
      const double h = 1e-5;
      std::array<double, 3> fd{};
      for (std::size_t k = 0; k < 3; ++k) {
        fd[k] = (dissipation_quadrature(*p, spinslide::detail::shifted_twist(w, k, h)) -
                 dissipation_quadrature(*p, spinslide::detail::shifted_twist(w, k, -h))) /
                (2 * h);
      }
      EXPECT_NEAR(fd[0], -f.force[0], 1e-8);
      EXPECT_NEAR(fd[1], -f.force[1], 1e-8);
      EXPECT_NEAR(fd[2], -f.torque, 1e-8);
    }
  }
}

}  // namespace
