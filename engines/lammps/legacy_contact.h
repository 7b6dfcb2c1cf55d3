//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file legacy_contact.h
/// LAMMPS' older granular styles, read as a model keyword of the plugin:
/// `gran/hooke`, `gran/hooke/history` and `gran/hertz/history kn kt|NULL
/// gamman gammat|NULL xmu dampflag [limit_damping]`, as `pair_style
/// gran/...` and `fix wall/gran hooke|hooke/history|hertz/history` take
/// them.  With the coupling off they are computed here in those styles' own
/// arithmetic (the separation vector not normalised, the spring stretched
/// before it is turned into the tangent plane, no length rescale, the torque
/// arm r_i), so that a converted input reproduces LAMMPS bit for bit.  They
/// have no twisting spring; coupled, the plugin runs their equivalent in
/// LAMMPS' newer keywords with Marshall's twisting spring added
/// (modern_equivalent).  No LAMMPS header.
///
/// Per contact, with del the vector from the partner's centre (or the
/// wall's nearest point) to the sphere's, r = |del|, overlap d and R*:
///   F_n = (k_n d - m* gamma_n v_n) [sqrt(d R*) for hertz]
///   F_t = -(k_t xi + m* gamma_t v_t) [sqrt(d R*) for hertz], |F_t| <= xmu |F_n|
/// (gran/hooke: no spring, F_t = -m* gamma_t v_t capped).

#ifndef SPINSLIDE_LAMMPS_LEGACY_CONTACT_H
#define SPINSLIDE_LAMMPS_LEGACY_CONTACT_H

#include "granular_model.h"

#include <cmath>
#include <string>
#include <vector>

