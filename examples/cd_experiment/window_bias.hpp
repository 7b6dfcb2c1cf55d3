//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The analysis's own bias over its window of frames, modelled on the
// noise-free film of each throw and subtracted (cd_experiment.hpp;
// docs/experiment.md, "The torque bias").
#ifndef SPINSLIDE_EXAMPLES_CD_WINDOW_BIAS_HPP
#define SPINSLIDE_EXAMPLES_CD_WINDOW_BIAS_HPP

#include <boost/numeric/odeint.hpp>

#include <cmath>
#include <vector>

#include "fit.hpp"

namespace cd_experiment {

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
    if (ti > tc) after.push_back((ti - tc) / system.time_unit());
  const auto ahead = spinslide::trajectory(cd, gamma_cd, v / system.velocity_unit(),
                                           w / system.spin_unit(), after);
  for (std::size_t i = 0, j = 0; i < t.size(); ++i) {
    if (t[i] > tc) {
      s[i] = ahead[j].distance * system.distance_unit();
      th[i] = ahead[j++].angle * system.angle_unit();
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

}  // namespace cd_experiment

#endif  // SPINSLIDE_EXAMPLES_CD_WINDOW_BIAS_HPP
