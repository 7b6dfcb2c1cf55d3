//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Generates tests/reference/profile_reference.csv: the dimensionless friction
// force 𝓕(ε) and torque 𝓣(ε) of a flat contact patch (unit disk) pressed by an
// axisymmetric pressure p(r), sliding along x̂ and spinning about ẑ with
// ε = v/(Rω), straight from the DEFINING AREA INTEGRALS
//   𝓕(ε) = ∬ p (ε − y)/ρ dA / ∬ p dA,
//   𝓣(ε) = ∬ p (x² + y² − ε y)/ρ dA / ∬ p dA,      ρ² = x² + (y − ε)²,
// by nested 2-D tanh_sinh quadrature of the raw integrand.  There is no
// closed-form inner integral and no elliptic integral anywhere: the table is
// meant to be independent of everything spinslide implements.
//
// Polar form (x = r sinθ, y = r cosθ, dA = r dr dθ, integrand even in θ):
//   𝓕 = ∫ p r I_F(r) dr / (π ∫ p r dr),  I_F(r) = ∫₀^π (ε − r cosθ)/ρ dθ,
//   𝓣 = ∫ p r I_T(r) dr / (π ∫ p r dr),  I_T(r) = ∫₀^π r (r − ε cosθ)/ρ dθ,
// with ρ² = r² + ε² − 2 r ε cosθ.  The integrand is evaluated in the
// algebraically identical, cancellation-free form (h = sin²(θ/2), d = r − ε)
//   ρ² = d² + 4 r ε h,  ε − r cosθ = −d + 2 r h,  r − ε cosθ = d + 2 ε h,
// which matters where r ≈ ε and θ ≈ 0 (the integrand's sharp peak).
//
// Quadrature: Boost tanh_sinh in cpp_bin_float_50 for both levels.  Every
// interval is mapped onto [0, 1] by hand (Boost 1.74's tanh_sinh can trip an
// internal BOOST_ASSERT for multiprecision intervals whose endpoints are away
// from 0).  The r-integral is split at r = ε (the inner integral has a
// logarithmically singular derivative there) and at the profile's own
// breakpoints; the sharp θ-peak for r ≈ ε sits at the endpoint θ = 0, where
// tanh_sinh clusters its nodes.  Hertz and Boussinesq use r = sin φ so that
// p r dr is smooth (sin φ cos² φ dφ and sin φ dφ).
//
// Tolerances: the outer level uses `tol` (relative to the L1 norm of its
// integrand, which is positive, so effectively relative to the result).  The
// inner θ-integral cancels: for r ≫ ε, (ε − r cosθ)/ρ = −cosθ + O(ε/r), so
// I_F = O(ε) while its L1 norm is O(1); likewise I_T = O(r²/ε) for ε ≫ r with
// L1 norm O(r).  The inner tolerance is therefore tol·min(1, ε)/100 for 𝓕 and
// tol·min(1, 1/ε)/100 for 𝓣, which keeps the relative error of the result at
// the level of `tol` at ε = 1e-6 and 1e6 (checked by the tolerance study and
// by the uniform-disk self-check).
//
// Usage:
//   generate_profile_reference [--tol T] > profile_reference.csv
//       computes the table (2 worker threads), then runs the self-checks
//       (uniform disk vs tests/reference/disk_reference.csv, exact sanity
//       facts, tolerance study) and exits nonzero if one fails.
//       --disk FILE   uniform-disk reference (default
//                     tests/reference/disk_reference.csv)
//   generate_profile_reference --compare FILE
//       recomputes every 10th data row of FILE and reports the largest
//       relative difference (exit status 1 above 1e-20).
//
// Build: g++ -std=c++17 -O2 -Wall -Wextra -Wpedantic -pthread
#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "csv.hpp"

