//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// From the measured throws to μ(n) and the μ-free test (cd_experiment.hpp):
// the tracking noise from the fits' residuals, each throw's covariance,
// μ(n) = a + b n by equal-weight and by generalized least squares, and the
// comparison of μ𝓣/μ𝓕 with 𝓣(ε)/𝓕(ε).
#ifndef SPINSLIDE_EXAMPLES_CD_FIT_HPP
#define SPINSLIDE_EXAMPLES_CD_FIT_HPP

#include <boost/math/distributions/chi_squared.hpp>

#include <cmath>
#include <vector>

#include "../../tools/least_squares.hpp"
#include "measure.hpp"

namespace cd_experiment {

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

}  // namespace cd_experiment

#endif  // SPINSLIDE_EXAMPLES_CD_FIT_HPP
