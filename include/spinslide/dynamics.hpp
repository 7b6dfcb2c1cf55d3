//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file dynamics.hpp
/// Equations of motion of a body sliding and spinning on a flat contact, in
/// the paper's dimensionless units and in SI, as an odeint system; and
/// spinslide's own integration through the singular stop, with the exact
/// stop time, distance and rotation (docs/theory.md §9).
///
/// Dimensionless units (the paper's): v* = v/(μ√(gR)), ω* = ω√(R/g)/μ,
/// t* = t√(g/R); then distance s = μR s* and angle θ = μ θ*.  γ = I/(mR²).

#ifndef SPINSLIDE_DYNAMICS_HPP
#define SPINSLIDE_DYNAMICS_HPP

#include <spinslide/detail/piecewise_chebyshev.hpp>
#include <spinslide/terminal.hpp>

#include <boost/math/tools/toms748_solve.hpp>
#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace spinslide {

/// The state the systems below integrate: {v, ω, s, θ} (speed, spin, distance
/// slid, angle turned), dimensionless or SI according to the system.
template <class Real>
using motion_state = std::array<Real, 4>;

namespace detail {

template <class Real, class Policy>
Real checked_positive(Real x, const char* function, const char* message, const Policy& pol) {
  if (!(x > 0) || !(boost::math::isfinite)(x))
    return boost::math::policies::raise_domain_error<Real>(function, message, x, pol);
  return x;
}

template <class Real, class Policy>
Real checked_speed(Real x, const char* function, const char* message, const Policy& pol) {
  if (!(x >= 0) || !(boost::math::isfinite)(x))
    return boost::math::policies::raise_domain_error<Real>(function, message, x, pol);
  return x;
}

template <class Real>
struct throw_input {
  Real gamma, v0, omega0;
  // False once a check has reported an error through a policy that does not
  // throw (errno_on_error, ignore_error): the entry point then returns NaN
  // instead of computing on, and reporting a second, different error.
  bool valid() const {
    return !(boost::math::isnan)(gamma) && !(boost::math::isnan)(v0) &&
           !(boost::math::isnan)(omega0);
  }
};

// γ for the integration to the stop: a normal number (≥ min_value) and at
// most max_value·epsilon (4e292 for double; a real body has γ of order 1).
// Above, the rates γ𝓕/𝓣 and γ/𝓣 overflow during the integration; below, γ
// has too few digits (both found by fuzz_stop_time).
template <class Real, class Policy>
Real checked_throw_inertia(Real gamma, const char* function, const Policy& pol) {
  if (!(gamma >= boost::math::tools::min_value<Real>()) ||
      !(gamma <= boost::math::tools::max_value<Real>() * boost::math::tools::epsilon<Real>()))
    return boost::math::policies::raise_domain_error<Real>(
        function, "Got inertia_ratio = %1%, but gamma must be in [min_value, max_value*epsilon].",
        gamma, pol);
  return gamma;
}

// The checks every throw entry point makes: γ as above, speeds finite and
// >= 0; otherwise a domain error naming `function`.
template <class Real, class Policy>
throw_input<Real> checked_throw(const char* function, Real gamma, Real v0, Real omega0,
                                const Policy& pol) {
  return {
      checked_throw_inertia(gamma, function, pol),
      checked_speed(v0, function, "Got v0 = %1%, but it must be finite and >= 0.", pol),
      checked_speed(omega0, function, "Got omega0 = %1%, but it must be finite and >= 0.", pol)};
}

}  // namespace detail

/// The paper's equations in dimensionless form, generalised to any profile
/// and γ:  dv*/dt* = −𝓕(ε), dω*/dt* = −𝓣(ε)/γ, ds*/dt* = v*, dθ*/dt* = ω*,
/// ε = v*/ω*.  An odeint system: sys(x, dxdt, t).  Pure sliding (ω* = 0) and
/// pure spinning (v* = 0) are handled exactly; at rest, or if a stepper
/// overshoots below zero, the friction vanishes (the body stays at rest).
template <class Profile>
class dimensionless_motion {
 public:
  /// The profile's floating-point type.
  using Real = typename Profile::value_type;

