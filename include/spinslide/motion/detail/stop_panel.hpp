//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file motion/detail/stop_panel.hpp
/// One Gauss–Legendre panel of a leg (docs/theory.md §9;
/// motion/detail/stop_integrator.hpp): its construction, in the path's parameter s
/// or, where the flow is slow, in u, and its error estimate.

#ifndef SPINSLIDE_MOTION_DETAIL_STOP_PANEL_HPP
#define SPINSLIDE_MOTION_DETAIL_STOP_PANEL_HPP

#include <spinslide/motion/detail/gauss_panel.hpp>
#include <spinslide/motion/detail/stop_leg.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace spinslide {
namespace detail {

/// The Gauss rule of the panels.
using stop_rule = gauss_panel<20>;

/// How a panel's nodes crowd towards its ends: towards a singular ratio
/// (𝓕″ and 𝓣″ are log-singular there; values/detail/singular_ratios.hpp) a cubic
/// map turns the log singularity into (1 − τ)⁶ log(1 − τ); between two,
/// 10τ³ − 15τ⁴ + 6τ⁵, flat to third order at both.
struct panel_grading {
  bool at_start = false;
  bool at_end = false;

  /// s − s_panel in units of the panel's width at τ ∈ [0, 1].
  double map(double tau) const {
    if (at_end && at_start) return tau * tau * tau * (10 - tau * (15 - 6 * tau));
    if (!at_end && !at_start) return tau;
    const double o = at_end ? 1 - tau : tau;
    return at_end ? 1 - o * o * o : o * o * o;
  }
  /// d map/dτ.
  double slope(double tau) const {
    if (at_end && at_start) return 30 * tau * tau * (1 - tau) * (1 - tau);
    if (!at_end && !at_start) return 1;
    const double o = at_end ? 1 - tau : tau;
    return 3 * o * o;
  }
};

/// One panel [s, s + h] of the path: the integrands at its nodes (per unit
/// of the panel's x ∈ [−1, 1]) and its error estimate.  A panel is in s, or
/// in u where the flow is slow (there 1/F carries the rounding of F, a
/// difference of O(1) terms, and the ratio hardly moves); then q at its
/// nodes comes from the collocation q = q_a + ∫F du (Picard iteration, which
/// converges at once where F and F′ are small) and dq holds F per unit x.
struct leg_panel {
  using values = stop_rule::values;
  double s = 0, h = 0;
  panel_grading grading{};
  bool in_u = false;
  values du{}, d_time{}, d_lead{}, d_other{}, dq{};  // u, t̂, ŝ_l, ŝ_o and q per unit x
  double q_end = 0;
  double error = 0;  // relative to the totals
};

/// Builds the panels ahead of a point of a leg.
template <class Profile>
class panel_builder {
 public:
  using value_type = typename Profile::value_type;
  using Real = value_type;
  using values = stop_rule::values;

  /// The panels from `at`, where the flow is `here`; `tolerance` is the
  /// error allowed per panel relative to the totals.
  panel_builder(const stop_leg<Profile>& leg, const leg_position& at, const flow_point<Real>& here,
                double tolerance)
      : leg_(leg), at_(at), here_(here), tolerance_(tolerance) {}

  /// The panel [s, s + h] in s, its nodes graded as `grading` says.
  leg_panel in_s(double s, double h, panel_grading grading) const {
    const stop_rule& r = stop_rule::rule();
    const leg_path& path = leg_.path();
    const bool collapse = leg_.rho_log() != 0;
    leg_panel pn;
    pn.s = s;
    pn.h = h;
    pn.grading = grading;
    values g{}, q{}, log_du{};
    for (std::size_t j = 0; j < n_nodes; ++j) {
      const double tau = (1 + r.node(j)) / 2;
      const double sj = s + h * grading.map(tau);
      const double e = path.finite_target ? path.delta * std::exp(-sj) : 0;  // q − q∞
      const flow_point<Real> f = leg_.at(path.finite_target ? path.q_target + e : path.q_of(sj));
      const double slope = path.finite_target ? -e : path.dq_ds(sj);
      double du = slope * f.inverse_rate * h * grading.slope(tau) / 2;
      if (!(du >= 0) || !std::isfinite(du)) du = 0;  // at the zero itself, to rounding
      pn.du[j] = du;
      g[j] = f.g;
      q[j] = f.q;
      // ln|du| where du may underflow (the ratio collapses at once).
      if (collapse)
        log_du[j] = std::log(std::fabs(slope) * h * grading.slope(tau) / 2) + log_inverse(f);
    }
    const values u_rel = r.integrals_to_nodes(pn.du);
    integrate(pn, u_rel, g, q);
    if (collapse) {
      for (std::size_t j = 0; j < n_nodes; ++j)
        pn.d_other[j] = leg_.rho_integrand(q[j], at_.u + u_rel[j], g[j], log_du[j]);
      pn.error = error_of(pn);
    }
    pn.q_end = path.q_of(s + h);
    return pn;
  }

