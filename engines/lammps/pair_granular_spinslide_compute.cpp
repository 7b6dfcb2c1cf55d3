//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
// The force computation of the pair style granular/spinslide
// (pair_granular_spinslide.h): compute(), one pair's contact in the
// plugin's law or in one of LAMMPS' older styles, and single().
//
// For spheres i and j with unit normal n (from j to i), overlap
// d = r_i + r_j - |x_i - x_j|, R* = r_i r_j/(r_i + r_j) and
// m* = m_i m_j/(m_i + m_j) (a frozen partner: the other's mass), the forces
// and the history update are spinslide_lammps::contact_force
// (spinslide_contact.h), which the fix wall/gran/spinslide shares: Hertz with
// viscoelastic damping, Mindlin and Marshall springs with damping, capped
// together on spinslide's Hertz limit set (coupling yes) or independently as
// pair_style granular (coupling no, the same arithmetic, step for step).
// The friction acts at the contact point, r - d/2 from each centre.

#include "pair_granular_spinslide.h"

#include "atom.h"
#include "error.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "neigh_list.h"
#include "update.h"

#include "legacy_contact.h"
#include "spinslide_contact.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

using namespace LAMMPS_NS;

using spinslide_lammps::kHistSize;
using spinslide_lammps::kHistSliding;

namespace {

// The pair's effective mass m_i m_j/(m_i + m_j), or the other sphere's mass
// where one is frozen (fix freeze: it does not move).
double effective_mass(const double* rmass, const int* mask, int freeze_group_bit, int i, int j) {
  double meff = rmass[i] * rmass[j] / (rmass[i] + rmass[j]);
  if (mask[i] & freeze_group_bit) meff = rmass[j];
  if (mask[j] & freeze_group_bit) meff = rmass[i];
  return meff;
}

}  // namespace

namespace {

// The statistics of compute pair granular/spinslide over this rank's pairs.
struct ContactStatistics {
  double contacts = 0.0, sliding = 0.0, force = 0.0, torque = 0.0;
  // The contact of i with j.  With newton off, a pair whose j is a ghost is
  // computed by both owners (or twice, across a periodic boundary): half
  // each, as LAMMPS' ev_tally weighs it, so that the sums count it once.
  void add(const spinslide_lammps::ContactForce& cf, int newton_pair, int j, int nlocal) {
    const double share = newton_pair != 0 || j < nlocal ? 1.0 : 0.5;
    contacts += share;
    sliding += cf.capped ? share : 0.0;
    force += share * std::sqrt(cf.fs[0] * cf.fs[0] + cf.fs[1] * cf.fs[1] + cf.fs[2] * cf.fs[2]);
    torque += share * std::fabs(cf.mt);
  }
};

}  // namespace

void PairGranularSpinslide::compute(int eflag, int vflag) {
  ev_init(eflag, vflag);
  for (int k = 0; k < nextra; ++k) pvector[k] = 0.0;

  double** x = atom->x;
  const double* radius = atom->radius;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  // setup() computes forces without advancing the springs
  const bool advance = update->setupflag == 0;

  const int inum = list->inum;
  const int* ilist = list->ilist;
  const int* numneigh = list->numneigh;
  int** firstneigh = list->firstneigh;
  int** firsttouch = fix_history->firstflag;
  double** firsthistory = fix_history->firstvalue;

  // The statistics (pvector) are only read by `compute pair`, which makes
  // LAMMPS tally energy on the steps it needs them: gather them only then.
  const bool tally = eflag_global != 0;
  ContactStatistics stats;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const double xi = x[i][0], yi = x[i][1], zi = x[i][2];
    int* touch = firsttouch[i];
    double* allhistory = firsthistory[i];
    const int* jlist = firstneigh[i];
    const int jnum = numneigh[i];

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = xi - x[j][0];
      const double dely = yi - x[j][1];
      const double delz = zi - x[j][2];
      // Most neighbours are apart and were apart: no contact forms without
      // an overlap in any model (JKR holds one beyond, but only one that
      // touched), and a pair that did not touch has its history zeroed
      // already (one_pair, when it came apart; LAMMPS, for a new
      // neighbour).  Decided here, the common case costs a distance test.
      const double radsum = radius[i] + radius[j];
      if (touch[jj] == 0 && delx * delx + dely * dely + delz * delz >= radsum * radsum) continue;
      double* history = &allhistory[static_cast<std::ptrdiff_t>(kHistSize) * jj];
      spinslide_lammps::ContactForce cf;
      double fij[3];
      if (!one_pair(i, j, touch[jj], history, advance, cf, fij)) continue;
      if (tally) stats.add(cf, newton_pair, j, nlocal);
      if (evflag)
        ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fij[0], fij[1], fij[2], delx, dely, delz);
    }
  }
  pvector[kExtraContacts] = stats.contacts;
  pvector[kExtraSliding] = stats.sliding;
  pvector[kExtraForce] = stats.force;
  pvector[kExtraTorque] = stats.torque;
}