  /// The system for `profile` and γ = `inertia_ratio` (finite and > 0,
  /// otherwise a domain error).
  dimensionless_motion(Profile profile, Real inertia_ratio)
      : profile_(std::move(profile)),
        gamma_(
            detail::checked_positive(inertia_ratio, "spinslide::dimensionless_motion<%1%>",
                                     "Got inertia_ratio = %1%, but gamma must be finite and > 0.",
                                     typename Profile::policy_type())) {}

  /// odeint's system call: x = {v*, ω*, s*, θ*} → dx/dt* =
  /// {−𝓕(ε), −𝓣(ε)/γ, v*, ω*}, ε = v*/ω*; a speed that overshot below 0
  /// counts as 0 (then no friction on it).  Never throws for finite x.
  template <class State, class Time>
  void operator()(const State& x, State& dxdt, Time) const {
    const Real v = x[0] > 0 ? Real(x[0]) : Real(0);
    const Real w = x[1] > 0 ? Real(x[1]) : Real(0);
    Real F = 0, T = 0;
    if (v > 0 && w > 0) {
      const auto ft = profile_.force_torque(v / w);
      F = ft.force;
      T = ft.torque;
    } else if (v > 0) {
      F = 1;  // pure sliding
    } else if (w > 0) {
      T = profile_.mean_radius();  // pure spinning
    }
    dxdt[0] = -F;
    dxdt[1] = -T / gamma_;
    dxdt[2] = v;
    dxdt[3] = w;
  }

  /// The profile.
  const Profile& profile() const { return profile_; }
  /// γ.
  Real inertia_ratio() const { return gamma_; }

 private:
  Profile profile_;
  Real gamma_;
};

/// The same in SI units: dv/dt = −μg𝓕, dω/dt = −μg𝓣/(γR), ds/dt = v, dθ/dt = ω;
/// v in m/s, ω in rad/s, s in m, θ in rad, t in s.  No mass is needed.
template <class Profile>
class si_motion {
 public:
  /// The profile's floating-point type.
  using Real = typename Profile::value_type;

  /// radius R [m], friction coefficient μ, gravity g [m/s²], γ = I/(mR²).
  si_motion(Profile profile, Real radius, Real friction_coefficient, Real gravity,
            Real inertia_ratio)
      : scaled_(std::move(profile), inertia_ratio),
        R_(check(radius, "Got radius = %1%, but it must be finite and > 0.")),
        mu_(check(friction_coefficient,
                  "Got friction_coefficient = %1%, but it must be finite and > 0.")),
        g_(check(gravity, "Got gravity = %1%, but it must be finite and > 0.")) {}

  /// odeint's system call: x = {v, ω, s, θ} (SI) → dx/dt =
  /// {−μg𝓕(ε), −μg𝓣(ε)/(γR), v, ω}, ε = v/(Rω).  Never throws for finite x.
  template <class State, class Time>
  void operator()(const State& x, State& dxdt, Time t) const {
    State xs = x;
    xs[0] = x[0] / velocity_scale();
    xs[1] = x[1] / spin_scale();
    State d = dxdt;
    scaled_(xs, d, t);
    dxdt[0] = d[0] * mu_ * g_;
    dxdt[1] = d[1] * mu_ * g_ / R_;
    dxdt[2] = x[0];
    dxdt[3] = x[1];
  }

