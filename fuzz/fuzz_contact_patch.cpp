//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Fuzz harness: contact_patch (contact/contact_patch.hpp), the patch of an
// engine contact from up to 12 points, in float and double.  The points
// are a rectangle's corners with noise (1e-3 to 1e-18 of its size), points
// on a line with noise, one point repeated, or any numbers (NaN, infinities,
// subnormals, 1e±300); loads and the merge tolerance are any numbers too.
// Every input is valid: it must never throw, and
// - the patch's centre is finite and within the finite points' bounding
//   box (to 1e-6 of the box, or 128 ε of the largest coordinate: the sums'
//   scale, and what contact_patch rounds to 0);
// - where the finite points' extent and coordinates are within the lengths
//   the wrench is made for (double 1e-100 to 1e100, float 1e-10 to 1e30),
//   the wrench of three twists is finite.

#include "fuzz.hpp"

#include <spinslide/contact/contact_patch.hpp>
#include <spinslide/values/friction_wrench.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace {

using namespace spinslide_fuzz;

template <class Real>
std::array<Real, 2> point_of(fuzz_input& in, int shape, std::size_t k) {
  const double noise = std::pow(10.0, -3.0 - static_cast<double>(in.byte() % 16));
  const double u = 2 * in.uniform01<double>() - 1, w = 2 * in.uniform01<double>() - 1;
  switch (shape) {
    case 0: {  // a 0.22 × 0.10 face's corners, with noise
      const double x = (k & 1U) ? 0.11 : -0.11, y = (k & 2U) ? 0.05 : -0.05;
      return {static_cast<Real>(x + noise * u), static_cast<Real>(y + noise * w)};
    }
    case 1:  // a line through (0.02, 0.01) along (3, 1), with noise across it
      return {static_cast<Real>(0.02 + 0.3 * u - noise * w),
              static_cast<Real>(0.01 + 0.1 * u + 0.3 * noise * w)};
    case 2:  // one point, repeated with noise
      return {static_cast<Real>(0.03 + noise * u), static_cast<Real>(-0.02 + noise * w)};
    default:
      return {in.real<Real>(), in.real<Real>()};
  }
}

template <class Real>
void one(fuzz_input& in) {
  const int shape = static_cast<int>(in.byte() % 4);
  const std::size_t n = in.byte() % 13;
  std::vector<spinslide::contact_point<Real>> points;
  for (std::size_t k = 0; k < n; ++k) {
    const auto x = point_of<Real>(in, shape, k);
    const Real load = in.byte() % 4 == 0 ? in.real<Real>() : in.uniform01<Real>();
    points.push_back({x, load});
    describe("x", x[0]);
    describe("y", x[1]);
    describe("load", load);
  }
  const Real tolerance = in.byte() % 4 == 0 ? in.real<Real>() : Real(1e-6);
  describe("tolerance", tolerance);
  Real lo[2] = {0, 0}, hi[2] = {0, 0}, largest = 0;
  bool any = false;
  for (const auto& p : points) {
    if (!std::isfinite(p.position[0]) || !std::isfinite(p.position[1])) continue;
    for (std::size_t i = 0; i < 2; ++i) {
      lo[i] = any ? std::min(lo[i], p.position[i]) : p.position[i];
      hi[i] = any ? std::max(hi[i], p.position[i]) : p.position[i];
      largest = std::max(largest, std::fabs(p.position[i]));
    }
    any = true;
  }
  const char* call = "contact_patch(points, merge_tolerance)";
  expect(validity::valid, call, [&] {
    const auto patch =
        spinslide::contact_patch(points, spinslide::merge_tolerance<Real>{tolerance});
    const auto& c = patch.centre();
    check_finite(c[0], call, "centre x");
    check_finite(c[1], call, "centre y");
    if (any)
      for (std::size_t i = 0; i < 2; ++i) {
        const Real slack = std::max(Real(1e-6) * (hi[i] - lo[i]),
                                    128 * std::numeric_limits<Real>::epsilon() * largest);
        check(c[i] >= lo[i] - slack && c[i] <= hi[i] + slack, call,
              "the centre is outside the points' bounding box");
      }
    // The wrench is held to the lengths it is made for: double from 1e-100
    // to 1e100, float from 1e-10 to 1e30 (a float line patch of 1e-17
    // overflows its line density's slope: polygon_patch computes a segment
    // in its own type).
    const bool dbl = std::numeric_limits<Real>::max_exponent10 > 100;
    const Real extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(largest <= Real(dbl ? 1e100 : 1e30))) return;
    if (extent > 0 && extent < Real(dbl ? 1e-100 : 1e-10)) return;
    for (const auto& w : {spinslide::planar_twist<Real>{{Real(0.3), Real(-0.1)}, Real(2)},
                          spinslide::planar_twist<Real>{{Real(0), Real(0)}, Real(-1)},
                          spinslide::planar_twist<Real>{{Real(0.3), Real(0.4)}, Real(0)}}) {
      const auto f = spinslide::friction_wrench(patch, w);
      check_finite(f.force[0], call, "wrench force x");
      check_finite(f.force[1], call, "wrench force y");
      check_finite(f.torque, call, "wrench torque");
    }
  });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz_input in(data, size);
  context().clear();
  if (in.byte() % 2)
    one<double>(in);
  else
    one<float>(in);
  return 0;
}
