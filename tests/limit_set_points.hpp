//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// What the tests of project_to_limit_set share (test_limit_set.cpp,
// test_limit_set_starts.cpp): a fixed set of random points, and the exact
// construction of a point on the curve's normal, which must project to the
// normal's foot.
#ifndef SPINSLIDE_TESTS_LIMIT_SET_POINTS_HPP
#define SPINSLIDE_TESTS_LIMIT_SET_POINTS_HPP

#include <gtest/gtest.h>

#include <spinslide/contact/limit_set.hpp>

#include <random>
#include <string>
#include <vector>

namespace spinslide_test {

struct points {
  std::vector<double> x, y;
};
inline const points& random_points() {
  static const points pts = [] {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(0, 1);
    points p;
    for (int i = 0; i < 300; ++i) {
      p.x.push_back(1.6 * u(rng));
      p.y.push_back(1.2 * u(rng));
    }
    return p;
  }();
  return pts;
}

// P = C(ε) + λ(wε, 1) has the displacement along the curve's normal in the
// metric, so it projects to C(ε) at ratio ε; searched from `start` (0: none).
template <class P>
void expect_normal_projects_to_foot(const P& p, double w, double eps, double lambda,
                                    double ratio_tolerance, const std::string& name,
                                    double start = 0) {
  const auto c = p.force_torque(eps);
  const double x = c.force + lambda * w * eps, y = c.torque + lambda;
  const auto r = spinslide::project_to_limit_set(p, x, y, w, spinslide::curve_point<double>{start});
  const std::string where = name + " w=" + std::to_string(w) + " eps=" + std::to_string(eps) +
                            " lambda=" + std::to_string(lambda) + " from " + std::to_string(start);
  EXPECT_FALSE(r.sticking) << where;
  EXPECT_NEAR(r.ratio / eps, 1, ratio_tolerance) << where;
  EXPECT_NEAR(r.force, c.force, 4e-16 + 1e-13 * x) << where;
  EXPECT_NEAR(r.torque, c.torque, 4e-16 + 1e-13 * y) << where;
}

}  // namespace spinslide_test

#endif  // SPINSLIDE_TESTS_LIMIT_SET_POINTS_HPP
