//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// contact_patch (contact/contact_patch.hpp): an engine contact's patch from
// its points and loads.  Every degenerate case (none, one, repeated,
// collinear, nearly collinear, unloaded, non-finite, an origin far away)
// gives the patch it should and never throws; the hull against a brute-force
// hull (every pair of points an edge if all others lie to its left); the
// centre of pressure against the loads' resultant, through the wrench of a
// pure translation (τ = −e × v̂ for the centre of pressure e, docs/patches.md),
// with e summed here in long double; random clouds, flat or not.
#include <gtest/gtest.h>

#include <spinslide/contact/contact_patch.hpp>
#include <spinslide/values/friction_wrench.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace {

using spinslide::contact_patch;
using spinslide::contact_point;
using spinslide::merge_tolerance;
using spinslide::patch_shape;
using spinslide::planar_twist;
using spinslide::polygon_patch;
using point = std::array<double, 2>;
using points = std::vector<contact_point<double>>;

// The load-weighted mean, in long double.
point resultant_centre(const points& p) {
  long double w = 0, x = 0, y = 0;
  for (const auto& c : p) {
    w += c.load;
    x += static_cast<long double>(c.load) * c.position[0];
    y += static_cast<long double>(c.load) * c.position[1];
  }
  return {static_cast<double>(x / w), static_cast<double>(y / w)};
}

// The centre of pressure the patch's friction acts from: a pure slide along
// x has τ = e_y, along y τ = −e_x.
point centre_from_wrench(const polygon_patch<double>& patch) {
  const auto along_x = spinslide::friction_wrench(patch, planar_twist<double>{{1, 0}, 0});
  const auto along_y = spinslide::friction_wrench(patch, planar_twist<double>{{0, 1}, 0});
  return {-along_y.torque, along_x.torque};
}

// The brute-force hull's vertices: the ends of every pair (i, j) with all
// other points strictly to its left (points in general position).
std::vector<point> brute_force_hull(const std::vector<point>& p) {
  std::vector<point> v;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (i == j) continue;
      bool edge = true;
      for (std::size_t k = 0; k < p.size(); ++k) {
        if (k == i || k == j) continue;
        const double t =
            (p[j][0] - p[i][0]) * (p[k][1] - p[i][1]) - (p[j][1] - p[i][1]) * (p[k][0] - p[i][0]);
        edge = edge && t > 0;
      }
      if (edge) v.push_back(p[i]);
    }
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

double shoelace(const std::vector<point>& v) {  // v counter-clockwise
  double a = 0;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const point& p = v[k];
    const point& q = v[(k + 1) % v.size()];
    a += p[0] * q[1] - p[1] * q[0];
  }
  return a / 2;
}

std::vector<point> outline_of(const polygon_patch<double>& patch) {
  return {patch.loaded_vertices().begin(), patch.loaded_vertices().end()};
}

const points box_face{
    {{-0.11, -0.05}, 1}, {{0.11, -0.05}, 2}, {{0.11, 0.05}, 3}, {{-0.11, 0.05}, 4}};

}  // namespace

TEST(ContactPatch, NoPointIsAPointAtTheOrigin) {
  const auto patch = contact_patch(points{});
  EXPECT_EQ(patch.shape(), patch_shape::point);
  EXPECT_EQ(patch.centre()[0], 0);
  EXPECT_EQ(patch.centre()[1], 0);
  const double nan = std::nan("");
  const auto none_finite = contact_patch(points{{{nan, 0}, 1}, {{0, HUGE_VAL}, 1}});
  EXPECT_EQ(none_finite.shape(), patch_shape::point);
}

TEST(ContactPatch, OnePointOrRepeatedPointsArePointContacts) {
  const auto one = contact_patch(points{{{0.03, -0.02}, 5}});
  EXPECT_EQ(one.shape(), patch_shape::point);
  EXPECT_EQ(one.centre()[0], 0.03);
  EXPECT_EQ(one.centre()[1], -0.02);
  // Bullet's first frame of a landing: the same corner several times, and
  // points that differ by rounding only.
  const auto same =
      contact_patch(points{{{0.03, -0.02}, 5}, {{0.03, -0.02}, 1}, {{0.03, -0.02}, 0}});
  EXPECT_EQ(same.shape(), patch_shape::point);
  const double x = 0.03, y = -0.02;
  const auto rounding = contact_patch(
      points{{{x, y}, 1}, {{std::nextafter(x, 1.0), y}, 1}, {{x, std::nextafter(y, 0.0)}, 2}});
  EXPECT_EQ(rounding.shape(), patch_shape::point);
  EXPECT_NEAR(rounding.centre()[0], x, 1e-17);
  EXPECT_NEAR(rounding.centre()[1], y, 1e-17);
}