/* ----------------------------------------------------------------------
   i's neighbour j: false if apart (the contact forgotten: touch 0, the
   history zeroed); else the contact's forces and torques applied (to j as
   well with newton on or j owned), fij the force on i, cf its friction
------------------------------------------------------------------------- */

bool PairGranularSpinslide::one_pair(int i, int j, int& touch, double* history, bool advance,
                                     spinslide_lammps::ContactForce& cf, double fij[3]) {
  double** x = atom->x;
  const int itype = atom->type[i], jtype = atom->type[j];
  const double delx = x[i][0] - x[j][0];
  const double dely = x[i][1] - x[j][1];
  const double delz = x[i][2] - x[j][2];
  const double rsq = delx * delx + dely * dely + delz * delz;
  const double radi = atom->radius[i], radj = atom->radius[j];
  const double radsum = radi + radj;
  const spinslide_lammps::ContactLaw& law = contact_law(itype, jtype);
  const spinslide_lammps::LegacyLaw& legacy = legacy_of(itype, jtype);
  const bool is_legacy = legacy.model != spinslide_lammps::LegacyModel::kNone;
  const bool touching = is_legacy ? rsq < radsum * radsum
                                  : spinslide_lammps::pair_touching(
                                        law, rsq, radsum, radi * radj / radsum, touch != 0);
  if (!touching) {
    touch = 0;
    for (int k = 0; k < kHistSize; ++k) history[k] = 0.0;
    return false;
  }
  touch = 1;
  if (is_legacy) {
    // LAMMPS' older styles, in their arithmetic
    cf = legacy_pair(i, j, legacy, history, advance, fij);
    return true;
  }
  const spinslide_lammps::ContactState state = contact_state(i, j, std::sqrt(rsq));
  spinslide_lammps::contact_force(law, state, history, dt, advance, coupled != 0, error,
                                  "pair granular/spinslide", cf);
  apply_forces(i, j, law, state, cf, force->newton_pair != 0 || j < atom->nlocal, fij);
  return true;
}

/* ----------------------------------------------------------------------
   the contact's forces and torques on i (and, if `on_j`, the opposite ones
   on j), in LAMMPS' pair granular's order: the friction acts at the contact
   point, r - d/2 from each centre; then the twisting torque about n; then
   the rolling resistance's torque R* n x F_r.  fij: the force on i.
------------------------------------------------------------------------- */

void PairGranularSpinslide::apply_forces(int i, int j, const spinslide_lammps::ContactLaw& law,
                                         const spinslide_lammps::ContactState& state,
                                         const spinslide_lammps::ContactForce& cf, bool on_j,
                                         double fij[3]) {
  double** f = atom->f;
  double** torque = atom->torque;
  const double nx = state.n[0], ny = state.n[1], nz = state.n[2];
  const double* fs = cf.fs;
  fij[0] = nx * cf.fn + fs[0];
  fij[1] = ny * cf.fn + fs[1];
  fij[2] = nz * cf.fn + fs[2];
  const double tor[3] = {ny * fs[2] - nz * fs[1], nz * fs[0] - nx * fs[2], nx * fs[1] - ny * fs[0]};
  const double tw[3] = {cf.mt * nx, cf.mt * ny, cf.mt * nz};
  const double* fr = cf.fr;
  const double reff = state.reff;
  const double tr[3] = {reff * (ny * fr[2] - nz * fr[1]), reff * (nz * fr[0] - nx * fr[2]),
                        reff * (nx * fr[1] - ny * fr[0])};
  const bool twisting = law.twist != spinslide_lammps::TwistModel::kNone;
  const double arm_i = atom->radius[i] - 0.5 * state.delta;
  for (int k = 0; k < 3; ++k) f[i][k] += fij[k];
  for (int k = 0; k < 3; ++k) torque[i][k] -= arm_i * tor[k];
  if (twisting)
    for (int k = 0; k < 3; ++k) torque[i][k] += tw[k];
  if (law.rolling)
    for (int k = 0; k < 3; ++k) torque[i][k] += tr[k];
  if (!on_j) return;
  const double arm_j = atom->radius[j] - 0.5 * state.delta;
  for (int k = 0; k < 3; ++k) f[j][k] -= fij[k];
  for (int k = 0; k < 3; ++k) torque[j][k] -= arm_j * tor[k];
  if (twisting)
    for (int k = 0; k < 3; ++k) torque[j][k] -= tw[k];
  if (law.rolling)
    for (int k = 0; k < 3; ++k) torque[j][k] -= tr[k];
}

