//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
// The pair style granular/spinslide (pair_granular_spinslide.h, README.md).
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
//
// Per-contact history (FixNeighHistory, kHistSize = 9 values): the
// tangential spring (3, lab frame), the twisting spring, and where the last
// slip left the limit curve (eps, F, T, F', F'': the next search's start).

#include "pair_granular_spinslide.h"
#include "keywords.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "fix_dummy.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

#include "legacy_contact.h"
#include "spinslide_contact.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

using spinslide_lammps::kHistRatio;
using spinslide_lammps::kHistRoll;
using spinslide_lammps::kHistShear;
using spinslide_lammps::kHistSize;
using spinslide_lammps::kHistSliding;
using spinslide_lammps::kHistTwist;

/* ---------------------------------------------------------------------- */

PairGranularSpinslide::PairGranularSpinslide(LAMMPS* lmp) : Pair(lmp) {
  single_enable = 1;
  single_extra = kSingleSize;
  svector = new double[single_extra];
  restartinfo = 0;
  no_virial_fdotr_compute = 1;
  centroidstressflag = CENTROID_NOTAVAIL;
  finitecutflag = 1;
  beyond_contact = 0;
  // The history's ratio keeps its sign when a contact changes owner.
  nondefault_history_transfer = 1;

  nextra = kExtraSize;
  pvector = new double[nextra];
  for (int k = 0; k < nextra; ++k) pvector[k] = 0.0;

  dt = update->dt;

  // A placeholder fix, replaced by the history fix in init_style(), so that
  // the history fix keeps this place in the fix list (before any fix the
  // input defines afterwards).  Its ID is fixed, SPINSLIDE_HISTORY (then
  // SPINSLIDE_HISTORY_2, ... for more granular/spinslide styles alive at
  // once, in pair_style hybrid): a restart finds it whatever pair styles
  // the writing or the reading input created before (numbered by
  // instance_me, as LAMMPS' own granular styles do, it was not found, and
  // every contact's history was silently dropped; issue 30).
  for (int k = 1;; ++k) {
    id_history =
        k == 1 ? std::string("SPINSLIDE_HISTORY") : "SPINSLIDE_HISTORY_" + std::to_string(k);
    id_dummy = id_history + "_DUMMY";
    if (modify->find_fix(id_history) < 0 && modify->find_fix(id_dummy) < 0) break;
  }
  modify->add_fix(id_dummy + " all DUMMY");
}

/* ---------------------------------------------------------------------- */

PairGranularSpinslide::~PairGranularSpinslide() {
  delete[] pvector;
  pvector = nullptr;
  delete[] svector;
  svector = nullptr;
  if (modify) {
    if (fix_history) {
      if (modify->find_fix(id_history) >= 0) modify->delete_fix(id_history);
    } else if (modify->find_fix(id_dummy) >= 0) {
      modify->delete_fix(id_dummy);
    }
  }
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(cutoff_type);
    delete[] onerad_dynamic;
    delete[] onerad_frozen;
    delete[] maxrad_dynamic;
    delete[] maxrad_frozen;
  }
}

/* ---------------------------------------------------------------------- */

namespace {

const char* const kCoeffSyntax =
    "pair_coeff I J E eta_n|e nu mu [xgammat x] [damping viscoelastic|tsuji] [limit_damping] "
    "[cutoff rc], or pair_coeff I J with LAMMPS' pair granular model keywords [cutoff rc]";

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

/* ---------------------------------------------------------------------- */

void PairGranularSpinslide::allocate() {
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) setflag[i][j] = 0;
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  memory->create(cutoff_type, n + 1, n + 1, "pair:cutoff_type");
  laws.assign(static_cast<std::size_t>(n + 1) * static_cast<std::size_t>(n + 1),
              spinslide_lammps::ContactLaw{});
  legacy_laws.assign(laws.size(), spinslide_lammps::LegacyLaw{});
  onerad_dynamic = new double[n + 1];
  onerad_frozen = new double[n + 1];
  maxrad_dynamic = new double[n + 1];
  maxrad_frozen = new double[n + 1];
}

/* ----------------------------------------------------------------------
   pair_style granular/spinslide [coupling yes|no] [twist_transfer symmetric|negate]
------------------------------------------------------------------------- */