TEST(ContactPatch, TwoPointsOrCollinearPointsAreALinePatch) {
  // A box on its edge: two points, or four whose pairs repeat, or four on
  // one line with noise far below the tolerance.
  for (const points& p :
       {points{{{-0.11, 0.05}, 1}, {{0.11, 0.05}, 3}},
        points{{{-0.11, 0.05}, 1}, {{0.11, 0.05}, 1}, {{0.11, 0.05}, 2}, {{-0.11, 0.05}, 0}},
        points{{{-0.11, 0.05}, 1},
               {{-0.02, 0.05 + 1e-9}, 1},
               {{0.04, 0.05 - 1e-9}, 1},
               {{0.11, 0.05}, 1}}}) {
    const auto patch = contact_patch(p);
    ASSERT_EQ(patch.shape(), patch_shape::line);
    const auto& v = patch.loaded_vertices();
    const auto e = resultant_centre(p);
    const auto c = centre_from_wrench(patch);
    EXPECT_NEAR(c[0], e[0], 1e-15);
    EXPECT_NEAR(c[1], 0.05, 1e-15);
    // The segment spans the extreme points (the loaded part may be less:
    // the triangular line pressure of a centre beyond the middle third).
    for (const auto& x : v) EXPECT_NEAR(x[1], 0.05, 1e-15);
  }
  // A larger tolerance makes a thin quadrilateral a line.
  const points thin{{{0, 0}, 1}, {{1, 0}, 1}, {{1, 1e-4}, 1}, {{0, 1e-4}, 1}};
  EXPECT_EQ(contact_patch(thin).shape(), patch_shape::area);
  EXPECT_EQ(contact_patch(thin, merge_tolerance<double>{1e-3}).shape(), patch_shape::line);
}

TEST(ContactPatch, AFaceIsItsHullUnderItsLoadsCentre) {
  const auto patch = contact_patch(box_face);
  ASSERT_EQ(patch.shape(), patch_shape::area);
  const auto e = resultant_centre(box_face);
  const auto c = centre_from_wrench(patch);
  EXPECT_NEAR(c[0], e[0], 1e-16);
  EXPECT_NEAR(c[1], e[1], 1e-16);
  // Interior points change the pressure's centre, not the outline.
  points more = box_face;
  more.push_back({{0.0, 0.0}, 10});
  more.push_back({{0.05, -0.01}, 3});
  const auto inner = contact_patch(more);
  ASSERT_EQ(inner.shape(), patch_shape::area);
  const auto e2 = resultant_centre(more), c2 = centre_from_wrench(inner);
  EXPECT_NEAR(c2[0], e2[0], 1e-16);
  EXPECT_NEAR(c2[1], e2[1], 1e-16);
  // Unloaded: uniform pressure over the hull (centre at the centroid).
  const auto uniform =
      contact_patch(points{{{0, 0}, 0}, {{0.2, 0}, 0}, {{0.2, 0.1}, 0}, {{0, 0.1}, 0}});
  EXPECT_NEAR(centre_from_wrench(uniform)[0], 0.1, 1e-16);
  EXPECT_NEAR(centre_from_wrench(uniform)[1], 0.05, 1e-16);
}

TEST(ContactPatch, BadLoadsCountAsNothingAndBadPositionsAreLeftOut) {
  const double nan = std::nan("");
  points p = box_face;
  p.push_back({{0.3, 0.3}, nan});  // a point of the hull, unloaded
  p.push_back({{nan, 0.0}, 7});    // left out
  p.push_back({{-0.3, 0.0}, -2});  // a point of the hull, unloaded
  p.push_back({{0.0, -0.3}, HUGE_VAL});
  const auto patch = contact_patch(p);
  ASSERT_EQ(patch.shape(), patch_shape::area);
  const auto e = resultant_centre(box_face), c = centre_from_wrench(patch);
  EXPECT_NEAR(c[0], e[0], 1e-16);
  EXPECT_NEAR(c[1], e[1], 1e-16);
}

