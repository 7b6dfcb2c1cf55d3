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

#include "fix_wall_gran_spinslide.h"
#include "keywords.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "update.h"
#include "utils.h"

#include "spinslide_contact.h"

#include <cmath>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;

using spinslide_lammps::kHistSize;

namespace {

// A wall given as NULL sits this far away.
constexpr double kFarAway = 1.0e20;

const char* const kSyntax =
    "fix ID group wall/gran/spinslide E eta_n|e nu mu [xgammat x] [coupling yes|no] "
    "[moduli exact|legacy] [limit_damping] [damping viscoelastic|tsuji] xplane|yplane|zplane lo "
    "hi";

}  // namespace

/* ---------------------------------------------------------------------- */

FixWallGranSpinslide::FixWallGranSpinslide(LAMMPS* lmp, int narg, char** arg)
    : Fix(lmp, narg, arg) {
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR,
               "Fix wall/gran/spinslide requires atom attributes radius, rmass, omega, "
               "torque (atom_style sphere)");
  for (int iarg = 3; iarg < narg; iarg++) {
    const std::string why = spinslide_lammps::unsupported_granular_keyword(arg[iarg]);
    if (!why.empty()) error->all(FLERR, "Fix wall/gran/spinslide: {}: {}", arg[iarg], why);
  }
  if (narg < 10) error->all(FLERR, "Illegal fix wall/gran/spinslide command: {}", kSyntax);

  const double e_one = utils::numeric(FLERR, arg[3], false, lmp);
  eta_n = utils::numeric(FLERR, arg[4], false, lmp);
  const double nu_one = utils::numeric(FLERR, arg[5], false, lmp);
  mu = utils::numeric(FLERR, arg[6], false, lmp);
  xgammat = 1.0;
  coupled = 1;
  legacy_moduli = 0;

  if (parse_walls_and_options(narg, arg) != 1)
    error->all(FLERR,
               "Illegal fix wall/gran/spinslide command: give one of xplane, yplane, "
               "zplane lo hi");
  check_parameters(e_one, nu_one);
  if (tsuji) {
    // damping tsuji: the second number is a coefficient of restitution.
    if (!(eta_n > 0.0 && eta_n <= 1.0))
      error->all(FLERR,
                 "Fix wall/gran/spinslide: with damping tsuji, the second number is the "
                 "coefficient of restitution, in (0, 1]");
    eta_n = spinslide_lammps::tsuji_alpha_by_pow(eta_n);
  }

  if (legacy_moduli) {
    // LAMMPS 29 Sep 2021 fix wall/gran's `hertz/material` and `mindlin NULL`
    // constants, for A/B runs: (4/3)E/(2(1-nu)), with 4/3 to 16 digits, and
    // E(2-nu)(1+nu)/4
    kn = e_one / (2 * (1 - nu_one)) * 1.333333333333333;
    kt = e_one / 4 * (2 - nu_one) * (1 + nu_one);
  } else {
    // the sphere against a wall of its own material
    kn = 4.0 / 3.0 * spinslide_lammps::effective_youngs(e_one, nu_one, e_one, nu_one);
    kt = 8 * spinslide_lammps::effective_shear(e_one, nu_one, e_one, nu_one);
  }

  create_attribute = 1;
  restart_peratom = 1;
  vector_flag = 1;
  size_vector = kStatSize;
  global_freq = 1;
  extvector = 1;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < kHistSize; k++) history[i][k] = 0.0;

  dt = update->dt;
}

/* ---------------------------------------------------------------------- */

// The keywords after the four numbers: the wall (xplane|yplane|zplane lo hi)
// and the options; returns how many walls were given.
int FixWallGranSpinslide::parse_walls_and_options(int narg, char** arg) {
  int nwalls = 0;
  for (int iarg = 7; iarg < narg;) {
    const std::string key = arg[iarg];
    if (key == "xplane" || key == "yplane" || key == "zplane") {
      if (iarg + 2 >= narg)
        error->all(FLERR, "Illegal fix wall/gran/spinslide command: {} needs lo and hi", key);
      axis = key[0] - 'x';
      lo = strcmp(arg[iarg + 1], "NULL") == 0 ? -kFarAway
                                              : utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      hi = strcmp(arg[iarg + 2], "NULL") == 0 ? kFarAway
                                              : utils::numeric(FLERR, arg[iarg + 2], false, lmp);
      ++nwalls;
      iarg += 3;
      continue;
    }
    if (key == "limit_damping") {  // (no value)
      limit_damping = 1;
      iarg += 1;
      continue;
    }
    if (iarg + 1 >= narg)
      error->all(FLERR, "Illegal fix wall/gran/spinslide command: {} needs a value", key);
    parse_option(key, arg[iarg + 1]);
    iarg += 2;
  }
  return nwalls;
}

