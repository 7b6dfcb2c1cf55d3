//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Flat plates thrown on a plane (docs/plate_dynamics.md): a 10 cm square, an
// equilateral triangle of circumradius 6 cm and a 22 x 10 cm sole, each a
// uniform lamina (k² = I/m of its shape), μ = 0.3, thrown from the origin
// with u0 = 1.5 m/s along x and ω0 = 20 rad/s.  Prints each throw's stop
// time, path, turn and terminal ratio and slip direction, and the fixed
// points of its direction flow; writes plate_throw.csv (the paths),
// plate_outline.csv (the outlines at a few instants; the three throws start
// 25 cm apart in y) and (with gnuplot)
// plate_throw.png into the output directory.
//   ./build/release/examples/plate_throw/plate_throw [output-directory]
#include <spinslide/motion/plate_terminal.hpp>
#include <spinslide/motion/plate_throw.hpp>

#include <boost/math/constants/constants.hpp>

#include "../gnuplot.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

using vertices = std::vector<std::array<double, 2>>;
const double pi = boost::math::constants::pi<double>();

// k² = (1/A) ∫ (x² + y²) dA of the uniform lamina (the shoelace sums of the
// polygon's moments; the centroid at the origin).
double lamina_gyration_squared(const vertices& v) {
  double area = 0, polar = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const auto& a = v[i];
    const auto& b = v[(i + 1) % v.size()];
    const double c = a[0] * b[1] - b[0] * a[1];
    area += c / 2;
    polar += c *
             (a[0] * a[0] + a[0] * b[0] + b[0] * b[0] + a[1] * a[1] + a[1] * b[1] + b[1] * b[1]) /
             12;
  }
  return polar / area;
}

struct plate_case {
  const char* name;
  vertices outline;
};

void write_outline(FILE* f, const vertices& v, const spinslide::plate_sample<double>& s,
                   double offset) {
  const double c = std::cos(s.angle), sn = std::sin(s.angle);
  for (std::size_t i = 0; i <= v.size(); ++i) {
    const auto& p = v[i % v.size()];
    std::fprintf(f, "%.6f %.6f\n", s.position[0] + c * p[0] - sn * p[1],
                 offset + s.position[1] + sn * p[0] + c * p[1]);
  }
  std::fprintf(f, "\n");
}

// One throw: its numbers on stdout, its path and outlines into the files.
void throw_one(const plate_case& p, double offset, FILE* path, FILE* outline) {
  const double k = std::sqrt(lamina_gyration_squared(p.outline));
  const spinslide::polygon_patch<double> patch(p.outline);
  const spinslide::plate_motion<double> plate(patch, spinslide::gyration_radius<double>{k},
                                              spinslide::friction_coefficient<double>{0.3},
                                              spinslide::gravity<double>{9.81});
  const auto r = spinslide::throw_plate(plate, spinslide::planar_twist<double>{{1.5, 0.0}, 20.0});
  std::printf(
      "%-8s stop %.6f s, path %.6f m, displacement (%.4f, %.4f) m, turn %.4f rad; "
      "terminal eps %.6f, slip at %.2f deg in the body frame%s\n",
      p.name, r.time, r.distance, r.displacement[0], r.displacement[1], r.rotation,
      r.terminal.ratio, r.terminal.direction * 180 / pi,
      r.terminal.converged ? "" : " (direction not converged)");
  for (const auto& f :
       spinslide::plate_terminal_points(patch, spinslide::gyration_radius<double>{k}))
    std::printf("         fixed point eps* %.6f, phi* %7.2f deg, exponents %.4f %.4f%s\n", f.ratio,
                f.direction * 180 / pi, f.exponents[0], f.exponents[1],
                f.stable ? " (stable)" : "");
  for (const auto& s : r.path)
    std::fprintf(path, "%.6f %.6f %.6f\n", s.position[0], offset + s.position[1], s.time);
  std::fprintf(path, "\n\n");
  // The outline at six instants, evenly spaced in time.
  std::size_t next = 0;
  for (int i = 0; i <= 5; ++i) {
    const double t = r.time * i / 5;
    while (next + 1 < r.path.size() && r.path[next].time < t) ++next;
    write_outline(outline, p.outline, r.path[next], offset);
  }
  std::fprintf(outline, "\n");
}

const char* script =
    "set terminal pngcairo size 1000,700 font ',11'\nset output 'plate_throw.png'\n"
    "set title 'Plates thrown with u_0 = 1.5 m/s along x, {/Symbol w}_0 = 20 rad/s, mu = 0.3 (25 "
    "cm "
    "apart; outlines at t = 0, T/5, ..., T)'\n"
    "set xlabel 'x [m]'\nset ylabel 'y [m]'\nset size ratio -1\nset grid\nset key top left\n"
    "plot 'plate_throw.csv' index 0 w l lw 2 lc 1 t 'square, 10 cm', "
    "'plate_outline.csv' index 0 w l lc 1 notitle, "
    "'plate_throw.csv' index 1 w l lw 2 lc 2 t 'triangle, 6 cm circumradius', "
    "'plate_outline.csv' index 1 w l lc 2 notitle, "
    "'plate_throw.csv' index 2 w l lw 2 lc 3 t 'sole, 22 x 10 cm', "
    "'plate_outline.csv' index 2 w l lc 3 notitle\n";

// The throws and the figure; false if an output file cannot be written.
bool run(const std::string& dir) {
  const std::vector<plate_case> cases{
      {"square", {{0.05, 0.05}, {-0.05, 0.05}, {-0.05, -0.05}, {0.05, -0.05}}},
      // The equilateral triangle of circumradius 6 cm, a vertex at +y.
      {"triangle", {{0.0, 0.06}, {-0.03 * std::sqrt(3.0), -0.03}, {0.03 * std::sqrt(3.0), -0.03}}},
      {"sole", {{-0.11, -0.05}, {0.11, -0.05}, {0.11, 0.05}, {-0.11, 0.05}}}};
  FILE* path = spinslide_examples::open_output(dir + "/plate_throw.csv", "plate_throw");
  FILE* outline = spinslide_examples::open_output(dir + "/plate_outline.csv", "plate_throw");
  if (!path || !outline) return false;
  std::fprintf(path,
               "# x [m], y [m] (each plate from y = 0, 0.25, 0.5), t [s]; one block per plate: "
               "square, triangle, sole\n");
  std::fprintf(outline, "# the outlines at t = 0, T/5, ..., T; one block per plate\n");
  for (std::size_t i = 0; i < cases.size(); ++i)
    throw_one(cases[i], 0.25 * double(i), path, outline);
  std::fclose(path);
  std::fclose(outline);
  const bool drawn = spinslide_examples::plot(dir, "plate_throw.gp", script);
  std::printf(drawn ? "wrote plate_throw.png\n"
                    : "wrote plate_throw.csv (no gnuplot: no figure)\n");
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc > 1 ? argv[1] : ".") ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "plate_throw: %s\n", e.what());
    return 1;
  }
}
