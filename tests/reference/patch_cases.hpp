//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The patches and twists of tests/reference/patch_reference.csv
// (generate_patch_reference.cpp writes it, test_patch_reference.cpp reads
// it): the outlines, in double (the generator integrates exactly these
// doubles), and the rows: shape × pressure × instantaneous centre × spin sense.
#ifndef SPINSLIDE_TESTS_REFERENCE_PATCH_CASES_HPP
#define SPINSLIDE_TESTS_REFERENCE_PATCH_CASES_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace patch_cases {

using point = std::array<double, 2>;

/// An outline by name: the shapes of the reference table.  None is centred
/// on the origin, so that the torque about the origin is tested too.
inline std::vector<point> outline(const std::string& name) {
  if (name == "square") return {{-0.4, -0.6}, {0.6, -0.6}, {0.6, 0.4}, {-0.4, 0.4}};
  if (name == "sole") return {{-0.1, -0.04}, {0.12, -0.04}, {0.12, 0.06}, {-0.1, 0.06}};
  if (name == "triangle") return {{0.0, 0.0}, {1.2, 0.1}, {0.3, 0.9}};
  if (name == "hexagon") {
    std::vector<point> h;
    for (int k = 0; k < 6; ++k) {
      const double a = k * 3.14159265358979323846 / 3;
      h.push_back({0.1 + std::cos(a), std::sin(a)});
    }
    return h;
  }
  if (name == "strip") return {{-1.0, -0.005}, {1.0, -0.005}, {1.0, 0.005}, {-1.0, 0.005}};
  return {};
}

/// ℓ: the largest distance of a vertex from the origin.
inline double size(const std::vector<point>& v) {
  double l = 0;
  for (const auto& p : v) l = std::fmax(l, std::hypot(p[0], p[1]));
  return l;
}

/// The vertex mean.
inline point mean(const std::vector<point>& v) {
  point m{0, 0};
  for (const auto& p : v) {
    m[0] += p[0] / static_cast<double>(v.size());
    m[1] += p[1] / static_cast<double>(v.size());
  }
  return m;
}

/// A row's input: the shape, the pressure ("uniform", or the centre of
/// pressure), the twist.
struct input {
  std::string shape;
  std::string pressure;  // uniform, linear (in the kern), no_tension (beyond it)
  point centre;          // the centre of pressure (linear, no_tension)
  std::string where;     // where the instantaneous centre is
  double vx, vy, omega;
};

/// The centres of pressure: in the kern (linear) and beyond it (no-tension);
/// the generator checks which (generate_patch_reference --compare).
inline point pressure_centre(const std::string& shape, bool beyond_kern) {
  const std::vector<point> v = outline(shape);
  const point m = mean(v);
  if (shape == "square")
    return beyond_kern ? point{m[0] + 0.3, m[1] + 0.12} : point{m[0] + 0.08, m[1] - 0.05};
  if (shape == "sole")
    return beyond_kern ? point{m[0] + 0.085, m[1] - 0.03} : point{m[0] + 0.015, m[1] + 0.005};
  if (shape == "triangle") return beyond_kern ? point{0.85, 0.25} : point{0.52, 0.34};
  if (shape == "hexagon")
    return beyond_kern ? point{m[0] + 0.55, m[1] + 0.3} : point{m[0] + 0.1, m[1] - 0.08};
  return beyond_kern ? point{m[0] + 0.8, m[1] + 0.002} : point{m[0] + 0.2, m[1] - 0.0005};
}

/// The instantaneous centres: inside, on an edge, on a vertex, outside, and at
/// 10, 1e3, 1e7 and 2e7 ℓ from the vertex mean; "slide" is ω = 0.
inline std::vector<std::pair<std::string, point>> centres(const std::string& shape) {
  const std::vector<point> v = outline(shape);
  const point m = mean(v);
  const double l = size(v);
  std::vector<std::pair<std::string, point>> c;
  c.push_back({"inside", {0.7 * m[0] + 0.3 * v[0][0], 0.6 * m[1] + 0.4 * v[1][1]}});
  // On the first edge: exactly, where it is horizontal.
  c.push_back({"edge",
               {0.7 * v[0][0] + 0.3 * v[1][0],
                v[0][1] == v[1][1] ? v[0][1] : 0.7 * v[0][1] + 0.3 * v[1][1]}});
  c.push_back({"vertex", v[2]});
  const double dir = 0.7;
  // Both sides of the expansion's crossover (4 loaded radii from the vertex
  // mean, for the polygons that carry load everywhere), and moderate distances.
  double rho = 0;
  for (const auto& p : v) rho = std::fmax(rho, std::hypot(p[0] - m[0], p[1] - m[1]));
  for (double r : {2.0, 3.999, 4.001, 6.0, 30.0})
    c.push_back({"rho_" + std::to_string(r).substr(0, 5),
                 {m[0] + r * rho * std::cos(dir + 1), m[1] + r * rho * std::sin(dir + 1)}});
  for (double r : {1.5, 10.0, 1e3, 1e7, 2e7})
    c.push_back({r == 1.5 ? "outside" : "far_" + std::to_string(static_cast<long long>(r)),
                 {m[0] + r * l * std::cos(dir), m[1] + r * l * std::sin(dir)}});
  return c;
}

/// Every row: for ω ≠ 0 the twist with centre c is v = ω(c_y, −c_x), with
/// |ω| the power of 2 nearest 1/max(1, |c|) (so that |v| stays O(1) and the
/// centre ẑ × v/ω is c exactly in double).
inline std::vector<input> inputs() {
  std::vector<input> rows;
  for (const char* shape : {"square", "sole", "triangle", "hexagon", "strip"}) {
    for (const char* pressure : {"uniform", "linear", "no_tension"}) {
      const point e = pressure_centre(shape, std::string(pressure) == "no_tension");
      for (const auto& c : centres(shape)) {
        for (double sense : {1.0, -1.0}) {
          const double r = std::fmax(1.0, std::hypot(c.second[0], c.second[1]));
          const double omega = sense * std::ldexp(1.0, -std::ilogb(r));
          rows.push_back(
              {shape, pressure, e, c.first, omega * c.second[1], -omega * c.second[0], omega});
        }
      }
      rows.push_back({shape, pressure, e, "slide", 0.6, -0.8, 0.0});
    }
  }
  return rows;
}

}  // namespace patch_cases

#endif  // SPINSLIDE_TESTS_REFERENCE_PATCH_CASES_HPP
