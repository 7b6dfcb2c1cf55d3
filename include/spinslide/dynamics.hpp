//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file dynamics.hpp
/// spinslide's own integration of a throw through the singular stop, with the
/// exact stop time, distance and rotation (docs/theory.md §9).  The equations
/// of motion are in equations_of_motion.hpp, the precomputed throws in
/// tabulated_throw.hpp.
///
/// Dimensionless units (the paper's): v* = v/(μ√(gR)), ω* = ω√(R/g)/μ,
/// t* = t√(g/R); then distance s = μR s* and angle θ = μ θ*.  γ = I/(mR²).

#ifndef SPINSLIDE_DYNAMICS_HPP
#define SPINSLIDE_DYNAMICS_HPP

#include <spinslide/detail/checks.hpp>
#include <spinslide/detail/product.hpp>
#include <spinslide/equations_of_motion.hpp>
#include <spinslide/profile_concept.hpp>
#include <spinslide/terminal.hpp>

#include <boost/math/tools/toms748_solve.hpp>
#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace spinslide {

/// One sample of a trajectory, dimensionless or SI.
template <class Real>
struct motion_sample {
  Real time;      ///< t (t* or s)
  Real speed;     ///< v (v* or m/s)
  Real spin;      ///< ω (ω* or rad/s)
  Real ratio;     ///< ε = v*/ω* (0 or ∞ once one of them is 0)
  Real distance;  ///< distance slid so far (s* or m)
  Real angle;     ///< angle turned so far (θ* or rad)
};

/// The outcome of a throw: when and where it stops, and how ε ended.
template <class Real>
struct stop_result {
  Real time;                      ///< the stop time (both v and ω reach 0 then)
  Real distance;                  ///< distance slid
  Real angle;                     ///< angle turned
  terminal_state<Real> terminal;  ///< the regime and the limit of ε at the stop
};