  /// v = v*·μ√(gR), ω = ω*·μ√(g/R), t = t*·√(R/g), s = s*·μR, θ = θ*·μ.
  Real velocity_scale() const { return mu_ * sqrt_(g_ * R_); }
  /// μ√(g/R) [rad/s per unit ω*].
  Real spin_scale() const { return mu_ * sqrt_(g_ / R_); }
  /// √(R/g) [s per unit t*].
  Real time_scale() const { return sqrt_(R_ / g_); }
  /// μR [m per unit s*].
  Real distance_scale() const { return mu_ * R_; }
  /// μ [rad per unit θ*].
  Real angle_scale() const { return mu_; }
  /// The same motion in the paper's units.
  const dimensionless_motion<Profile>& dimensionless() const { return scaled_; }

 private:
  static Real sqrt_(Real x) {
    BOOST_MATH_STD_USING
    return sqrt(x);
  }
  static Real check(Real x, const char* message) {
    return detail::checked_positive(x, "spinslide::si_motion<%1%>", message,
                                    typename Profile::policy_type());
  }
  dimensionless_motion<Profile> scaled_;
  Real R_, mu_, g_;
};

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

// spinslide's integration through the stop (docs/theory.md §9).  In the
// regimes that end with a finite or vanishing ratio it integrates in
// x = −ln ω*, where dε/dx = f(ε) and
//   dt/dx = γe^{−x}/𝓣,  ds/dx = γεe^{−2x}/𝓣,  dθ/dx = γe^{−2x}/𝓣,
// and in the pure-sliding regime in y = −ln v* with ε̃ = ω*/v*:
//   dε̃/dy = ε̃ − 𝓣/(γ𝓕),  dt/dy = e^{−y}/𝓕,  ds/dy = e^{−2y}/𝓕,  dθ/dy = ε̃e^{−2y}/𝓕.
// Both are regular up to the stop (x, y → ∞).  The state is integrated
// relative to the start (u = x − x₀), so e^{−u} ≤ 1, and stops once the time
// integrand is below 1e-18 of the accumulated time; the remaining tail is
// added from the current rate.  Work is bounded: u grows by at least the
// integrand's decay, which is exponential in every regime.
//
// `times` (sorted, may be empty): the trajectory is also sampled at these
// times into `at_times`, by inverting t(u) on the dense output with TOMS 748;
// times at or after the stop give the rest state.
template <class Profile, class Observer>
stop_result<typename Profile::value_type> integrate_stop(
    const Profile& p, typename Profile::value_type gamma, typename Profile::value_type v0,
    typename Profile::value_type w0, Observer observe,
    const std::vector<typename Profile::value_type>& times,
    std::vector<motion_sample<typename Profile::value_type>>& at_times) {
  using Real = typename Profile::value_type;
  using boost::numeric::odeint::integrate_adaptive;
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
    // γ ω0/⟨r⟩, not ω0/rate: ⟨r⟩/γ overflows for a subnormal γ (found by
    // fuzz_stop_time); γ ω0 first where ω0/⟨r⟩ overflows.
    const Real per_r = w0 / p.mean_radius();
    out.time =
        (boost::math::isfinite)(per_r) ? Real(gamma * per_r) : Real(gamma * w0 / p.mean_radius());
    out.terminal = {terminal_regime::pure_spinning, Real(0)};
    return uniform(0, rate, 0);
  }
  const Real eps0 = v0 / w0;
  out.terminal = terminal_motion(p, gamma, eps0);
  const bool by_speed = out.terminal.regime == terminal_regime::pure_sliding;
  // z = (ratio, t, s, θ) as functions of u; ratio is ε (by spin) or ε̃ = 1/ε (by speed).
  using state = std::array<double, 4>;
  const Real scale = by_speed ? v0 : w0;  // e^{−x₀} or e^{−y₀}
  // Integrated in units of the start: t̂ = t/scale, ŝ = s/scale², θ̂ = θ/scale²,
  // so that the stepper's tolerances are relative to O(1) quantities.
  auto rhs = [&](const state& z, state& dz, double u) {
    const Real r = z[0] > 0 ? Real(z[0]) : Real(0);
    const Real decay = Real(std::exp(-u));
    if (!by_speed) {
      const auto ft = r > 0 ? p.force_torque(r) : force_torque_result<Real>{0, p.mean_radius()};
      dz[0] = static_cast<double>(r > 0 ? Real(r - gamma * ft.force / ft.torque) : Real(0));
      const Real dt = gamma * decay / ft.torque;
      dz[1] = static_cast<double>(dt);
      dz[2] = static_cast<double>(dt * r * decay);
      dz[3] = static_cast<double>(dt * decay);
    } else {
      // ε̃ = r; 𝓕 and 𝓣 at ε = 1/ε̃ (ε̃ = 0 is pure sliding).
      const auto ft = r > 0 ? p.force_torque(1 / r) : force_torque_result<Real>{1, 0};
      dz[0] = static_cast<double>(r > 0 ? Real(r - ft.torque / (gamma * ft.force)) : Real(0));
      const Real dt = decay / ft.force;
      dz[1] = static_cast<double>(dt);
      dz[2] = static_cast<double>(dt * decay);
      dz[3] = static_cast<double>(dt * r * decay);
    }
  };
  auto sample = [&](const state& z, double u) {
    const Real decay = scale * Real(std::exp(-u));
    const Real r = Real(z[0]);
    motion_sample<Real> m;
    m.time = scale * Real(z[1]);
    // scale (scale z), not scale² z: scale² overflows where z is 0 (∞ · 0).
    m.distance = scale * (scale * Real(z[2]));
    m.angle = scale * (scale * Real(z[3]));
    if (!by_speed) {
      m.spin = decay;
      m.ratio = r;
      m.speed = r * decay;
    } else {
      m.speed = decay;
      m.ratio = r > 0 ? Real(1 / r) : inf;
      m.spin = r * decay;
    }
    return m;
  };
  state z = {static_cast<double>(by_speed ? Real(1 / eps0) : eps0), 0, 0, 0};
  auto stepper = make_dense_output(1e-14, 1e-14, runge_kutta_dopri5<state>());
  stepper.initialize(z, 0.0, 1e-3);
  observe(sample(z, 0.0));
  std::size_t next_time = 0;
  const int max_steps = 100000;
  for (int step = 0; step < max_steps; ++step) {
    stepper.do_step(rhs);
    const state& zc = stepper.current_state();
    const double u = stepper.current_time();
    // Requested times inside this step: solve t(u) = t_k on the dense output.
    while (next_time < times.size() && times[next_time] <= scale * Real(zc[1])) {
      const double tk = static_cast<double>(times[next_time] / scale);
      state zi;
      auto t_of = [&](double uu) {
        stepper.calc_state(uu, zi);
        return zi[1] - tk;
      };
      double lo = stepper.previous_time(), hi = u;
      if (tk <= 0) {
        lo = hi = 0;
      } else if (t_of(lo) < 0 && t_of(hi) > 0) {
        boost::uintmax_t iters = 100;
        const auto r = boost::math::tools::toms748_solve(
            t_of, lo, hi, boost::math::tools::eps_tolerance<double>(50), iters);
        lo = hi = (r.first + r.second) / 2;
      }
      stepper.calc_state(hi, zi);
      motion_sample<Real> m = sample(zi, hi);
      m.time = times[next_time];
      at_times.push_back(m);
      ++next_time;
    }
    observe(sample(zc, u));
    state dz;
    rhs(zc, dz, u);
    // The time integrand decays at least like e^{−u}: stop when the rest is negligible.
    if (dz[1] <= 1e-18 * zc[1] && u > 1) {
      out.time = scale * (Real(zc[1]) + Real(dz[1]));
      out.distance = scale * (scale * (Real(zc[2]) + Real(dz[2]) / 2));
      out.angle = scale * (scale * (Real(zc[3]) + Real(dz[3]) / 2));
      const motion_sample<Real> rest{out.time, 0, 0, out.terminal.ratio, out.distance, out.angle};
      observe(rest);
      for (; next_time < times.size(); ++next_time) {
        motion_sample<Real> m = rest;
        m.time = times[next_time];
        at_times.push_back(m);
      }
      return out;
    }
  }
  out.time = boost::math::policies::raise_evaluation_error<Real>(
      "spinslide::stop_time<%1%>", "No stop found after %1% steps.", Real(max_steps),
      typename Profile::policy_type());
  return out;
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
  const auto in = detail::checked_throw("spinslide::simulate_throw<%1%>", inertia_ratio, v0, omega0,
                                        typename Profile::policy_type());
  if (!in.valid()) {
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    return {nan, nan, nan, {terminal_regime::sliding_and_spinning, nan}};
  }
  std::vector<Real> none;
  std::vector<motion_sample<Real>> unused;
  return detail::integrate_stop(profile, in.gamma, in.v0, in.omega0, observer, none, unused);
}

