//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
// The fix wall/gran/spinslide (fix_wall_gran_spinslide.h, README.md).
//
// A sphere i of radius r_i and mass m_i whose centre is at a distance
// s < r_i from a wall touches it with overlap d = r_i - s, unit normal n from
// the wall to the centre, R* = r_i and m* = m_i (the wall: infinite radius
// and mass, at rest); its slip velocity at the contact is v_i - r_i w_i x n
// and its spin about the normal w_i.n.  The forces and the history update
// are spinslide_lammps::contact_force (spinslide_contact.h), the pair style
// granular/spinslide's.  As LAMMPS' fix wall/gran, the friction acts at r_i
// from the centre, and the springs are not advanced during setup.
//
// The contact history (spinslide_lammps::kHistSize values: the tangential
// spring, the twisting spring, the last slip's curve point) is one per atom (a sphere
// touches at most one of two parallel walls), kept in `history`, which moves
// with its atom between processes and into restart files.
//
// The command's parsing is in fix_wall_gran_spinslide_args.cpp.

#include "fix_wall_gran_spinslide.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "update.h"
#include "utils.h"

#include "legacy_contact.h"
#include "spinslide_contact.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace FixConst;

using spinslide_lammps::kHistSize;

/* ---------------------------------------------------------------------- */

FixWallGranSpinslide::~FixWallGranSpinslide() {
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(history);
}

/* ---------------------------------------------------------------------- */

int FixWallGranSpinslide::setmask() { return POST_FORCE; }

/* ---------------------------------------------------------------------- */

void FixWallGranSpinslide::init() {
  dt = update->dt;
  int dropped_all = 0;
  MPI_Allreduce(&dropped, &dropped_all, 1, MPI_INT, MPI_SUM, world);
  if (dropped_all > 0 && comm->me == 0)
    error->warning(FLERR,
                   "Fix {}: the restart file's wall history of {} atoms has another layout (an "
                   "earlier plugin's): dropped, those contacts start unloaded",
                   style, dropped_all);
  dropped = 0;
  // moduli legacy with damping tsuji: LAMMPS 29 Sep 2021's fix wall/gran
  // turns its damping number into Tsuji's alpha at every init (every run),
  // so that a second run damps with alpha(alpha(e)); reproduced for A/B
  // runs only (moduli exact: alpha(e) throughout).
  if (legacy_moduli && law.damping == spinslide_lammps::DampingModel::kTsuji && ninit++ > 0)
    law.damp = spinslide_lammps::tsuji_alpha_by_pow(law.damp);
  if (!utils::strmatch(update->integrate_style, "^verlet"))
    error->all(FLERR, "Fix {} supports run_style verlet only", style);
  for (int i = 0; i < modify->nfix; i++)
    if (modify->fix[i]->rigid_flag)
      error->all(FLERR, "Fix {} does not support rigid bodies yet", style);
}

/* ---------------------------------------------------------------------- */

void FixWallGranSpinslide::setup(int vflag) { post_force(vflag); }

/* ---------------------------------------------------------------------- */

void FixWallGranSpinslide::reset_dt() { dt = update->dt; }

/* ---------------------------------------------------------------------- */

void FixWallGranSpinslide::clear_statistics() {
  for (double& s : stats_local) s = 0.0;
  stats_reduced = 0;
}

/* ----------------------------------------------------------------------
   sphere i against the wall at `touch`: the effective radius as LAMMPS'
   fix wall/gran takes it (R* = r_i on a flat wall, r_i r_w/(r_i + r_w) on
   one of curvature radius r_w), the velocity relative to the wall's
   surface, the spin about the normal (the wall does not spin)
------------------------------------------------------------------------- */