namespace detail {

// spinslide's integration through the stop (docs/theory.md §9): in
// x = −ln ω* ("by spin") or y = −ln v* ("by speed"), where the stop is at
// infinity and regular, with the log of the ratio as state and everything
// scaled by the motions where the variable starts (details below).  It stops
// once the remaining time (and the distance and angle) are below 1e-18 of
// the totals.  Work is bounded: u grows by at least the time integrand's
// decay, which is exponential in every regime, and at most 10⁵ steps are
// taken before evaluation_error.
//
// `times` (sorted, may be empty): the trajectory is also sampled at these
// times into `at_times`, by inverting t(u) on the dense output with TOMS 748;
// times at or after the stop give the rest state.
template <class Profile, class Observer>
// NOLINTNEXTLINE(readability-function-cognitive-complexity): the dynamics issue (16) rewrites it.
stop_result<typename Profile::value_type> integrate_stop(
    const Profile& p, typename Profile::value_type gamma, typename Profile::value_type v0,
    typename Profile::value_type w0, Observer observe,
    const std::vector<typename Profile::value_type>& times,
    std::vector<motion_sample<typename Profile::value_type>>& at_times) {
  using Real = typename Profile::value_type;
  using boost::numeric::odeint::make_dense_output;
  using boost::numeric::odeint::runge_kutta_dopri5;
  const Real inf = std::numeric_limits<Real>::infinity();
  stop_result<Real> out{0, 0, 0, {terminal_regime::sliding_and_spinning, Real(0)}};
  // Pure sliding and pure spinning decelerate uniformly: exact.
  auto uniform = [&](Real a_v, Real a_w, Real ratio) {
    auto at = [&](Real t) {
      const Real te = t < out.time ? t : out.time;
      // The speeds lost by te; at the stop exactly v0 and ω0 (a ∞ · 0 there
      // otherwise, for a subnormal γ).  te (v0 − Δv/2), not v0 te − a te²/2,
      // which is ∞ − ∞ at the largest speeds (both found by fuzz_stop_time).
      const Real dv = t < out.time ? Real(a_v * te) : v0, dw = t < out.time ? Real(a_w * te) : w0;
      const Real v = v0 - dv, w = w0 - dw;
      // The mean speed times te; 0 for a speed that stays 0, even where te overflows.
      auto travelled = [te](Real x0, Real dx) {
        const Real mean = x0 - dx / 2;
        return mean == 0 ? Real(0) : Real(te * mean);
      };
      return motion_sample<Real>{t,     v > 0 ? v : Real(0), w > 0 ? w : Real(0),
                                 ratio, travelled(v0, dv),   travelled(w0, dw)};
    };
    observe(at(0));
    observe(at(out.time));
    for (const Real& t : times) at_times.push_back(at(t));
    out.distance = at(out.time).distance;
    out.angle = at(out.time).angle;
    return out;
  };
  if (v0 == 0 && w0 == 0) {
    out.terminal = {terminal_regime::pure_spinning, Real(0)};
    return uniform(0, 0, 0);
  }
  if (w0 == 0) {  // pure sliding: 𝓕(∞) = 1, v = v0 − t
    out.time = v0;
    out.terminal = {terminal_regime::pure_sliding, inf};
    return uniform(1, 0, inf);
  }
  if (v0 == 0) {  // pure spinning: 𝓣(0) = ⟨r⟩, ω = ω0 − ⟨r⟩t/γ
    const Real rate = p.mean_radius() / gamma;
    // (γω0)/⟨r⟩, not ω0/rate: ⟨r⟩/γ overflows for a subnormal γ; and where
    // γω0 leaves the normal range, a product without spurious over- or
    // underflow (a subnormal ω0/⟨r⟩ rounded away 20%; found by fuzz_stop_time).
    const Real gw = gamma * w0;
    out.time =
        gw >= boost::math::tools::min_value<Real>() && gw <= boost::math::tools::max_value<Real>()
            ? Real(gw / p.mean_radius())
            : detail::product(gamma, w0, Real(1 / p.mean_radius()));
    out.terminal = {terminal_regime::pure_spinning, Real(0)};
    return uniform(0, rate, 0);
  }
  BOOST_MATH_STD_USING
  using boost::math::tools::max_value;
  using boost::math::tools::min_value;
  // ε0 = v0/ω0 for terminal_motion, kept finite and > 0 where the quotient
  // over- or underflows (only its side of the flow's zeros matters there).
  const Real quotient = v0 / w0;
  out.terminal = terminal_motion(p, gamma,
                                 quotient > max_value<Real>() ? max_value<Real>()
                                 : quotient > 0               ? quotient
                                                              : min_value<Real>());
  const terminal_regime end = out.terminal.regime;
  // The state z = (q, t̂, ŝ, θ̂) as functions of u, in one of two variables:
  //   by spin:  u = −ln(ω/L), q = ln ε,      t = γL t̂,  s = γLM ŝ,  θ = γL² θ̂;
  //   by speed: u = −ln(v/L), q = ln ε̃ = −ln ε, t = L t̂,   s = L² ŝ,   θ = LM θ̂;
  // L and M are the leading and the other motion (ω and v by spin) where the
  // variable starts, q_s the q there and ρ = e^{q − q_s}.  Then
  //   by spin:  dq/du = 1 − γ(𝓕/ε)/𝓣,  t̂′ = e^{−u}/𝓣, ŝ′ = ρe^{−2u}/𝓣, θ̂′ = e^{−2u}/𝓣;
  //   by speed: dq/du = 1 − (ε𝓣/𝓕)/γ,  t̂′ = e^{−u}/𝓕, ŝ′ = e^{−2u}/𝓕,  θ̂′ = ρe^{−2u}/𝓕.
  // The log of the ratio keeps its flow regular where it is fast (dq/du tends
  // to a constant as the ratio tends to 0: for a tiny or huge γ the ratio
  // itself is a stiff equation), and the scales keep every component of z in
  // range for any start the type can hold.  Once both e^q and ρ are 0 to
  // double precision (q below q_floor and below q_s + q_floor), q stops falling.
  using state = std::array<double, 4>;
  const double q_floor = -1000, q_flip = std::log(1e8);
  const double inf_d = std::numeric_limits<double>::infinity();
  bool by_speed = end == terminal_regime::pure_sliding;
  // ln ε0 from the quotient where it is a normal number, else ln v0 − ln ω0.
  double q = static_cast<double>(quotient >= min_value<Real>() && quotient <= max_value<Real>()
                                     ? Real(log(quotient))
                                     : Real(log(v0) - log(w0)));
  if (by_speed) q = -q;
  // The integration starts in the variable whose ratio is at most 10⁸, and
  // switches once if the ratio passes 10⁸ (ε is monotone along the flow).
  if (q > q_flip) {
    by_speed = !by_speed;
    q = -q;
  }
  Real lead = by_speed ? v0 : w0, other = by_speed ? w0 : v0;
  // The state's first component: q; or, for a model whose 𝓕/ε or ε𝓣 has no
  // finite limit (uncoupled_caps: ⟨1/r⟩ = ⟨r²⟩ = ∞), where one motion stops
  // strictly before the other and q would reach −∞ at a finite u, the ratio
  // relative to its start, ρ = r/r_s, with dρ/du = (r − γ𝓕/𝓣)/r_s (by spin)
  // or (r − 𝓣/(γ𝓕))/r_s (by speed), which simply reaches 0 and stays there.
  const bool log_ratio = (boost::math::isfinite)(p.mean_inverse_radius()) &&
                         (boost::math::isfinite)(p.mean_square_radius());
  double r_start = std::exp(q);  // the ratio where the variable starts (≤ 10⁸)
  double z_start = log_ratio ? q : 1.0;
  // ln ρ; −∞ once the ratio is 0.
  auto ln_rho = [&](double z0) {
    return log_ratio ? z0 - z_start : z0 > 0 ? std::log(z0) : -inf_d;
  };
  Real t_off = 0, s_off = 0, th_off = 0;  // t, s, θ where the current variable starts
  auto g_unit = [&] { return by_speed ? Real(1) : gamma; };  // the unit of t̂: γ by spin
  // The ratio e^q, and 0 below the floor or where the type underflows.
  auto ratio_of = [&](double z0) {
    return log_ratio ? (z0 > q_floor ? Real(exp(Real(z0))) : Real(0))
                     : Real(z0 > 0 ? z0 * r_start : 0);
  };
  // The flow's terms at the last state rhs saw, and dq/du there (before any cap).
  detail::flow_terms<Real> now_terms{0, 0, 0, 0};
  Real now_rate = 0;
  auto rhs = [&](const state& z, state& dz, double u) {
    const Real r = ratio_of(z[0]);
    const double decay = std::exp(-u), rho_decay = std::exp(ln_rho(z[0]) - u);
    // 𝓕/ε and 𝓣 at ε (by spin), 𝓕 and ε𝓣 at ε = 1/ε̃ (by speed; the largest
    // value where 1/ε̃ overflows: ∞ is pure sliding, where a model may jump);
    // detail::flow_terms_at supplies their limits.
    const Real eps = !by_speed ? r : r > 0 ? (std::min)(Real(1 / r), max_value<Real>()) : inf;
    const auto ft = detail::flow_terms_at(p, eps);
    now_terms = ft;
    const Real now_a = by_speed ? ft.force : ft.force_over_ratio;
    const Real now_b = by_speed ? ft.ratio_torque : ft.torque;
    const Real rate = by_speed ? 1 - (now_b / now_a) / gamma : 1 - gamma * now_a / now_b;  // dq/du
    const double dt = decay / static_cast<double>(by_speed ? now_a : now_b);  // e^{−u}/𝓕 or /𝓣
    dz[1] = dt;
    dz[2] = dt * (by_speed ? decay : rho_decay);
    dz[3] = dt * (by_speed ? rho_decay : decay);
    // A rate beyond −1e304 (γ within ~1e4 of the ends of its domain) is
    // capped so that a step never takes q to −∞; the part of ŝ or θ̂ it
    // decides is then below 1e-304 of LM.
    now_rate = rate;
    double dq = static_cast<double>(rate);
    if (!(dq >= -1e304)) dq = -1e304;
    if (!log_ratio) {  // dr/du = r − γ𝓕/𝓣 (by spin), r − 𝓣/(γ𝓕) (by speed), 0 once r is 0
      const Real dr = !(r > 0)   ? Real(0)
                      : by_speed ? Real(r - ft.torque / (gamma * ft.force))
                                 : Real(r - gamma * ft.force / ft.torque);
      const double drho = static_cast<double>(dr) / r_start;
      dz[0] = drho >= -1e304 ? drho : -1e304;
    } else {
      dz[0] = z[0] <= q_floor && z[0] <= z_start + q_floor && dq < 0 ? 0.0 : dq;
    }
  };
  // t, s, θ from the scaled state, each a product taken without spurious
  // over- or underflow (γ, L and M may each be near the ends of the type).
  auto time_of = [&](double t_hat) { return t_off + detail::product(g_unit(), lead, Real(t_hat)); };
  auto distance_of = [&](double s_hat) {
    return s_off + (by_speed ? detail::product(lead, lead, Real(s_hat))
                             : detail::product(g_unit(), lead, other, Real(s_hat)));
  };
  auto angle_of = [&](double th_hat) {
    return th_off + (by_speed ? detail::product(lead, other, Real(th_hat))
                              : detail::product(g_unit(), lead, lead, Real(th_hat)));
  };
  auto sample = [&](const state& z, double u) {
    const Real leading = detail::product(lead, Real(exp(-Real(u))));
    const Real following = detail::product(other, Real(exp(Real(ln_rho(z[0])) - Real(u))));
    motion_sample<Real> m;
    m.time = time_of(z[1]);
    m.distance = distance_of(z[2]);
    m.angle = angle_of(z[3]);
    const Real r = ratio_of(z[0]);
    m.spin = by_speed ? following : leading;
    m.speed = by_speed ? leading : following;
    m.ratio = by_speed ? (r > 0 ? Real(1 / r) : inf) : r;
    return m;
  };
  // The stop is only recognised in the variable of the terminal regime's
  // dominant motion (in the other, the remaining motion need not be small).
  auto may_stop = [&] {
    return by_speed ? end != terminal_regime::pure_spinning : end != terminal_regime::pure_sliding;
  };
  // 1e-14, or ten of Real's epsilon: the right-hand side is evaluated in Real,
  // so for float its rounding would otherwise force steps of ~1e-7.
  const double tol =
      (std::max)(1e-14, 10 * static_cast<double>(std::numeric_limits<Real>::epsilon()));
  state z = {z_start, 0, 0, 0};
  auto stepper = make_dense_output(tol, tol, runge_kutta_dopri5<state>());
  stepper.initialize(z, 0.0, 1e-3);
  observe(sample(z, 0.0));
  std::size_t next_time = 0;
  const int max_steps = 100000;
  for (int step = 0; step < max_steps; ++step) {
    stepper.do_step(rhs);
    const state& zc = stepper.current_state();
    const double u = stepper.current_time();
    // The motion at the end of this step: observed, and used by the switch and
    // the stop tests below.
    const motion_sample<Real> now = sample(zc, u);
    // Requested times inside this step: solve t(u) = t_k on the dense output.
    while (next_time < times.size() && times[next_time] <= now.time) {
      const Real tk = times[next_time];
      state zi;
      auto t_of = [&](double uu) {
        stepper.calc_state(uu, zi);
        return static_cast<double>(time_of(zi[1]) - tk);
      };
      double lo = stepper.previous_time(), hi = u;
      if (t_of(lo) < 0 && t_of(hi) > 0) {
        boost::uintmax_t iters = 100;
        const auto r = boost::math::tools::toms748_solve(
            t_of, lo, hi, boost::math::tools::eps_tolerance<double>(50), iters);
        lo = hi = (r.first + r.second) / 2;
      } else if (!(t_of(hi) <= 0)) {
        hi = lo;
      }
      stepper.calc_state(hi, zi);
      motion_sample<Real> m = sample(zi, hi);
      m.time = tk;
      at_times.push_back(m);
      ++next_time;
    }
    observe(now);
    if (log_ratio ? zc[0] > q_flip : ratio_of(zc[0]) > 1e8) {  // continue in the other variable
      t_off = now.time;
      s_off = now.distance;
      th_off = now.angle;
      by_speed = !by_speed;
      lead = by_speed ? now.speed : now.spin;
      other = by_speed ? now.spin : now.speed;
      r_start = 1 / static_cast<double>(ratio_of(zc[0]));
      z = {log_ratio ? -zc[0] : 1.0, 0, 0, 0};
      z_start = z[0];
      stepper.initialize(z, 0.0, 1e-3);
      continue;
    }
    state dz;
    rhs(zc, dz, u);
    auto stop_here = [&](Real t, Real dist, Real angle) {
      out.time = t;
      out.distance = dist;
      out.angle = angle;
      const motion_sample<Real> rest{out.time, 0, 0, out.terminal.ratio, out.distance, out.angle};
      observe(rest);
      for (; next_time < times.size(); ++next_time) {
        motion_sample<Real> m = rest;
        m.time = times[next_time];
        at_times.push_back(m);
      }
      return out;
    };
    // The time integrand decays at least like e^{−u}: stop when the rest is
    // negligible, and add it (in the terminal regime's variable).
    if (may_stop()) {
      if (u > 1 && detail::product(g_unit(), lead, Real(dz[1])) <= Real(1e-18) * now.time)
        return stop_here(time_of(zc[1] + dz[1]), distance_of(zc[2] + dz[2] / 2),
                         angle_of(zc[3] + dz[3] / 2));
      continue;
    }
    // In the other variable: a bound on the remaining time.  ε moves monotonically,
    // so 𝓕 (growing ε) or 𝓣 (falling ε) only grows from here, and both motions
    // stop within v/𝓕 = ω/(𝓕/ε) or γω/𝓣 = γv/(ε𝓣) respectively.  Once that
    // bound, and the distance and angle it allows, are below 1e-18 of their
    // totals (or below the smallest subnormal), stop.  (Where the flow only
    // creeps towards 0 or ∞, at the edges of the inertia window, the switch
    // at 10⁸ may be astronomically far.)  Only magnitudes matter here, so the
    // bound is taken in logs, where neither motion under- or overflows: each
    // is its scale times e^{−u} (leading) or ρe^{−u} (the other).  Each bound
    // is the larger of its two forms (a NaN form is ignored); at a zero of
    // the flow ε stays, and both bounds hold.
    const Real ln_lead = -Real(u), ln_other = Real(ln_rho(zc[0])) - Real(u);
    const Real ln_v = log(by_speed ? lead : other) + (by_speed ? ln_lead : ln_other);
    const Real ln_w = log(by_speed ? other : lead) + (by_speed ? ln_other : ln_lead);
    const auto& ft = now_terms;
    auto larger = [](Real a, Real b) { return a >= b || b != b ? a : b; };
    const Real ln_by_force = larger(ln_v - log(ft.force), ln_w - log(ft.force_over_ratio));
    const Real ln_by_torque =
        log(gamma) + larger(ln_w - log(ft.torque), ln_v - log(ft.ratio_torque));
    const Real ln_left = now_rate == 0 ? (std::min)(ln_by_force, ln_by_torque)
                         : (by_speed ? now_rate < 0 : now_rate > 0) ? ln_by_force
                                                                    : ln_by_torque;
    const Real ln_tiny = log(Real(1e-18)), ln_floor = log(std::numeric_limits<Real>::denorm_min());
    auto negligible = [&](Real ln_part, Real total) {
      return ln_part <= ln_tiny + log(total) || ln_part < ln_floor;
    };
    if (negligible(ln_left, now.time) && negligible(ln_v + ln_left, now.distance) &&
        negligible(ln_w + ln_left, now.angle))
      return stop_here(now.time, now.distance, now.angle);
  }
  out.time = boost::math::policies::raise_evaluation_error<Real>(
      "spinslide::stop_time<%1%>", "No stop found after %1% steps.", Real(max_steps),
      typename Profile::policy_type());
  return out;
}

}  // namespace detail

