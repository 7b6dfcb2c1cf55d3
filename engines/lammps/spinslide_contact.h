//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
/// \file spinslide_contact.h
/// The per-contact law shared by the pair style granular/spinslide (sphere
/// against sphere) and the wall fixes (sphere against a wall, a body of
/// infinite mass): the normal force of LAMMPS' pair granular models with
/// their damping, a tangential spring (linear or Mindlin) or viscous
/// friction, a twisting spring (Marshall's or sds) and a rolling spring
/// (sds), capped at the friction limit, and the update of the contact's
/// history.  granular_model.h reads the law.
///
/// Per contact and step, with n the unit normal from the partner to the
/// sphere, d the overlap, R* the effective radius, m* the effective mass and
/// a the patch radius (sqrt(R* d); JKR: its adhesive patch):
///
///   normal     F_n = k_n d [a] - gamma_n v_n      (hooke: without a; DMT, JKR: adhesive)
///   tangential F_t = -k_t xi - x_gt gamma_n v_t,  k_t = kt a (Mindlin) or kt (linear)
///   twisting   M   = -k_w phi - g_w w_n,          Marshall: k_w = k_t a^2/2, g_w = x_gt gamma_n
///   a^2/2 rolling    F_r = -k_r rho - g_r v_r,          torque R* n x F_r
///
/// xi is the tangential spring (kept in the contact's tangent plane, its
/// length preserved as the plane turns), phi the twisting spring, rho the
/// rolling spring, v_t the slip velocity at the contact, w_n the relative
/// spin about n and v_r = R* (w_i - w_j) x n; the springs are stretched by
/// v_t dt, w_n dt and v_r dt each step.  The friction (F_t, M) is capped at
/// the load mu F_c (F_c = |F_n|; DMT, JKR: |F_n + 2 F_pulloff|):
///
///   independent: |F_t| <= mu F_c and |M| <= mu_w F_c separately, mu_w =
///                (2/3) a mu (Marshall) or as given (sds) (LAMMPS' pair
///                granular, the same arithmetic in the same order);
///   coupled:     (F_t, M) in mu F_c L, L spinslide's exact limit set of the
///                patch's pressure profile (Hertz's unless the `profile`
///                keyword names another; patch_profile): outside it, the trial is replaced by its
///                nearest point of mu F_c L in the springs' energy metric
///                |dF|^2/k_t + |dM|^2/k_w (a tangential spring and
///                Marshall's twisting spring only).
///
/// The rolling force is capped by itself at mu_roll F_c.  When capped, the
/// springs are rewritten so that spring + damping equals the capped value.
/// engines/lammps/README.md documents the model.

#ifndef SPINSLIDE_LAMMPS_SPINSLIDE_CONTACT_H
#define SPINSLIDE_LAMMPS_SPINSLIDE_CONTACT_H

#include "error.h"
#include "granular_model.h"

#include <boost/config.hpp>
#include <spinslide/contact/trial_cap.hpp>
#include <spinslide/values/profile.hpp>

#include <array>
#include <cmath>
#include <cstddef>
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
  kHistRoll = 10,    ///< rolling spring displacement, 3 components (lab frame)
  kHistSize = 13
};

/// One contact's geometry and relative motion, seen from the sphere.
struct ContactState {
  double n[3];        ///< unit normal, from the partner to the sphere
  double delta;       ///< overlap
  double reff;        ///< effective radius R* (a flat wall: the sphere's radius)
  double meff;        ///< effective mass m* (a wall: the sphere's mass)
  double vr[3];       ///< velocity of the sphere's centre relative to the partner's
  double wr[3];       ///< r_i w_i + r_j w_j (a wall: r_i w_i)
  double relrot[3];   ///< w_i - w_j (a wall: w_i)
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
  double fr[3];  ///< rolling resistance force (its torque: R* n x fr)
  double a;      ///< patch radius
  bool capped;   ///< the friction (F_t, M) at its limit (sliding)
};

