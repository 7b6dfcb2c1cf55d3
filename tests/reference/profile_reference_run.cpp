//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// generate_profile_reference: the ε grid, the parallel evaluation of a list of
// jobs, and --compare FILE.
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "csv.hpp"
#include "profile_reference.hpp"

namespace profile_reference {

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

std::string fmt(const big& x, int digits) {
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

std::vector<values> run(const std::vector<profile>& ps, const std::vector<job>& jobs,
                        const char* label, run_stats* stats) {
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

}  // namespace profile_reference