namespace detail {

// A throw's checks (named after the entry point `function`), then integrate_stop.
template <class Profile, class Real, class Observer>
stop_result<Real> checked_throw_to_stop(const char* function, const Profile& profile,
                                        Real inertia_ratio, Real v0, Real omega0,
                                        Observer observer) {
  static_assert(requires_profile<Profile>());
  const auto in = check_throw(function, inertia_ratio, v0, omega0, typename Profile::policy_type());
  if (!in.valid()) {
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    return {nan, nan, nan, {terminal_regime::sliding_and_spinning, nan}};
  }
  std::vector<Real> none;
  std::vector<motion_sample<Real>> unused;
  return integrate_stop(profile, in.gamma, in.v0, in.omega0, observer, none, unused);
}

}  // namespace detail

/// The throw of a body with `profile` and inertia ratio γ from dimensionless
/// speed v0* and spin ω0* (both ≥ 0): the exact stop time, distance, angle and
/// terminal regime.  `observer(motion_sample)` is called at every adaptive
/// step (dimensionless), and at the stop.  Bad input is a domain error: γ not
/// in [min_value, max_value·epsilon] (2e-308 to 4e292 for double), or a speed
/// that is negative or not finite.
template <class Profile, class Real, class Observer>
stop_result<Real> simulate_throw(const Profile& profile, Real inertia_ratio, Real v0, Real omega0,
                                 Observer observer) {
  return detail::checked_throw_to_stop("spinslide::simulate_throw<%1%>(profile, %1%, %1%, %1%)",
                                       profile, inertia_ratio, v0, omega0, observer);
}