namespace spinslide_lammps {

/// Which of LAMMPS' older styles.
enum class LegacyModel { kNone, kHooke, kHookeHistory, kHertzHistory };

/// The numbers of an older style, as that style resolves them (kt NULL:
/// 2 kn/7; gammat NULL: gamman/2; dampflag 0: gammat = 0; hertz: kn and
/// kt divided by LAMMPS' nktv2p).
struct LegacyLaw {
  LegacyModel model = LegacyModel::kNone;
  double kn = 0.0, kt = 0.0, gamman = 0.0, gammat = 0.0, xmu = 0.0;
  bool limit_damping = false;
};

/// Reads `words` = `gran/hooke|gran/hooke/history|gran/hertz/history kn kt
/// gamman gammat xmu dampflag [limit_damping]` (the `gran/` prefix may be
/// left out, as fix wall/gran writes them); nktv2p is LAMMPS' pressure
/// conversion.  Returns an error message, or an empty string.
inline std::string parse_legacy(const std::vector<std::string>& words, const NumberReader& number,
                                double nktv2p, LegacyLaw& law) {
  law = LegacyLaw{};
  if (words.empty()) return "no model";
  std::string name = words[0];
  if (name.rfind("gran/", 0) == 0) name = name.substr(5);
  if (name == "hooke")
    law.model = LegacyModel::kHooke;
  else if (name == "hooke/history")
    law.model = LegacyModel::kHookeHistory;
  else if (name == "hertz/history")
    law.model = LegacyModel::kHertzHistory;
  else
    return words[0] + " is not one of LAMMPS' older granular styles";
  if (words.size() != 7 && !(words.size() == 8 && words[7] == "limit_damping"))
    return words[0] + " needs kn kt gamman gammat xmu dampflag [limit_damping]";
  law.kn = number(words[1]);
  law.kt = words[2] == "NULL" ? law.kn * 2.0 / 7.0 : number(words[2]);
  law.gamman = number(words[3]);
  law.gammat = words[4] == "NULL" ? 0.5 * law.gamman : number(words[4]);
  law.xmu = number(words[5]);
  const double dampflag = number(words[6]);
  if (dampflag == 0.0) law.gammat = 0.0;
  law.limit_damping = words.size() == 8;
  if (law.kn < 0.0 || law.kt < 0.0 || law.gamman < 0.0 || law.gammat < 0.0 || law.xmu < 0.0 ||
      law.xmu > 10000.0 || (dampflag != 0.0 && dampflag != 1.0))
    return words[0] + ": kn, kt, gamman, gammat >= 0, 0 <= xmu <= 10000, dampflag 0 or 1";
  if (law.model == LegacyModel::kHertzHistory) {
    law.kn /= nktv2p;
    law.kt /= nktv2p;
  }
  return "";
}

/// The same contact in LAMMPS' newer keywords, with Marshall's twisting
/// spring added (what `coupling yes` runs): hooke with mass_velocity
/// damping, hertz with viscoelastic damping (gamman sqrt(d R*) m*), a linear
/// or Mindlin spring of stiffness kt (gran/hooke: a linear spring of 2 kn/7,
/// since a twisting spring needs one), xgammat = gammat/gamman.
inline ContactLaw modern_equivalent(const LegacyLaw& legacy) {
  ContactLaw law;
  const bool hertz = legacy.model == LegacyModel::kHertzHistory;
  law.normal = hertz ? NormalModel::kHertz : NormalModel::kHooke;
  law.kn = legacy.kn;
  law.damp = legacy.gamman;
  law.damping = hertz ? DampingModel::kViscoelastic : DampingModel::kMassVelocity;
  law.limit_damping = legacy.limit_damping;
  law.tangential = hertz ? TangentialModel::kMindlin : TangentialModel::kLinearHistory;
  law.kt_null = false;
  law.kt = legacy.model == LegacyModel::kHooke ? legacy.kn * 2.0 / 7.0 : legacy.kt;
  law.xgammat = legacy.gamman > 0.0 ? legacy.gammat / legacy.gamman : 0.0;
  law.mu = legacy.xmu;
  law.twist = TwistModel::kMarshall;
  return law;
}

/// One contact of an older style, in its arithmetic.
struct LegacyContact {
  double del[3];     ///< from the partner (the wall's nearest point) to the sphere's centre
  double rsq;        ///< |del|^2, as the caller computed it
  double radsum;     ///< the contact distance (a wall: the sphere's radius)
  double polyhertz;  ///< hertz/history: sqrt(d R*) as the style computes it (set by the caller)
  double vr[3];      ///< the sphere's velocity relative to the partner (the wall's surface)
  double wr[3];      ///< r_i w_i + r_j w_j (a wall: r_i w_i), not yet divided by r
  double meff;       ///< the effective mass
};

/// What one contact of an older style gives the sphere.
struct LegacyForce {
  double f[3];    ///< the force on the sphere
  double fs[3];   ///< its friction part
  double tor[3];  ///< the vector whose r_i multiple is taken off the sphere's torque (r_j: the
                  ///< partner's)
  double ccel;    ///< the normal force per unit of del (del ccel is the normal force)
  bool capped;    ///< the friction at its limit
};

/// One contact of an older style.  shear: the tangential spring (3 values;
/// unused by gran/hooke), advanced by dt if `advance`.  `wall_hertz` selects
/// fix wall/gran hertz/history's v_n (it divides by rsq where the pair
/// multiplies by 1/rsq).
inline LegacyForce legacy_force(const LegacyLaw& law, const LegacyContact& c, double* shear,
                                double dt, bool advance, bool wall_hertz) {
  const double* d = c.del;
  const double r = std::sqrt(c.rsq);
  const double rinv = 1.0 / r;
  const double rsqinv = 1.0 / c.rsq;
  const double vnnr = c.vr[0] * d[0] + c.vr[1] * d[1] + c.vr[2] * d[2];
  double vn[3];
  for (int k = 0; k < 3; ++k) vn[k] = wall_hertz ? d[k] * vnnr / c.rsq : d[k] * vnnr * rsqinv;
  const double vt[3] = {c.vr[0] - vn[0], c.vr[1] - vn[1], c.vr[2] - vn[2]};
  const double wr[3] = {c.wr[0] * rinv, c.wr[1] * rinv, c.wr[2] * rinv};
  const double meff = c.meff;

  LegacyForce out{};
  const double damp = meff * law.gamman * vnnr * rsqinv;
  double ccel = law.kn * (c.radsum - r) * rinv - damp;
  const bool hertz = law.model == LegacyModel::kHertzHistory;
  if (hertz) ccel *= c.polyhertz;
  if (law.limit_damping && (ccel < 0.0)) ccel = 0.0;
  out.ccel = ccel;

  const double vtr[3] = {vt[0] - (d[2] * wr[1] - d[1] * wr[2]),
                         vt[1] - (d[0] * wr[2] - d[2] * wr[0]),
                         vt[2] - (d[1] * wr[0] - d[0] * wr[1])};
  const double fn = law.xmu * std::fabs(ccel * r);
  double* fs = out.fs;
  if (law.model == LegacyModel::kHooke) {
    const double vrel = std::sqrt(vtr[0] * vtr[0] + vtr[1] * vtr[1] + vtr[2] * vtr[2]);
    const double ft_all = meff * law.gammat * vrel;
    out.capped = ft_all > fn;
    const double ft = vrel != 0.0 ? (fn < ft_all ? fn : ft_all) / vrel : 0.0;
    for (int k = 0; k < 3; ++k) fs[k] = -ft * vtr[k];
  } else {
    if (advance)
      for (int k = 0; k < 3; ++k) shear[k] += vtr[k] * dt;
    const double shrmag =
        std::sqrt(shear[0] * shear[0] + shear[1] * shear[1] + shear[2] * shear[2]);
    const double rsht = (shear[0] * d[0] + shear[1] * d[1] + shear[2] * d[2]) * rsqinv;
    if (advance)
      for (int k = 0; k < 3; ++k) shear[k] -= rsht * d[k];
    for (int k = 0; k < 3; ++k) {
      const double spring = law.kt * shear[k] + meff * law.gammat * vtr[k];
      fs[k] = hertz ? -c.polyhertz * spring : -spring;
    }
    const double fsmag = std::sqrt(fs[0] * fs[0] + fs[1] * fs[1] + fs[2] * fs[2]);
    out.capped = fsmag > fn;
    if (out.capped && shrmag != 0.0) {
      for (int k = 0; k < 3; ++k)
        shear[k] = (fn / fsmag) * (shear[k] + meff * law.gammat * vtr[k] / law.kt) -
                   meff * law.gammat * vtr[k] / law.kt;
      for (int k = 0; k < 3; ++k) fs[k] *= fn / fsmag;
    } else if (out.capped) {
      fs[0] = fs[1] = fs[2] = 0.0;
    }
  }
  for (int k = 0; k < 3; ++k) out.f[k] = d[k] * ccel + fs[k];
  out.tor[0] = rinv * (d[1] * fs[2] - d[2] * fs[1]);
  out.tor[1] = rinv * (d[2] * fs[0] - d[0] * fs[2]);
  out.tor[2] = rinv * (d[0] * fs[1] - d[1] * fs[0]);
  return out;
}

}  // namespace spinslide_lammps

#endif  // SPINSLIDE_LAMMPS_LEGACY_CONTACT_H