TEST(ContactPatch, ACentreBeyondTheHullIsClampedOntoIt) {
  // A point the hull drops as flat (0.2·1e-6 outside the edge x = 0.11, on
  // its line within the tolerance) with nearly all the load: the loads'
  // centre is outside the hull; the patch is the line patch on that edge.
  points p = box_face;
  p.push_back({{0.11 + 2e-8, 0.0}, 1e9});
  const auto patch = contact_patch(p);
  EXPECT_EQ(patch.shape(), patch_shape::line);
  const auto c = centre_from_wrench(patch);
  EXPECT_NEAR(c[0], 0.11, 1e-15);
  EXPECT_NEAR(c[1], resultant_centre(p)[1], 1e-15);
}

TEST(ContactPatch, AnOriginFarAwayDoesNotThrow) {
  for (const double far : {1e3, 1e8, 1e12, 1e300}) {
    points p;
    for (const auto& c : box_face)
      p.push_back({{c.position[0] + far, c.position[1] - far}, c.load});
    const auto patch = contact_patch(p);
    const auto w = spinslide::friction_wrench(patch, planar_twist<double>{{0.1, 0.2}, 1.0});
    EXPECT_TRUE(std::isfinite(w.force[0] + w.force[1] + w.torque)) << far;
    // Two points: a segment, or a point once it is too short for its distance.
    const auto line = contact_patch(points{p[0], p[1]});
    EXPECT_TRUE(line.shape() == (far < 1 ? patch_shape::line : patch_shape::point)) << far;
  }
}

TEST(ContactPatch, InFloat) {
  using pf = contact_point<float>;
  const std::vector<pf> face{
      {{-0.11f, -0.05f}, 1}, {{0.11f, -0.05f}, 2}, {{0.11f, 0.05f}, 3}, {{-0.11f, 0.05f}, 4}};
  EXPECT_EQ(contact_patch(face).shape(), patch_shape::area);
  const std::vector<pf> edge{{{-0.11f, 0.05f}, 1}, {{0.11f, 0.05f}, 2}, {{0.0f, 0.05f}, 2}};
  EXPECT_EQ(contact_patch(edge).shape(), patch_shape::line);
}

TEST(ContactPatch, HullAndCentreOfRandomClouds) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> coordinate(-0.2, 0.2), load(0.1, 1);
  std::uniform_int_distribution<int> count(3, 12);
  for (int trial = 0; trial < 2000; ++trial) {
    const int n = count(rng);
    std::vector<point> xs;
    points loaded, unloaded;
    for (int k = 0; k < n; ++k) {
      const point x{coordinate(rng), coordinate(rng)};
      xs.push_back(x);
      loaded.push_back({x, load(rng)});
      unloaded.push_back({x, 0});
    }
    const auto expect = brute_force_hull(xs);
    const auto uniform = contact_patch(unloaded);
    ASSERT_EQ(uniform.shape(), patch_shape::area);
    auto got = outline_of(uniform);
    const double area = shoelace(got);
    EXPECT_GT(area, 0) << "counter-clockwise";
    std::sort(got.begin(), got.end());
    // General position: a hull vertex the brute force finds is one the hull
    // keeps, unless it is within the tolerance of its neighbours' chord.
    EXPECT_EQ(got, expect) << trial;
    std::vector<point> ordered = expect;  // the brute force's, in angle order about its mean
    point m{0, 0};
    for (const auto& v : ordered)
      m = {m[0] + v[0] / double(ordered.size()), m[1] + v[1] / double(ordered.size())};
    std::sort(ordered.begin(), ordered.end(), [&](const point& a, const point& b) {
      return std::atan2(a[1] - m[1], a[0] - m[0]) < std::atan2(b[1] - m[1], b[0] - m[0]);
    });
    EXPECT_NEAR(area, shoelace(ordered), 1e-15);
    const auto patch = contact_patch(loaded);
    const auto e = resultant_centre(loaded), c = centre_from_wrench(patch);
    const double scale = 1e-15 + (patch.shape() == patch_shape::area ? 0 : 1e-6);
    EXPECT_NEAR(c[0], e[0], scale) << trial;
    EXPECT_NEAR(c[1], e[1], scale) << trial;
  }
}

