//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Each filmed throw measured (cd_experiment.hpp; docs/experiment.md derives
// it): parabolas over the first frames after release give v, ω and the
// accelerations at the middle frame, hence μ𝓕, μ𝓣 and ε, and μ from each.
#ifndef SPINSLIDE_EXAMPLES_CD_MEASURE_HPP
#define SPINSLIDE_EXAMPLES_CD_MEASURE_HPP

#include <array>
#include <cmath>
#include <vector>

#include "../../tools/least_squares.hpp"
#include "film.hpp"

namespace cd_experiment {

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

}  // namespace cd_experiment

#endif  // SPINSLIDE_EXAMPLES_CD_MEASURE_HPP
