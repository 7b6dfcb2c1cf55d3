//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// generate_profile_reference: the self-checks of the computed table (the
// table is written only if every one passes).
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

#include "profile_reference.hpp"

namespace profile_reference {

// Self-check 1: the uniform disk against disk_reference.csv (limit 1e-22).
bool check_uniform_disk(const computed_table& c, std::size_t uniform, const disk_check& disk,
                        std::vector<std::string>& notes) {
  double worst_disk = 0;
  double worst_disk_eps = 0;
  for (std::size_t i : disk.pick) {
    const disk_row& row = disk.rows[i];
    const values& v =
        on_grid(c.grid, row.eps) ? c.value_of(uniform, row.eps) : c.vals[c.extra_job[i]];
    const double d = std::max(rel(v.force, row.force), rel(v.torque, row.torque));
    if (d > worst_disk) {
      worst_disk = d;
      worst_disk_eps = row.eps;
    }
  }
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "self-check: uniform disk vs %s at %zu eps (%zu on the grid, %zu extra): "
                "largest relative difference %.2e (at eps=%.17g) [limit 1e-22]",
                disk.file, disk.pick.size(), disk.n_overlap, disk.pick.size() - disk.n_overlap,
                worst_disk, worst_disk_eps);
  std::fprintf(stderr, "%s\n", buf);
  notes.push_back(buf);
  return worst_disk < 1e-22;
}

// Self-check 2: the exact limits of every profile, approached at ε = 1e-6 and
// 1e6 (printed; each within its bound).
bool check_limits(const computed_table& c) {
  std::fprintf(stderr,
               "\nsanity (limits; deviations are the O(ε)/O(1/ε²) approach, not errors):\n");
  std::fprintf(stderr, "%-14s %-24s %-24s %-24s %-24s\n", "profile", "F/eps/(<1/r>/2)-1 @1e-6",
               "T/<r>-1 @1e-6", "eps*T/(<r2>/2)-1 @1e6", "1-F @1e6");
  bool ok = true;
  for (std::size_t p = 0; p < c.ps.size(); ++p) {
    const profile& pr = c.ps[p];
    const values& lo = c.value_of(p, 1e-6);
    const values& hi = c.value_of(p, 1e6);
    const big a = lo.force / big(1e-6) / (pr.mean_inv_r / 2) - 1;
    const big b = lo.torque / pr.mean_r - 1;
    const big cc = hi.torque * big(1e6) / (pr.mean_r2 / 2) - 1;
    const big d = 1 - hi.force;
    char buf[512];
    std::snprintf(buf, sizeof buf, "%-14s %-24.3e %-24.3e %-24.3e %-24.3e", pr.name.c_str(),
                  static_cast<double>(a), static_cast<double>(b), static_cast<double>(cc),
                  static_cast<double>(d));
    std::fprintf(stderr, "%s\n", buf);
    if (!(abs(a) < 1e-4 && abs(b) < 1e-4 && abs(cc) < 1e-9 && abs(d) < 1e-9)) {
      std::fprintf(stderr, "  ^ sanity limit FAILED\n");
      ok = false;
    }
  }
  return ok;
}