/// The trajectory of a throw sampled at the given times (dimensionless,
/// sorted ascending, ≥ 0); samples at or after the stop are the rest state.
template <class Profile, class Real>
std::vector<motion_sample<Real>> trajectory(const Profile& profile, Real inertia_ratio, Real v0,
                                            Real omega0, const std::vector<Real>& times) {
  static_assert(detail::requires_profile<Profile>());
  using Policy = typename Profile::policy_type;
  static const char* function = "spinslide::trajectory<%1%>(profile, %1%, %1%, %1%, times)";
  const auto in = detail::check_throw(function, inertia_ratio, v0, omega0, Policy());
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!(times[i] >= 0) || (i > 0 && times[i] < times[i - 1]))
      detail::raise_argument_error(function, "a time", ">= 0 and not below the time before it",
                                   times[i], Policy());
  }
  std::vector<motion_sample<Real>> samples;
  if (!in.valid()) {
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    samples.assign(times.size(), motion_sample<Real>{nan, nan, nan, nan, nan, nan});
    return samples;
  }
  samples.reserve(times.size());
  detail::integrate_stop(
      profile, in.gamma, in.v0, in.omega0, [](const motion_sample<Real>&) {}, times, samples);
  return samples;
}

/// simulate_throw without an observer.
template <class Profile, class Real>
stop_result<Real> simulate_throw(const Profile& profile, Real inertia_ratio, Real v0, Real omega0) {
  return simulate_throw(profile, inertia_ratio, v0, omega0, [](const motion_sample<Real>&) {});
}