namespace {

using big = boost::multiprecision::cpp_bin_float_50;
using boost::math::quadrature::tanh_sinh;

const big pi = boost::math::constants::pi<big>();
const big half_pi = boost::math::constants::half_pi<big>();

// ---------------------------------------------------------------------------
// Quadrature helpers

struct quad {
  // Non-const on purpose: Boost 1.74 declares tanh_sinh::integrate const but
  // defines it non-const.  Separate objects for the two levels, because the
  // abscissa tables grow lazily and the levels are nested.
  tanh_sinh<big> outer{20};
  tanh_sinh<big> inner{20};
  double worst_outer = 0;  // largest error estimate / L1 seen (diagnostics)
  double worst_inner = 0;
};

// ∫_a^b f, with the interval mapped onto [0, 1] by hand.
template <class F>
big integrate01(tanh_sinh<big>& q, F f, const big& a, const big& b, const big& tol, double& worst) {
  const big w = b - a;
  auto g = [&](const big& s) -> big { return f(a + w * s); };
  big err = 0, l1 = 0;
  std::size_t levels = 0;
  const big v = q.integrate(g, big(0), big(1), tol, &err, &l1, &levels);
  if (l1 != 0) worst = std::max(worst, static_cast<double>(err / l1));
  return w * v;
}

enum class quantity { force, torque };

// I_F(r) or I_T(r): ∫₀^π of the raw polar integrand.  The quadrature variable
// is u = tan(θ/4) ∈ [0, 1] (θ = 4 atan u, dθ = 4 du/(1 + u²),
// sin(θ/2) = 2u/(1 + u²)): a plain change of variables that makes the
// integrand rational in u apart from ρ's square root, i.e. no sin/cos in the
// innermost loop (they dominate the cost in 50-digit arithmetic).  θ = 0, where
// the integrand peaks for r ≈ ε, stays an endpoint (u = 0).
big theta_integral(quad& q, quantity what, const big& r, const big& eps, const big& tol) {
  const big d = r - eps;
  const big four_r_eps = 4 * r * eps;
  auto f = [&](const big& u) -> big {
    const big t = u * u;
    const big inv = 1 / (1 + t);
    const big h = 4 * t * inv * inv;  // sin²(θ/2) = (1 − cosθ)/2
    const big rho2 = d * d + four_r_eps * h;
    if (rho2 == 0) return big(0);                   // ρ = 0: a single point, measure zero
    const big jac_over_rho = 4 * inv / sqrt(rho2);  // (dθ/du)/ρ
    if (what == quantity::force) return big((2 * r * h - d) * jac_over_rho);  // (ε − r cosθ)/ρ
    return big(r * (d + 2 * eps * h) * jac_over_rho);  // r (r − ε cosθ)/ρ
  };
  return integrate01(q.inner, f, big(0), big(1), tol, q.worst_inner);
}

// ---------------------------------------------------------------------------
// Profiles.  The outer variable u is r (or φ with r = sin φ); weight(u, tier)
// is p(r) r dr/du; norm = ∫ p r dr (exact); breaks are the profile's own
// interior breakpoints in u; moments are the load-weighted ⟨r⟩, ⟨1/r⟩, ⟨r²⟩.

struct profile {
  std::string name;
  bool ring = false;  // all load on r = 1
  bool phi = false;   // u = φ, r = sin φ
  big u0, u1;         // range of u
  std::vector<big> breaks;
  std::function<big(const big& u, const big& u_mid)> weight;  // u_mid: midpoint of the piece
  big norm;
  big mean_r, mean_inv_r, mean_r2;
};

std::vector<profile> make_profiles() {
  std::vector<profile> ps;
  {
    profile p;
    p.name = "uniform";
    p.u0 = 0;
    p.u1 = 1;
    p.weight = [](const big& r, const big&) { return r; };
    p.norm = big(1) / 2;
    p.mean_r = big(2) / 3;
    p.mean_inv_r = 2;
    p.mean_r2 = big(1) / 2;
    ps.push_back(p);
  }
  {
    const big b = big(1) / 8;
    profile p;
    p.name = "annulus_0.125";
    p.u0 = b;
    p.u1 = 1;
    p.weight = [](const big& r, const big&) { return r; };
    p.norm = (1 - b * b) / 2;
    p.mean_r = big(2) / 3 * (1 - b * b * b) / (1 - b * b);
    p.mean_inv_r = 2 / (1 + b);
    p.mean_r2 = (1 + b * b) / 2;
    ps.push_back(p);
  }
  {
    profile p;  // p = √(1 − r²): p r dr = sin φ cos² φ dφ
    p.name = "hertz";
    p.phi = true;
    p.u0 = 0;
    p.u1 = half_pi;
    p.weight = [](const big& phi, const big&) {
      const big c = cos(phi);
      return big(sin(phi) * c * c);
    };
    p.norm = big(1) / 3;
    p.mean_r = 3 * pi / 16;
    p.mean_inv_r = 3 * pi / 4;
    p.mean_r2 = big(2) / 5;
    ps.push_back(p);
  }
  {
    profile p;  // p = 1/√(1 − r²): p r dr = sin φ dφ
    p.name = "boussinesq";
    p.phi = true;
    p.u0 = 0;
    p.u1 = half_pi;
    p.weight = [](const big& phi, const big&) { return big(sin(phi)); };
    p.norm = 1;
    p.mean_r = pi / 4;
    p.mean_inv_r = pi / 2;
    p.mean_r2 = big(2) / 3;
    ps.push_back(p);
  }
  {
    profile p;
    p.name = "ring";
    p.ring = true;
    p.u0 = 1;
    p.u1 = 1;
    p.norm = 1;
    p.mean_r = 1;
    p.mean_inv_r = 1;
    p.mean_r2 = 1;
    ps.push_back(p);
  }
  {
    // p1 on r < 1/2, p2 on 1/2 < r ≤ 1 with p1·π/4 : p2·3π/4 = 0.6 : 0.4;
    // p1 = 12/5, p2 = 8/15 gives ∫ p r dr = 3/10 + 1/5 = 1/2.
    profile p;
    p.name = "two_tier";
    p.u0 = 0;
    p.u1 = 1;
    p.breaks = {big(1) / 2};
    p.weight = [](const big& r, const big& mid) {
      return big(mid < big(1) / 2 ? r * 12 / 5 : r * 8 / 15);
    };
    p.norm = big(1) / 2;
    p.mean_r = big(23) / 45;
    p.mean_inv_r = big(44) / 15;
    p.mean_r2 = big(13) / 40;
    ps.push_back(p);
  }
  {
    profile p;
    p.name = "parabolic";
    p.u0 = 0;
    p.u1 = 1;
    p.weight = [](const big& r, const big&) { return big(r * (1 - r * r)); };
    p.norm = big(1) / 4;
    p.mean_r = big(8) / 15;
    p.mean_inv_r = big(8) / 3;
    p.mean_r2 = big(1) / 3;
    ps.push_back(p);
  }
  return ps;
}

struct values {
  big force, torque;
};

values compute(quad& q, const profile& p, const big& eps, const big& tol) {
  const big one(1);
  const big tol_f = tol * std::min(one, eps) / 100;
  const big tol_t = tol * std::min(one, one / eps) / 100;
  values v;
  if (p.ring) {
    // Both are positive 1-D integrals (no outer level); tanh_sinh's tolerance
    // is relative to the L1 norm, so use the cancellation-aware one.
    v.force = theta_integral(q, quantity::force, one, eps, tol_f) / pi;
    v.torque = theta_integral(q, quantity::torque, one, eps, tol_t) / pi;
    return v;
  }
  // Pieces of the u-range: profile breakpoints plus u(r = ε).
  std::vector<big> cuts{p.u0, p.u1};
  for (const big& b : p.breaks) cuts.push_back(b);
  if (eps < 1) cuts.push_back(p.phi ? big(asin(eps)) : eps);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  big sum_f = 0, sum_t = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const big a = cuts[i], b = cuts[i + 1];
    if (a < p.u0 || b > p.u1) continue;
    const big mid = (a + b) / 2;
    auto outer_f = [&](const big& u) -> big {
      const big w = p.weight(u, mid);
      if (w == 0) return big(0);
      const big r = p.phi ? big(sin(u)) : u;
      return big(w * theta_integral(q, quantity::force, r, eps, tol_f));
    };
    auto outer_t = [&](const big& u) -> big {
      const big w = p.weight(u, mid);
      if (w == 0) return big(0);
      const big r = p.phi ? big(sin(u)) : u;
      return big(w * theta_integral(q, quantity::torque, r, eps, tol_t));
    };
    sum_f += integrate01(q.outer, outer_f, a, b, tol, q.worst_outer);
    sum_t += integrate01(q.outer, outer_t, a, b, tol, q.worst_outer);
  }
  v.force = sum_f / (pi * p.norm);
  v.torque = sum_t / (pi * p.norm);
  return v;
}