/// The trajectory of a throw sampled at the given times (dimensionless,
/// sorted ascending, ≥ 0); samples at or after the stop are the rest state.
template <class Profile, class Real>
std::vector<motion_sample<Real>> trajectory(const Profile& profile, Real inertia_ratio, Real v0,
                                            Real omega0, const std::vector<Real>& times) {
  using Policy = typename Profile::policy_type;
  static const char* function = "spinslide::trajectory<%1%>";
  const auto in = detail::checked_throw(function, inertia_ratio, v0, omega0, Policy());
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!(times[i] >= 0) || (i > 0 && times[i] < times[i - 1]))
      boost::math::policies::raise_domain_error<Real>(
          function, "Got time %1%: the times must be >= 0, finite and sorted ascending.", times[i],
          Policy());
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
  static const char* function = "spinslide::simulate_throw_si<%1%>";
  const Real R = detail::checked_positive(
      radius, function, "Got radius = %1%, but it must be finite and > 0.", Policy());
  const Real mu = detail::checked_positive(
      friction_coefficient, function,
      "Got friction_coefficient = %1%, but it must be finite and > 0.", Policy());
  const Real g = detail::checked_positive(
      gravity, function, "Got gravity = %1%, but it must be finite and > 0.", Policy());
  const si_motion<Profile> units(profile, R, mu, g, inertia_ratio);
  const Real v = detail::checked_speed(v0, function,
                                       "Got v0 = %1%, but it must be finite and >= 0.", Policy());
  const Real w = detail::checked_speed(
      omega0, function, "Got omega0 = %1%, but it must be finite and >= 0.", Policy());
  stop_result<Real> r =
      simulate_throw(profile, inertia_ratio, v / units.velocity_scale(), w / units.spin_scale());
  r.time *= units.time_scale();
  r.distance *= units.distance_scale();
  r.angle *= units.angle_scale();
  return r;
}

