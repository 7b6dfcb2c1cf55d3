//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
/// \file spinslide_contact.h
/// The per-contact law shared by the pair style granular/spinslide (sphere
/// against sphere) and the fix wall/gran/spinslide (sphere against a wall,
/// a body of infinite radius and mass): Hertz with viscoelastic damping, a
/// Mindlin tangential spring and a Marshall twisting spring with their
/// damping, capped together on spinslide's Hertz limit set or independently,
/// and the update of the contact's history.
///
/// Per contact and step, with n the unit normal from the partner to the
/// sphere, d the overlap, R* the effective radius, m* the effective mass and
/// a = sqrt(R* d) the patch radius:
///
///   normal     F_n = kn d a - eta_n a m* v_n              (Hertz, kn = (4/3) E*)
///   tangential F_t = -k_t xi - x_gt eta_n a m* v_t,       k_t = kt a  (kt = 8 G*)
///   twisting   M   = -k_w phi - (x_gt eta_n a m* a^2/2) w_n,  k_w = k_t a^2/2
///
/// xi is the tangential spring (kept in the contact's tangent plane, its
/// length preserved as the plane turns), phi the twisting spring, v_t the
/// slip velocity at the contact and w_n the relative spin about n; the
/// springs are stretched by v_t dt and w_n dt each step.  The trial friction
/// (F_t, M) is capped at the load mu |F_n|:
///
///   independent: |F_t| <= mu |F_n| and |M| <= (2/3) a mu |F_n| separately
///                (LAMMPS' `tangential mindlin NULL x_gt mu twisting
///                marshall`, the same arithmetic in the same order);
///   coupled:     (F_t, M) in mu |F_n| L, L spinslide's exact limit set of a
///                Hertzian patch: outside it, the trial is replaced by its
///                nearest point of mu |F_n| L in the springs' energy metric
///                |dF|^2/k_t + |dM|^2/k_w.
///
/// When capped, the springs are rewritten so that spring + damping equals the
/// capped friction.  engines/lammps/README.md documents the model.

#ifndef SPINSLIDE_LAMMPS_SPINSLIDE_CONTACT_H
#define SPINSLIDE_LAMMPS_SPINSLIDE_CONTACT_H

#include "error.h"

#include <spinslide/profile.hpp>
#include <spinslide/trial_cap.hpp>

#include <array>
#include <cmath>
#include <exception>
#include <limits>