// ---------------------------------------------------------------------------
// ε grid: 10^(k/4), k = −24..24, plus extra points near 1 and near the
// profiles' breakpoints.  All doubles, converted exactly to cpp_bin_float_50.

std::vector<double> eps_grid() {
  std::vector<double> e;
  for (int k = -24; k <= 24; ++k) e.push_back(std::pow(10.0, k / 4.0));
  for (double x : {0.125, 0.25, 0.5, 0.653, 0.9, 0.99, 0.999, 0.999999, 1.0, 1.000001, 1.001, 1.01,
                   1.1, 2.0, 8.0, 0.124, 0.126, 0.499, 0.501})
    e.push_back(x);
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  return e;
}

std::string fmt(const big& x, int digits = 32) {
  std::ostringstream os;
  os.precision(digits - 1);
  os << std::scientific << x;
  return os.str();
}

double rel(const big& a, const big& b) {
  if (b == 0) return a == 0 ? 0.0 : 1.0;
  return static_cast<double>(abs((a - b) / b));
}

// ---------------------------------------------------------------------------
// Parallel evaluation of a list of (profile, ε, tol) jobs with 2 workers.

struct job {
  std::size_t profile;
  double eps;
  big tol;
};

struct run_stats {
  double worst_outer = 0, worst_inner = 0;
};