// Self-check 3: the ring's reciprocity 𝓕(ε) = 𝓣(1/ε), on the grid and, for
// ε = 0.653 and 1e-6, against 1/ε computed exactly in 50 digits (limit 1e-22).
bool check_ring_reciprocity(const computed_table& c, const big& tol,
                            std::vector<std::string>& notes) {
  const std::size_t ring = profile_index(c.ps, "ring");
  quad q;
  double worst_recip = 0;
  for (double e : {0.5, 0.125, 1.0}) {
    const double d1 = rel(c.value_of(ring, e).force, c.value_of(ring, 1 / e).torque);
    const double d2 = rel(c.value_of(ring, 1 / e).force, c.value_of(ring, e).torque);
    std::fprintf(stderr, "ring: F(%g)/T(%g)-1 = %.2e, F(%g)/T(%g)-1 = %.2e\n", e, 1 / e, d1, 1 / e,
                 e, d2);
    worst_recip = std::max({worst_recip, d1, d2});
  }
  for (double e : {0.653, 1e-6}) {  // exact reciprocal in 50 digits
    const values inv = compute(q, c.ps[ring], 1 / big(e), tol);
    const double d1 = rel(c.value_of(ring, e).force, inv.torque);
    const double d2 = rel(inv.force, c.value_of(ring, e).torque);
    std::fprintf(stderr, "ring: F(%g)/T(1/%g)-1 = %.2e, F(1/%g)/T(%g)-1 = %.2e\n", e, e, d1, e, e,
                 d2);
    worst_recip = std::max({worst_recip, d1, d2});
  }
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "self-check: ring F(eps) = T(1/eps): largest relative difference %.2e",
                worst_recip);
  std::fprintf(stderr, "%s\n", buf);
  notes.push_back(buf);
  return worst_recip < 1e-22;
}

// Self-check 4: Boussinesq's closed form for ε ≥ 1 at ε = 1, 2, 8 (limit 1e-22).
bool check_boussinesq(const computed_table& c, std::vector<std::string>& notes) {
  const std::size_t bous = profile_index(c.ps, "boussinesq");
  double worst_b = 0;
  for (double e : {1.0, 2.0, 8.0}) {
    const big k = 1 / big(e);
    const big exact = (asin(k) / k + sqrt(1 - k * k)) / 2;
    const double d = rel(c.value_of(bous, e).force, exact);
    std::fprintf(stderr, "boussinesq: F(%g) = %s, closed form %s, rel diff %.2e\n", e,
                 fmt(c.value_of(bous, e).force).c_str(), fmt(exact).c_str(), d);
    worst_b = std::max(worst_b, d);
  }
  char buf[512];
  std::snprintf(
      buf, sizeof buf,
      "self-check: boussinesq F = (asin(k)/k + sqrt(1-k^2))/2, k = 1/eps, at eps = 1, 2, 8: "
      "largest relative difference %.2e",
      worst_b);
  std::fprintf(stderr, "%s\n", buf);
  notes.push_back(buf);
  return worst_b < 1e-22;
}

// Self-check 5, the tolerance study: tol vs tol·1e-5 for 3 profiles at 4 ε
// (limit 1e-20).
bool check_tolerance(const computed_table& c, const options& o, std::vector<std::string>& notes) {
  const big tight = o.tol / big("1e5");
  std::vector<job> tj;
  const std::vector<std::string> names{"hertz", "boussinesq", "two_tier"};
  const std::vector<double> es{1e-6, 0.499, 1.0, 1e6};
  for (const std::string& n : names)
    for (double e : es) tj.push_back({profile_index(c.ps, n), e, tight});
  const std::vector<values> tv = run(c.ps, tj, "tolerance study");
  std::fprintf(stderr, "\ntolerance study: relative change of (F, T) from tol %s to tol %s:\n",
               o.tol_text.c_str(), fmt(tight, 2).c_str());
  double worst_t = 0;
  for (std::size_t i = 0; i < tj.size(); ++i) {
    const values& v = c.value_of(tj[i].profile, tj[i].eps);
    const double df = rel(v.force, tv[i].force), dt = rel(v.torque, tv[i].torque);
    std::fprintf(stderr, "  %-12s eps=%-8g dF %.2e  dT %.2e\n", c.ps[tj[i].profile].name.c_str(),
                 tj[i].eps, df, dt);
    worst_t = std::max({worst_t, df, dt});
  }
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "tolerance study (hertz, boussinesq, two_tier at eps = 1e-6, 0.499, 1, 1e6): "
                "largest relative change from tol %s to %s: %.2e",
                o.tol_text.c_str(), fmt(tight, 2).c_str(), worst_t);
  std::fprintf(stderr, "%s\n", buf);
  notes.push_back(buf);
  return worst_t < 1e-20;
}

}  // namespace profile_reference