void FixWallGranSpinslide::apply_contact(int i, const WallTouch& touch, double* h, bool advance) {
  if (legacy.model != spinslide_lammps::LegacyModel::kNone) {
    apply_legacy_contact(i, touch, h, advance);
    return;
  }
  double** v = atom->v;
  double** f = atom->f;
  double** omega = atom->omega;
  double** torque = atom->torque;
  const double radi = atom->radius[i];
  const double* d = touch.d;

  const double dist = std::sqrt(touch.rsq);
  const double inv = 1.0 / dist;
  spinslide_lammps::ContactState state;
  state.n[0] = d[0] * inv;
  state.n[1] = d[1] * inv;
  state.n[2] = d[2] * inv;
  state.delta = radi - dist;
  state.reff = touch.rwall == 0.0 ? radi : radi * touch.rwall / (radi + touch.rwall);
  state.meff = atom->rmass[i];
  for (int k = 0; k < 3; ++k) {
    state.vr[k] = v[i][k] - touch.vwall[k];
    state.wr[k] = radi * omega[i][k];
    state.relrot[k] = omega[i][k];
  }
  const double nx = state.n[0], ny = state.n[1], nz = state.n[2];
  state.twist_rate = omega[i][0] * nx + omega[i][1] * ny + omega[i][2] * nz;

  spinslide_lammps::ContactForce cf;
  spinslide_lammps::contact_force(law, state, h, dt, advance, coupled != 0, error, style, cf);
  const double* fs = cf.fs;

  stats_local[kStatContacts] += 1.0;
  if (cf.capped) stats_local[kStatSliding] += 1.0;
  stats_local[kStatForce] += std::sqrt(fs[0] * fs[0] + fs[1] * fs[1] + fs[2] * fs[2]);
  stats_local[kStatTorque] += std::fabs(cf.mt);

  // the normal force and the friction, which acts at r_i from the centre
  f[i][0] += nx * cf.fn + fs[0];
  f[i][1] += ny * cf.fn + fs[1];
  f[i][2] += nz * cf.fn + fs[2];
  const double tor1 = ny * fs[2] - nz * fs[1];
  const double tor2 = nz * fs[0] - nx * fs[2];
  const double tor3 = nx * fs[1] - ny * fs[0];
  torque[i][0] -= radi * tor1;
  torque[i][1] -= radi * tor2;
  torque[i][2] -= radi * tor3;
  if (law.twist != spinslide_lammps::TwistModel::kNone) {
    torque[i][0] += cf.mt * nx;
    torque[i][1] += cf.mt * ny;
    torque[i][2] += cf.mt * nz;
  }
  // rolling resistance: R* n x F_r
  if (law.rolling) {
    const double* fr = cf.fr;
    torque[i][0] += state.reff * (ny * fr[2] - nz * fr[1]);
    torque[i][1] += state.reff * (nz * fr[0] - nx * fr[2]);
    torque[i][2] += state.reff * (nx * fr[1] - ny * fr[0]);
  }
}

/* ----------------------------------------------------------------------
   sphere i against the wall at `touch` in one of LAMMPS' older styles
   (legacy_contact.h), in fix wall/gran's arithmetic: R* from the wall's
   curvature radius for hertz/history, the friction at r_i from the centre
------------------------------------------------------------------------- */

void FixWallGranSpinslide::apply_legacy_contact(int i, const WallTouch& touch, double* h,
                                                bool advance) {
  double** v = atom->v;
  double** omega = atom->omega;
  const double radi = atom->radius[i];
  spinslide_lammps::LegacyContact c{};
  for (int k = 0; k < 3; ++k) {
    c.del[k] = touch.d[k];
    c.vr[k] = v[i][k] - touch.vwall[k];
    c.wr[k] = radi * omega[i][k];
  }
  c.rsq = touch.rsq;
  c.radsum = radi;
  c.meff = atom->rmass[i];
  if (legacy.model == spinslide_lammps::LegacyModel::kHertzHistory) {
    const double r = std::sqrt(touch.rsq);
    const double rwall = touch.rwall;
    c.polyhertz = rwall == 0.0 ? std::sqrt((radi - r) * radi)
                               : std::sqrt((radi - r) * radi * rwall / (rwall + radi));
  }
  const spinslide_lammps::LegacyForce lf = spinslide_lammps::legacy_force(
      legacy, c, h, dt, advance, legacy.model == spinslide_lammps::LegacyModel::kHertzHistory);
  h[spinslide_lammps::kHistSliding] = lf.capped ? 1.0 : 0.0;
  for (int k = 0; k < 3; ++k) {
    atom->f[i][k] += lf.f[k];
    atom->torque[i][k] -= radi * lf.tor[k];
  }
  stats_local[kStatContacts] += 1.0;
  if (lf.capped) stats_local[kStatSliding] += 1.0;
  stats_local[kStatForce] +=
      std::sqrt(lf.fs[0] * lf.fs[0] + lf.fs[1] * lf.fs[1] + lf.fs[2] * lf.fs[2]);
}

/* ----------------------------------------------------------------------
   the planes: the signed distance from the nearer wall (positive above lo,
   negative below hi); the z cylinder: the vector from the nearest point of
   its surface, the curvature radius -2R inside it and 2R outside (LAMMPS'
   fix wall/gran convention, kept for identical results)
------------------------------------------------------------------------- */