std::vector<values> run(const std::vector<profile>& ps, const std::vector<job>& jobs,
                        const char* label, run_stats* stats = nullptr) {
  std::vector<values> out(jobs.size());
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::mutex mu;
  std::vector<std::size_t> left(ps.size(), 0);
  for (const job& j : jobs) ++left[j.profile];
  const auto t0 = std::chrono::steady_clock::now();
  run_stats total;
  auto work = [&] {
    quad q;
    for (;;) {
      const std::size_t i = next++;
      if (i >= jobs.size()) break;
      out[i] = compute(q, ps[jobs[i].profile], big(jobs[i].eps), jobs[i].tol);
      std::lock_guard<std::mutex> lock(mu);
      ++done;
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::fprintf(stderr, "\r[%s] %zu / %zu  (%.0f s)   ", label, done, jobs.size(), s);
      if (--left[jobs[i].profile] == 0)
        std::fprintf(stderr, "\n[%s] profile %s done at %.0f s\n", label,
                     ps[jobs[i].profile].name.c_str(), s);
    }
    std::lock_guard<std::mutex> lock(mu);
    total.worst_outer = std::max(total.worst_outer, q.worst_outer);
    total.worst_inner = std::max(total.worst_inner, q.worst_inner);
  };
  std::vector<std::thread> workers;
  workers.reserve(2);
  for (int t = 0; t < 2; ++t) workers.emplace_back(work);
  for (auto& w : workers) w.join();
  std::fprintf(stderr,
               "\r[%s] %zu jobs in %.0f s; largest tanh_sinh error/L1: outer %.1e, inner %.1e\n",
               label, jobs.size(),
               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
               total.worst_outer, total.worst_inner);
  if (stats) *stats = total;
  return out;
}

std::size_t profile_index(const std::vector<profile>& ps, const std::string& name) {
  for (std::size_t i = 0; i < ps.size(); ++i)
    if (ps[i].name == name) return i;
  return ps.size();
}

// ---------------------------------------------------------------------------
// --compare FILE

int compare(const char* file, const big& tol) {
  std::vector<std::vector<std::string>> table;
  if (!spinslide_reference::read_csv_rows(file, "profile", table)) return 2;
  const std::vector<profile> ps = make_profiles();
  std::vector<job> jobs;
  std::vector<values> expected;
  std::vector<std::string> lines;
  for (std::size_t n = 0; n < table.size(); n += 10) {
    const std::vector<std::string>& f = table[n];
    const std::size_t pi_ = f.size() >= 5 ? profile_index(ps, f[0]) : ps.size();
    if (pi_ == ps.size()) {
      std::fprintf(stderr, "bad row %zu of %s\n", n + 1, file);
      return 2;
    }
    jobs.push_back({pi_, std::strtod(f[1].c_str(), nullptr), tol});
    expected.push_back({big(f[3]), big(f[4])});
    lines.push_back(f[0] + " eps=" + f[2]);
  }
  const std::vector<values> got = run(ps, jobs, "compare");
  double worst = 0;
  std::size_t worst_i = 0;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const double d =
        std::max(rel(got[i].force, expected[i].force), rel(got[i].torque, expected[i].torque));
    if (d > worst) {
      worst = d;
      worst_i = i;
    }
  }
  std::printf("compared %zu rows (every 10th): largest relative difference %.2e%s%s\n", jobs.size(),
              worst, jobs.empty() ? "" : " at ", jobs.empty() ? "" : lines[worst_i].c_str());
  return worst > 1e-20 ? 1 : 0;
}

// ---------------------------------------------------------------------------

