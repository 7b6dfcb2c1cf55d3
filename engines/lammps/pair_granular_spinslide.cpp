//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
// The pair style granular/spinslide (pair_granular_spinslide.h, README.md):
// its life cycle (the history fix, init_style, init_one's cutoffs and
// mixing, the per-type arrays and their memory).  The force computation is in
// pair_granular_spinslide_compute.cpp, pair_style/pair_coeff's parsing in
// pair_granular_spinslide_coeff.cpp, the restart file's section in
// pair_granular_spinslide_restart.cpp.
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
// Per-contact history (FixNeighHistory, kHistSize = 13 values): the
// tangential spring (3, lab frame), the twisting spring, where the last
// slip left the limit curve (eps, F, T, F', F'': the next search's start),
// whether it slid, and the rolling spring (3).

#include "pair_granular_spinslide.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "fix_dummy.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

#include "legacy_contact.h"
#include "spinslide_contact.h"

#include <algorithm>
#include <cstddef>
#include <string>

using namespace LAMMPS_NS;

using spinslide_lammps::kHistRatio;
using spinslide_lammps::kHistRoll;
using spinslide_lammps::kHistShear;
using spinslide_lammps::kHistSize;
using spinslide_lammps::kHistTwist;

/* ---------------------------------------------------------------------- */

PairGranularSpinslide::PairGranularSpinslide(LAMMPS* lmp) : Pair(lmp) {
  single_enable = 1;
  single_extra = kSingleSize;
  svector = new double[single_extra];
  // pair_style's settings and pair_coeff's coefficients go into restart
  // files (pair_granular_spinslide_restart.cpp)
  restartinfo = 1;
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

/* ----------------------------------------------------------------------
   the bytes this pair allocated: Pair's per-atom energy and virial arrays;
   per type pair, (ntypes + 1)^2 each, setflag, cutsq and cutoff_type (with
   their row pointers, as LAMMPS counts them), the contact laws and the
   older styles' laws; per type the four radius arrays; the extra
   quantities of compute pair and single().  (The contact history is the
   history fix's, which counts it.)
------------------------------------------------------------------------- */

double PairGranularSpinslide::memory_usage() {
  double bytes = Pair::memory_usage();
  bytes += static_cast<double>(nextra + single_extra) * sizeof(double);
  if (!allocated) return bytes;
  const int n = atom->ntypes + 1;
  bytes += memory->usage(setflag, n, n);
  bytes += memory->usage(cutsq, n, n);
  bytes += memory->usage(cutoff_type, n, n);
  bytes += static_cast<double>(laws.capacity()) * sizeof(spinslide_lammps::ContactLaw);
  bytes += static_cast<double>(legacy_laws.capacity()) * sizeof(spinslide_lammps::LegacyLaw);
  // onerad_dynamic, onerad_frozen, maxrad_dynamic, maxrad_frozen
  bytes += 4.0 * n * sizeof(double);
  return bytes;
}

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