void FixWallGranSpinslide::post_force(int /*vflag*/) {
  // setup() computes forces without advancing the springs
  const bool advance = update->setupflag == 0;
  clear_statistics();
  begin_step();
  const int* mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) touch_atom(i, advance);
}

void FixWallGranSpinslide::begin_step() {}

void FixWallGranSpinslide::touch_atom(int i, bool advance) {
  double** x = atom->x;
  const double radi = atom->radius[i];
  double* h = history[i];
  WallTouch touch{{0.0, 0.0, 0.0}, 0.0, 0.0, {0.0, 0.0, 0.0}};
  bool near = true;
  if (wallstyle == WallStyle::kPlane) {
    const double above_lo = x[i][axis] - lo;
    const double below_hi = hi - x[i][axis];
    touch.d[axis] = above_lo < below_hi ? above_lo : -below_hi;
  } else {
    const double delxy = std::sqrt(x[i][0] * x[i][0] + x[i][1] * x[i][1]);
    const double delr = cylradius - delxy;
    near = delr <= radi;
    if (near) {
      touch.d[0] = -delr / delxy * x[i][0];
      touch.d[1] = -delr / delxy * x[i][1];
      touch.rwall = delxy < cylradius ? -2 * cylradius : 2 * cylradius;
    }
  }
  touch.rsq = touch.d[0] * touch.d[0] + touch.d[1] * touch.d[1] + touch.d[2] * touch.d[2];
  if (!near || touch.rsq > radi * radi) {
    // apart: forget the contact
    for (int k = 0; k < kHistSize; k++) h[k] = 0.0;
    return;
  }
  apply_contact(i, touch, h, advance);
}

/* ---------------------------------------------------------------------- */

double FixWallGranSpinslide::compute_vector(int n) {
  if (!stats_reduced) {
    MPI_Allreduce(stats_local, stats_all, kStatSize, MPI_DOUBLE, MPI_SUM, world);
    stats_reduced = 1;
  }
  return stats_all[n];
}

/* ---------------------------------------------------------------------- */

// the per-atom history, with its row pointers (as LAMMPS counts them)
double FixWallGranSpinslide::memory_usage() {
  return history == nullptr ? 0.0 : memory->usage(history, atom->nmax, kHistSize);
}

/* ----------------------------------------------------------------------
   the per-atom history: one contact per atom, following its atom
------------------------------------------------------------------------- */

void FixWallGranSpinslide::grow_arrays(int nmax) {
  memory->grow(history, nmax, kHistSize, "wall/gran/spinslide:history");
}

void FixWallGranSpinslide::copy_arrays(int i, int j, int /*delflag*/) {
  for (int k = 0; k < kHistSize; k++) history[j][k] = history[i][k];
}

void FixWallGranSpinslide::set_arrays(int i) {
  for (int k = 0; k < kHistSize; k++) history[i][k] = 0.0;
}

int FixWallGranSpinslide::pack_exchange(int i, double* buf) {
  for (int k = 0; k < kHistSize; k++) buf[k] = history[i][k];
  return kHistSize;
}

int FixWallGranSpinslide::unpack_exchange(int nlocal, double* buf) {
  for (int k = 0; k < kHistSize; k++) history[nlocal][k] = buf[k];
  return kHistSize;
}

/* ----------------------------------------------------------------------
   restart files: each fix's block of an atom's extra values starts with
   the block's length (itself included)
------------------------------------------------------------------------- */

int FixWallGranSpinslide::pack_restart(int i, double* buf) {
  buf[0] = kHistSize + 1;
  for (int k = 0; k < kHistSize; k++) buf[k + 1] = history[i][k];
  return kHistSize + 1;
}

void FixWallGranSpinslide::unpack_restart(int nlocal, int nth) {
  const double* extra = atom->extra[nlocal];
  int m = 0;
  for (int skip = 0; skip < nth; skip++) m += static_cast<int>(extra[m]);
  // a record of another length (an earlier plugin's shorter history) is
  // dropped, with a warning at init(): the contact starts unloaded
  if (static_cast<int>(extra[m]) != kHistSize + 1) {
    for (int k = 0; k < kHistSize; k++) history[nlocal][k] = 0.0;
    ++dropped;
    return;
  }
  m++;
  for (int k = 0; k < kHistSize; k++) history[nlocal][k] = extra[m + k];
}
int FixWallGranSpinslide::size_restart(int /*nlocal*/) { return kHistSize + 1; }

int FixWallGranSpinslide::maxsize_restart() { return kHistSize + 1; }