namespace detail {

// A spring's trial state is turned into the contact's plane only when its
// normal component matters against the friction limit (relative threshold).
constexpr double kFrameTolerance = 1e-10;

// The normal force and what the friction needs of it.
struct NormalForce {
  double fn;              // the normal force, damping included
  double fncrit;          // the load of the friction limits
  double a;               // the patch radius
  double damp_prefactor;  // gamma_n: the normal damping force per normal velocity
};

inline NormalForce normal_force(const ContactLaw& law, const ContactState& s) {
  const double vnnr = s.vr[0] * s.n[0] + s.vr[1] * s.n[1] + s.vr[2] * s.n[2];
  const double dr = s.delta * s.reff;
  double a = 0.0, fne = 0.0, knfac = law.kn;
  if (law.normal == NormalModel::kJkr) {
    jkr_patch(law, s.reff, dr, a, fne);
    knfac = law.kn * a;
  } else {
    fne = knfac * s.delta;
    a = std::sqrt(dr);
    if (law.normal != NormalModel::kHooke) {
      fne *= a;
      knfac *= a;
    }
    if (law.normal == NormalModel::kDmt) fne -= 4 * kPi * law.cohesion * s.reff;
  }
  double damp_normal = 0.0;
  switch (law.damping) {
    case DampingModel::kVelocity:
      damp_normal = 1;
      break;
    case DampingModel::kMassVelocity:
      damp_normal = s.meff;
      break;
    case DampingModel::kViscoelastic:
      damp_normal = a * s.meff;
      break;
    case DampingModel::kTsuji:
      damp_normal = std::sqrt(s.meff * knfac);
      break;
  }
  NormalForce out{0.0, 0.0, a, law.damp * damp_normal};
  out.fn = fne + (-out.damp_prefactor * vnnr);
  // limit_damping: the damping may not pull the spheres together (as
  // LAMMPS' pair granular, before the friction limit is taken from |F_n|).
  if (law.limit_damping && out.fn < 0.0) out.fn = 0.0;
  if (law.normal == NormalModel::kJkr)
    out.fncrit = std::fabs(fne + 2 * (3 * kPi * law.cohesion * s.reff));
  else if (law.normal == NormalModel::kDmt)
    out.fncrit = std::fabs(fne + 2 * (4 * kPi * law.cohesion * s.reff));
  else
    out.fncrit = std::fabs(out.fn);
  return out;
}

// Keeps a spring h (3 components) in the contact's tangent plane as the
// plane turns: drops its normal part and restores its length, when that
// part matters against the limit `crit` at stiffness k.
inline void keep_in_plane(double* h, const double* n, double k, double crit) {
  const double hn = h[0] * n[0] + h[1] * n[1] + h[2] * n[2];
  if (!(std::fabs(hn) * k > kFrameTolerance * crit)) return;
  const double len = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  h[0] -= hn * n[0];
  h[1] -= hn * n[1];
  h[2] -= hn * n[2];
  const double plen = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  const double scale = plen > 0 ? len / plen : 0;
  h[0] *= scale;
  h[1] *= scale;
  h[2] *= scale;
}

// A spring force f = -k h - g v capped at crit: the spring h rewritten to
// hold the capped force with the damping.  True if capped.
inline bool cap_spring(double* h, const double* v, double k, double g, double crit, double* f) {
  f[0] = -k * h[0] - g * v[0];
  f[1] = -k * h[1] - g * v[1];
  f[2] = -k * h[2] - g * v[2];
  const double fmag = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
  if (!(fmag > crit)) return false;
  const double hmag = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  if (hmag != 0.0) {
    for (int c = 0; c < 3; ++c) h[c] = -1.0 / k * (crit * f[c] / fmag + g * v[c]);
    for (int c = 0; c < 3; ++c) f[c] *= crit / fmag;
  } else {
    f[0] = f[1] = f[2] = 0.0;
  }
  return true;
}

// The twisting spring's torque capped at mtcrit (LAMMPS caps against the
// spin's direction, not the trial's).  True if capped.
inline bool cap_twist(double* h, double twist_rate, double k_tw, double damp_tw, double mtcrit,
                      double& mt) {
  mt = -k_tw * h[kHistTwist] - damp_tw * twist_rate;
  if (!(std::fabs(mt) > mtcrit)) return false;
  const double spin_sign = (twist_rate > 0) - (twist_rate < 0);
  h[kHistTwist] = 1.0 / k_tw * (mtcrit * spin_sign - damp_tw * twist_rate);
  mt = -mtcrit * spin_sign;
  return true;
}

// The history's curve point (kHistRatio and the four values after it).
inline void store_curve_point(const spinslide::curve_point<double>& p, double* h) {
  h[kHistRatio] = p.ratio;
  h[kHistRatio + 1] = p.force;
  h[kHistRatio + 2] = p.torque;
  h[kHistRatio + 3] = p.slope;
  h[kHistRatio + 4] = p.curvature;
}

// The springs of one contact (their stiffness and damping at this step).
struct Springs {
  double kt, damp_t;     // tangential
  double k_tw, damp_tw;  // twisting
};

// A contact without load or patch (or with a spring of no stiffness): no
// friction, and the springs hold only the damping.  No trial friction at all
// (a new contact, an exact touch with a = 0): nothing to rewrite.  False:
// nothing capped where there is no trial, true otherwise.
inline bool friction_without_load(double* h, const double* vtr, double twist_rate, const Springs& k,
                                  double* fs, double& mt) {
  fs[0] = fs[1] = fs[2] = mt = 0.0;
  const double trial_torque = -k.k_tw * h[kHistTwist] - k.damp_tw * twist_rate;
  bool none = trial_torque == 0.0;
  for (int c = 0; c < 3; ++c) none = none && -k.kt * h[c] - k.damp_t * vtr[c] == 0.0;
  if (none) return false;
  if (k.kt > 0.0)
    for (int c = 0; c < 3; ++c) h[c] = -(k.damp_t * vtr[c]) / k.kt;
  if (k.k_tw > 0.0) h[kHistTwist] = -(k.damp_tw * twist_rate) / k.k_tw;
  return true;
}

// The coupled cap on the limit set of the patch's `profile` (a concrete
// profile: with_patch_profile), at the load `load` = mu N with patch radius
// a: spinslide::cap_trial_state (trial_cap.hpp) on the springs h (already
// rotated and stretched) and the damping, which keeps the trial if it
// sticks and otherwise caps it in the springs' energy metric and rewrites
// the springs to hold the cap with the damping; the history's curve point
// starts the search and is updated by a slip.  The friction fs and twisting
// torque mt out; true if capped.  It raises no error for numerical reasons;
// a non-finite input (lost atoms) is a domain error.
template <class Profile>
bool friction_coupled(const Profile& profile, double* h, const double* vtr, double twist_rate,
                      const Springs& k, double load, double a, double* fs, double& mt) {
  if (!(load > 0.0) || !(a > 0.0) || !(k.kt > 0.0) || !(k.k_tw > 0.0))
    return friction_without_load(h, vtr, twist_rate, k, fs, mt);
  using vec = std::array<double, 3>;
  const spinslide::spring_trial<vec, double> trial{
      vec{h[0], h[1], h[2]}, h[kHistTwist],
      vec{-k.damp_t * vtr[0], -k.damp_t * vtr[1], -k.damp_t * vtr[2]}, -k.damp_tw * twist_rate};
  const spinslide::spring_stiffness<double> springs{spinslide::tangential_stiffness<double>{k.kt},
                                                    spinslide::twisting_stiffness<double>{k.k_tw}};
  const spinslide::force_contact<double> contact{spinslide::patch_radius<double>{a},
                                                 spinslide::normal_force<double>{load},
                                                 spinslide::friction_coefficient<double>{1.0}};
  // Most contacts of a pile or a pour stick inside the inner triangle of
  // every limit set: the trial is the friction and the springs stay, as
  // cap_trial_state decides by the same test first (here without its call).
  // (0.0 + : a trial of exactly zero gives +0, as before the test came
  // first.)
  if (spinslide::surely_sticks(profile, trial, springs, contact)) {
    for (std::size_t c = 0; c < 3; ++c) fs[c] = 0.0 + (-k.kt * h[c] + trial.damping_force[c]);
    mt = 0.0 + (-k.k_tw * h[kHistTwist] + trial.damping_torque);
    return false;
  }
  const double* c = h + kHistRatio;
  const spinslide::curve_point<double> start{c[0], c[1], c[2], c[3], c[4]};
  const auto r = spinslide::cap_trial_state(profile, trial, springs, contact, start);
  for (std::size_t i = 0; i < 3; ++i) {
    fs[i] = r.force[i];
    h[i] = r.displacement[i];
  }
  mt = r.torque;
  h[kHistTwist] = r.twist;
  if (!r.sticking) store_curve_point(r.curve(), h);
  return !r.sticking;
}

// Viscous friction without a spring (tangential linear_nohistory): the
// damping force along the slip, capped at fscrit.  True if capped.
inline bool friction_viscous(const double* vtr, double damp_t, double fscrit, double* fs) {
  const double vrel = std::sqrt(vtr[0] * vtr[0] + vtr[1] * vtr[1] + vtr[2] * vtr[2]);
  const double f = damp_t * vrel;
  const double ft = vrel != 0.0 ? std::fmin(fscrit, f) / vrel : 0.0;
  fs[0] = -ft * vtr[0];
  fs[1] = -ft * vtr[1];
  fs[2] = -ft * vtr[2];
  return f > fscrit;
}

// The rolling resistance (sds): its spring (history kHistRoll) advanced
// by R* (w_i - w_j) x n dt if `advance`, the force capped at mu_roll F_c.
inline void rolling_resistance(const ContactLaw& law, const ContactState& s, double* history,
                               double dt, bool advance, double fncrit, double* fr) {
  const double* n = s.n;
  const double* w = s.relrot;
  const double vrl[3] = {s.reff * (w[1] * n[2] - w[2] * n[1]), s.reff * (w[2] * n[0] - w[0] * n[2]),
                         s.reff * (w[0] * n[1] - w[1] * n[0])};
  double* h = history + kHistRoll;
  const double frcrit = law.mu_roll * fncrit;
  if (advance) {
    keep_in_plane(h, n, law.k_roll, frcrit);
    for (int c = 0; c < 3; ++c) h[c] += vrl[c] * dt;
  }
  cap_spring(h, vrl, law.k_roll, law.gamma_roll, frcrit, fr);
}

}  // namespace detail

