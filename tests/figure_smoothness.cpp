//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// figure_smoothness: fails when a figure's curves would show corners at the
// size the figure is drawn (issue 31).
//
//   figure_smoothness FILE.csv X_COLUMN Y_COLUMN xlin|xlog ylin|ylog MAX_DEGREES [END [stop]]
//
// FILE.csv: blocks of rows (one curve each) separated by blank lines, as the
// examples write them for gnuplot; cells separated by commas or blanks;
// columns counted from 0; header lines and lines starting with # skipped.  Each curve is taken
// in plot coordinates (the logarithm on a log axis), scaled by the range of
// all curves, so that 1 is the width or height of the panel.  Points closer
// than 1/500 of the panel (a pixel of a 500-pixel figure) to the last kept
// point are passed over, as a reader cannot see them; the turning angle
// between consecutive kept segments must stay below MAX_DEGREES.  Prints the
// largest angle and where it is.  Rows with a non-finite or, on a log axis,
// non-positive coordinate are left out (they are not drawn).  END (default
// 0): vertices closer than END (in panel units) to a curve's last point are
// not judged, for curves that end in a true corner (a throw's path in the
// (v*, ω*) plane turns onto the terminal ratio's line within a few pixels
// of the origin, however densely it is sampled).  `stop`: nor are vertices
// closer than END to a point where y is 0, a time series' true corner where
// the motion stops (the speed reaches 0 with a finite or, for ω ∝
// √(t_stop − t), an infinite slope, and stays there).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct point {
  double x, y;
  bool at_rest = false;  // y is exactly 0 in the data
};
using curve = std::vector<point>;

struct axis {
  int column;
  bool log;
  double lo = std::numeric_limits<double>::infinity(),
         hi = -std::numeric_limits<double>::infinity();
  bool take(double& v) const {
    if (!std::isfinite(v) || (log && !(v > 0))) return false;
    if (log) v = std::log10(v);
    return true;
  }
};

// The cells of a row, separated by commas or blanks.
std::vector<std::string> split(std::string line) {
  std::replace(line.begin(), line.end(), ',', ' ');
  std::vector<std::string> out;
  std::stringstream s(line);
  std::string cell;
  while (s >> cell) out.push_back(cell);
  return out;
}

// A row of text (a header), not of numbers.
bool is_header(const std::vector<std::string>& cells) {
  if (cells.empty()) return false;
  char* end = nullptr;
  std::strtod(cells[0].c_str(), &end);
  return end == cells[0].c_str();
}

std::vector<curve> read_curves(const char* path, axis& x, axis& y) {
  std::ifstream in(path);
  std::vector<curve> curves(1);
  std::string line;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) {
      if (!curves.back().empty()) curves.emplace_back();
      continue;
    }
    if (line[line.find_first_not_of(" \t")] == '#') continue;  // a comment
    const auto cells = split(line);
    if (is_header(cells) || static_cast<int>(cells.size()) <= std::max(x.column, y.column))
      continue;
    double px = std::strtod(cells[static_cast<std::size_t>(x.column)].c_str(), nullptr);
    double py = std::strtod(cells[static_cast<std::size_t>(y.column)].c_str(), nullptr);
    if (!x.take(px) || !y.take(py)) continue;
    x.lo = std::min(x.lo, px);
    x.hi = std::max(x.hi, px);
    y.lo = std::min(y.lo, py);
    y.hi = std::max(y.hi, py);
    curves.back().push_back({px, py, py == 0});
  }
  if (curves.back().empty()) curves.pop_back();
  return curves;
}

// The curve in panel units, with the points a reader cannot tell apart
// passed over.
curve visible(const curve& c, const axis& x, const axis& y) {
  const double wx = x.hi > x.lo ? x.hi - x.lo : 1, wy = y.hi > y.lo ? y.hi - y.lo : 1;
  curve out;
  for (const point& p : c) {
    const point q{(p.x - x.lo) / wx, (p.y - y.lo) / wy, p.at_rest};
    if (out.empty() || std::hypot(q.x - out.back().x, q.y - out.back().y) >= 1.0 / 500)
      out.push_back(q);
  }
  return out;
}

// True if p lies within `distance` of a point of c where y is 0 (or is
// next to one).
bool near_rest(const curve& c, const point& p, double distance) {
  return std::any_of(c.begin(), c.end(), [&](const point& q) {
    return q.at_rest && std::hypot(q.x - p.x, q.y - p.y) < std::max(distance, 2.0 / 500);
  });
}

double turning_degrees(const point& a, const point& b, const point& c) {
  const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - b.x, vy = c.y - b.y;
  const double cosine = (ux * vx + uy * vy) / (std::hypot(ux, uy) * std::hypot(vx, vy));
  const double degree = 3.14159265358979323846 / 180;
  return std::acos(std::clamp(cosine, -1.0, 1.0)) / degree;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 7 || argc > 9) {
    std::fprintf(stderr,
                 "usage: figure_smoothness FILE.csv X_COLUMN Y_COLUMN xlin|xlog ylin|ylog "
                 "MAX_DEGREES [END [stop]]\n");
    return 2;
  }
  const double end = argc >= 8 ? std::strtod(argv[7], nullptr) : 0.0;
  const bool skip_stop = argc == 9 && std::string(argv[8]) == "stop";
  axis x{std::atoi(argv[2]), std::string(argv[4]) == "xlog"};
  axis y{std::atoi(argv[3]), std::string(argv[5]) == "ylog"};
  const double limit = std::strtod(argv[6], nullptr);
  const std::vector<curve> curves = read_curves(argv[1], x, y);
  if (curves.empty()) {
    std::fprintf(stderr, "figure_smoothness: no curve in %s\n", argv[1]);
    return 2;
  }
  double worst = 0;
  std::size_t worst_curve = 0, worst_point = 0, kept = 0;
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const curve c = visible(curves[k], x, y);
    kept += c.size();
    for (std::size_t i = 1; i + 1 < c.size(); ++i) {
      if (std::hypot(c[i].x - c.back().x, c[i].y - c.back().y) < end) continue;
      if (skip_stop && near_rest(c, c[i], end)) continue;
      const double angle = turning_degrees(c[i - 1], c[i], c[i + 1]);
      if (angle > worst) {
        worst = angle;
        worst_curve = k;
        worst_point = i;
      }
    }
  }
  std::printf(
      "%s, columns %d-%d: %zu curves, %zu visible points, largest turn %.2f degrees "
      "(curve %zu, point %zu); limit %.2f\n",
      argv[1], x.column, y.column, curves.size(), kept, worst, worst_curve, worst_point, limit);
  return worst <= limit ? 0 : 1;
}