namespace spinslide_lammps {

/// The history of one contact, in this order.
enum : int {
  kHistShear = 0,    ///< tangential spring displacement, 3 components (lab frame)
  kHistTwist = 3,    ///< twisting spring angle
  kHistRatio = 4,    ///< where the last slip left the limit curve (a spinslide::curve_point):
                     ///< eps (0: none), then F, T, F' and F'' there, the warm start
  kHistSliding = 9,  ///< 1 if the last force computation capped the contact (its
                     ///< sliding state, for compute pair/local), else 0
  kHistSize = 10
};

/// The effective Young's modulus E* of two materials (Hertz).
inline double effective_youngs(double e1, double nu1, double e2, double nu2) {
  return 1 / ((1 - nu1 * nu1) / e1 + (1 - nu2 * nu2) / e2);
}
/// The effective shear modulus G* of two materials (Mindlin).
inline double effective_shear(double e1, double nu1, double e2, double nu2) {
  return 1 / ((2 * (2 - nu1) * (1 + nu1) / e1) + (2 * (2 - nu2) * (1 + nu2) / e2));
}

/// The constants of one pair of materials.
struct ContactLaw {
  double kn = 0.0;             ///< (4/3) E*: F_n = kn d a
  double kt = 0.0;             ///< 8 G*: k_t = kt a
  double eta_n = 0.0;          ///< viscoelastic normal damping: gamma_n = eta_n a m*
  double xgammat = 1.0;        ///< gamma_t = xgammat gamma_n
  double mu = 0.0;             ///< friction coefficient
  bool limit_damping = false;  ///< the normal force not below 0 (LAMMPS' limit_damping)
  bool tsuji = false;          ///< eta_n is Tsuji's alpha(e): gamma_n = alpha sqrt(m* kn a)
};

/// Tsuji's damping coefficient alpha for a coefficient of restitution e
/// (Tsuji, Tanaka and Ishida 1992, the polynomial fit LAMMPS' `damping
/// tsuji` uses), evaluated with the same products as LAMMPS' pair granular
/// (e^4 = (e e)(e e), e^5 = e e^4, e^6 = (e e) e^4), so that the two agree
/// to the last bit.
inline double tsuji_alpha(double e) {
  const double e2 = e * e, e3 = e2 * e, e4 = e2 * e2, e5 = e * e4, e6 = e2 * e4;
  return 1.2728 - 4.2783 * e + 11.087 * e2 - 22.348 * e3 + 27.467 * e4 - 18.022 * e5 + 4.8218 * e6;
}

/// The same fit with the powers by std::pow, as LAMMPS' fix wall/gran
/// evaluates it (the last bits may differ from tsuji_alpha; each reproduces
/// its own LAMMPS style).
inline double tsuji_alpha_by_pow(double e) {
  return 1.2728 - 4.2783 * e + 11.087 * std::pow(e, 2) - 22.348 * std::pow(e, 3) +
         27.467 * std::pow(e, 4) - 18.022 * std::pow(e, 5) + 4.8218 * std::pow(e, 6);
}

/// One contact's geometry and relative motion, seen from the sphere.
struct ContactState {
  double n[3];        ///< unit normal, from the partner to the sphere
  double delta;       ///< overlap
  double reff;        ///< effective radius R* (a wall: the sphere's radius)
  double meff;        ///< effective mass m* (a wall: the sphere's mass)
  double vr[3];       ///< velocity of the sphere's centre relative to the partner's
  double wr[3];       ///< r_i w_i + r_j w_j (a wall: r_i w_i)
  double twist_rate;  ///< (w_i - w_j).n (a wall: w_i.n)
};

/// The slip velocity at the contact point: the tangential relative velocity
/// minus the surfaces' rotation (r_i w_i + r_j w_j) x n.
inline void slip_velocity(const ContactState& s, double vtr[3]) {
  const double nx = s.n[0], ny = s.n[1], nz = s.n[2];
  const double vnnr = s.vr[0] * nx + s.vr[1] * ny + s.vr[2] * nz;
  const double wr1 = s.wr[0], wr2 = s.wr[1], wr3 = s.wr[2];
  vtr[0] = s.vr[0] - nx * vnnr - (nz * wr2 - ny * wr3);
  vtr[1] = s.vr[1] - ny * vnnr - (nx * wr3 - nz * wr1);
  vtr[2] = s.vr[2] - nz * vnnr - (ny * wr1 - nx * wr2);
}

/// The contact's ratio eps = |v_slip|/(a |w_n|), a = sqrt(delta R*): +inf
/// without relative spin, 0 at rest.
inline double slip_ratio(const ContactState& s) {
  double vtr[3];
  slip_velocity(s, vtr);
  const double slip = std::sqrt(vtr[0] * vtr[0] + vtr[1] * vtr[1] + vtr[2] * vtr[2]);
  const double spin = std::sqrt(s.delta * s.reff) * std::fabs(s.twist_rate);
  if (slip == 0.0) return 0.0;
  return spin > 0.0 ? slip / spin : std::numeric_limits<double>::infinity();
}

/// The forces on the sphere (the partner takes the opposite ones).
struct ContactForce {
  double fn;     ///< normal force, along n
  double fs[3];  ///< friction force
  double mt;     ///< twisting torque about n
  double a;      ///< patch radius
  bool capped;   ///< at the friction limit (sliding)
};

namespace detail {

// A spring's trial state is turned into the contact's plane only when its
// normal component matters against the friction limit (relative threshold).
constexpr double kFrameTolerance = 1e-10;

inline const spinslide::hertz<double>& hertz_patch() {
  static const spinslide::hertz<double> patch{};
  return patch;
}

// Independent caps (pair_style granular's and fix wall/gran's mindlin +
// marshall): the springs h (already rotated and stretched) in, the friction
// force fs and twisting torque mt out; true if capped.
inline bool friction_uncoupled(double* h, const double* vtr, double twist_rate, double kt,
                               double damp_t, double k_tw, double damp_tw, double fscrit,
                               double mtcrit, double* fs, double& mt) {
  bool capped = false;
  fs[0] = -kt * h[0] - damp_t * vtr[0];
  fs[1] = -kt * h[1] - damp_t * vtr[1];
  fs[2] = -kt * h[2] - damp_t * vtr[2];
  const double fmag = std::sqrt(fs[0] * fs[0] + fs[1] * fs[1] + fs[2] * fs[2]);
  if (fmag > fscrit) {
    capped = true;
    const double hmag = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    if (hmag != 0.0) {
      // the spring that, with the damping, gives the capped force
      for (int k = 0; k < 3; ++k) h[k] = -1.0 / kt * (fscrit * fs[k] / fmag + damp_t * vtr[k]);
      const double scale = fscrit / fmag;
      fs[0] *= scale;
      fs[1] *= scale;
      fs[2] *= scale;
    } else {
      fs[0] = fs[1] = fs[2] = 0.0;
    }
  }

  mt = -k_tw * h[kHistTwist] - damp_tw * twist_rate;
  if (std::fabs(mt) > mtcrit) {
    capped = true;
    // LAMMPS caps against the spin's direction, not the trial's
    const double spin_sign = (twist_rate > 0) - (twist_rate < 0);
    h[kHistTwist] = 1.0 / k_tw * (mtcrit * spin_sign - damp_tw * twist_rate);
    mt = -mtcrit * spin_sign;
  }
  return capped;
}

// The history's curve point (kHistRatio and the four values after it).
inline void store_curve_point(const spinslide::curve_point<double>& p, double* h) {
  h[kHistRatio] = p.ratio;
  h[kHistRatio + 1] = p.force;
  h[kHistRatio + 2] = p.torque;
  h[kHistRatio + 3] = p.slope;
  h[kHistRatio + 4] = p.curvature;
}

// The coupled cap on spinslide's Hertz limit set, at the load `load` = mu N
// with patch radius a: spinslide::cap_trial_state (trial_cap.hpp) on the
// springs h (already rotated and stretched) and the damping, which keeps
// the trial if it sticks and otherwise caps it in the springs' energy
// metric and rewrites the springs to hold the cap with the damping; the
// history's curve point starts the search and is updated by a slip.  The
// friction fs and twisting torque mt out; true if capped.  It raises no
// error for numerical reasons; a non-finite input (lost atoms) is a domain
// error.
inline bool friction_coupled(double* h, const double* vtr, double twist_rate, double kt,
                             double damp_t, double k_tw, double damp_tw, double load, double a,
                             double* fs, double& mt) {
  // No trial friction (a new contact, an exact touch with a = 0): nothing
  // to cap, nothing to rewrite.
  const double trial_force[3] = {-kt * h[0] - damp_t * vtr[0], -kt * h[1] - damp_t * vtr[1],
                                 -kt * h[2] - damp_t * vtr[2]};
  const double trial_torque = -k_tw * h[kHistTwist] - damp_tw * twist_rate;
  if (trial_force[0] == 0.0 && trial_force[1] == 0.0 && trial_force[2] == 0.0 &&
      trial_torque == 0.0) {
    fs[0] = fs[1] = fs[2] = mt = 0.0;
    return false;
  }
  if (!(load > 0.0) || !(a > 0.0) || !(kt > 0.0) || !(k_tw > 0.0)) {
    // no load, no friction: the springs hold only the damping
    fs[0] = fs[1] = fs[2] = mt = 0.0;
    if (kt > 0.0)
      for (int k = 0; k < 3; ++k) h[k] = -(damp_t * vtr[k]) / kt;
    if (k_tw > 0.0) h[kHistTwist] = -(damp_tw * twist_rate) / k_tw;
    return true;
  }
  using vec = std::array<double, 3>;
  const spinslide::spring_trial<vec, double> trial{
      vec{h[0], h[1], h[2]}, h[kHistTwist],
      vec{-damp_t * vtr[0], -damp_t * vtr[1], -damp_t * vtr[2]}, -damp_tw * twist_rate};
  const spinslide::spring_stiffness<double> springs{spinslide::tangential_stiffness<double>{kt},
                                                    spinslide::twisting_stiffness<double>{k_tw}};
  const spinslide::force_contact<double> contact{spinslide::patch_radius<double>{a},
                                                 spinslide::normal_force<double>{load},
                                                 spinslide::friction_coefficient<double>{1.0}};
  const double* c = h + kHistRatio;
  const auto r =
      spinslide::cap_trial_state(hertz_patch(), trial, springs, contact,
                                 spinslide::curve_point<double>{c[0], c[1], c[2], c[3], c[4]});
  for (int k = 0; k < 3; ++k) {
    fs[k] = r.force[k];
    h[k] = r.displacement[k];
  }
  mt = r.torque;
  h[kHistTwist] = r.twist;
  if (!r.sticking) store_curve_point(r.curve(), h);
  return !r.sticking;
}

}  // namespace detail

/// One contact's forces from its state and history (kHistSize values),
/// advancing the springs by dt if `advance` (not during LAMMPS' setup), the
/// friction capped together (`coupled`) or independently.  A non-finite
/// input to the cap is reported through `error->one` with `style` in the
/// message.
inline void contact_force(const ContactLaw& law, const ContactState& s, double* history, double dt,
                          bool advance, bool coupled, LAMMPS_NS::Error* error, const char* style,
                          ContactForce& out) {
  const double nx = s.n[0], ny = s.n[1], nz = s.n[2];
  const double vr1 = s.vr[0], vr2 = s.vr[1], vr3 = s.vr[2];
  const double vnnr = vr1 * nx + vr2 * ny + vr3 * nz;

  // Hertz with viscoelastic damping
  const double a = std::sqrt(s.delta * s.reff);
  const double fn_elastic = law.kn * s.delta * a;
  const double damp_n =
      law.tsuji ? law.eta_n * std::sqrt(s.meff * (law.kn * a)) : law.eta_n * (a * s.meff);
  double fn = fn_elastic + (-damp_n * vnnr);
  // limit_damping: the damping may not pull the spheres together (as
  // LAMMPS' pair granular, before the friction limit is taken from |F_n|).
  if (law.limit_damping && fn < 0.0) fn = 0.0;
  const double load_n = std::fabs(fn);
  const double fscrit = law.mu * load_n;

  double vtr[3];
  slip_velocity(s, vtr);

  // Mindlin and Marshall springs and their damping
  const double kt = law.kt * a;
  const double damp_t = law.xgammat * damp_n;
  const double k_tw = 0.5 * kt * a * a;
  const double damp_tw = 0.5 * damp_t * a * a;
  const double twist_rate = s.twist_rate;

  if (advance) {
    // Keep the tangential spring in the tangent plane as the contact turns:
    // drop its normal part and restore its length.
    const double hn = history[0] * nx + history[1] * ny + history[2] * nz;
    if (std::fabs(hn) * kt > detail::kFrameTolerance * fscrit) {
      const double len =
          std::sqrt(history[0] * history[0] + history[1] * history[1] + history[2] * history[2]);
      history[0] -= hn * nx;
      history[1] -= hn * ny;
      history[2] -= hn * nz;
      const double plen =
          std::sqrt(history[0] * history[0] + history[1] * history[1] + history[2] * history[2]);
      const double scale = plen > 0 ? len / plen : 0;
      history[0] *= scale;
      history[1] *= scale;
      history[2] *= scale;
    }
    history[0] += vtr[0] * dt;
    history[1] += vtr[1] * dt;
    history[2] += vtr[2] * dt;
    history[kHistTwist] += twist_rate * dt;
  }

  out.fn = fn;
  out.a = a;
  if (coupled) {
    try {
      out.capped = detail::friction_coupled(history, vtr, twist_rate, kt, damp_t, k_tw, damp_tw,
                                            fscrit, a, out.fs, out.mt);
    } catch (std::exception& e) {
      // Only a non-finite input reaches here (the cap raises nothing for
      // numerical reasons): lost atoms or a broken overlap.
      error->one(FLERR, "{}: a contact's friction input is not finite: {}", style, e.what());
    }
  } else {
    const double mtcrit = (2.0 / 3.0) * a * law.mu * load_n;
    out.capped = detail::friction_uncoupled(history, vtr, twist_rate, kt, damp_t, k_tw, damp_tw,
                                            fscrit, mtcrit, out.fs, out.mt);
  }
  history[kHistSliding] = out.capped ? 1.0 : 0.0;
}

}  // namespace spinslide_lammps

#endif  // SPINSLIDE_LAMMPS_SPINSLIDE_CONTACT_H
