//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The paper's cylinder standing on one face: the tilted pressure turns part
// of the friction along v × ω and the path curves; past a centre of pressure
// of R/4 the rear of the face lifts off, and the cylinder tips only when no
// pressure on the face balances the moment (docs/theory.md §10).
// Throws a solid cylinder (R = 5 cm, γ = 1/2, μ = 0.3) with v0 = 1.5 m/s and
// ω0 = 30 rad/s (ε0 = 1) for heights h of the centre of mass from 0 up to
// tipping, and once with the spin reversed; prints the height at which the
// cylinder tips for a few ε; writes cylinder_path.csv, cylinder_deflection.csv
// and (with gnuplot) cylinder_path.png into the output directory.
//   ./build/release/examples/cylinder_path [output-directory]
// About a minute: a call in partial contact solves the contact and the moment
// balance together (about 10 ms), so each height's friction is tabulated over ε
// first.
#include <spinslide/values/cylinder.hpp>

#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>
#include <boost/numeric/odeint.hpp>

#include "../gnuplot.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using state = std::array<double, 6>;  // x, y, vx, vy, omega, angle
using spline = boost::math::interpolators::cardinal_cubic_b_spline<double>;
const double R = 0.05, mu = 0.3, g = 9.81, gamma_z = 0.5, v0 = 1.5, w0 = 30.0;

// The cylinder's friction at one height as a function of ε: the library on a
// uniform grid of ε in [0, eps_max], cubic B-splines between the nodes; the
// library itself outside the grid or where the grid holds a tipped node.
class friction_of_eps {
 public:
  explicit friction_of_eps(double h) : h_(h) {
    std::vector<double> along, side, torque;
    for (int i = 0; i <= nodes; ++i) {
      const auto f = spinslide::tilted_cylinder_friction(i * step, h, R, mu);
      tipped_ = tipped_ || f.contact == spinslide::cylinder_contact::tipped;
      along.push_back(f.force[0]);
      side.push_back(f.force[1]);
      torque.push_back(f.torque);
    }
    if (tipped_) return;
    along_ = spline(along.begin(), along.end(), 0.0, step);
    side_ = spline(side.begin(), side.end(), 0.0, step);
    torque_ = spline(torque.begin(), torque.end(), 0.0, step);
  }
  // along, sideways, torque; false if the cylinder tips at this ε.
  bool operator()(double eps, std::array<double, 3>& f) const {
    if (tipped_ || !(eps <= nodes * step)) {
      const auto c = spinslide::tilted_cylinder_friction(eps, h_, R, mu);
      f = {c.force[0], c.force[1], c.torque};
      return c.contact != spinslide::cylinder_contact::tipped;
    }
    f = {along_(eps), side_(eps), torque_(eps)};
    return true;
  }

 private:
  static constexpr int nodes = 100;
  static constexpr double step = 0.025;
  double h_;
  bool tipped_ = false;
  spline along_, side_, torque_;
};

struct tips {};  // thrown out of the integration when the cylinder tips

struct cylinder {
  const friction_of_eps* friction;
  void operator()(const state& s, state& d, double) const {
    const double speed = std::hypot(s[2], s[3]), w = s[4];
    d = {s[2], s[3], 0, 0, 0, w};
    if (speed <= 0 && w == 0) return;
    const double sign = w >= 0 ? 1 : -1;
    const double eps = w == 0 ? INFINITY : speed / (R * std::fabs(w));
    std::array<double, 3> f{};
    if (!(*friction)(eps, f)) throw tips{};
    if (speed > 0) {
      const double ex = s[2] / speed, ey = s[3] / speed;
      // v × ω for ω = sign·|ω| ẑ: sign·(e_v × ẑ) = sign·(ey, −ex).
      d[2] = mu * g * (f[0] * ex + f[1] * sign * ey);
      d[3] = mu * g * (f[0] * ey - f[1] * sign * ex);
    }
    d[4] = mu * g * f[2] * sign / (gamma_z * R);
  }
};

struct run_result {
  std::vector<state> path;
  double t_stop;
  bool tipped;
};