/// f(profile) on the profile of `law`'s patch (its `profile` keyword,
/// checked by check_law), whose limit set the coupled cap projects onto:
/// the concrete profile, so that the cap is compiled for each and a contact
/// pays no run-time handle (spinslide::contact_profile) or its dispatch.
template <class F>
decltype(auto) with_patch_profile(const ContactLaw& law, F&& f) {
  switch (law.profile) {
    case PatchProfile::kDisk:
      return f(spinslide::uniform_disk<double>{});
    case PatchProfile::kRing:
      return f(spinslide::ring<double>{});
    case PatchProfile::kBoussinesq:
      return f(spinslide::boussinesq<double>{});
    case PatchProfile::kAnnulus:
      return f(spinslide::annulus<double>{law.annulus_inner});
    case PatchProfile::kHertz:
      break;
  }
  return f(spinslide::hertz<double>{});
}

/// One contact's forces from its state and history (kHistSize values),
/// advancing the springs by dt if `advance` (not during LAMMPS' setup), the
/// friction capped together (`coupled`, where the law has a tangential
/// spring and Marshall's twisting spring) or independently.  A non-finite
/// input to the cap is reported through `error->one` with `style` in the
/// message.  Always inlined into the pair's and the walls' loops, as stock
/// computes a contact inline: 807 -> 722 instructions a touching contact of
/// the settled pile with the coupling off, stock's 709, with this and the
/// pair's own path inlined (docs/lammps.md, "Cost").
BOOST_FORCEINLINE void contact_force(const ContactLaw& law, const ContactState& s, double* history,
                                     double dt, bool advance, bool coupled, LAMMPS_NS::Error* error,
                                     const char* style, ContactForce& out) {
  const detail::NormalForce normal = detail::normal_force(law, s);
  const double a = normal.a;
  const double fscrit = law.mu * normal.fncrit;
  out.fn = normal.fn;
  out.a = a;
  out.mt = 0.0;
  out.fr[0] = out.fr[1] = out.fr[2] = 0.0;

  double vtr[3];
  slip_velocity(s, vtr);
  detail::Springs k{law.kt, law.xgammat * normal.damp_prefactor, 0.0, 0.0};
  if (law.tangential == TangentialModel::kMindlin) k.kt *= a;
  double mtcrit = 0.0;
  if (law.twist == TwistModel::kMarshall) {
    k.k_tw = 0.5 * k.kt * a * a;
    k.damp_tw = 0.5 * k.damp_t * a * a;
    mtcrit = (2.0 / 3.0) * a * law.mu * normal.fncrit;
  } else if (law.twist == TwistModel::kSds) {
    k.k_tw = law.k_twist;
    k.damp_tw = law.gamma_twist;
    mtcrit = law.mu_twist * normal.fncrit;
  }

  if (advance && law.tangential_spring()) {
    detail::keep_in_plane(history + kHistShear, s.n, k.kt, fscrit);
    for (int c = 0; c < 3; ++c) history[kHistShear + c] += vtr[c] * dt;
  }
  if (advance && law.twist != TwistModel::kNone) history[kHistTwist] += s.twist_rate * dt;

  if (coupled && law.couplable()) {
    try {
      out.capped = with_patch_profile(law, [&](const auto& profile) {
        return detail::friction_coupled(profile, history, vtr, s.twist_rate, k, fscrit, a, out.fs,
                                        out.mt);
      });
    } catch (std::exception& e) {
      // Only a non-finite input reaches here (the cap raises nothing for
      // numerical reasons): lost atoms or a broken overlap.
      error->one(FLERR, "{}: a contact's friction input is not finite: {}", style, e.what());
    }
  } else {
    // the independent caps: the tangential friction, then the twisting torque
    out.capped = law.tangential_spring()
                     ? detail::cap_spring(history + kHistShear, vtr, k.kt, k.damp_t, fscrit, out.fs)
                     : detail::friction_viscous(vtr, k.damp_t, fscrit, out.fs);
    if (law.twist != TwistModel::kNone)
      out.capped =
          detail::cap_twist(history, s.twist_rate, k.k_tw, k.damp_tw, mtcrit, out.mt) || out.capped;
  }
  if (law.rolling) detail::rolling_resistance(law, s, history, dt, advance, normal.fncrit, out.fr);
  history[kHistSliding] = out.capped ? 1.0 : 0.0;
}

}  // namespace spinslide_lammps

#endif  // SPINSLIDE_LAMMPS_SPINSLIDE_CONTACT_H