/// Dimensionless stop time t* of a throw (v0*, ω0*) for any profile and γ.
template <class Profile, class Real>
Real stop_time(const Profile& profile, Real inertia_ratio, Real v0, Real omega0) {
  return simulate_throw(profile, inertia_ratio, v0, omega0).time;
}

/// Stop times and distances of every throw of one (profile, γ), precomputed.
/// The flow depends on ε only, so t*(v0, ω0) = ω0 P(ε) and s*(v0, ω0) = ω0² S(ε)
/// with ε = v0/ω0 (docs/theory.md §9).  With t = ε/(1+ε) the bounded functions
///   P(ε)/(1+ε)   (→ γ/⟨r⟩ at ε = 0, → 1 at ε = ∞) and
///   S(ε)/(1+ε)²  (→ 0 at ε = 0,     → 1/2 at ε = ∞)
/// are tabulated with the machinery of tabulated_profile (sampled by
/// simulate_throw, ~1e-14), so a throw then costs one table lookup.  Measured:
/// stop times within 4e-14 of the integration; distances within ~1e-9 (their
/// table resolves the ε = 1 kink of ring-like profiles less well).
/// Construction takes a few thousand throws (about a second); calls are
/// allocation-free and thread-safe.
template <class Profile>
class tabulated_throw {
 public:
  /// The profile's floating-point type.
  using Real = typename Profile::value_type;

