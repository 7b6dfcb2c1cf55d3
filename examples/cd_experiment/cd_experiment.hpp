//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// cd_experiment: the paper's experiment, end to end (the simulation and
// analysis; main.cpp is the command line, examples/paper draws Fig. 5 with it).
//
//   cd_experiment [--throws N] [--seed S] [--out DIR]      simulate, film, analyse
//   cd_experiment --analyse FILE [--out DIR]               analyse tracked frames
//
// Simulation.  N throws (default 60) of a CD on fabric: R = 6 cm with a hole
// of 1.5 cm diameter (an annulus, b = 0.125, γ = (1 + b²)/2), friction
// coefficient μ = 0.202 + 0.00053 n for throw n = 1..N (the paper's fit),
// hand-thrown: v0 uniform in [0.4, 1.2] m/s, ω0 uniform in [5, 30] rad/s, any
// direction.  The motion is integrated with spinslide's SI odeint system
// (Boost.Odeint dopri5) and filmed at 25 frames/s up to the exact stop time,
// with tracking noise: 0.5 mm in each coordinate of the centre and 0.01 rad
// in the angle (a sub-pixel tracker on PAL video of a 12 cm disk).
//
// Analysis, as the authors did.  For each throw, second-degree polynomials
// are fitted to x(t), y(t) and θ(t) over the first 7 frames after release;
// at the middle frame they give v, ω and the accelerations, hence
//   μ𝓕 = −(a·v̂)/g,   μ𝓣 = −γRω̇/g,   ε = v/(Rω).
// Each throw then gives μ from its force and from its torque (dividing by
// the annulus's 𝓕(ε) and 𝓣(ε)); μ(n) = a + b n is fitted to both by least
// squares, and the measured 𝓕 and 𝓣 divided by the fitted μ(n) are Fig. 5's
// points over the theory curves.
//
// Tracked data format (also what the simulation writes, cd_frames.csv): a CSV
// file with a header line and the columns
//   throw,t,x,y,theta
// throw: the throw number n (1, 2, ...; μ(n) is fitted against it), t in s,
// x and y in m (the centre of the disk, any fixed origin and axes), theta in
// rad (the disk's orientation, unwrapped: continuous, not reduced mod 2π).
// Frames of one throw are consecutive rows in time order, starting at
// release.  R = 0.06 m, b = 0.125, γ = (1 + b²)/2 and g = 9.81 m/s² are the
// CD's; change them below for another disk.
//
// Writes into DIR (default "."): cd_frames.csv (simulation only),
// cd_measured.csv (per throw: n, ε, μ𝓕, μ𝓣, μ from each, the fitted μ(n), 𝓕,
// 𝓣), and, with gnuplot, fig5_experiment.png.
#ifndef SPINSLIDE_EXAMPLES_CD_EXPERIMENT_HPP
#define SPINSLIDE_EXAMPLES_CD_EXPERIMENT_HPP

#include <spinslide/spinslide.hpp>

#include <boost/numeric/odeint.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../../tools/least_squares.hpp"
#include "../gnuplot.hpp"

