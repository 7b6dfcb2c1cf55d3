//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Compares the statistics printed by engines/lammps/examples/in.pour_mpi in
// two LAMMPS logs (a serial and an MPI run; docs/lammps.md):
//  - the `EARLY step ...` lines up to step EARLY_UNTIL: the four counts
//    (pair and wall contacts, sliding) exactly, the four sums to relative
//    EARLY_RTOL (the decomposition changes only the order of the sums);
//  - the `STAT name value` lines: |A - B| <= tol, with tol the line
//    `COUPLING name tol ...` of TOLERANCES (pour_statistics_tolerances.txt).
// Prints a table; exit status 0 if all pass, 1 if not, 2 on a malformed
// input.
//
//   compare_statistics A.log B.log TOLERANCES COUPLING EARLY_UNTIL EARLY_RTOL
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct run_log {
  std::vector<std::vector<std::string>> early;  // the words of each EARLY line
  std::vector<std::pair<std::string, double>> stats;
};

bool read_log(const char* path, run_log& out) {
  std::ifstream in(path);
  if (!in) return false;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string head;
    words >> head;
    if (head == "EARLY") {
      std::vector<std::string> w;
      std::string x;
      while (words >> x) w.push_back(x);
      if (w.size() != 9) return false;
      if (w[0].find_first_not_of("0123456789") != std::string::npos) continue;  // the command echo
      out.early.push_back(w);
    } else if (head == "STAT") {
      std::string name, value;
      if (!(words >> name >> value)) continue;
      char* end = nullptr;
      const double v = std::strtod(value.c_str(), &end);
      if (end == value.c_str() || *end != '\0') continue;  // the command echo
      out.stats.emplace_back(name, v);
    }
  }
  return true;
}

// The tolerances of one coupling (lines "COUPLING name tol mean ...").  A
// tolerance "dropped" (NaN here) marks a statistic whose seed-to-seed
// spread is as large as its mean: a tolerance for it would pass a zero, so
// it is printed and checked to be finite and >= 0, not compared.  A
// tolerance that is not below the mean it guards is refused (issue 28: the
// file had three such).
std::map<std::string, double> read_tolerances(const char* path, const std::string& coupling,
                                              bool& well_formed) {
  std::map<std::string, double> tol;
  std::ifstream in(path);
  std::string line;
  well_formed = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::string c, name, t;
    double mean = 0;
    if (!(words >> c >> name >> t >> mean) || c != coupling) continue;
    const double value = t == "dropped" ? std::nan("") : std::atof(t.c_str());
    if (!std::isnan(value) && !(value < std::fabs(mean))) {
      std::fprintf(stderr, "compare_statistics: %s %s: tolerance %s is not below its mean %g\n",
                   c.c_str(), name.c_str(), t.c_str(), mean);
      well_formed = false;
    }
    tol[name] = value;
  }
  return tol;
}

enum status { pass = 0, fail = 1, malformed = 2 };

// One EARLY line of each log: the counts exactly, the sums to `rtol`.
status compare_early_line(const std::vector<std::string>& wa, const std::vector<std::string>& wb,
                          double rtol, double& worst) {
  status s = pass;
  const long step = std::atol(wa[0].c_str());
  for (std::size_t c = 1; c <= 4; ++c)
    if (wa[c] != wb[c]) {
      std::printf("step %ld: count %zu differs: %s against %s\n", step, c, wa[c].c_str(),
                  wb[c].c_str());
      s = fail;
    }
  for (std::size_t c = 5; c <= 8; ++c) {
    const double x = std::atof(wa[c].c_str()), y = std::atof(wb[c].c_str());
    const double rel = x == y ? 0.0 : std::fabs(x - y) / std::fmax(std::fabs(x), std::fabs(y));
    worst = std::fmax(worst, rel);
    if (!(rel <= rtol)) {
      std::printf("step %ld: sum %zu differs by %.3g (relative)\n", step, c - 4, rel);
      s = fail;
    }
  }
  return s;
}

// The EARLY lines up to step `until`.
status compare_early(const run_log& a, const run_log& b, long until, double rtol) {
  status s = pass;
  double worst = 0;
  long checked_until = 0;
  for (std::size_t k = 0; k < a.early.size(); ++k) {
    if (a.early[k][0] != b.early[k][0]) {
      std::fprintf(stderr, "compare_statistics: EARLY steps differ\n");
      return malformed;
    }
    const long step = std::atol(a.early[k][0].c_str());
    if (step > until) break;
    checked_until = step;
    if (compare_early_line(a.early[k], b.early[k], rtol, worst) != pass) s = fail;
  }
  std::printf("early (steps <= %ld): counts %s, sums within %.3g relative (tolerance %.3g)\n",
              checked_until, s == pass ? "identical" : "DIFFER", worst, rtol);
  return s;
}

// The STAT lines against the tolerances.
status compare_stats(const run_log& a, const run_log& b, const std::map<std::string, double>& tol,
                     const std::string& coupling) {
  status s = pass;
  std::printf("%-30s %14s %14s %12s %12s\n", "statistic", "A", "B", "|A - B|", "tolerance");
  for (std::size_t k = 0; k < a.stats.size(); ++k) {
    const auto& [name, x] = a.stats[k];
    const auto t = tol.find(name);
    if (b.stats[k].first != name || t == tol.end()) {
      std::fprintf(stderr,
                   "compare_statistics: STAT %s differs between the logs, or %s has no "
                   "tolerance for it\n",
                   name.c_str(), coupling.c_str());
      return malformed;
    }
    const double d = std::fabs(x - b.stats[k].second);
    if (std::isnan(t->second)) {  // dropped: finite and >= 0 only
      const bool sane = x >= 0 && b.stats[k].second >= 0 && std::isfinite(d);
      if (!sane) s = fail;
      std::printf("%-30s %14.8g %14.8g %12.4g %12s%s\n", name.c_str(), x, b.stats[k].second, d,
                  "dropped", sane ? "" : "  FAIL");
      continue;
    }
    const bool within = d <= t->second;
    if (!within) s = fail;
    std::printf("%-30s %14.8g %14.8g %12.4g %12.4g%s\n", name.c_str(), x, b.stats[k].second, d,
                t->second, within ? "" : "  FAIL");
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 7) {
    std::fprintf(
        stderr,
        "usage: compare_statistics A.log B.log TOLERANCES COUPLING EARLY_UNTIL EARLY_RTOL\n");
    return malformed;
  }
  run_log a, b;
  if (!read_log(argv[1], a) || !read_log(argv[2], b)) {
    std::fprintf(stderr, "compare_statistics: cannot read %s or %s\n", argv[1], argv[2]);
    return malformed;
  }
  if (a.early.size() != b.early.size() || a.early.empty() || a.stats.empty() ||
      a.stats.size() != b.stats.size()) {
    std::fprintf(stderr, "compare_statistics: the logs' EARLY or STAT lines differ in number\n");
    return malformed;
  }
  const std::string coupling = argv[4];
  const status early = compare_early(a, b, std::atol(argv[5]), std::atof(argv[6]));
  if (early == malformed) return malformed;
  bool well_formed = true;
  const auto tolerances = read_tolerances(argv[3], coupling, well_formed);
  if (!well_formed) return malformed;
  const status stats = compare_stats(a, b, tolerances, coupling);
  if (stats == malformed) return malformed;
  return early == pass && stats == pass ? pass : fail;
}