  /// The panel of width h in u from the present point.
  leg_panel in_u(double h) const {
    const stop_rule& r = stop_rule::rule();
    leg_panel pn;
    pn.s = at_.s;
    pn.h = h;
    pn.in_u = true;
    values q{}, g{}, u_rel{};
    first_guess(h, q, u_rel);
    for (std::size_t j = 0; j < n_nodes; ++j) pn.du[j] = h / 2;
    // q is settled when its change moves the rest of the motion by a tenth
    // of the tolerance (G changes like q: d ln G/dq is O(1)).
    const double rest_t = std::exp(-at_.u) * here_.g;
    const double settled = (std::max)(1e-15 * (1 + std::fabs(here_.q)),
                                      tolerance_ / 10 * (at_.time + rest_t) / rest_t);
    double change = inf;
    for (int it = 0; it < 8 && !(change <= settled); ++it) {
      for (std::size_t j = 0; j < n_nodes; ++j) {
        const flow_point<Real> f = leg_.at(q[j]);
        pn.dq[j] = f.rate * h / 2;
        g[j] = f.g;
      }
      const values dq = r.integrals_to_nodes(pn.dq);
      // An iterate that left the numbers (the flow blows up within the
      // panel: q → −∞ at a finite u, as the spin dies in a pure slide) ends
      // the iteration unsettled, on the last finite iterate: the panel is
      // then too wide, and the controller shrinks it.
      if (!all_finite(dq)) {
        change = inf;
        break;
      }
      change = 0;
      for (std::size_t j = 0; j < n_nodes; ++j) {
        const double qn = here_.q + dq[j];
        change = (std::max)(change, std::fabs(qn - q[j]));
        q[j] = qn;
      }
    }
    integrate(pn, u_rel, g, q);
    pn.q_end = here_.q + r.integral(pn.dq);
    if (!(change <= settled) || !std::isfinite(pn.q_end)) pn.error = inf;
    return pn;
  }

 private:
  static constexpr std::size_t n_nodes = stop_rule::size;
  static constexpr double inf = std::numeric_limits<double>::infinity();

  static bool all_finite(const values& v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
  }

  // q and u at the nodes of a panel of width h in u, to start the collocation
  // from: exact for a linear flow towards the zero q∞ (q − q∞ ∝ e^{−λu}),
  // else Euler's.
  void first_guess(double h, values& q, values& u_rel) const {
    const stop_rule& r = stop_rule::rule();
    const leg_path& path = leg_.path();
    const double x = here_.q - path.q_target;
    const double lam = path.finite_target ? -here_.rate / x : 0;
    for (std::size_t j = 0; j < n_nodes; ++j) {
      u_rel[j] = h * (1 + r.node(j)) / 2;
      q[j] = lam > 0 && std::isfinite(lam) ? path.q_target + x * std::exp(-lam * u_rel[j])
                                           : here_.q + here_.rate * u_rel[j];
    }
  }

  // The integrands at the nodes from u (relative to the panel's start), G and q.
  void integrate(leg_panel& pn, const values& u_rel, const values& g, const values& q) const {
    for (std::size_t j = 0; j < n_nodes; ++j) {
      const double decay = std::exp(-(at_.u + u_rel[j]));
      pn.d_time[j] = decay * g[j] * pn.du[j];
      pn.d_lead[j] = pn.d_time[j] * decay;
      pn.d_other[j] = leg_.rho_integrand(q[j], at_.u + u_rel[j], g[j]) * pn.du[j];
    }
    pn.error = error_of(pn);
  }

  // The panel's error relative to the totals: u at the nodes (its
  // interpolation error, weighted by the motion left), and each Gauss sum
  // (the square of its relative interpolation error, the order it converges at).
  double error_of(const leg_panel& pn) const {
    const stop_rule& r = stop_rule::rule();
    const double rest_t = std::exp(-at_.u) * here_.g;
    const double rest_lead = rest_t * std::exp(-at_.u) / 2;
    auto sum_error = [&](const values& f, double total) {
      const double c0 = std::fabs(r.coefficient(0, f));
      if (std::isnan(c0)) return c0;
      if (!(c0 > 0)) return 0.0;
      const double rel = r.tail(f) / c0;
      return rel * rel * 2 * c0 / total;
    };
    // The largest of the estimates; a NaN one (an integrand that left the
    // numbers) makes the whole NaN, which is taken as ∞.
    auto worst = [](double a, double b) { return b > a || std::isnan(b) ? b : a; };
    double err = 2 * r.tail(pn.du) * rest_t / (at_.time + rest_t);
    err = worst(err, sum_error(pn.d_time, at_.time + rest_t));
    err = worst(err, sum_error(pn.d_lead, at_.lead_travel + rest_lead));
    const double rest_other = leg_.rest_at_rate(here_, at_.u);
    err = worst(err, sum_error(pn.d_other, at_.other_travel + rest_other));
    return std::isnan(err) ? std::numeric_limits<double>::infinity() : err;
  }

  const stop_leg<Profile>& leg_;
  const leg_position& at_;
  const flow_point<Real>& here_;
  double tolerance_;
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_DETAIL_STOP_PANEL_HPP