TEST(ContactPatch, RandomDegenerateCloudsNeverThrowNorGiveNaN) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> count(0, 9), kind(0, 3);
  for (int trial = 0; trial < 5000; ++trial) {
    const int n = count(rng), k = kind(rng);
    const point a{u(rng), u(rng)}, d{u(rng), u(rng)};
    points p;
    for (int i = 0; i < n; ++i) {
      const double t = u(rng), noise = k == 1 ? 1e-9 * u(rng) : (k == 2 ? 1e-15 * u(rng) : 0);
      point x = k == 3 ? a : point{a[0] + t * d[0] - noise * d[1], a[1] + t * d[1] + noise * d[0]};
      if (k == 0 && i % 3 == 2) x = {u(rng), u(rng)};  // a few off the line
      p.push_back({x, i % 4 == 0 ? 0.0 : std::fabs(u(rng))});
    }
    polygon_patch<double> patch = polygon_patch<double>::point({0, 0});
    ASSERT_NO_THROW(patch = contact_patch(p)) << trial;
    for (const auto& w :
         {planar_twist<double>{{0.3, -0.1}, 2.0}, planar_twist<double>{{0, 0}, -1.0},
          planar_twist<double>{{0.3, 0.4}, 0.0}}) {
      const auto f = spinslide::friction_wrench(patch, w);
      ASSERT_TRUE(std::isfinite(f.force[0] + f.force[1] + f.torque)) << trial;
    }
    if (k == 3 && n > 0) {
      EXPECT_EQ(patch.shape(), patch_shape::point) << trial;
    }
    if (k == 2 && n > 1) {
      EXPECT_NE(patch.shape(), patch_shape::area) << trial;
    }
  }
}

// What fuzz_contact_patch found, each once a throw or a NaN: loads times
// coordinates beyond the largest double (the centre's sums overflowed); the
// loads' centre on the vertex of a sliver 1e-6 across (polygon_patch found
// it a rounding outside); a sliver whose short edge is 2e-7 of its length
// under a tolerance of 0 (the polygon's pressure solve loaded nothing); a
// coordinate that is a subnormal beside the others (the wrench's edge sums
// lost a pivot that close to a vertex).
TEST(ContactPatch, WhatFuzzingFound) {
  const auto finite_wrenches = [](const polygon_patch<double>& patch) {
    for (const auto& w :
         {planar_twist<double>{{0.3, -0.1}, 2.0}, planar_twist<double>{{0, 0}, -1.0},
          planar_twist<double>{{0.3, 0.4}, 0.0}}) {
      const auto f = spinslide::friction_wrench(patch, w);
      if (!std::isfinite(f.force[0] + f.force[1] + f.torque)) return false;
    }
    return true;
  };
  const points overflow{{{7.3e196, 1.6}, 1.7e120}, {{0.7, 1.0e221}, 0.77}, {{0.37, -3.3e112}, 0.9}};
  const auto far = contact_patch(overflow);
  EXPECT_TRUE(std::isfinite(far.centre()[0]) && std::isfinite(far.centre()[1]));
  EXPECT_EQ(far.shape(), patch_shape::point);
  const points sliver{{{0.0300000005507530427551, -0.0199999991887761935372}, 3.3e41},
                      {{0.0299999999999999988898, -0.0200000000000000004163}, 3.2e176},
                      {{0.0299990484614043248501, -0.0199991700236014750824}, 0.21}};
  polygon_patch<double> on_vertex = polygon_patch<double>::point({0, 0});
  ASSERT_NO_THROW(on_vertex = contact_patch(sliver));
  EXPECT_NEAR(on_vertex.centre()[0], 0.03, 1e-15);
  EXPECT_TRUE(finite_wrenches(on_vertex));
  points short_edge{{{0.0300000000000004603262, -0.0200000000000063772598}, 0},
                    {{0.0299999998999999975546, -0.0200000001000000017515}, 0}};
  for (int i = 0; i < 6; ++i) short_edge.push_back({{0.029, -0.021}, 0});
  EXPECT_TRUE(finite_wrenches(contact_patch(short_edge, merge_tolerance<double>{0})));
  const points subnormal{{{-3.18839202664133069083e-307, 2.19766720473301768735}, 0.68},
                         {{5.4681986958194851322e-71, 0.032918977522178989592}, 0.96},
                         {{1.18575755001899170602e-321, 0}, 0},
                         {{0, 0}, 0}};
  EXPECT_TRUE(finite_wrenches(contact_patch(subnormal, merge_tolerance<double>{0})));
}
