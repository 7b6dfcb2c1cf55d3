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
// The program's parts: profile_reference.hpp (what they share),
// profile_reference_quadrature.cpp (the quadrature and the profiles),
// profile_reference_run.cpp (the ε grid, the parallel run and --compare),
// profile_reference_checks.cpp (the self-checks), and this file (the command
// line and the table).
//
// Build: g++ -std=c++17 -O2 -Wall -Wextra -Wpedantic -pthread, the four
// sources generate_profile_reference.cpp and profile_reference_*.cpp
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "csv.hpp"
#include "profile_reference.hpp"

namespace {

using namespace profile_reference;

// ---------------------------------------------------------------------------
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

// The rows of the uniform disk's table that the self-check recomputes
// (disk_check).
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
