//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The parts of generate_profile_reference (its main file,
// generate_profile_reference.cpp, says what it computes and how):
//   profile_reference_quadrature.cpp  the nested tanh_sinh quadrature of the
//                                     area integrals, and the profiles;
//   profile_reference_run.cpp         the ε grid, the parallel run of a list
//                                     of jobs, and --compare FILE;
//   profile_reference_checks.cpp      the self-checks of the computed table.
// Standard library and Boost only: nothing of spinslide.
#ifndef SPINSLIDE_TESTS_REFERENCE_PROFILE_REFERENCE_HPP
#define SPINSLIDE_TESTS_REFERENCE_PROFILE_REFERENCE_HPP

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace profile_reference {

using big = boost::multiprecision::cpp_bin_float_50;
using boost::math::quadrature::tanh_sinh;

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

enum class quantity { force, torque };

// I_F(r) or I_T(r), the inner (θ) integral.
big theta_integral(quad& q, quantity what, const big& r, const big& eps, const big& tol);

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

// The profiles of the table, and "uniform" (the self-check's).
std::vector<profile> make_profiles();

struct values {
  big force, torque;
};

// 𝓕(ε) and 𝓣(ε) of profile p at tolerance tol.
values compute(quad& q, const profile& p, const big& eps, const big& tol);

// ---------------------------------------------------------------------------
// The ε grid, numbers as text and relative differences
// (profile_reference_run.cpp)

std::vector<double> eps_grid();
std::string fmt(const big& x, int digits = 32);
double rel(const big& a, const big& b);

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
                        const char* label, run_stats* stats = nullptr);
std::size_t profile_index(const std::vector<profile>& ps, const std::string& name);

// --compare FILE: every 10th data row of FILE recomputed (exit status 1 above
// 1e-20, 2 if FILE cannot be read).
int compare(const char* file, const big& tol);

// ---------------------------------------------------------------------------
// The table and its self-checks (generate_profile_reference.cpp,
// profile_reference_checks.cpp)

// A row of the uniform disk's table (disk_reference.csv).
struct disk_row {
  double eps;
  big force, torque;
};

// The command line.
struct options {
  big tol{"1e-20"};
  std::string tol_text = "1e-20";
  const char* disk_file = "tests/reference/disk_reference.csv";
};

inline bool on_grid(const std::vector<double>& grid, double e) {
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

// The self-checks: each prints what it finds on stderr (those with `notes`
// also add a line for the CSV's header) and returns whether it passes.
bool check_uniform_disk(const computed_table& c, std::size_t uniform, const disk_check& disk,
                        std::vector<std::string>& notes);
bool check_limits(const computed_table& c);
bool check_ring_reciprocity(const computed_table& c, const big& tol,
                            std::vector<std::string>& notes);
bool check_boussinesq(const computed_table& c, std::vector<std::string>& notes);
bool check_tolerance(const computed_table& c, const options& o, std::vector<std::string>& notes);

}  // namespace profile_reference

#endif  // SPINSLIDE_TESTS_REFERENCE_PROFILE_REFERENCE_HPP
