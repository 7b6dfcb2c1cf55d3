//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Compares two LAMMPS text dumps (`dump custom`, sorted by id, the same
// columns), snapshot by snapshot: for each column but `id`, the largest
// absolute difference, relative to that column's largest magnitude in the
// first dump.  Prints one line per snapshot and the largest relative
// difference; exit status 0 if it is at most TOL (default 0: identical),
// 1 if not, 2 if the dumps do not have the same shape or cannot be read.
//
//   compare_dumps A.dump B.dump [TOL]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct snapshot {
  long step = -1;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

// The next snapshot of `in`; step −1 at the end.
snapshot next_snapshot(std::ifstream& in) {
  snapshot s;
  std::string line;
  while (std::getline(in, line) && line.rfind("ITEM: TIMESTEP", 0) != 0) {
  }
  if (!in) return s;
  std::getline(in, line);
  s.step = std::stol(line);
  std::getline(in, line);  // ITEM: NUMBER OF ATOMS
  std::getline(in, line);
  const long n = std::stol(line);
  for (int i = 0; i < 4; ++i) std::getline(in, line);  // the box
  std::getline(in, line);                              // ITEM: ATOMS id ...
  std::istringstream header(line.substr(line.find("ATOMS") + 5));
  for (std::string c; header >> c;) s.columns.push_back(c);
  for (long i = 0; i < n && std::getline(in, line); ++i) {
    std::istringstream row(line);
    std::vector<double> values;
    for (double v; row >> v;) values.push_back(v);
    s.rows.push_back(values);
  }
  return s;
}

// The largest relative difference of b from a over the columns but `id`.
double difference(const snapshot& a, const snapshot& b, std::string* worst_column) {
  double worst = 0;
  for (std::size_t c = 0; c < a.columns.size(); ++c) {
    if (a.columns[c] == "id") continue;
    double scale = 1e-300, largest = 0;
    for (std::size_t i = 0; i < a.rows.size(); ++i) {
      scale = std::max(scale, std::fabs(a.rows[i][c]));
      largest = std::max(largest, std::fabs(a.rows[i][c] - b.rows[i][c]));
    }
    if (largest / scale > worst) {
      worst = largest / scale;
      *worst_column = a.columns[c];
    }
  }
  return worst;
}

bool same_shape(const snapshot& a, const snapshot& b) {
  if (a.step != b.step || a.columns != b.columns || a.rows.size() != b.rows.size()) return false;
  for (std::size_t i = 0; i < a.rows.size(); ++i)
    if (a.rows[i].size() != a.columns.size() || b.rows[i].size() != a.columns.size()) return false;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: compare_dumps A.dump B.dump [TOL]\n");
    return 2;
  }
  const double tolerance = argc > 3 ? std::strtod(argv[3], nullptr) : 0.0;
  std::ifstream a_file(argv[1]), b_file(argv[2]);
  if (!a_file || !b_file) {
    std::fprintf(stderr, "compare_dumps: cannot read %s or %s\n", argv[1], argv[2]);
    return 2;
  }
  double worst = 0;
  int snapshots = 0;
  for (;;) {
    const snapshot a = next_snapshot(a_file), b = next_snapshot(b_file);
    if (a.step < 0 && b.step < 0) break;
    if (!same_shape(a, b)) {
      std::fprintf(stderr, "compare_dumps: snapshot %d differs in shape (steps %ld and %ld)\n",
                   snapshots, a.step, b.step);
      return 2;
    }
    std::string column = "-";
    const double d = difference(a, b, &column);
    std::printf("step %8ld: largest relative difference %.3e (column %s)\n", a.step, d,
                column.c_str());
    worst = std::max(worst, d);
    ++snapshots;
  }
  if (snapshots == 0) {
    std::fprintf(stderr, "compare_dumps: no snapshot in %s\n", argv[1]);
    return 2;
  }
  std::printf(
      "%d snapshots: %s\n", snapshots,
      worst == 0 ? "identical" : ("largest relative difference " + std::to_string(worst)).c_str());
  return worst <= tolerance ? 0 : 1;
}