namespace cd_experiment {

inline const double R = 0.06, hole = 0.125, gamma_cd = (1 + hole * hole) / 2, g = 9.81;
inline const double fps = 25, position_noise = 0.5e-3, angle_noise = 0.01;
inline const int fit_frames = 7;
inline const double true_a = 0.202, true_b = 0.00053;

struct frame {
  double t, x, y, theta;
};
using throws_t = std::map<int, std::vector<frame>>;

// Simulates and films N throws.
inline throws_t simulate(int n_throws, unsigned seed) {
  using state = std::array<double, 4>;  // v, ω, s, θ (si_motion)
  namespace odeint = boost::numeric::odeint;
  const spinslide::annulus<> cd(hole);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> speed(0.4, 1.2), spin(5, 30), angle(0, 6.283185307179586);
  std::normal_distribution<double> noise(0, 1);
  throws_t out;
  for (int n = 1; n <= n_throws; ++n) {
    const double mu = true_a + true_b * n;
    const double v0 = speed(rng), w0 = spin(rng), direction = angle(rng), theta0 = angle(rng);
    const auto stop = spinslide::simulate_throw_si(cd, R, mu, g, gamma_cd, v0, w0);
    const spinslide::si_motion<spinslide::annulus<>> system(cd, R, mu, g, gamma_cd);
    state x = {v0, w0, 0, 0};
    double t = 0;
    auto stepper = odeint::make_dense_output(1e-12, 1e-12, odeint::runge_kutta_dopri5<state>());
    std::vector<frame>& frames = out[n];
    for (int k = 0;; ++k) {
      const double tk = k / fps;
      double s, th;
      if (tk < stop.time * (1 - 1e-9)) {
        if (tk > t) {
          odeint::integrate_const(stepper, system, x, t, tk, (tk - t) / 4);
          t = tk;
        }
        s = x[2];
        th = x[3];
      } else {  // at rest
        s = stop.distance;
        th = stop.angle;
      }
      frames.push_back({tk, s * std::cos(direction) + position_noise * noise(rng),
                        s * std::sin(direction) + position_noise * noise(rng),
                        theta0 + th + angle_noise * noise(rng)});
      if (tk >= stop.time) break;
    }
  }
  return out;
}

inline void write_frames(const std::string& path, const throws_t& throws) {
  std::ofstream f(path);
  f << "throw,t,x,y,theta\n";
  f.precision(10);
  for (const auto& [n, frames] : throws)
    for (const frame& fr : frames)
      f << n << ',' << fr.t << ',' << fr.x << ',' << fr.y << ',' << fr.theta << '\n';
}

inline throws_t read_frames(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error("cannot read " + path);
  std::string line;
  std::getline(f, line);
  if (line.rfind("throw,t,x,y,theta", 0) != 0)
    throw std::runtime_error(path + ": the first line must be the header throw,t,x,y,theta");
  throws_t out;
  int row = 1;
  while (std::getline(f, line)) {
    ++row;
    if (line.empty()) continue;
    std::istringstream in(line);
    int n;
    frame fr;
    char c1, c2, c3, c4;
    if (!(in >> n >> c1 >> fr.t >> c2 >> fr.x >> c3 >> fr.y >> c4 >> fr.theta) || c1 != ',' ||
        c2 != ',' || c3 != ',' || c4 != ',')
      throw std::runtime_error(path + ", line " + std::to_string(row) +
                               ": expected throw,t,x,y,theta (five numbers)");
    auto& frames = out[n];
    if (!frames.empty() && !(fr.t > frames.back().t))
      throw std::runtime_error(path + ", line " + std::to_string(row) + ": times must increase");
    frames.push_back(fr);
  }
  if (out.empty()) throw std::runtime_error(path + ": no frames");
  return out;
}

// Least-squares parabola through (t_i, y_i): value, slope and curvature at tc.
inline std::array<double, 3> parabola(const std::vector<double>& t, const std::vector<double>& y,
                                      double tc) {
  std::vector<std::vector<double>> A;
  for (const double ti : t) {
    const double u = ti - tc;
    A.push_back({1, u, u * u});
  }
  const std::vector<double> c = spinslide_tools::least_squares(A, y);
  return {c[0], c[1], 2 * c[2]};
}

struct measured {
  int n;
  double eps, muF, muT, mu_from_force, mu_from_torque;
};

inline int analyse(const throws_t& throws, const std::string& dir, bool simulated) {
  const spinslide::annulus<> cd(hole);
  std::vector<measured> m;
  for (const auto& [n, frames] : throws) {
    if (static_cast<int>(frames.size()) < fit_frames) {
      std::printf("throw %d: only %zu frames, skipped (need %d)\n", n, frames.size(), fit_frames);
      continue;
    }
    std::vector<double> t, x, y, th;
    for (std::size_t i = 0; i < static_cast<std::size_t>(fit_frames); ++i) {
      t.push_back(frames[i].t);
      x.push_back(frames[i].x);
      y.push_back(frames[i].y);
      th.push_back(frames[i].theta);
    }
    const double tc = t[fit_frames / 2];
    const auto px = parabola(t, x, tc), py = parabola(t, y, tc), pt = parabola(t, th, tc);
    const double v = std::hypot(px[1], py[1]), w = std::fabs(pt[1]);
    if (!(v > 0) || !(w > 0)) continue;
    const double along = -(px[2] * px[1] + py[2] * py[1]) / v;  // deceleration along v
    const double spin_down = -pt[2] * (pt[1] > 0 ? 1 : -1);
    measured r;
    r.n = n;
    r.eps = v / (R * w);
    r.muF = along / g;
    r.muT = gamma_cd * R * spin_down / g;
    const auto ft = cd.force_torque(r.eps);
    r.mu_from_force = r.muF / ft.force;
    r.mu_from_torque = r.muT / ft.torque;
    m.push_back(r);
  }
  if (m.size() < 3) {
    std::fprintf(stderr, "cd_experiment: fewer than 3 usable throws\n");
    return 1;
  }
  // μ(n) = a + b n by least squares over both estimates of every throw; the
  // standard errors from σ² (XᵀX)⁻¹, XᵀX = [S0 S1; S1 S2].
  std::vector<std::vector<double>> X;
  std::vector<double> mus;
  double S0 = 0, S1 = 0, S2 = 0;
  for (const auto& r : m)
    for (const double mu : {r.mu_from_force, r.mu_from_torque}) {
      X.push_back({1, double(r.n)});
      mus.push_back(mu);
      S0 += 1, S1 += r.n, S2 += double(r.n) * r.n;
    }
  const std::vector<double> fit = spinslide_tools::least_squares(X, mus);
  const double a = fit[0], b = fit[1], D = S0 * S2 - S1 * S1;
  double rss = 0;
  for (const auto& r : m)
    for (const double mu : {r.mu_from_force, r.mu_from_torque})
      rss += std::pow(mu - a - b * r.n, 2);
  const double sigma2 = rss / (S0 - 2);
  const double se_a = std::sqrt(sigma2 * S2 / D), se_b = std::sqrt(sigma2 * S0 / D);
  std::printf("%zu throws analysed (quadratic fits over the first %d frames at %g frames/s)\n",
              m.size(), fit_frames, fps);
  std::printf("fitted mu(n) = a + b n:  a = %.5f +- %.5f,  b = %.6f +- %.6f\n", a, se_a, b, se_b);
  bool ok = true;
  if (simulated) {
    const double za = (a - true_a) / se_a, zb = (b - true_b) / se_b;
    std::printf("truth:                   a = %.5f,            b = %.6f\n", true_a, true_b);
    std::printf("deviation in standard errors: a %.2f, b %.2f\n", za, zb);
    ok = std::fabs(za) < 3 && std::fabs(zb) < 3;
  }
  // Fig. 5: measured F and T with the fitted μ(n), over the theory curves.
  const std::string csv = dir + "/cd_measured.csv";
  FILE* f = spinslide_examples::open_output(csv, "cd_experiment");
  if (!f) return 1;
  std::fprintf(f, "n,eps,muF,muT,mu_from_force,mu_from_torque,mu_fit,F,T\n");
  double rms_F = 0, rms_T = 0;
  for (const auto& r : m) {
    const double mu = a + b * r.n;
    const auto ft = cd.force_torque(r.eps);
    rms_F += std::pow(r.muF / mu - ft.force, 2);
    rms_T += std::pow(r.muT / mu - ft.torque, 2);
    std::fprintf(f, "%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", r.n, r.eps, r.muF, r.muT,
                 r.mu_from_force, r.mu_from_torque, mu, r.muF / mu, r.muT / mu);
  }
  std::fprintf(f, "\n\n");
  for (int i = 0; i <= 300; ++i) {  // the theory curves (annulus b = 0.125)
    const double e = 0.05 * std::pow(100.0, i / 300.0);
    const auto ft = cd.force_torque(e);
    std::fprintf(f, "0,%.6g,0,0,0,0,0,%.9g,%.9g\n", e, ft.force, ft.torque);
  }
  std::fclose(f);
  std::printf("measured points against the theory: rms deviation F %.4f, T %.4f\n",
              std::sqrt(rms_F / static_cast<double>(m.size())),
              std::sqrt(rms_T / static_cast<double>(m.size())));
  const std::string script =
      "set terminal pngcairo size 800,550 font ',11'\nset output 'fig5_experiment.png'\n"
      "set datafile separator ','\nset logscale x\nset grid\nset key top left\n"
      "set xlabel '{/Symbol e} = v/(R{/Symbol w})'\nset ylabel 'F, T'\nset yrange [0:1.1]\n"
      "set title 'Fig. 5: friction force (crosses) and torque (circles) of a CD, one pair per "
      "throw'\n"
      "plot 'cd_measured.csv' index 1 using 2:8 with lines lw 2 lc rgb '#1f77b4' title "
      "'F({/Symbol e})', '' index 1 using 2:9 with lines lw 2 dt 2 lc rgb '#d62728' title "
      "'T({/Symbol e})', '' index 0 using 2:8 with points pt 2 lc rgb '#1f77b4' title "
      "'measured F', '' index 0 using 2:9 with points pt 6 lc rgb '#d62728' title 'measured T'\n";
  if (spinslide_examples::plot(dir, "fig5_experiment.gp", script))
    std::printf("wrote %s and %s/fig5_experiment.png\n", csv.c_str(), dir.c_str());
  else
    std::printf("wrote %s (no gnuplot: no PNG)\n", csv.c_str());
  if (simulated) std::printf("recovery of mu(n): %s\n", ok ? "PASS" : "FAIL");
  return ok ? 0 : 1;
}

}  // namespace cd_experiment

#endif  // SPINSLIDE_EXAMPLES_CD_EXPERIMENT_HPP