// Integrates until the motion has decayed to 1e-4 of its start (the stop
// itself is singular; the path there is settled to well below a micrometre),
// or until the cylinder tips.
run_result throw_cylinder(const friction_of_eps& friction, double spin) {
  namespace odeint = boost::numeric::odeint;
  run_result r{{}, 0, false};
  state s = {0, 0, v0, 0, spin, 0};
  const double start = v0 + R * std::fabs(spin);
  auto stepper = odeint::make_controlled(1e-10, 1e-10, odeint::runge_kutta_dopri5<state>());
  double t = 0, dt = 1e-4;
  r.path.push_back(s);
  try {
    for (int i = 0; i < 200000; ++i) {
      if (std::hypot(s[2], s[3]) + R * std::fabs(s[4]) < 1e-4 * start) break;
      if (stepper.try_step(cylinder{&friction}, s, t, dt) == odeint::success) r.path.push_back(s);
    }
  } catch (const tips&) {
    r.tipped = true;
  }
  r.t_stop = t;
  return r;
}

// The least height (to 0.1 mm) at which the cylinder tips at this ε, searched
// in [lo, hi]; NaN if it stands at hi.
double tipping_height(double eps, double lo, double hi) {
  auto tipped = [eps](double h) {
    return spinslide::tilted_cylinder_friction(eps, h, R, mu).contact ==
           spinslide::cylinder_contact::tipped;
  };
  if (!tipped(hi)) return NAN;
  while (hi - lo > 1e-4) {
    const double mid = (lo + hi) / 2;
    (tipped(mid) ? hi : lo) = mid;
  }
  return hi;
}

bool print_tipping_heights() {
  std::printf("tipping height (mu = %.1f, R = %.2f m; R/mu = %.4f m):\n", mu, R, R / mu);
  const double h1 = tipping_height(1.0, 0.15, 0.2);
  for (double eps : {0.9, 0.99, 1.0, 1.002, 1.01, 1.5, 3.0}) {
    const double h = eps == 1.0 ? h1 : tipping_height(eps, 0.15, 0.3);
    if (std::isnan(h))
      std::printf("  eps = %5.3f: stands up to h = 0.3 m (4 R/mu > 1.8)\n", eps);
    else
      std::printf("  eps = %5.3f: tips at h = %.4f m (mu h/R = %.4f)\n", eps, h, mu * h / R);
  }
  return h1 > 0.172 && h1 < 0.174 && std::fabs(tipping_height(2.0, 0.15, 0.2) - R / mu) < 2e-4;
}

void write_paths(const std::string& out, const std::vector<double>& heights,
                 const std::vector<run_result>& runs, const run_result& mirrored) {
  FILE* f = spinslide_examples::open_output(out + "/cylinder_path.csv", "cylinder_path");
  if (!f) return;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    std::fprintf(f, "# h = %.3f\n", heights[k]);
    for (const state& s : runs[k].path) std::fprintf(f, "%.8f %.8f\n", s[0], s[1]);
    std::fprintf(f, "\n\n");
  }
  std::fprintf(f, "# h = 0.02, spin reversed\n");
  for (const state& s : mirrored.path) std::fprintf(f, "%.8f %.8f\n", s[0], s[1]);
  std::fclose(f);
  f = spinslide_examples::open_output(out + "/cylinder_deflection.csv", "cylinder_path");
  if (!f) return;
  std::fprintf(f, "# h [m], x at the stop [m], y at the stop [m] (stands up to the last row)\n");
  for (std::size_t k = 0; k < runs.size(); ++k)
    if (!runs[k].tipped)
      std::fprintf(f, "%.4f %.8f %.8f\n", heights[k], runs[k].path.back()[0],
                   runs[k].path.back()[1]);
  std::fclose(f);
}

