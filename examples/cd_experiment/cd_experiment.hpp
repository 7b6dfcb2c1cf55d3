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
// direction.  The motion is spinslide::trajectory's, filmed at 25 frames/s
// up to the exact stop time, with tracking noise: 0.5 mm in each coordinate of the centre and 0.01
// rad in the angle (a sub-pixel tracker on PAL video of a 12 cm disk).
//
// Analysis (docs/experiment.md derives it).  For each throw, second-degree
// polynomials are fitted to x(t), y(t) and θ(t) over the first 7 frames
// after release, as the authors did; at the middle frame they give v, ω and
// the accelerations, hence
//   μ𝓕 = −(a·v̂)/g,   μ𝓣 = −γRω̇/g,   ε = v/(Rω).
// Then, beyond the authors' analysis:
// - the window bias (the motion is not a parabola over 0.24 s: μ from the
//   torque came out 1.9 % high at 0.8 ≤ ε < 2) is modelled by fitting the
//   noise-free film of the throw's own motion and subtracted;
// - each throw's μ from its force and from its torque (dividing by the
//   annulus's 𝓕(ε) and 𝓣(ε)) get their covariance propagated from the
//   tracking noise, which is estimated from the fits' residuals, and
//   μ(n) = a + b n is fitted by generalized least squares (inverse-covariance
//   weights; the authors' equal-weight fit is printed beside it);
// - the μ-free test: μ𝓣/μ𝓕 against 𝓣(ε)/𝓕(ε), a χ² and a scale s that is
//   1 if torque and force agree with the theory (Fig. 5, left panel); the
//   right panel is the authors' 𝓕 and 𝓣 divided by the fitted μ(n).
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
// 𝓣, μ𝓣/μ𝓕 and its sd, the sd of each μ), and, with gnuplot,
// fig5_experiment.png.  cd_sweep (sweep.cpp) runs the analysis over seeds.
#ifndef SPINSLIDE_EXAMPLES_CD_EXPERIMENT_HPP
#define SPINSLIDE_EXAMPLES_CD_EXPERIMENT_HPP

#include <spinslide/spinslide.hpp>

#include <boost/math/distributions/chi_squared.hpp>

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
inline const double fps = 25;
inline const int default_fit_frames = 7;

// The tracking noise of the simulated film: the sd of each coordinate of the
// centre (m) and of the angle (rad) in every frame.
struct film_noise {
  double position, angle;
};
inline const film_noise tracking_noise = {0.5e-3, 0.01};
inline const double true_a = 0.202, true_b = 0.00053;

struct frame {
  double t, x, y, theta;
};
using throws_t = std::map<int, std::vector<frame>>;

// The frame times of a throw that stops at `stop` (s): k/fps up to the
// first frame at or after the stop (at rest).
inline std::vector<double> frame_times(double stop) {
  std::vector<double> t;
  for (int k = 0;; ++k) {
    t.push_back(k / fps);
    if (t.back() >= stop) return t;
  }
}

