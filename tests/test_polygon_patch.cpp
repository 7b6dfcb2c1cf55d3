//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// polygon_patch (values/polygon_patch.hpp): its set-up errors, each a
// std::domain_error with its message; either orientation; the pressure
// (uniform, linear, no-tension) against its defining conditions, integrated
// here by Gauss quadrature of the loaded triangles (∬ p = 1, ∬ p x = the
// centre, p ≥ 0, p = 0 on the lift-off line, which lies on the outline); a
// centre of pressure on an edge or a vertex degrading to a line or point
// patch, and the wrench's errors for a zero or non-finite twist.
#include <gtest/gtest.h>

#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "patch_quadrature.hpp"

namespace {

using spinslide::centre_of_pressure;
using spinslide::patch_shape;
using spinslide::planar_twist;
using spinslide::polygon_patch;
using point = std::array<double, 2>;

const std::vector<point> square{{-0.4, -0.6}, {0.6, -0.6}, {0.6, 0.4}, {-0.4, 0.4}};

// The message of the std::domain_error that `make` throws ("" if none).
template <class Make>
std::string domain_error_of(Make make) {
  try {
    make();
  } catch (const std::domain_error& e) {
    return e.what();
  }
  return "";
}

TEST(PolygonPatchErrors, EachSetUpErrorNamesItsProblem) {
  struct bad_case {
    std::vector<point> vertices;
    const char* expect;
  };
  const double nan = std::nan("");
  const std::vector<bad_case> cases{
      {{{0, 0}, {1, 0}}, "the number of vertices"},
      {{{0, 0}, {1, nan}, {0, 1}}, "vertex y"},
      {{{0, 0}, {HUGE_VAL, 0}, {0, 1}}, "vertex x"},
      {{{0, 0}, {1, 0}, {1, 0}, {0, 1}}, "no repeated vertex"},
      {{{0, 0}, {1, 0}, {2, 0}}, "the area"},
      {{{0, 0}, {2, 0}, {1, 0.3}, {2, 2}, {0, 2}}, "convex"},
      {{{0, 0}, {2, 0}, {0.2, 1}, {1, -1}, {1.8, 1}}, "convex"},  // a star
  };
  for (const auto& c : cases) {
    const std::string what = domain_error_of([&] { polygon_patch<double> p(c.vertices); });
    EXPECT_NE(what.find(c.expect), std::string::npos) << "got: " << what;
    EXPECT_NE(what.find("polygon_patch<double>"), std::string::npos) << what;
  }
  const std::string outside = domain_error_of([&] {
    polygon_patch<double> p(square, centre_of_pressure<double>{{0.7, 0.0}});
  });
  EXPECT_NE(outside.find("centre of pressure"), std::string::npos) << outside;
  const std::string off_segment = domain_error_of([] {
    polygon_patch<double>::segment({0, 0}, {1, 0}, centre_of_pressure<double>{{0.5, 0.1}});
  });
  EXPECT_NE(off_segment.find("segment"), std::string::npos) << off_segment;
  EXPECT_FALSE(domain_error_of([] { polygon_patch<double>::segment({0, 0}, {0, 0}); }).empty());
}

TEST(PolygonPatchErrors, ZeroOrNonFiniteTwistIsAPolicyError) {
  const polygon_patch<double> p(square);
  EXPECT_THROW(spinslide::friction_wrench(p, planar_twist<double>{{0, 0}, 0}), std::domain_error);
  EXPECT_THROW(spinslide::friction_wrench(p, planar_twist<double>{{std::nan(""), 0}, 1}),
               std::domain_error);
  EXPECT_THROW(spinslide::friction_wrench(p, planar_twist<double>{{0, 0}, HUGE_VAL}),
               std::domain_error);
  using namespace boost::math::policies;
  const auto w = spinslide::friction_wrench(p, planar_twist<double>{{0, 0}, 0},
                                            policy<domain_error<ignore_error>>());
  EXPECT_TRUE(std::isnan(w.force[0]) && std::isnan(w.force[1]) && std::isnan(w.torque));
}

// ∬ f over the loaded polygon: 10 × 10 Gauss points per triangle, exact for
// the quadratics tested here.
template <class F>
double loaded_integral(const polygon_patch<double>& p, F f) {
  return patch_quadrature::loaded_integral<10>(p, f);
}

// The three pressures reproduce their resultant and centre; the no-tension
// one is ≥ 0 on its loaded part, 0 on the lift-off line, which lies on the
// outline's edges.
TEST(PolygonPatchPressure, ResultantAndCentre) {
  const std::vector<point> centres{{0.1, -0.1}, {0.15, -0.05}, {0.5, 0.3}, {0.58, -0.55}};
  const std::vector<std::vector<point>> outlines{
      square,
      {{0.0, 0.0}, {1.2, 0.1}, {0.3, 0.9}},
      {{0, 0}, {0.3, -0.1}, {0.9, 0.2}, {1, 0.8}, {0.2, 0.7}}};
  for (const auto& outline : outlines) {
    for (const auto& c0 : centres) {
      // The centres, mapped into each outline (between its vertex mean and its first vertex).
      point m{0, 0};
      const double n = static_cast<double>(outline.size());
      for (const auto& v : outline) m = {m[0] + v[0] / n, m[1] + v[1] / n};
      const point c{m[0] + (c0[0] + 0.4) * (outline[2][0] - m[0]) * 0.9,
                    m[1] + (c0[1] + 0.6) * (outline[2][1] - m[1]) * 0.9};
      const polygon_patch<double> p(outline, centre_of_pressure<double>{c});
      ASSERT_EQ(p.shape(), patch_shape::area);
      const double load = loaded_integral(p, [&](const point& x) { return p.pressure(x); });
      const double mx = loaded_integral(p, [&](const point& x) { return p.pressure(x) * x[0]; });
      const double my = loaded_integral(p, [&](const point& x) { return p.pressure(x) * x[1]; });
      EXPECT_NEAR(load, 1, 1e-14);
      EXPECT_NEAR(mx, c[0], 1e-14);
      EXPECT_NEAR(my, c[1], 1e-14);
      for (const auto& v : p.loaded_vertices()) EXPECT_GE(p.pressure(v), -1e-13);
      // Every loaded vertex is on the outline (a vertex, or on an edge).
      for (const auto& v : p.loaded_vertices()) {
        double nearest = 1;
        for (std::size_t i = 0; i < outline.size(); ++i) {
          const point& a = outline[i];
          const point& b = outline[(i + 1) % outline.size()];
          const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
          const double t =
              ((v[0] - a[0]) * (b[0] - a[0]) + (v[1] - a[1]) * (b[1] - a[1])) / (len * len);
          const double d = ((b[0] - a[0]) * (v[1] - a[1]) - (b[1] - a[1]) * (v[0] - a[0])) / len;
          if (t >= -1e-14 && t <= 1 + 1e-14) nearest = std::fmin(nearest, std::fabs(d));
        }
        EXPECT_LE(nearest, 1e-14);
      }
    }
  }
}

TEST(PolygonPatchPressure, UniformAndEitherOrientation) {
  std::vector<point> clockwise(square.rbegin(), square.rend());
  const polygon_patch<double> a(square), b(clockwise);
  EXPECT_NEAR(a.pressure({0, 0}), 1.0, 1e-15);  // area 1
  EXPECT_NEAR(a.pressure_gradient()[0], 0, 1e-15);
  EXPECT_NEAR(a.centre()[0], 0.1, 1e-15);
  EXPECT_NEAR(a.centre()[1], -0.1, 1e-15);
  const planar_twist<double> w{{0.3, -0.2}, 0.7};
  const auto wa = spinslide::friction_wrench(a, w), wb = spinslide::friction_wrench(b, w);
  EXPECT_NEAR(wa.force[0], wb.force[0], 1e-15);
  EXPECT_NEAR(wa.force[1], wb.force[1], 1e-15);
  EXPECT_NEAR(wa.torque, wb.torque, 1e-15);
  // An initializer list, a std::array and float work the same.
  const polygon_patch<double> c{{-0.4, -0.6}, {0.6, -0.6}, {0.6, 0.4}, {-0.4, 0.4}};
  EXPECT_EQ(spinslide::friction_wrench(c, w).torque, wa.torque);
  const std::array<std::array<float, 2>, 3> tri{{{0, 0}, {1, 0}, {0, 1}}};
  EXPECT_NEAR(polygon_patch<float>(tri).pressure({0.2f, 0.2f}), 2.0f, 1e-6f);
}

// A centre of pressure on an edge: a line patch on that edge; on a vertex: a
// point patch.  Neither gives a NaN, and each is the limit of centres just inside.
TEST(PolygonPatchDegenerate, BoundaryCentresDegrade) {
  const polygon_patch<double> on_edge(square, centre_of_pressure<double>{{0.1, -0.6}});
  EXPECT_EQ(on_edge.shape(), patch_shape::line);
  const polygon_patch<double> near_third(square, centre_of_pressure<double>{{0.5, -0.6}});
  EXPECT_EQ(near_third.shape(), patch_shape::line);  // triangular on [0.3, 0.6]
  EXPECT_NEAR(near_third.loaded_vertices()[0][0], 0.3, 1e-15);
  const polygon_patch<double> on_vertex(square, centre_of_pressure<double>{{0.6, 0.4}});
  EXPECT_EQ(on_vertex.shape(), patch_shape::point);
  for (const auto& w :
       {planar_twist<double>{{0.3, -0.2}, 0.7}, planar_twist<double>{{1, 0}, 0},
        planar_twist<double>{{0.0, 0.0}, 1.0}, planar_twist<double>{{-0.6, 0.1}, 1.0},
        planar_twist<double>{{0.4, -0.6}, 1.0}}) {
    for (const auto* p : {&on_edge, &near_third, &on_vertex}) {
      const auto f = spinslide::friction_wrench(*p, w);
      EXPECT_TRUE(std::isfinite(f.force[0]) && std::isfinite(f.force[1]) &&
                  std::isfinite(f.torque));
    }
  }
  // Centres approaching the edge's midpoint and a vertex from inside converge
  // to the degenerate patches (error ~ the distance).  Off the midpoint the
  // area model's limit is a quadratic line density, not the line patch's
  // linear one (docs/patches.md, "The line patch"), so only the midpoint,
  // where both are uniform, is a limit.
  const planar_twist<double> w{{0.3, -0.2}, 0.7};
  for (double d : {1e-4, 1e-5, 1e-6}) {
    const auto inside = spinslide::friction_wrench(
        polygon_patch<double>(square, centre_of_pressure<double>{{0.1, -0.6 + d}}), w);
    const auto line = spinslide::friction_wrench(on_edge, w);
    EXPECT_NEAR(inside.force[0], line.force[0], 30 * d);
    EXPECT_NEAR(inside.force[1], line.force[1], 30 * d);
    EXPECT_NEAR(inside.torque, line.torque, 30 * d);
    const auto corner = spinslide::friction_wrench(
        polygon_patch<double>(square, centre_of_pressure<double>{{0.6 - d, 0.4 - d}}), w);
    const auto at_vertex = spinslide::friction_wrench(on_vertex, w);
    EXPECT_NEAR(corner.force[0], at_vertex.force[0], 30 * std::sqrt(d));
    EXPECT_NEAR(corner.torque, at_vertex.torque, 30 * std::sqrt(d));
  }
}

// Point friction: −û at the point, and nothing at a pivot.
TEST(PolygonPatchDegenerate, PointFriction) {
  const auto p = polygon_patch<double>::point({0.3, 0.4});
  const auto f = spinslide::friction_wrench(p, planar_twist<double>{{1, 0}, 1});
  // u = v + ω ẑ × x = (1 − 0.4, 0.3): F = −u/|u|, τ = x × F.
  const double ux = 0.6, uy = 0.3, s = std::hypot(ux, uy);
  EXPECT_NEAR(f.force[0], -ux / s, 1e-15);
  EXPECT_NEAR(f.force[1], -uy / s, 1e-15);
  EXPECT_NEAR(f.torque, 0.3 * (-uy / s) - 0.4 * (-ux / s), 1e-15);
  const auto pivot = spinslide::friction_wrench(p, planar_twist<double>{{0.4, -0.3}, 1});
  EXPECT_EQ(pivot.force[0], 0.0);
  EXPECT_EQ(pivot.torque, 0.0);
}

}  // namespace