// One option keyword and its value.
void FixWallGranSpinslide::parse_option(const std::string& key, const char* arg) {
  const std::string value = arg;
  if (key == "xgammat") {
    xgammat = utils::numeric(FLERR, arg, false, lmp);
  } else if (key == "coupling") {
    coupled = spinslide_lammps::either(value, {"yes", "on"}, {"no", "off"});
    if (coupled < 0)
      error->all(FLERR, "Illegal fix wall/gran/spinslide command: coupling {}", value);
  } else if (key == "damping") {
    tsuji = spinslide_lammps::either(value, {"tsuji"}, {"viscoelastic"});
    if (tsuji < 0)
      error->all(FLERR, "Fix wall/gran/spinslide: damping {}: viscoelastic (default) or tsuji",
                 value);
  } else if (key == "moduli") {
    legacy_moduli = spinslide_lammps::either(value, {"legacy"}, {"exact"});
    if (legacy_moduli < 0)
      error->all(FLERR, "Illegal fix wall/gran/spinslide command: moduli {}", value);
  } else {
    error->all(FLERR, "Illegal fix wall/gran/spinslide command: unknown keyword {} ({})", key,
               kSyntax);
  }
}

// The material and the walls, checked.
void FixWallGranSpinslide::check_parameters(double e_one, double nu_one) {
  if (!(e_one > 0.0)) error->all(FLERR, "Fix wall/gran/spinslide: E must be > 0");
  if (!(nu_one > -1.0 && nu_one <= 0.5))
    error->all(FLERR, "Fix wall/gran/spinslide: nu must be in (-1, 0.5]");
  if (!(eta_n >= 0.0) || !(mu >= 0.0) || !(xgammat >= 0.0))
    error->all(FLERR, "Fix wall/gran/spinslide: eta_n, mu and xgammat must be >= 0");
  if (!(lo < hi)) error->all(FLERR, "Fix wall/gran/spinslide: the walls need lo < hi");
  if (domain->periodicity[axis])
    error->all(FLERR, "Fix wall/gran/spinslide: no wall in a periodic dimension");
}

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
  if (!utils::strmatch(update->integrate_style, "^verlet"))
    error->all(FLERR, "Fix wall/gran/spinslide supports run_style verlet only");
  for (int i = 0; i < modify->nfix; i++)
    if (modify->fix[i]->rigid_flag)
      error->all(FLERR, "Fix wall/gran/spinslide does not support rigid bodies yet");
}

/* ---------------------------------------------------------------------- */

void FixWallGranSpinslide::setup(int vflag) { post_force(vflag); }

/* ---------------------------------------------------------------------- */

void FixWallGranSpinslide::reset_dt() { dt = update->dt; }

/* ---------------------------------------------------------------------- */

void FixWallGranSpinslide::post_force(int /*vflag*/) {
  double** x = atom->x;
  double** v = atom->v;
  double** f = atom->f;
  double** omega = atom->omega;
  double** torque = atom->torque;
  const double* radius = atom->radius;
  const double* rmass = atom->rmass;
  const int* mask = atom->mask;
  const int nlocal = atom->nlocal;
  // setup() computes forces without advancing the springs
  const bool advance = update->setupflag == 0;

  spinslide_lammps::ContactLaw law;
  law.kn = kn;
  law.kt = kt;
  law.eta_n = eta_n;
  law.xgammat = xgammat;
  law.mu = mu;
  law.limit_damping = limit_damping != 0;
  law.tsuji = tsuji != 0;

  for (double& s : stats_local) s = 0.0;
  stats_reduced = 0;

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;

    // the signed distance from the nearer wall (positive above lo, negative
    // below hi), and the squared distance
    const double above_lo = x[i][axis] - lo;
    const double below_hi = hi - x[i][axis];
    const double s = above_lo < below_hi ? above_lo : -below_hi;
    double d[3] = {0.0, 0.0, 0.0};
    d[axis] = s;
    const double rsq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    const double radi = radius[i];
    double* h = history[i];

    if (rsq > radi * radi) {
      // apart: forget the contact
      for (int k = 0; k < kHistSize; k++) h[k] = 0.0;
      continue;
    }

    const double dist = std::sqrt(rsq);
    const double inv = 1.0 / dist;
    spinslide_lammps::ContactState state;
    state.n[0] = d[0] * inv;
    state.n[1] = d[1] * inv;
    state.n[2] = d[2] * inv;
    state.delta = radi - dist;
    state.reff = radi;
    state.meff = rmass[i];
    // the wall is at rest and does not spin
    state.vr[0] = v[i][0];
    state.vr[1] = v[i][1];
    state.vr[2] = v[i][2];
    state.wr[0] = radi * omega[i][0];
    state.wr[1] = radi * omega[i][1];
    state.wr[2] = radi * omega[i][2];
    const double nx = state.n[0], ny = state.n[1], nz = state.n[2];
    state.twist_rate = omega[i][0] * nx + omega[i][1] * ny + omega[i][2] * nz;

    spinslide_lammps::ContactForce cf;
    spinslide_lammps::contact_force(law, state, h, dt, advance, coupled != 0, error,
                                    "fix wall/gran/spinslide", cf);
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
    torque[i][0] += cf.mt * nx;
    torque[i][1] += cf.mt * ny;
    torque[i][2] += cf.mt * nz;
  }
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

double FixWallGranSpinslide::memory_usage() {
  return static_cast<double>(atom->nmax) * kHistSize * sizeof(double);
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
  m++;
  for (int k = 0; k < kHistSize; k++) history[nlocal][k] = extra[m + k];
}

int FixWallGranSpinslide::size_restart(int /*nlocal*/) { return kHistSize + 1; }

int FixWallGranSpinslide::maxsize_restart() { return kHistSize + 1; }