  /// Tabulates the throws of `profile` with γ = `inertia_ratio` (in
  /// [min_value, max_value·epsilon], otherwise a domain error); about a
  /// second, allocates.
  tabulated_throw(const Profile& profile, Real inertia_ratio)
      : gamma_(detail::checked_throw_inertia(inertia_ratio, "spinslide::tabulated_throw<%1%>",
                                             typename Profile::policy_type())),
        spin_rate_(profile.mean_radius() / gamma_) {
    auto g = [&](double t) {
      const double eps = t / (1 - t);
      const auto r = simulate_throw(profile, gamma_, Real(eps), Real(1));
      const double s = 1 + eps;
      return std::make_pair(static_cast<double>(r.time) / s,
                            static_cast<double>(r.distance) / (s * s));
    };
    table_ = detail::piecewise_chebyshev_pair<double, 8>(g, 1e-13, 16);
  }

  /// t*(v0, ω0); bad input is a domain error, ω0 = 0 is exact (t* = v0).
  Real stop_time(Real v0, Real omega0) const { return evaluate(v0, omega0).first; }
  /// s*(v0, ω0): the distance slid.
  Real distance(Real v0, Real omega0) const { return evaluate(v0, omega0).second; }
  /// The number of Chebyshev pieces of the table.
  std::size_t pieces() const { return table_.size(); }

 private:
  std::pair<Real, Real> evaluate(Real v0, Real w0) const {
    static const char* function = "spinslide::tabulated_throw<%1%>";
    using Policy = typename Profile::policy_type;
    v0 = detail::checked_speed(v0, function, "Got v0 = %1%, but it must be finite and >= 0.",
                               Policy());
    w0 = detail::checked_speed(w0, function, "Got omega0 = %1%, but it must be finite and >= 0.",
                               Policy());
    if ((boost::math::isnan)(v0) || (boost::math::isnan)(w0)) return {v0 + w0, v0 + w0};
    if (w0 == 0) return {v0, v0 * v0 / 2};           // pure sliding, exact
    if (v0 == 0) return {w0 / spin_rate_, Real(0)};  // pure spinning, exact
    const Real s = v0 + w0;                          // ω0 (1 + ε)
    const auto g = table_(static_cast<double>(v0 / s));
    // The table's error near ε = 0 is ~1e-18 absolute, so g can come out just
    // below 0 where the distance is tiny: clamp it (the exact g is > 0).  And
    // s (s g) rather than s² g, with g = 0 giving 0: s² overflows first, and
    // ∞ · 0 would be NaN (both found by fuzz_stop_time).
    const Real gd = (std::max)(Real(g.second), Real(0));
    const Real d = gd == 0 ? Real(0) : Real(s * (s * gd));
    return {s * Real(g.first), d};
  }
  Real gamma_, spin_rate_;
  detail::piecewise_chebyshev_pair<double, 8> table_;
};

/// Dimensionless stop time t* of the paper's disk (uniform, γ = 1/2).  In
/// double it uses a tabulated_throw built on first use (thread-safe static);
/// other types integrate.
template <class Real>
Real stop_time(Real v0, Real omega0) {
  if constexpr (std::is_same<Real, double>::value) {
    // Check before the one-time build, so that bad input fails fast.
    detail::checked_throw("spinslide::stop_time<%1%>(%1%, %1%)", 0.5, v0, omega0,
                          boost::math::policies::policy<>());
    static const tabulated_throw<uniform_disk<double>> table(uniform_disk<double>(), 0.5);
    return table.stop_time(v0, omega0);
  } else {
    return stop_time(uniform_disk<Real>(), Real(0.5), v0, omega0);
  }
}

}  // namespace spinslide

#endif  // SPINSLIDE_DYNAMICS_HPP