struct disk_row {
  double eps;
  big force, torque;
};

// The uniform disk's table (empty if it cannot be read: main reports that).
std::vector<disk_row> read_disk(const char* file) {
  std::vector<std::vector<std::string>> table;
  std::vector<disk_row> rows;
  if (spinslide_reference::read_csv_rows(file, "eps_hex", table))
    for (const auto& f : table)
      if (f.size() >= 5) rows.push_back({std::strtod(f[0].c_str(), nullptr), big(f[3]), big(f[4])});
  return rows;
}

// ---------------------------------------------------------------------------
// The command line and the table with its self-checks

struct options {
  big tol{"1e-20"};
  std::string tol_text = "1e-20";
  const char* disk_file = "tests/reference/disk_reference.csv";
};

// Reads the options into `o`.  --compare FILE runs the comparison at once,
// with the --tol given before it.  False, with the exit status in `status`,
// when there is nothing more to do (the comparison ran, or a usage error).
bool parse_command_line(int argc, char** argv, options& o, int& status) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--tol" && i + 1 < argc) {
      o.tol_text = argv[++i];
      o.tol = big(o.tol_text);
    } else if (a == "--disk" && i + 1 < argc) {
      o.disk_file = argv[++i];
    } else if (a == "--compare" && i + 1 < argc) {
      status = compare(argv[++i], o.tol);
      return false;
    } else {
      std::fprintf(stderr, "usage: %s [--tol T] [--disk FILE] [--compare FILE]\n", argv[0]);
      status = 2;
      return false;
    }
  }
  return true;
}

bool on_grid(const std::vector<double>& grid, double e) {
  return std::find(grid.begin(), grid.end(), e) != grid.end();
}

// The uniform disk's table and the rows of it the self-check recomputes:
// those on the grid (the first n_overlap of `pick`), then ~10 spread over the
// file.
struct disk_check {
  const char* file;
  std::vector<disk_row> rows;
  std::vector<std::size_t> pick;  // indices into `rows`
  std::size_t n_overlap = 0;
};

disk_check pick_disk_rows(const char* file, std::vector<disk_row> rows,
                          const std::vector<double>& grid) {
  disk_check d{file, std::move(rows), {}, 0};
  for (std::size_t i = 0; i < d.rows.size(); ++i)
    if (on_grid(grid, d.rows[i].eps)) d.pick.push_back(i);
  d.n_overlap = d.pick.size();
  for (std::size_t k = 0; k < 10; ++k) {
    const std::size_t i = (k * (d.rows.size() - 1)) / 9;
    if (std::find(d.pick.begin(), d.pick.end(), i) == d.pick.end()) d.pick.push_back(i);
  }
  return d;
}

// The computed table: every profile on the full grid (uniform too: it is the
// self-check profile), jobs [0, n_table), then the extra uniform-disk points
// of the self-check that are not on the grid (extra_job[i] for row i).
struct computed_table {
  const std::vector<profile>& ps;
  const std::vector<double>& grid;
  std::vector<job> jobs;
  std::size_t n_table = 0;
  std::vector<std::size_t> extra_job;
  std::vector<values> vals;
  run_stats stats;

  const values& value_of(std::size_t p, double e) const {
    const auto k = static_cast<std::size_t>(std::find(grid.begin(), grid.end(), e) - grid.begin());
    return vals[p * grid.size() + k];
  }
};

computed_table compute_table(const std::vector<profile>& ps, const std::vector<double>& grid,
                             std::size_t uniform, const disk_check& disk, const big& tol) {
  computed_table c{ps, grid, {}, 0, {}, {}, {}};
  for (std::size_t p = 0; p < ps.size(); ++p)
    for (double e : grid) c.jobs.push_back({p, e, tol});
  c.n_table = c.jobs.size();
  c.extra_job.assign(disk.rows.size(), 0);
  for (std::size_t i : disk.pick) {
    if (on_grid(grid, disk.rows[i].eps)) continue;
    c.extra_job[i] = c.jobs.size();
    c.jobs.push_back({uniform, disk.rows[i].eps, tol});
  }
  c.vals = run(ps, c.jobs, "table", &c.stats);
  return c;
}

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