namespace {

// ω → 0 from either side tends to pure sliding (the expansion's limit, with
// nothing divided by ω): the wrench at ω = ±10⁻ᵏ is within ~10⁻ᵏ (and a few
// ulp) of ω = 0's.
TEST(PolygonPatchWrench, SpinToZeroIsPureSliding) {
  const polygon_patch<double> p(square, centre_of_pressure<double>{{0.3, 0.1}});
  const planar_twist<double> slide{{0.6, -0.8}, 0};
  const auto s = spinslide::friction_wrench(p, slide);
  EXPECT_NEAR(s.force[0], -0.6, 1e-16);
  EXPECT_NEAR(s.force[1], 0.8, 1e-16);
  EXPECT_NEAR(s.torque, 0.3 * 0.8 - 0.1 * -0.6, 1e-16);  // −e × v̂
  for (double omega : {1e-3, 1e-6, 1e-9, 1e-300}) {
    for (double sense : {1.0, -1.0}) {
      const auto f =
          spinslide::friction_wrench(p, planar_twist<double>{{0.6, -0.8}, sense * omega});
      EXPECT_NEAR(f.force[0], s.force[0], 2 * omega + 4e-16);
      EXPECT_NEAR(f.force[1], s.force[1], 2 * omega + 4e-16);
      EXPECT_NEAR(f.torque, s.torque, 2 * omega + 4e-16);
    }
  }
}

}  // namespace