/// A throw in SI units: radius R [m], friction coefficient μ, gravity g
/// [m/s²], γ = I/(mR²), speed v0 [m/s] and spin ω0 [rad/s] (both ≥ 0).
/// Returns the stop time [s], distance [m] and angle [rad].  Bad input
/// (R, μ, g not finite and > 0, γ as for simulate_throw, negative or NaN
/// speeds) is a domain error.
template <class Profile, class Real>
stop_result<Real> simulate_throw_si(const Profile& profile, Real radius, Real friction_coefficient,
                                    Real gravity, Real inertia_ratio, Real v0, Real omega0) {
  using Policy = typename Profile::policy_type;
  using detail::argument_rule;
  static const char* function =
      "spinslide::simulate_throw_si<%1%>(profile, %1%, %1%, %1%, %1%, %1%, %1%)";
  const si_units<Real> units{
      detail::checked(function, "radius", radius, argument_rule::finite_positive, Policy()),
      detail::checked(function, "friction_coefficient", friction_coefficient,
                      argument_rule::finite_positive, Policy()),
      detail::checked(function, "gravity", gravity, argument_rule::finite_positive, Policy())};
  const auto in = detail::check_throw(function, inertia_ratio, v0, omega0, Policy());
  if (detail::any_reported(units.radius, units.friction_coefficient, units.gravity) ||
      !in.valid()) {
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    return {nan, nan, nan, {terminal_regime::sliding_and_spinning, nan}};
  }
  stop_result<Real> r = simulate_throw(profile, in.gamma, in.v0 / units.velocity_scale(),
                                       in.omega0 / units.spin_scale());
  r.time *= units.time_scale();
  r.distance *= units.distance_scale();
  r.angle *= units.angle_scale();
  return r;
}

/// Dimensionless stop time t* of a throw (v0*, ω0*) for any profile and γ.
template <class Profile, class Real>
Real stop_time(const Profile& profile, Real inertia_ratio, Real v0, Real omega0) {
  return detail::checked_throw_to_stop("spinslide::stop_time<%1%>(profile, %1%, %1%, %1%)", profile,
                                       inertia_ratio, v0, omega0, [](const motion_sample<Real>&) {})
      .time;
}

}  // namespace spinslide

#endif  // SPINSLIDE_DYNAMICS_HPP