bool plot(const std::string& out, double tip, std::size_t mirrored_index) {
  const std::string script =
      "set terminal pngcairo size 1200,500 font ',11'\nset output 'cylinder_path.png'\n"
      "set multiplot layout 1,2\nset grid\n"
      "set title 'Paths, v0 = 1.5 m/s along x, omega0 = 30 rad/s (counter-clockwise)'\n"
      "set xlabel 'x [m]'; set ylabel 'y [m]'; set key left bottom\n"
      "plot 'cylinder_path.csv' index 0 w l lw 2 t 'h = 0 (flat disk)', "
      "'' index 2 w l lw 2 t 'h = 4 cm', '' index 4 w l lw 2 t 'h = 8 cm', "
      "'' index 6 w l lw 2 t 'h = 12 cm', '' index 8 w l lw 2 t 'h = 16 cm', "
      "'' index " +
      std::to_string(mirrored_index) +
      " w l dt 2 lw 2 t 'h = 2 cm, spin reversed'\n"
      "set title 'Sideways deflection at the stop against the height of the centre of mass'\n"
      "set xlabel 'h [cm]'; set ylabel '-y at the stop [cm]'; set key left top\n"
      "set arrow from " +
      std::to_string(100 * tip) + ", graph 0 to " + std::to_string(100 * tip) +
      ", graph 1 nohead dt 2\n"
      "set label 'tips (eps = 1)' at " +
      std::to_string(100 * tip) +
      ", graph 0.5 right offset -1,0\n"
      "plot 'cylinder_deflection.csv' u (100*$1):(-100*$3) w lp pt 7 lw 2 t "
      "'v0 = 1.5 m/s, omega0 = 30 rad/s (eps0 = 1)'\n"
      "unset multiplot\n";
  return spinslide_examples::plot(out, "cylinder_path.gp", script);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : ".";
  std::printf(
      "solid cylinder: R = %.2f m, gamma = %.1f, mu = %.1f, v0 = %.1f m/s, omega0 = %.0f rad/s\n",
      R, gamma_z, mu, v0, w0);
  const bool tipping_ok = print_tipping_heights();
  const double tip = tipping_height(1.0, 0.15, 0.2);
  std::vector<double> heights;
  for (int k = 0; k <= 8; ++k) heights.push_back(0.02 * k);
  heights.push_back(0.168);
  heights.push_back(tip + 0.001);
  std::vector<run_result> runs;
  for (double h : heights) {
    runs.push_back(throw_cylinder(friction_of_eps(h), w0));
    const run_result& r = runs.back();
    const state& e = r.path.back();
    if (r.tipped)
      std::printf("h = %.3f m (mu h/R = %.3f): tips at t = %.4f s\n", h, mu * h / R, r.t_stop);
    else
      std::printf("h = %.3f m (mu h/R = %.3f): stops after %.4f s at x = %.5f m, y = %.6f m\n", h,
                  mu * h / R, r.t_stop, e[0], e[1]);
  }
  const run_result mirrored = throw_cylinder(friction_of_eps(0.02), -w0);
  const state& m = mirrored.path.back();
  std::printf("h = 0.020 m, spin reversed: stops at x = %.5f m, y = %.6f m (the mirror image)\n",
              m[0], m[1]);
  write_paths(out, heights, runs, mirrored);
  const bool figure = plot(out, tip, runs.size());
  std::printf("%s\n", figure ? "wrote cylinder_path.csv, cylinder_deflection.csv and "
                               "cylinder_path.png"
                             : "wrote cylinder_path.csv and cylinder_deflection.csv (no gnuplot: "
                               "no figure)");
  // The checks this example's test relies on.
  const bool straight = std::fabs(runs[0].path.back()[1]) < 1e-12;
  bool curves = true;
  for (std::size_t k = 1; k + 1 < runs.size(); ++k)
    curves = curves && !runs[k].tipped && runs[k].path.back()[1] < runs[k - 1].path.back()[1];
  const bool tips_last = runs.back().tipped;
  const state& a = runs[1].path.back();
  const bool mirror = std::fabs(a[0] - m[0]) < 1e-9 && std::fabs(a[1] + m[1]) < 1e-9;
  std::printf(
      "checks: h = 0 straight %s, curves along v x omega and more with h up to tipping %s, tips "
      "above the tipping height %s, reversed spin mirrors %s, tipping heights %s\n",
      straight ? "yes" : "NO", curves ? "yes" : "NO", tips_last ? "yes" : "NO",
      mirror ? "yes" : "NO", tipping_ok ? "yes" : "NO");
  return straight && curves && tips_last && mirror && tipping_ok ? 0 : 1;
}