namespace {

// Any length unit: the square and its centre of pressure scaled by 10^±100
// with the twist's velocity scaled alike give the same force and the torque
// scaled by the unit (no overflow of ρ⁴ in the edge sums, no underflow), to
// the inputs' rounding.
TEST(PolygonPatchWrench, AnyLengthUnit) {
  auto wrench_at = [](double unit, const planar_twist<double>& w) {
    std::vector<point> v;
    v.reserve(square.size());
    for (const auto& x : square) v.push_back({unit * x[0], unit * x[1]});
    const polygon_patch<double> p(v, centre_of_pressure<double>{{0.3 * unit, 0.2 * unit}});
    return spinslide::friction_wrench(
        p, planar_twist<double>{{unit * w.velocity[0], unit * w.velocity[1]}, w.omega});
  };
  for (const auto& w :
       {planar_twist<double>{{0.3, -0.2}, 0.7}, planar_twist<double>{{30, -20}, 0.07},
        planar_twist<double>{{3e5, -2e5}, 0.7}}) {
    const auto one = wrench_at(1, w);
    for (double unit : {1e-100, 1e-30, 1e30, 1e100}) {
      const auto f = wrench_at(unit, w);
      EXPECT_NEAR(f.force[0], one.force[0], 2e-15) << unit;
      EXPECT_NEAR(f.force[1], one.force[1], 2e-15) << unit;
      EXPECT_NEAR(f.torque / unit, one.torque, 2e-15) << unit;
    }
  }
}

}  // namespace