void PairGranularSpinslide::settings(int narg, char** arg) {
  coupled = 1;
  twist_negate = 0;
  for (int iarg = 0; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Illegal pair_style granular/spinslide command: {} needs a value",
                 arg[iarg]);
    const std::string key = arg[iarg], value = arg[iarg + 1];
    if (key == "coupling") {
      coupled = spinslide_lammps::either(value, {"yes", "on"}, {"no", "off"});
      if (coupled < 0)
        error->all(FLERR, "Illegal pair_style granular/spinslide command: coupling {}", value);
    } else if (key == "twist_transfer") {
      twist_negate = spinslide_lammps::either(value, {"negate"}, {"symmetric"});
      if (twist_negate < 0)
        error->all(FLERR, "Illegal pair_style granular/spinslide command: twist_transfer {}",
                   value);
    } else {
      error->all(FLERR, "Illegal pair_style granular/spinslide command: unknown keyword {}", key);
    }
  }
}

/* ----------------------------------------------------------------------
   pair_coeff's words after I J: the short form E eta_n|e nu mu [xgammat x]
   [damping viscoelastic|tsuji] [limit_damping] [cutoff rc], or LAMMPS'
   pair granular model keywords [cutoff rc]
------------------------------------------------------------------------- */

spinslide_lammps::ContactLaw PairGranularSpinslide::read_law(int narg, char** arg, double& cutoff) {
  const std::vector<std::string> words(arg + 2, arg + narg);
  const bool short_form = utils::is_double(arg[2]);
  if (short_form && words.size() < 4)
    error->all(FLERR, "Incorrect args for pair coefficients: {}", kCoeffSyntax);
  const spinslide_lammps::NumberReader number = [this](const std::string& w) {
    return utils::numeric(FLERR, w.c_str(), false, lmp);
  };
  spinslide_lammps::ContactLaw law;
  std::vector<std::string> rest;
  const std::string why = spinslide_lammps::parse_lammps_model(
      short_form ? spinslide_lammps::expand_short_form(words) : words, number, law, rest);
  if (!why.empty()) error->all(FLERR, "pair_coeff granular/spinslide: {}", why);
  for (std::size_t k = 0; k < rest.size(); ++k) {
    if (rest[k] == "cutoff" && k + 1 < rest.size()) {
      cutoff = number(rest[++k]);
      // (LAMMPS' granular takes cutoff -1 for automatic; here the automatic
      // cutoff is the default, and a given one must be a distance.)
      if (!(cutoff > 0.0))
        error->all(FLERR,
                   "pair_coeff granular/spinslide: cutoff must be > 0 (leave it out for the "
                   "automatic cutoff, the contact distance of the largest spheres)");
      continue;
    }
    const std::string why = spinslide_lammps::unsupported_granular_keyword(rest[k]);
    if (!why.empty()) error->all(FLERR, "pair_coeff granular/spinslide: {}: {}", rest[k], why);
    error->all(FLERR, "Incorrect args for pair coefficients: unknown keyword {} ({})", rest[k],
               kCoeffSyntax);
  }
  return law;
}