/* ----------------------------------------------------------------------
   i's contact with j in one of LAMMPS' older styles (legacy_contact.h), as
   gran/hooke, gran/hooke/history and gran/hertz/history compute it, the
   spring in history advanced if `advance`; nothing applied
------------------------------------------------------------------------- */

spinslide_lammps::LegacyForce PairGranularSpinslide::legacy_contact(
    int i, int j, const spinslide_lammps::LegacyLaw& legacy, double* history, bool advance) const {
  double** x = atom->x;
  double** v = atom->v;
  double** omega = atom->omega;
  const double radi = atom->radius[i], radj = atom->radius[j];
  spinslide_lammps::LegacyContact c{};
  for (int k = 0; k < 3; ++k) {
    c.del[k] = x[i][k] - x[j][k];
    c.vr[k] = v[i][k] - v[j][k];
    c.wr[k] = radi * omega[i][k] + radj * omega[j][k];
  }
  c.rsq = c.del[0] * c.del[0] + c.del[1] * c.del[1] + c.del[2] * c.del[2];
  c.radsum = radi + radj;
  c.meff = effective_mass(atom->rmass, atom->mask, freeze_group_bit, i, j);
  if (legacy.model == spinslide_lammps::LegacyModel::kHertzHistory)
    c.polyhertz = std::sqrt((c.radsum - std::sqrt(c.rsq)) * radi * radj / c.radsum);
  return spinslide_lammps::legacy_force(legacy, c, history, dt, advance, false);
}

/* ----------------------------------------------------------------------
   the same contact's forces and torques added to i (and j, with newton on
   or j owned); fij the force on i; the friction in the result, for the
   statistics
------------------------------------------------------------------------- */

spinslide_lammps::ContactForce PairGranularSpinslide::legacy_pair(
    int i, int j, const spinslide_lammps::LegacyLaw& legacy, double* history, bool advance,
    double fij[3]) {
  double** f = atom->f;
  double** torque = atom->torque;
  const spinslide_lammps::LegacyForce lf = legacy_contact(i, j, legacy, history, advance);
  history[kHistSliding] = lf.capped ? 1.0 : 0.0;
  const double radi = atom->radius[i], radj = atom->radius[j];
  for (int k = 0; k < 3; ++k) {
    fij[k] = lf.f[k];
    f[i][k] += lf.f[k];
    torque[i][k] -= radi * lf.tor[k];
  }
  if (force->newton_pair || j < atom->nlocal) {
    for (int k = 0; k < 3; ++k) {
      f[j][k] -= lf.f[k];
      torque[j][k] -= radj * lf.tor[k];
    }
  }
  spinslide_lammps::ContactForce out{};
  for (int k = 0; k < 3; ++k) out.fs[k] = lf.fs[k];
  out.capped = lf.capped;
  return out;
}

/* ---------------------------------------------------------------------- */

// The geometry and relative motion of i's contact with j at distance r.
spinslide_lammps::ContactState PairGranularSpinslide::contact_state(int i, int j, double r) const {
  double** x = atom->x;
  double** v = atom->v;
  double** omega = atom->omega;
  const double radi = atom->radius[i], radj = atom->radius[j];
  const double radsum = radi + radj;
  const double rinv = 1.0 / r;
  spinslide_lammps::ContactState state;
  for (int k = 0; k < 3; ++k) {
    state.n[k] = (x[i][k] - x[j][k]) * rinv;
    state.vr[k] = v[i][k] - v[j][k];
    state.wr[k] = radi * omega[i][k] + radj * omega[j][k];
    state.relrot[k] = omega[i][k] - omega[j][k];
  }
  state.delta = radsum - r;
  state.reff = radi * radj / radsum;
  state.meff = effective_mass(atom->rmass, atom->mask, freeze_group_bit, i, j);
  state.twist_rate =
      state.relrot[0] * state.n[0] + state.relrot[1] * state.n[1] + state.relrot[2] * state.n[2];
  return state;
}

