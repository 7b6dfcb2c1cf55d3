//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Fuzz harness: project_to_limit_set on the profiles of zoo.hpp but the Padé
// approximants (which do not compile there: their curve's normal is not
// (ε, 1)), with and without a starting ratio.  Valid: force and torque finite
// and ≥ 0, the weight finite and > 0, the start ≥ 0.  Then: no exception;
// sticking returns the point unchanged with a NaN ratio; otherwise the result
// lies in [0, 1] × [0, ⟨r⟩], its ratio is ≥ 0 (or NaN for none), and it is no
// farther from the point than the corners (1, 0) and (0, ⟨r⟩) and the curve
// at ε·(1 ± 1e-3) (a nearest point cannot be beaten by its neighbours), to
// 1e-9 relative; a start does not change the answer beyond 1e-6.

#include "zoo.hpp"

#include <spinslide/contact/limit_set.hpp>
#include <spinslide/values/coupling.hpp>

#include <cmath>
#include <limits>
#include <type_traits>

namespace {

using namespace spinslide_fuzz;

struct query {
  double x, y, w;
};

double squared(const query& q, double f, double t) {
  return (f - q.x) * (f - q.x) + q.w * (t - q.y) * (t - q.y);
}

// How much a few ulp (~9) of f and t (of sizes 1 and ⟨r⟩) can move the squared
// distance d in this metric: 2√d·u + u² with u = 1e-15 (1 + √w ⟨r⟩).  With
// an extreme weight this is all there is to resolve.
double rounding_allowance(const query& q, double d, double top) {
  const double u = 1e-15 * (1 + std::sqrt(q.w) * top);
  return 2 * std::sqrt(d) * u + u * u;
}

// The result is no farther than the corners and the curve beside it.
template <class P>
void check_nearest(const P& p, const query& q,
                   const spinslide::friction_result<double, double>& r) {
  const double d = squared(q, r.force, r.torque);
  if (!std::isfinite(d)) return;  // a point near the largest value: distances overflow
  const double slack = 1 + 1e-9, allow = rounding_allowance(q, d, p.mean_radius());
  check(d <= squared(q, 1, 0) * slack + allow, "project_to_limit_set", "farther than (1, 0)");
  check(d <= squared(q, 0, p.mean_radius()) * slack + allow, "project_to_limit_set",
        "farther than (0, <r>)");
  if (!(r.ratio > 0 && r.ratio < 1e300)) return;
  for (const double k : {1 - 1e-3, 1 + 1e-3}) {
    const auto c = p.force_torque(r.ratio * k);
    check(d <= squared(q, c.force, c.torque) * slack + allow, "project_to_limit_set",
          "farther than the curve beside it");
  }
}

// A sticking point lies in L: x ≤ 1 and y ≤ 𝓣 where 𝓕 = x (from the
// coupling inverse; the uncoupled caps' box: y ≤ ⟨r⟩), to 1e-9.
template <class P>
void check_inside(const P& p, const query& q, bool caps) {
  check(q.x <= 1 + 1e-12, "project_to_limit_set", "sticking with f > 1");
  const double top = p.mean_radius();
  if (q.x >= 1 - 1e-9 || q.x <= 1e-300) {
    check(q.y <= top * (1 + 1e-9), "project_to_limit_set", "sticking with t > <r>");
    return;
  }
  const double limit = caps ? top : spinslide::torque_at_force(p, q.x);
  check(q.y <= limit * (1 + 1e-9) + 1e-9 * top, "project_to_limit_set", "sticking above the curve");
}

template <class P>
void check_projection(const P& p, const query& q,
                      const spinslide::friction_result<double, double>& r, bool caps) {
  if (r.sticking) {
    check(r.force == q.x && r.torque == q.y, "project_to_limit_set", "sticking but moved");
    check(std::isnan(r.ratio), "project_to_limit_set", "sticking with a ratio");
    check_inside(p, q, caps);
    return;
  }
  check_finite(r.force, "project_to_limit_set", "force");
  check_finite(r.torque, "project_to_limit_set", "torque");
  check(r.force >= 0 && r.force <= 1, "project_to_limit_set", "force outside [0, 1]");
  check(r.torque >= 0 && r.torque <= p.mean_radius() * (1 + 1e-12), "project_to_limit_set",
        "torque outside [0, <r>]");
  check(r.ratio >= 0, "project_to_limit_set", "ratio < 0 or NaN");
  check_nearest(p, q, r);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz_input in(data, size);
  context().clear();
  with_projectable_profile(in, [&](const auto& p, const char* name) {
    const bool caps = std::string(name) == "uncoupled_caps";
    const query q{in.unit<double>() * 2, in.unit<double>() * 2, in.real<double>()};
    const double start = in.real<double>();
    describe("force", q.x);
    describe("torque", q.y);
    describe("torque_weight", q.w);
    describe("start", start);
    const validity v = valid_if(q.x >= 0 && std::isfinite(q.x) && q.y >= 0 && std::isfinite(q.y) &&
                                q.w > 0 && std::isfinite(q.w));
    spinslide::friction_result<double, double> cold{};
    const bool ran = expect(v, "project_to_limit_set", [&] {
      cold = spinslide::project_to_limit_set(p, q.x, q.y, q.w);
      check_projection(p, q, cold, caps);
    });
    const validity vs = v == validity::valid ? valid_if(start >= 0) : v;
    expect(vs, "project_to_limit_set(start)", [&] {
      const auto warm =
          spinslide::project_to_limit_set(p, q.x, q.y, q.w, spinslide::curve_point<double>{start});
      check_projection(p, q, warm, caps);
      if (ran && warm.sticking == cold.sticking && !cold.sticking) {
        // Both nearest to rounding.
        const double dc = squared(q, cold.force, cold.torque);
        const double dw = squared(q, warm.force, warm.torque);
        check(!std::isfinite(dc) ||
                  std::fabs(dw - dc) <= 1e-6 * dc + rounding_allowance(q, dc, p.mean_radius()),
              "project_to_limit_set(start)", "the start changed the distance");
      }
    });
  });
  return 0;
}
