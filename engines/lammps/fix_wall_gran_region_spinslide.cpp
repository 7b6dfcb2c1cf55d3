//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
// The fix wall/gran/region/spinslide (fix_wall_gran_region_spinslide.h).
//
// Each step, a sphere of the group whose centre is inside the region (as
// the region's `side` defines inside) asks the region for the faces within
// its radius: for each, the vector from the face's nearest point to the
// centre, the face's curvature radius there and its index.  Each contact is
// a wall contact of fix wall/gran/spinslide (apply_contact), with the
// velocity of the region's surface at the contact point when the region
// moves or rotates.  The history of each contact (kHistSize values) is kept
// per atom in a slot tagged with the face's index, so that a sphere rolling
// across an edge of a block keeps the history of the face it stays on.

#include "fix_wall_gran_region_spinslide.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "lmptype.h"
#include "memory.h"
#include "region.h"
#include "update.h"

#include <cstdio>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;

using spinslide_lammps::kHistSize;

/* ---------------------------------------------------------------------- */

FixWallGranRegionSpinslide::FixWallGranRegionSpinslide(LAMMPS* lmp, int narg, char** arg)
    : FixWallGranSpinslide(lmp, narg, arg) {
  // (the base checked that the region exists)
  region = domain->regions[domain->find_region(idregion)];
  region_style = region->style;
  nregion = region->nregion;
  tmax = region->tmax;
  if (tmax > kMaxSlots)
    error->all(FLERR, "Fix {}: region {} lets a sphere touch {} faces at once, more than {}", style,
               idregion, tmax, kMaxSlots);
  restart_global = 1;

  // the base's one history per atom is replaced by one per contact
  memory->destroy(history);
  history = nullptr;
  slot_of_contact = new int[tmax];
  FixWallGranRegionSpinslide::grow_arrays(atom->nmax);
  for (int i = 0; i < atom->nlocal; i++) ncontact[i] = 0;
}

/* ---------------------------------------------------------------------- */

FixWallGranRegionSpinslide::~FixWallGranRegionSpinslide() {
  delete[] slot_of_contact;
  memory->destroy(ncontact);
  memory->destroy(walls);
  memory->destroy(history_many);
}

/* ---------------------------------------------------------------------- */

void FixWallGranRegionSpinslide::init() {
  FixWallGranSpinslide::init();
  const int iregion = domain->find_region(idregion);
  if (iregion < 0) error->all(FLERR, "Fix {}: region {} does not exist", style, idregion);
  region = domain->regions[iregion];
  if (region->tmax > tmax)
    error->all(FLERR,
               "Fix {}: region {} was redefined with more faces a sphere can touch ({} > {}); "
               "define the fix again",
               style, idregion, region->tmax, tmax);
  // A region deleted and defined again (another style or shape), or a
  // restart whose region motion does not fit: its motion starts afresh, as
  // in LAMMPS' fix wall/gran/region.
  if (region_style != region->style || nregion != region->nregion) {
    error->warning(FLERR, "Fix {}: region {} changed between runs: its motion is reset", style,
                   idregion);
    region->reset_vel();
  }
  if (motion_reset) {
    error->warning(FLERR,
                   "Fix {}: the restart's motion of region {} does not fit the region: its "
                   "motion is reset",
                   style, idregion);
    region->reset_vel();
  }
}

/* ---------------------------------------------------------------------- */

void FixWallGranRegionSpinslide::begin_step() {
  // a moving region: its displacement and velocities of this step
  moving = region->dynamic_check() != 0;
  if (moving) {
    region->prematch();
    region->set_velocity();
  }
}

void FixWallGranRegionSpinslide::touch_atom(int i, bool advance) {
  double** x = atom->x;
  // A centre outside the region (a sphere pushed through a face) touches
  // nothing, and its contacts keep their history until it comes back, as
  // in LAMMPS' fix wall/gran/region (in.pour.drum's spheres thrown up
  // through the drum's lid do this).
  if (region->match(x[i][0], x[i][1], x[i][2]) == 0) return;
  const int nc = region->surface(x[i][0], x[i][1], x[i][2], atom->radius[i]);
  if (nc > tmax)
    error->one(FLERR, "Fix {}: region {} reports {} contacts for one sphere, more than its {}",
               style, idregion, nc, tmax);
  match_contacts(i, nc);
  for (int ic = 0; ic < nc; ic++) {
    const Region::Contact& c = region->contact[ic];
    WallTouch touch{{c.delx, c.dely, c.delz}, c.r * c.r, c.radius, {0.0, 0.0, 0.0}};
    if (moving) region->velocity_contact(touch.vwall, x[i], ic);
    apply_contact(i, touch, history_many[i][slot_of_contact[ic]], advance);
  }
}

/* ---------------------------------------------------------------------- */

