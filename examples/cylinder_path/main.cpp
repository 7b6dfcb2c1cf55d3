//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The paper's cylinder standing on one face: the tilted pressure turns part
// of the friction along v × ω and the path curves (docs/theory.md §10).
// Throws a solid cylinder (R = 5 cm, γ = 1/2, μ = 0.3) with v0 = 1.5 m/s and
// ω0 = 30 rad/s for several heights h of the centre of mass, and once with
// the spin reversed; writes cylinder_path.csv and (with gnuplot)
// cylinder_path.png into the output directory.
//   ./build/release/examples/cylinder_path [output-directory]
#include <spinslide/cylinder.hpp>

#include <boost/numeric/odeint.hpp>

#include "../gnuplot.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using state = std::array<double, 6>;  // x, y, vx, vy, omega, angle
const double R = 0.05, mu = 0.3, g = 9.81, gamma_z = 0.5;

struct cylinder {
  double h;
  void operator()(const state& s, state& d, double) const {
    const double speed = std::hypot(s[2], s[3]), w = s[4];
    d = {s[2], s[3], 0, 0, 0, w};
    if (speed <= 0 && w == 0) return;
    const double sign = w >= 0 ? 1 : -1;
    const double eps = w == 0 ? INFINITY : speed / (R * std::fabs(w));
    const auto f = spinslide::tilted_cylinder_friction(eps, h, R, mu);
    if (speed > 0) {
      const double ex = s[2] / speed, ey = s[3] / speed;
      // v × ω for ω = sign·|ω| ẑ: sign·(e_v × ẑ) = sign·(ey, −ex).
      d[2] = mu * g * (f.along * ex + f.sideways * sign * ey);
      d[3] = mu * g * (f.along * ey - f.sideways * sign * ex);
    }
    d[4] = mu * g * f.torque * sign / (gamma_z * R);
  }
};

struct run_result {
  std::vector<state> path;
  double t_stop;
};

// Integrates until the motion has decayed to 1e-4 of its start (the stop
// itself is singular; the path there is settled to well below a micrometre).
run_result throw_cylinder(double h, double v0, double w0) {
  namespace odeint = boost::numeric::odeint;
  run_result r;
  state s = {0, 0, v0, 0, w0, 0};
  const double start = v0 + R * std::fabs(w0);
  auto stepper = odeint::make_controlled(1e-10, 1e-10, odeint::runge_kutta_dopri5<state>());
  double t = 0, dt = 1e-4;
  r.path.push_back(s);
  for (int i = 0; i < 200000; ++i) {
    if (std::hypot(s[2], s[3]) + R * std::fabs(s[4]) < 1e-4 * start) break;
    if (stepper.try_step(cylinder{h}, s, t, dt) == odeint::success) r.path.push_back(s);
  }
  r.t_stop = t;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : ".";
  const double v0 = 1.5, w0 = 30.0;
  std::printf(
      "solid cylinder: R = %.2f m, gamma = %.1f, mu = %.1f, v0 = %.1f m/s, omega0 = %.0f rad/s\n",
      R, gamma_z, mu, v0, w0);
  const std::vector<double> heights = {0.0, 0.01, 0.02, 0.03};
  std::vector<run_result> runs;
  for (double h : heights) {
    runs.push_back(throw_cylinder(h, v0, w0));
    const state& e = runs.back().path.back();
    std::printf(
        "h = %.2f m (4 mu h/R = %.2f): stops after %.4f s at x = %.5f m, y = %.6f m "
        "(deflected %s, along v x omega)\n",
        heights[runs.size() - 1], 4 * mu * heights[runs.size() - 1] / R, runs.back().t_stop, e[0],
        e[1], e[1] < 0 ? "to the right" : (e[1] > 0 ? "to the left" : "not at all"));
  }
  const run_result mirrored = throw_cylinder(0.02, v0, -w0);
  const state& m = mirrored.path.back();
  std::printf("h = 0.02 m, spin reversed: stops at x = %.5f m, y = %.6f m (the mirror image)\n",
              m[0], m[1]);

  const std::string csv = out + "/cylinder_path.csv";
  if (FILE* f = std::fopen(csv.c_str(), "w")) {
    for (std::size_t k = 0; k < runs.size(); ++k) {
      std::fprintf(f, "# h = %.2f\n", heights[k]);
      for (const state& s : runs[k].path) std::fprintf(f, "%.8f %.8f\n", s[0], s[1]);
      std::fprintf(f, "\n\n");
    }
    std::fprintf(f, "# h = 0.02, spin reversed\n");
    for (const state& s : mirrored.path) std::fprintf(f, "%.8f %.8f\n", s[0], s[1]);
    std::fclose(f);
  }
  const bool figure = spinslide_examples::plot(
      out, "cylinder_path.gp",

      "set terminal pngcairo size 900,500 font ',11'\nset output 'cylinder_path.png'\n"
      "set xlabel 'x [m]'; set ylabel 'y [m]'; set key left bottom; set grid\n"
      "set title 'Cylinder on one face, v0 = 1.5 m/s along x, omega0 = 30 rad/s "
      "(counter-clockwise)'\n"
      "plot 'cylinder_path.csv' index 0 w l lw 2 t 'h = 0 (flat disk)', '' index 1 w l lw 2 t 'h "
      "= 1 cm', "
      "'' index 2 w l lw 2 t 'h = 2 cm', '' index 3 w l lw 2 t 'h = 3 cm', '' index 4 w l dt 2 "
      "lw 2 t "
      "'h = 2 cm, spin reversed'\n");
  std::printf("%s\n", figure ? "wrote cylinder_path.csv and cylinder_path.png"
                             : "wrote cylinder_path.csv (no gnuplot: no figure)");
  // The checks this example's test relies on.
  const bool straight = std::fabs(runs[0].path.back()[1]) < 1e-12;
  const bool curves =
      runs[2].path.back()[1] < -1e-4 && runs[3].path.back()[1] < runs[2].path.back()[1];
  const state& a = runs[2].path.back();
  const bool mirror = std::fabs(a[0] - m[0]) < 1e-9 && std::fabs(a[1] + m[1]) < 1e-9;
  std::printf(
      "checks: h = 0 straight %s, curves along v x omega and more with h %s, reversed spin mirrors "
      "%s\n",
      straight ? "yes" : "NO", curves ? "yes" : "NO", mirror ? "yes" : "NO");
  return straight && curves && mirror ? 0 : 1;
}
