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
//
// The parts: film.hpp (the simulated throws and their frames), measure.hpp
// (each throw measured), fit.hpp (μ(n) and the μ-free test), window_bias.hpp
// (the window's bias, subtracted); this header reports and draws.
#ifndef SPINSLIDE_EXAMPLES_CD_EXPERIMENT_HPP
#define SPINSLIDE_EXAMPLES_CD_EXPERIMENT_HPP

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "../gnuplot.hpp"
#include "film.hpp"
#include "fit.hpp"
#include "measure.hpp"
#include "window_bias.hpp"

namespace cd_experiment {

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