// The law of the type pair.
const spinslide_lammps::ContactLaw& PairGranularSpinslide::contact_law(int itype, int jtype) const {
  return laws[static_cast<std::size_t>(itype) * static_cast<std::size_t>(atom->ntypes + 1) +
              static_cast<std::size_t>(jtype)];
}

spinslide_lammps::LegacyLaw& PairGranularSpinslide::legacy_of(int itype, int jtype) {
  return legacy_laws[static_cast<std::size_t>(itype) * static_cast<std::size_t>(atom->ntypes + 1) +
                     static_cast<std::size_t>(jtype)];
}

spinslide_lammps::ContactLaw& PairGranularSpinslide::law_of(int itype, int jtype) {
  return laws[static_cast<std::size_t>(itype) * static_cast<std::size_t>(atom->ntypes + 1) +
              static_cast<std::size_t>(jtype)];
}

/* ----------------------------------------------------------------------
   One pair for compute pair/local: the force of the last step, from the
   history as the step left it (not advanced, nothing written back).
   fforce: the normal force over r (LAMMPS' convention: the force on i along
   x_i - x_j is fforce (x_i - x_j)); svector (p1 ... p7 of pair/local):
   the friction force on i (x, y, z), its magnitude, the twisting torque on i
   about n, the contact's kinematic ratio eps = |v_slip|/(a |w_n|) (inf
   without spin, 0 at rest), 1 if at the friction limit (sliding) and 1 if in
   contact (all 0 for a pair apart, so that sums over pairs count contacts).
------------------------------------------------------------------------- */

double PairGranularSpinslide::single(int i, int j, int itype, int jtype, double rsq,
                                     double /*factor_coul*/, double /*factor_lj*/, double& fforce) {
  for (int m = 0; m < single_extra; m++) svector[m] = 0.0;
  fforce = 0.0;
  if (fix_history == nullptr || fix_history->firstvalue == nullptr || list == nullptr)
    error->one(FLERR, "Pair granular/spinslide: single() needs the history of a run");
  // i's neighbor list holds the pair and its history (compute pair/local
  // walks that list).
  const int jnum = list->numneigh[i];
  const int* jlist = list->firstneigh[i];
  int jj = 0;
  while (jj < jnum && (jlist[jj] & NEIGHMASK) != j) ++jj;
  if (jj == jnum) return 0.0;
  // in contact as compute() decides (JKR: until the pull-off distance)
  const spinslide_lammps::ContactLaw& law = contact_law(itype, jtype);
  const spinslide_lammps::LegacyLaw& legacy = legacy_of(itype, jtype);
  const bool is_legacy = legacy.model != spinslide_lammps::LegacyModel::kNone;
  const double radi = atom->radius[i], radj = atom->radius[j];
  const double radsum = radi + radj;
  const bool touching =
      is_legacy ? rsq < radsum * radsum
                : spinslide_lammps::pair_touching(law, rsq, radsum, radi * radj / radsum,
                                                  fix_history->firstflag[i][jj] != 0);
  if (!touching) return 0.0;
  double history[kHistSize];
  const double* stored = &fix_history->firstvalue[i][static_cast<std::ptrdiff_t>(kHistSize) * jj];
  std::copy(stored, stored + kHistSize, history);

  const double r = std::sqrt(rsq);
  const spinslide_lammps::ContactState state = contact_state(i, j, r);
  spinslide_lammps::ContactForce cf{};
  if (is_legacy) {
    // LAMMPS' older styles, in their arithmetic (the spring not advanced)
    const spinslide_lammps::LegacyForce lf = legacy_contact(i, j, legacy, history, false);
    fforce = lf.ccel;
    for (int k = 0; k < 3; ++k) cf.fs[k] = lf.fs[k];
  } else {
    spinslide_lammps::contact_force(law, state, history, dt, false, coupled != 0, error,
                                    "pair granular/spinslide", cf);
    fforce = cf.fn / r;
  }
  for (int k = 0; k < 3; ++k) svector[k] = cf.fs[k];
  svector[3] = std::sqrt(cf.fs[0] * cf.fs[0] + cf.fs[1] * cf.fs[1] + cf.fs[2] * cf.fs[2]);
  svector[4] = cf.mt;
  svector[5] = spinslide_lammps::slip_ratio(state);
  // (The force computation of the step rewrote a capped contact's springs
  // onto the cap, from which the recomputation above may land a rounding
  // inside it: the step's own verdict is the one kept.)
  svector[6] = stored[kHistSliding];
  svector[7] = 1.0;
  return 0.0;
}