// The CSV on stdout: the header comment (with the self-checks' notes) and
// every row of the table but the uniform disk's.
void print_table(const computed_table& c, std::size_t uniform, const options& o,
                 const std::vector<std::string>& notes, double seconds) {
  std::printf(
      "# spinslide reference: friction force F and torque T of a flat circular contact with an\n");
  std::printf("# axisymmetric pressure p(r), from the defining area integrals\n");
  std::printf(
      "#   F(eps) = int p (eps - y)/rho dA / int p dA,  T(eps) = int p (x^2 + y^2 - eps y)/rho dA "
      "/ int p dA,\n");
  std::printf("#   rho = sqrt(x^2 + (y - eps)^2), unit disk, eps = v/(R omega)\n");
  std::printf(
      "# generated by tests/reference/generate_profile_reference.cpp: nested 2-D tanh_sinh "
      "quadrature\n");
  std::printf(
      "# of the raw polar integrand (no closed-form inner integral, no elliptic integrals),\n");
  std::printf(
      "# cpp_bin_float_50, tolerance %s per level (inner level scaled by min(eps,1/eps)/100 for\n",
      o.tol_text.c_str());
  std::printf(
      "# cancellation), r split at eps and at profile breakpoints, r = sin(phi) for "
      "hertz/boussinesq.\n");
  std::printf(
      "# profiles: annulus_0.125 p=1 on 1/8<=r<=1; hertz p=sqrt(1-r^2); boussinesq "
      "p=1/sqrt(1-r^2);\n");
  std::printf(
      "#   ring: all load on r=1; two_tier: p1 on r<1/2, p2 on 1/2<r<=1, inner 60%% / outer 40%% "
      "of load;\n");
  std::printf(
      "#   parabolic p=1-r^2.  (The uniform disk is computed for the self-check only; not "
      "listed.)\n");
  for (const std::string& n : notes) std::printf("# %s\n", n.c_str());
  std::printf("# largest tanh_sinh error estimate / L1: outer %.1e, inner %.1e; run time %.0f s\n",
              c.stats.worst_outer, c.stats.worst_inner, seconds);
  std::printf(
      "# columns: profile, eps as hex float (exact), eps decimal, F, T (32 significant digits)\n");
  std::printf("profile,eps_hex,eps,force,torque\n");
  for (std::size_t i = 0; i < c.n_table; ++i) {
    const job& j = c.jobs[i];
    if (j.profile == uniform) continue;
    std::printf("%s,%a,%.17g,%s,%s\n", c.ps[j.profile].name.c_str(), j.eps, j.eps,
                fmt(c.vals[i].force).c_str(), fmt(c.vals[i].torque).c_str());
  }
}

// The table: computed, self-checked, and written only if every check passes
// (exit status 1 if one fails, 2 if the uniform-disk reference cannot be read).
int generate_table(const options& o) {
  const auto t_start = std::chrono::steady_clock::now();
  const std::vector<profile> ps = make_profiles();
  const std::vector<double> grid = eps_grid();
  const std::size_t uniform = profile_index(ps, "uniform");

  std::vector<disk_row> disk_rows = read_disk(o.disk_file);
  if (disk_rows.empty()) {
    std::fprintf(stderr, "cannot read uniform-disk reference %s\n", o.disk_file);
    return 2;
  }
  const disk_check disk = pick_disk_rows(o.disk_file, std::move(disk_rows), grid);
  const computed_table c = compute_table(ps, grid, uniform, disk, o.tol);

  bool ok = true;
  std::vector<std::string> notes;  // echoed into the CSV header
  if (!check_uniform_disk(c, uniform, disk, notes)) ok = false;
  if (!check_limits(c)) ok = false;
  if (!check_ring_reciprocity(c, o.tol, notes)) ok = false;
  if (!check_boussinesq(c, notes)) ok = false;
  if (!check_tolerance(c, o, notes)) ok = false;

  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  if (!ok) {
    std::fprintf(stderr, "\nSELF-CHECK FAILED: no table written\n");
    return 1;
  }
  print_table(c, uniform, o, notes, seconds);
  std::fprintf(stderr, "\ntotal %.0f s; all self-checks passed\n", seconds);
  return 0;
}

int generate(int argc, char** argv) {
  options o;
  int status = 0;
  if (!parse_command_line(argc, argv, o, status)) return status;
  return generate_table(o);
}

}  // namespace

// An exception (a row of the --compare FILE that does not parse, a failed
// quadrature) is reported with the program's name, and the exit status is 2,
// as for a file that cannot be read.
int main(int argc, char** argv) {
  try {
    return generate(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "generate_profile_reference: %s\n", e.what());
    return 2;
  }
}