void FixWallGranRegionSpinslide::match_contacts(int i, int nc) {
  const Region::Contact* contact = region->contact;
  // drop the contacts whose face is not touched now (the last slot moves
  // into the hole)
  int n = ncontact[i];
  for (int s = 0; s < n;) {
    bool touched = false;
    for (int c = 0; c < nc && !touched; c++) touched = contact[c].iwall == walls[i][s];
    if (touched) {
      ++s;
      continue;
    }
    --n;
    walls[i][s] = walls[i][n];
    for (int k = 0; k < kHistSize; k++) history_many[i][s][k] = history_many[i][n][k];
  }
  // the slot of each contact: its face's, or a new one, unloaded
  const int kept = n;
  for (int c = 0; c < nc; c++) {
    int s = 0;
    while (s < kept && walls[i][s] != contact[c].iwall) ++s;
    if (s == kept) {
      s = n++;
      walls[i][s] = contact[c].iwall;
      for (int k = 0; k < kHistSize; k++) history_many[i][s][k] = 0.0;
    }
    slot_of_contact[c] = s;
  }
  ncontact[i] = n;
  // slots legacy: LAMMPS 29 Sep 2021's fix wall/gran/region indexes its
  // slot-to-contact map with the contact (history_many[i][c2r[ic]]), which
  // gives a sphere touching three faces another face's history when their
  // order turns; reproduced for A/B runs only (issue 30, in.granregion.box)
  if (legacy_slots && nc > 2) {
    int contact_in_slot[kMaxSlots];
    for (int c = 0; c < nc; c++) contact_in_slot[slot_of_contact[c]] = c;
    for (int c = 0; c < nc; c++) slot_of_contact[c] = contact_in_slot[c];
  }
}

/* ---------------------------------------------------------------------- */

// the per-atom arrays, with their row pointers (as LAMMPS counts them),
// and this step's slot per contact
double FixWallGranRegionSpinslide::memory_usage() {
  const int nmax = atom->nmax;
  double bytes = static_cast<double>(tmax) * sizeof(int);
  if (ncontact == nullptr) return bytes;
  bytes += memory->usage(ncontact, nmax);
  bytes += memory->usage(walls, nmax, tmax);
  bytes += memory->usage(history_many, nmax, tmax, kHistSize);
  return bytes;
}

/* ----------------------------------------------------------------------
   the region's motion (displacement, angle, previous state), as LAMMPS'
   fix wall/gran/region writes it: its length, then the region's record
------------------------------------------------------------------------- */

void FixWallGranRegionSpinslide::write_restart(FILE* fp) {
  if (comm->me != 0) return;
  int len = 0;
  region->length_restart_string(len);
  fwrite(&len, sizeof(int), 1, fp);
  region->write_restart(fp);
}

void FixWallGranRegionSpinslide::restart(char* buf) {
  int n = 0;
  if (!region->restart(buf, n)) motion_reset = 1;
}

/* ----------------------------------------------------------------------
   the per-atom arrays: the count of contacts, then per contact the face's
   index and the history
------------------------------------------------------------------------- */

void FixWallGranRegionSpinslide::grow_arrays(int nmax) {
  memory->grow(ncontact, nmax, "wall/gran/region/spinslide:ncontact");
  memory->grow(walls, nmax, tmax, "wall/gran/region/spinslide:walls");
  memory->grow(history_many, nmax, tmax, kHistSize, "wall/gran/region/spinslide:history");
}

void FixWallGranRegionSpinslide::copy_arrays(int i, int j, int /*delflag*/) {
  ncontact[j] = ncontact[i];
  for (int s = 0; s < ncontact[i]; s++) {
    walls[j][s] = walls[i][s];
    for (int k = 0; k < kHistSize; k++) history_many[j][s][k] = history_many[i][s][k];
  }
}

void FixWallGranRegionSpinslide::set_arrays(int i) { ncontact[i] = 0; }

int FixWallGranRegionSpinslide::pack_atom(int i, double* buf) const {
  int m = 0;
  buf[m++] = ubuf(ncontact[i]).d;
  for (int s = 0; s < ncontact[i]; s++) {
    buf[m++] = ubuf(walls[i][s]).d;
    for (int k = 0; k < kHistSize; k++) buf[m++] = history_many[i][s][k];
  }
  return m;
}

int FixWallGranRegionSpinslide::unpack_atom(int i, const double* buf) {
  int m = 0;
  ncontact[i] = static_cast<int>(ubuf(buf[m++]).i);
  for (int s = 0; s < ncontact[i]; s++) {
    walls[i][s] = static_cast<int>(ubuf(buf[m++]).i);
    for (int k = 0; k < kHistSize; k++) history_many[i][s][k] = buf[m++];
  }
  return m;
}

int FixWallGranRegionSpinslide::pack_exchange(int i, double* buf) { return pack_atom(i, buf); }

int FixWallGranRegionSpinslide::unpack_exchange(int nlocal, double* buf) {
  return unpack_atom(nlocal, buf);
}

// Restart files: each fix's block of an atom's extra values starts with the
// block's length (itself included).
int FixWallGranRegionSpinslide::pack_restart(int i, double* buf) {
  const int n = 1 + pack_atom(i, buf + 1);
  buf[0] = n;
  return n;
}

void FixWallGranRegionSpinslide::unpack_restart(int nlocal, int nth) {
  const double* extra = atom->extra[nlocal];
  int m = 0;
  for (int skip = 0; skip < nth; skip++) m += static_cast<int>(extra[m]);
  // a record of another layout (an earlier plugin's shorter history) is
  // dropped, with a warning at init(): the sphere starts without contacts
  const int count = static_cast<int>(ubuf(extra[m + 1]).i);
  if (count < 0 || count > tmax || static_cast<int>(extra[m]) != 2 + count * (kHistSize + 1)) {
    ncontact[nlocal] = 0;
    ++dropped;
    return;
  }
  unpack_atom(nlocal, extra + m + 1);
}

int FixWallGranRegionSpinslide::size_restart(int nlocal) {
  return 2 + ncontact[nlocal] * (kHistSize + 1);
}

int FixWallGranRegionSpinslide::maxsize_restart() { return 2 + tmax * (kHistSize + 1); }