// Simulates and films N throws.  The motion is spinslide::trajectory's,
// sampled at the frame times in the paper's units (it steps through the
// stop exactly and gives the rest state after it), converted to SI.
inline throws_t simulate(int n_throws, unsigned seed, film_noise noise_sd = tracking_noise) {
  const spinslide::annulus<> cd(hole);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> speed(0.4, 1.2), spin(5, 30), angle(0, 6.283185307179586);
  std::normal_distribution<double> noise(0, 1);
  throws_t out;
  for (int n = 1; n <= n_throws; ++n) {
    const double mu = true_a + true_b * n;
    const double v0 = speed(rng), w0 = spin(rng), direction = angle(rng), theta0 = angle(rng);
    const spinslide::si_motion<spinslide::annulus<>> units(cd, R, mu, g, gamma_cd);
    const auto stop = spinslide::simulate_throw_si(cd, R, mu, g, gamma_cd, v0, w0);
    const std::vector<double> t = frame_times(stop.time);
    std::vector<double> t_scaled;
    t_scaled.reserve(t.size());
    for (const double tk : t) t_scaled.push_back(tk / units.time_scale());
    const auto motion = spinslide::trajectory(cd, gamma_cd, v0 / units.velocity_scale(),
                                              w0 / units.spin_scale(), t_scaled);
    std::vector<frame>& frames = out[n];
    for (std::size_t k = 0; k < t.size(); ++k) {
      const double s = motion[k].distance * units.distance_scale();
      const double th = motion[k].angle * units.angle_scale();
      frames.push_back({t[k], s * std::cos(direction) + noise_sd.position * noise(rng),
                        s * std::sin(direction) + noise_sd.position * noise(rng),
                        theta0 + th + noise_sd.angle * noise(rng)});
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

// How the frames are analysed.  The defaults are the authors' analysis:
// 7 frames from release, everything taken at the middle frame.
struct analysis_options {
  int fit_frames = default_fit_frames;
  int evaluate_at = -1;  // frame of the window where v, ω, a, ω̇ are taken; −1: the middle
  bool window_correction = true;
  int correction_iterations = 2;
};

// A window's design: the variances of the fitted slope and curvature for
// unit noise variance, [(AᵀA)⁻¹]₁₁ and 4 [(AᵀA)⁻¹]₂₂ for the rows (1, u, u²),
// u = t − tc, and the residual degrees of freedom.
struct window_design {
  double slope_var, curvature_var;
  int dof;
};

inline window_design design(const std::vector<double>& t, double tc) {
  std::array<double, 5> m{};  // Σ uᵏ
  for (const double ti : t) {
    double p = 1;
    for (double& mk : m) mk += p, p *= ti - tc;
  }
  const double det = m[0] * (m[2] * m[4] - m[3] * m[3]) - m[1] * (m[1] * m[4] - m[2] * m[3]) +
                     m[2] * (m[1] * m[3] - m[2] * m[2]);
  return {(m[0] * m[4] - m[2] * m[2]) / det, 4 * (m[0] * m[2] - m[1] * m[1]) / det,
          static_cast<int>(t.size()) - 3};
}

// Least-squares parabola through (t_i, y_i): value, slope and curvature at tc,
// and the residual sum of squares.
struct parabola_fit {
  double value, slope, curvature, rss;
};

inline parabola_fit parabola(const std::vector<double>& t, const std::vector<double>& y,
                             double tc) {
  std::vector<std::vector<double>> A;
  for (const double ti : t) {
    const double u = ti - tc;
    A.push_back({1, u, u * u});
  }
  const std::vector<double> c = spinslide_tools::least_squares(A, y);
  double rss = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double u = t[i] - tc;
    rss += std::pow(y[i] - c[0] - (c[1] + c[2] * u) * u, 2);
  }
  return {c[0], c[1], 2 * c[2], rss};
}

// One throw's measurement.  F, T: the annulus's 𝓕 and 𝓣 at the measured ε;
// dlnF, dlnT: d ln 𝓕/d ln ε and d ln 𝓣/d ln ε there (for the error
// propagation).  rss_position: x and y together.
struct measured {
  int n;
  double eps, v, w, muF, muT;
  double F, T, dlnF, dlnT;
  double mu_from_force, mu_from_torque;
  window_design window;
  double rss_position, rss_angle;
};

inline double log_slope(double eps, double (*part)(const spinslide::force_torque_result<double>&)) {
  const spinslide::annulus<> cd(hole);
  const double h = 1e-4;
  return (std::log(part(cd.force_torque(eps * (1 + h)))) -
          std::log(part(cd.force_torque(eps * (1 - h))))) /
         (std::log1p(h) - std::log1p(-h));
}

inline double force_part(const spinslide::force_torque_result<double>& ft) { return ft.force; }
inline double torque_part(const spinslide::force_torque_result<double>& ft) { return ft.torque; }

// Fits one throw's window; false if the throw has too few frames or no motion.
inline bool measure_throw(int n, const std::vector<frame>& frames, const analysis_options& opt,
                          measured& r) {
  if (static_cast<int>(frames.size()) < opt.fit_frames) return false;
  std::vector<double> t, x, y, th;
  for (std::size_t i = 0; i < static_cast<std::size_t>(opt.fit_frames); ++i) {
    t.push_back(frames[i].t);
    x.push_back(frames[i].x);
    y.push_back(frames[i].y);
    th.push_back(frames[i].theta);
  }
  const int at = opt.evaluate_at < 0 ? opt.fit_frames / 2 : opt.evaluate_at;
  const double tc = t[static_cast<std::size_t>(at)];
  const auto px = parabola(t, x, tc), py = parabola(t, y, tc), pt = parabola(t, th, tc);
  const double v = std::hypot(px.slope, py.slope), w = std::fabs(pt.slope);
  if (!(v > 0) || !(w > 0)) return false;
  r.n = n;
  r.v = v;
  r.w = w;
  r.eps = v / (R * w);
  r.muF = -(px.curvature * px.slope + py.curvature * py.slope) / v / g;  // deceleration along v
  r.muT = gamma_cd * R * -pt.curvature * (pt.slope > 0 ? 1 : -1) / g;
  r.window = design(t, tc);
  r.rss_position = px.rss + py.rss;
  r.rss_angle = pt.rss;
  return true;
}

// Divides by the theory: μ from the force and from the torque.
inline void divide_by_theory(measured& r) {
  const spinslide::annulus<> cd(hole);
  const auto ft = cd.force_torque(r.eps);
  r.F = ft.force;
  r.T = ft.torque;
  r.dlnF = log_slope(r.eps, force_part);
  r.dlnT = log_slope(r.eps, torque_part);
  r.mu_from_force = r.muF / r.F;
  r.mu_from_torque = r.muT / r.T;
}

inline std::vector<measured> measure(const throws_t& throws, const analysis_options& opt,
                                     bool quiet = false) {
  std::vector<measured> m;
  for (const auto& [n, frames] : throws) {
    measured r{};
    if (!measure_throw(n, frames, opt, r)) {
      if (!quiet)
        std::printf("throw %d: %zu frames or no motion, skipped (need %d)\n", n, frames.size(),
                    opt.fit_frames);
      continue;
    }
    divide_by_theory(r);
    m.push_back(r);
  }
  return m;
}

// The tracking noise, estimated from the fits' residuals pooled over all
// throws (variances: per coordinate of the centre, and of the angle).
struct noise_estimate {
  double position_var, angle_var;
};

inline noise_estimate pooled_noise(const std::vector<measured>& m) {
  double rp = 0, ra = 0, dof = 0;
  for (const auto& r : m) rp += r.rss_position, ra += r.rss_angle, dof += r.window.dof;
  return {rp / (2 * dof), ra / dof};
}

// The covariance of a throw's two estimates of μ, propagated from the
// tracking noise to first order (docs/experiment.md, "The weights").
struct pair_covariance {
  double ff, tt, ft;
};

inline pair_covariance covariance(const measured& r, const noise_estimate& s, double mu) {
  const double var_ln_eps =
      r.window.slope_var * (s.position_var / (r.v * r.v) + s.angle_var / (r.w * r.w));
  const double var_muF = s.position_var * r.window.curvature_var / (g * g);
  const double k = gamma_cd * R / g;
  const double var_muT = k * k * s.angle_var * r.window.curvature_var;
  const double m2 = mu * mu * var_ln_eps;
  return {var_muF / (r.F * r.F) + m2 * r.dlnF * r.dlnF,
          var_muT / (r.T * r.T) + m2 * r.dlnT * r.dlnT, m2 * r.dlnF * r.dlnT};
}

// μ(n) = a + b n fitted to the estimates.
struct mu_fit {
  double a, b, se_a, se_b, chi2;
  int dof;
};

// Which estimates of each throw a fit uses.
enum class estimates { both, force, torque };

// One throw in a generalized least-squares fit: n, its two estimates and the
// inverse of their covariance (zero rows for an estimate left out).
struct block {
  double n, y_force, y_torque, w_ff, w_tt, w_ft;
};

// Solves the normal equations Σ XᵢᵀWᵢXᵢ (a, b) = Σ XᵢᵀWᵢyᵢ, Xᵢ = [1 n; 1 n].
// The covariance of (a, b) is (Σ XᵢᵀWᵢXᵢ)⁻¹, times χ²/dof if `scale`.
inline mu_fit solve(const std::vector<block>& blocks, bool scale) {
  double S0 = 0, S1 = 0, S2 = 0, B0 = 0, B1 = 0;
  int observations = 0;
  for (const block& k : blocks) {
    const double s = k.w_ff + k.w_tt + 2 * k.w_ft;
    const double q = (k.w_ff + k.w_ft) * k.y_force + (k.w_tt + k.w_ft) * k.y_torque;
    S0 += s, S1 += s * k.n, S2 += s * k.n * k.n, B0 += q, B1 += q * k.n;
    observations += (k.w_ff > 0) + (k.w_tt > 0);
  }
  const double D = S0 * S2 - S1 * S1;
  mu_fit f{(S2 * B0 - S1 * B1) / D, (S0 * B1 - S1 * B0) / D, 0, 0, 0, observations - 2};
  for (const block& k : blocks) {
    const double rf = k.y_force - f.a - f.b * k.n, rt = k.y_torque - f.a - f.b * k.n;
    f.chi2 += k.w_ff * rf * rf + k.w_tt * rt * rt + 2 * k.w_ft * rf * rt;
  }
  const double factor = scale ? f.chi2 / f.dof : 1;
  f.se_a = std::sqrt(factor * S2 / D);
  f.se_b = std::sqrt(factor * S0 / D);
  return f;
}

// The authors' fit: ordinary least squares, every estimate weighted equally,
// σ² from the residuals.
inline mu_fit pooled_fit(const std::vector<measured>& m, estimates use = estimates::both) {
  std::vector<block> blocks;
  blocks.reserve(m.size());
  for (const auto& r : m)
    blocks.push_back({double(r.n), r.mu_from_force, r.mu_from_torque,
                      use != estimates::torque ? 1.0 : 0.0, use != estimates::force ? 1.0 : 0.0,
                      0});
  return solve(blocks, true);
}

// Inverse-covariance weights: the propagated covariance of each throw's pair,
// evaluated at the previous iteration's μ(n), starting from the pooled fit.
inline mu_fit weighted_fit(const std::vector<measured>& m, estimates use = estimates::both,
                           int iterations = 3) {
  const noise_estimate noise = pooled_noise(m);
  mu_fit f = pooled_fit(m, use);
  for (int it = 0; it < iterations; ++it) {
    std::vector<block> blocks;
    for (const auto& r : m) {
      pair_covariance c = covariance(r, noise, f.a + f.b * r.n);
      if (use == estimates::force) c.tt = 1, c.ft = 0;  // placeholder variance, weight zeroed below
      if (use == estimates::torque) c.ff = 1, c.ft = 0;
      const double det = c.ff * c.tt - c.ft * c.ft;
      block k{double(r.n), r.mu_from_force, r.mu_from_torque, c.tt / det, c.ff / det, -c.ft / det};
      if (use == estimates::force) k.w_tt = 0;
      if (use == estimates::torque) k.w_ff = 0;
      blocks.push_back(k);
    }
    f = solve(blocks, false);
  }
  return f;
}

// The analysis's own bias (docs/experiment.md, "The torque bias"): over 7
// frames ε, and with it 𝓣(ε), changes enough that θ(t) and s(t) are not
// parabolas, and the fitted slopes and curvatures differ from v, ω, v̇ and ω̇
// at the middle frame by terms of order h² ω⃛ and h² v⃛ (h the window's
// length).  The bias is modelled by filming the noise-free motion from the
// measured state at tc with the fitted μ over the same frames, fitting it
// like the data, and subtracting the truth at tc.
struct window_bias {
  double v, w, muF, muT;
};

// The noise-free film at the times t of the motion through (v, ω) at tc:
// after tc by spinslide::trajectory (which steps through the stop, and
// holds the rest state after it), before tc by odeint on the time-reversed
// equations (no stop on the way back).
inline void film_noise_free(const std::vector<double>& t, double tc, double v, double w, double mu,
                            std::vector<double>& s, std::vector<double>& th) {
  using state = std::array<double, 4>;  // v, ω, s, θ (si_motion)
  namespace odeint = boost::numeric::odeint;
  const spinslide::annulus<> cd(hole);
  const spinslide::si_motion<spinslide::annulus<>> system(cd, R, mu, g, gamma_cd);
  const auto reversed = [&system](const state& x, state& dxdt, double time) {
    system(x, dxdt, time);
    for (double& d : dxdt) d = -d;
  };
  s.assign(t.size(), 0);
  th.assign(t.size(), 0);
  std::vector<double> after;  // dimensionless times after tc
  for (const double ti : t)
    if (ti > tc) after.push_back((ti - tc) / system.time_scale());
  const auto ahead = spinslide::trajectory(cd, gamma_cd, v / system.velocity_scale(),
                                           w / system.spin_scale(), after);
  for (std::size_t i = 0, j = 0; i < t.size(); ++i) {
    if (t[i] > tc) {
      s[i] = ahead[j].distance * system.distance_scale();
      th[i] = ahead[j++].angle * system.angle_scale();
    } else if (t[i] < tc) {
      state x = {v, w, 0, 0};
      auto stepper = odeint::make_controlled(1e-12, 1e-12, odeint::runge_kutta_dopri5<state>());
      odeint::integrate_adaptive(stepper, reversed, x, 0.0, tc - t[i], 1e-3);
      s[i] = x[2];
      th[i] = x[3];
    }
  }
}

// The bias at one throw.
inline window_bias window_bias_at(const std::vector<double>& t, double tc, double v, double w,
                                  double mu) {
  const spinslide::annulus<> cd(hole);
  std::vector<double> s, th;
  film_noise_free(t, tc, v, w, mu, s, th);
  const auto ps = parabola(t, s, tc), pt = parabola(t, th, tc);
  const auto ft = cd.force_torque(v / (R * w));
  return {ps.slope - v, pt.slope - w, -ps.curvature / g - mu * ft.force,
          -gamma_cd * R * pt.curvature / g - mu * ft.torque};
}

inline void correct_window(measured& r, const std::vector<frame>& frames,
                           const analysis_options& opt, double mu) {
  std::vector<double> t;
  for (std::size_t i = 0; i < static_cast<std::size_t>(opt.fit_frames); ++i)
    t.push_back(frames[i].t);
  const int at = opt.evaluate_at < 0 ? opt.fit_frames / 2 : opt.evaluate_at;
  // Fixed-point iteration: the bias is modelled at the corrected state.
  window_bias b{};
  for (int k = 0; k < opt.correction_iterations; ++k)
    b = window_bias_at(t, t[static_cast<std::size_t>(at)], r.v - b.v, r.w - b.w, mu);
  r.v -= b.v;
  r.w -= b.w;
  r.eps = r.v / (R * r.w);
  r.muF -= b.muF;
  r.muT -= b.muT;
  divide_by_theory(r);
}

// measure(), then with opt.window_correction each throw's window bias
// removed, modelled at the μ(n) of a first weighted fit.
inline std::vector<measured> measure_corrected(const throws_t& throws, const analysis_options& opt,
                                               bool quiet = false) {
  std::vector<measured> m = measure(throws, opt, quiet);
  if (!opt.window_correction || m.size() < 3) return m;
  const mu_fit first = weighted_fit(m);
  for (auto& r : m) correct_window(r, throws.at(r.n), opt, first.a + first.b * r.n);
  return m;
}

// The μ-free comparison: a throw's torque against its force, μ𝓣 − ρ(ε) μ𝓕
// with ρ = 𝓣/𝓕, which is zero in expectation whatever μ is.  Its variance
// is propagated like the weights' (the ε term at the measured μ𝓕).
struct ratio_point {
  double ratio, theory, sd;  // μ𝓣/μ𝓕, 𝓣(ε)/𝓕(ε), the sd of μ𝓣/μ𝓕
  double d, var_d;           // μ𝓣 − ρ μ𝓕 and its variance
};

inline ratio_point ratio_test_point(const measured& r, const noise_estimate& s) {
  const double rho = r.T / r.F;
  const double var_ln_eps =
      r.window.slope_var * (s.position_var / (r.v * r.v) + s.angle_var / (r.w * r.w));
  const double k = gamma_cd * R / g;
  const double var_muF = s.position_var * r.window.curvature_var / (g * g);
  const double var_muT = k * k * s.angle_var * r.window.curvature_var;
  const double slope = rho * r.muF * (r.dlnT - r.dlnF);
  ratio_point p{};
  p.ratio = r.muT / r.muF;
  p.theory = rho;
  p.d = r.muT - rho * r.muF;
  p.var_d = var_muT + rho * rho * var_muF + slope * slope * var_ln_eps;
  p.sd = std::sqrt(p.var_d) / std::fabs(r.muF);
  return p;
}

// The μ-free test over all throws: χ² of the d's, and the scale s in
// μ𝓣 = s ρ(ε) μ𝓕 (1 if torque and force agree with the theory), as the
// ratio Σ wᵢ μ𝓣ᵢ / Σ wᵢ ρᵢ μ𝓕ᵢ with wᵢ = ρᵢ 𝓕ᵢ / var dᵢ.  The weights hold the
// theory's 𝓕 where a regression of μ𝓣 on ρ μ𝓕 would hold the noisy μ𝓕 (and
// be biased low by its noise, −0.2 % here); μ(n) cancels but for its
// variation with n.
struct ratio_summary {
  double chi2, p_value, s, se_s;
  int dof;
};

inline ratio_summary ratio_test(const std::vector<measured>& m, const noise_estimate& noise) {
  ratio_summary out{};
  double num = 0, den = 0, var_num = 0;
  for (const auto& r : m) {
    const ratio_point p = ratio_test_point(r, noise);
    out.chi2 += p.d * p.d / p.var_d;
    const double w = p.theory * r.F / p.var_d;
    num += w * r.muT;
    den += w * p.theory * r.muF;
    var_num += w * w * p.var_d;
  }
  out.dof = static_cast<int>(m.size());
  out.p_value = boost::math::cdf(
      boost::math::complement(boost::math::chi_squared_distribution<double>(out.dof), out.chi2));
  out.s = num / den;
  out.se_s = std::sqrt(var_num) / den;
  return out;
}

// `weighted`: chi2 is χ²; otherwise the residual sum of squares.
inline void print_fit(const char* name, const mu_fit& f, bool weighted) {
  std::printf("%s a = %.5f +- %.5f,  b = %.6f +- %.6f  (%s %.4g)\n", name, f.a, f.se_a, f.b, f.se_b,
              weighted ? "chi2/dof" : "residual sd",
              weighted ? f.chi2 / f.dof : std::sqrt(f.chi2 / f.dof));
}

// Fig. 5's data: per throw, then the theory curves.
inline bool write_measured(const std::string& csv, const std::vector<measured>& m,
                           const mu_fit& fit, const noise_estimate& noise) {
  FILE* f = spinslide_examples::open_output(csv, "cd_experiment");
  if (!f) return false;
  std::fprintf(f,
               "n,eps,muF,muT,mu_from_force,mu_from_torque,mu_fit,F,T,T_over_F,T_over_F_sd,"
               "sd_mu_from_force,sd_mu_from_torque\n");
  for (const auto& r : m) {
    const double mu = fit.a + fit.b * r.n;
    const pair_covariance c = covariance(r, noise, mu);
    const ratio_point p = ratio_test_point(r, noise);
    std::fprintf(f, "%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", r.n, r.eps,
                 r.muF, r.muT, r.mu_from_force, r.mu_from_torque, mu, r.muF / mu, r.muT / mu,
                 p.ratio, p.sd, std::sqrt(c.ff), std::sqrt(c.tt));
  }
  std::fprintf(f, "\n\n");
  const spinslide::annulus<> cd(hole);
  for (int i = 0; i <= 300; ++i) {  // the theory curves (annulus b = 0.125)
    const double e = 0.05 * std::pow(100.0, i / 300.0);
    const auto ft = cd.force_torque(e);
    std::fprintf(f, "0,%.6g,0,0,0,0,0,%.9g,%.9g,%.9g,0,0,0\n", e, ft.force, ft.torque,
                 ft.torque / ft.force);
  }
  std::fclose(f);
  return true;
}

// Fig. 5: left, the μ-free comparison 𝓣/𝓕 against ε (the primary one);
// right, 𝓕 and 𝓣 divided by the fitted μ(n) (circular: μ(n) was fitted to
// these points).
inline const char* fig5_script =
    "set terminal pngcairo size 1200,520 font ',11'\nset output 'fig5_experiment.png'\n"
    "set datafile separator ','\nset multiplot layout 1,2 title 'Fig. 5: the simulated CD "
    "experiment, one point per throw'\nset logscale x\nset xrange [0.1:6]\nset grid\n"
    "set xlabel '{/Symbol e} = v/(R{/Symbol w})'\n"
    "set logscale y\nset yrange [0.04:5]\nset key top right\nset ylabel 'T/F = {/Symbol m}T / "
    "{/Symbol m}F'\n"
    "set title 'torque over force (no {/Symbol m} needed)'\n"
    "plot 'cd_measured.csv' index 1 using 2:10 with lines lw 2 lc rgb '#2ca02c' title "
    "'T({/Symbol e})/F({/Symbol e})', '' index 0 using 2:10:11 with yerrorbars pt 7 ps 0.6 "
    "lc rgb '#000000' title 'measured'\n"
    "unset logscale y\nset yrange [0:1.1]\nset key top left\nset ylabel 'F, T'\n"
    "set title 'divided by the fitted {/Symbol m}(n) (circular)'\n"
    "plot 'cd_measured.csv' index 1 using 2:8 with lines lw 2 lc rgb '#1f77b4' title "
    "'F({/Symbol e})', '' index 1 using 2:9 with lines lw 2 dt 2 lc rgb '#d62728' title "
    "'T({/Symbol e})', '' index 0 using 2:8 with points pt 2 lc rgb '#1f77b4' title "
    "'measured F', '' index 0 using 2:9 with points pt 6 lc rgb '#d62728' title 'measured T'\n"
    "unset multiplot\n";

inline int analyse(const throws_t& throws, const std::string& dir, bool simulated,
                   const analysis_options& opt = {}) {
  const std::vector<measured> m = measure_corrected(throws, opt);
  if (m.size() < 3) {
    std::fprintf(stderr, "cd_experiment: fewer than 3 usable throws\n");
    return 1;
  }
  const noise_estimate noise = pooled_noise(m);
  const mu_fit pooled = pooled_fit(measure(throws, opt, true)), fit = weighted_fit(m);
  const ratio_summary rt = ratio_test(m, noise);
  std::printf("%zu throws analysed (quadratic fits over the first %d frames at %g frames/s)\n",
              m.size(), opt.fit_frames, fps);
  std::printf("tracking noise from the fits' residuals: %.3f mm, %.4f rad\n",
              1e3 * std::sqrt(noise.position_var), std::sqrt(noise.angle_var));
  std::printf(
      "mu-free test, T/F against eps: chi2 = %.1f for %d throws (p = %.3f); "
      "mu T = s rho(eps) mu F with s = %.4f +- %.4f\n",
      rt.chi2, rt.dof, rt.p_value, rt.s, rt.se_s);
  print_fit("the authors' fit (no window correction, equal weights):", pooled, false);
  print_fit("fitted mu(n) = a + b n (corrected, weighted):      ", fit, true);
  bool ok = rt.p_value > 1e-3 && std::fabs(rt.s - 1) < 3 * rt.se_s;
  if (simulated) {
    const double za = (fit.a - true_a) / fit.se_a, zb = (fit.b - true_b) / fit.se_b;
    std::printf(
        "truth:                                               a = %.5f,            b = %.6f\n",
        true_a, true_b);
    std::printf("deviation in standard errors: a %.2f, b %.2f\n", za, zb);
    ok = ok && std::fabs(za) < 3 && std::fabs(zb) < 3;
  }
  const std::string csv = dir + "/cd_measured.csv";
  if (!write_measured(csv, m, fit, noise)) return 1;
  if (spinslide_examples::plot(dir, "fig5_experiment.gp", fig5_script))
    std::printf("wrote %s and %s/fig5_experiment.png\n", csv.c_str(), dir.c_str());
  else
    std::printf("wrote %s (no gnuplot: no PNG)\n", csv.c_str());
  if (simulated) std::printf("recovery of mu(n): %s\n", ok ? "PASS" : "FAIL");
  return ok ? 0 : 1;
}

}  // namespace cd_experiment

#endif  // SPINSLIDE_EXAMPLES_CD_EXPERIMENT_HPP