void PairGranularSpinslide::coeff(int narg, char** arg) {
  if (narg < 3) error->all(FLERR, "Incorrect args for pair coefficients: {}", kCoeffSyntax);
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  double cut_one = -1.0;
  // LAMMPS' older styles (gran/hooke, gran/hooke/history, gran/hertz/history):
  // in their arithmetic with the coupling off, as their equivalent with
  // Marshall's twisting spring coupled (legacy_contact.h)
  spinslide_lammps::LegacyLaw legacy;
  if (utils::strmatch(arg[2], "^gran/")) {
    const std::vector<std::string> words(arg + 2, arg + narg);
    const std::string why = spinslide_lammps::parse_legacy(
        words,
        [this](const std::string& w) { return utils::numeric(FLERR, w.c_str(), false, lmp); },
        force->nktv2p, legacy);
    if (!why.empty()) error->all(FLERR, "pair_coeff granular/spinslide: {}", why);
  }
  const spinslide_lammps::ContactLaw read = legacy.model != spinslide_lammps::LegacyModel::kNone
                                                ? spinslide_lammps::modern_equivalent(legacy)
                                                : read_law(narg, arg, cut_one);
  if (coupled) legacy.model = spinslide_lammps::LegacyModel::kNone;
  const std::string why = spinslide_lammps::check_law(read);
  if (!why.empty()) error->all(FLERR, "pair_coeff granular/spinslide: {}", why);
  const spinslide_lammps::ContactLaw law =
      spinslide_lammps::resolve(read, spinslide_lammps::Moduli::kExact, false);
  // JKR: contacts last beyond touching, until the pull-off distance
  if (law.normal == spinslide_lammps::NormalModel::kJkr) beyond_contact = 1;

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      law_of(i, j) = law_of(j, i) = law;
      legacy_of(i, j) = legacy_of(j, i) = legacy;
      cutoff_type[i][j] = cutoff_type[j][i] = cut_one;
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

/* ---------------------------------------------------------------------- */

void PairGranularSpinslide::init_style() {
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR,
               "Pair granular/spinslide requires atom attributes radius, rmass, omega, "
               "torque (atom_style sphere)");
  if (comm->ghost_velocity == 0)
    error->all(FLERR,
               "Pair granular/spinslide requires ghost atoms store velocity "
               "(comm_modify vel yes)");
  for (int i = 0; i < modify->nfix; i++)
    if (modify->fix[i]->rigid_flag)
      error->all(FLERR, "Pair granular/spinslide does not support rigid bodies yet");

  const int irequest = neighbor->request(this, instance_me);
  neighbor->requests[irequest]->size = 1;
  neighbor->requests[irequest]->history = 1;

  dt = update->dt;

  if (fix_history == nullptr) {
    fix_history = dynamic_cast<FixNeighHistory*>(modify->replace_fix(
        id_dummy, id_history + " all NEIGH_HISTORY/SPINSLIDE " + std::to_string(int(kHistSize)),
        1));
    if (fix_history == nullptr)
      error->all(FLERR, "Pair granular/spinslide could not create its history fix");
    fix_history->pair = this;
    // A restart file with per-atom fix data but none for this history fix
    // (written by another pair style, or by spinslide before issue 30, whose
    // IDs were SPINSLIDE_HISTORY<n>): say so, not only in LAMMPS' list of
    // unused restart info.
    if (modify->nfix_restart_peratom > 0 && fix_history->restart_reset == 0 && comm->me == 0)
      error->warning(FLERR,
                     "Pair granular/spinslide: the restart file holds no contact history for "
                     "fix ID " +
                         id_history +
                         " (see 'Unused restart file peratom fix info' in the log): every "
                         "contact starts with unloaded springs");
  }

  const int ifreeze = modify->find_fix_by_style("^freeze");
  freeze_group_bit = ifreeze < 0 ? 0 : modify->fix[ifreeze]->groupbit;

  // The largest radius of each type, owned now or to come from a pour or a
  // deposit, sets the neighbor cutoffs (init_one).
  const int ipour = modify->find_fix_by_style("^pour");
  const int ideposit = modify->find_fix_by_style("^deposit");
  const int ntypes = atom->ntypes;
  for (int t = 1; t <= ntypes; t++) {
    onerad_dynamic[t] = onerad_frozen[t] = 0.0;
    for (int ifix : {ipour, ideposit}) {
      if (ifix < 0) continue;
      int itype = t;
      auto* rmax = static_cast<double*>(modify->fix[ifix]->extract("radius", itype));
      if (rmax) onerad_dynamic[t] = *rmax;
    }
  }
  const double* radius = atom->radius;
  const int* mask = atom->mask;
  const int* type = atom->type;
  for (int i = 0; i < atom->nlocal; i++) {
    double& slot = (mask[i] & freeze_group_bit) ? onerad_frozen[type[i]] : onerad_dynamic[type[i]];
    slot = std::max(slot, radius[i]);
  }
  MPI_Allreduce(&onerad_dynamic[1], &maxrad_dynamic[1], ntypes, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(&onerad_frozen[1], &maxrad_frozen[1], ntypes, MPI_DOUBLE, MPI_MAX, world);
}

/* ---------------------------------------------------------------------- */

double PairGranularSpinslide::init_one(int i, int j) {
  if (setflag[i][j] == 0) {
    // mixed materials: the effective moduli of the two, and the geometric
    // means of the other numbers (granular_model.h, mix)
    if (legacy_of(i, i).model != spinslide_lammps::LegacyModel::kNone ||
        legacy_of(j, j).model != spinslide_lammps::LegacyModel::kNone)
      error->all(FLERR,
                 "Pair granular/spinslide: types {} and {}: LAMMPS' older styles do not mix; "
                 "give their pair_coeff",
                 i, j);
    if (!spinslide_lammps::same_forms(law_of(i, i), law_of(j, j)))
      error->all(FLERR,
                 "Pair granular/spinslide: types {} and {} have different models; give their "
                 "pair_coeff",
                 i, j);
    law_of(i, j) = law_of(j, i) = spinslide_lammps::mix(law_of(i, i), law_of(j, j));
    cutoff_type[i][j] = cutoff_type[j][i] = -1.0;
  }
  if (coupled && law_of(i, j).twist == spinslide_lammps::TwistModel::kSds)
    error->all(FLERR,
               "Pair granular/spinslide: coupling yes needs twisting marshall (types {} {}): the "
               "coupled cap takes the twisting limit from the contact patch, not from sds' "
               "coefficient; give twisting marshall, or coupling no",
               i, j);

  if (cutoff_type[i][j] > 0.0) return cutoff_type[i][j];

  // No cutoff given: contact distance of the largest spheres of the two
  // types (dynamic with dynamic or frozen); if a type has no sphere yet,
  // the largest contact distance of any.
  const bool known = (maxrad_dynamic[i] > 0.0 && maxrad_dynamic[j] > 0.0) ||
                     (maxrad_dynamic[i] > 0.0 && maxrad_frozen[j] > 0.0) ||
                     (maxrad_frozen[i] > 0.0 && maxrad_dynamic[j] > 0.0);
  if (known) {
    // JKR: LAMMPS' cutoff, which adds the overlap at pull-off (negative):
    // kept for the same neighbor bins, hence the same order of summation,
    // as LAMMPS; the skin must then reach the pull-off distance.
    const spinslide_lammps::ContactLaw& law = law_of(i, j);
    const auto reach = [&law](double ri, double rj) {
      return ri + rj + spinslide_lammps::pulloff_distance(law, ri, rj);
    };
    double cut = reach(maxrad_dynamic[i], maxrad_dynamic[j]);
    cut = std::max(cut, reach(maxrad_frozen[i], maxrad_dynamic[j]));
    cut = std::max(cut, reach(maxrad_dynamic[i], maxrad_frozen[j]));
    const double pulloff =
        spinslide_lammps::pulloff_distance(law, maxrad_dynamic[i], maxrad_dynamic[j]);
    if (cut + neighbor->skin < maxrad_dynamic[i] + maxrad_dynamic[j] - pulloff && comm->me == 0)
      error->warning(FLERR,
                     "Pair granular/spinslide: types {} {}: the neighbor skin {} does not reach "
                     "the JKR pull-off distance {}: contacts may break early; give a larger skin",
                     i, j, neighbor->skin, maxrad_dynamic[i] + maxrad_dynamic[j] - pulloff);
    return cut;
  }
  double cut = 0.0;
  for (int t = 1; t <= atom->ntypes; t++) {
    cut = std::max(cut, 2.0 * maxrad_dynamic[t]);
    cut = std::max(cut, 2.0 * maxrad_frozen[t]);
  }
  return cut;
}

/* ---------------------------------------------------------------------- */

void PairGranularSpinslide::reset_dt() { dt = update->dt; }

/* ---------------------------------------------------------------------- */

double PairGranularSpinslide::memory_usage() { return 0.0; }

/* ---------------------------------------------------------------------- */

double PairGranularSpinslide::atom2cut(int i) { return 2.0 * atom->radius[i]; }

double PairGranularSpinslide::radii2cut(double r1, double r2) { return r1 + r2; }

/* ----------------------------------------------------------------------
   the history of contact (j, i) from that of (i, j): the tangential
   spring's displacement changes sign with the normal; the twisting spring's
   angle does not (the relative spin about the normal is the same seen from
   either sphere), unless `twist_transfer negate` (pair_style granular's
   convention); the curve point does not
------------------------------------------------------------------------- */

void PairGranularSpinslide::transfer_history(double* source, double* target) {
  target[kHistShear + 0] = -source[kHistShear + 0];
  target[kHistShear + 1] = -source[kHistShear + 1];
  target[kHistShear + 2] = -source[kHistShear + 2];
  target[kHistTwist] = twist_negate ? -source[kHistTwist] : source[kHistTwist];
  for (int k = kHistRatio; k < kHistRoll; ++k) target[k] = source[k];
  // the rolling spring, like the tangential one, changes sign
  for (int k = kHistRoll; k < kHistRoll + 3; ++k) target[k] = -source[k];
}
