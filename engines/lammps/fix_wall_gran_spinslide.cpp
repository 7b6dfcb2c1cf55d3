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

// The command's syntax, for messages.
std::string syntax(bool region_style) {
  return std::string(region_style ? "fix ID group wall/gran/region/spinslide"
                                  : "fix ID group wall/gran/spinslide") +
         " E eta_n|e nu mu [xgammat x] [coupling yes|no] [moduli exact|legacy] [limit_damping] "
         "[damping viscoelastic|tsuji] " +
         (region_style ? "region ID" : "xplane|yplane|zplane lo hi | zcylinder radius");
}

}  // namespace

/* ---------------------------------------------------------------------- */

FixWallGranSpinslide::FixWallGranSpinslide(LAMMPS* lmp, int narg, char** arg)
    : Fix(lmp, narg, arg) {
  const bool region_style = utils::strmatch(style, "region");
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR,
               "Fix {} requires atom attributes radius, rmass, omega, torque (atom_style sphere)",
               style);
  for (int iarg = 3; iarg < narg; iarg++) {
    const std::string key = arg[iarg];
    if (key == "region" && !region_style)
      error->all(FLERR, "Fix {}: region: a region wall is fix wall/gran/region/spinslide", style);
    if (key == "region" || key == "zcylinder") continue;
    const std::string why = spinslide_lammps::unsupported_granular_keyword(key);
    if (!why.empty()) error->all(FLERR, "Fix {}: {}: {}", style, key, why);
  }
  if (narg < 9) error->all(FLERR, "Illegal fix {} command: {}", style, syntax(region_style));

  const double e_one = utils::numeric(FLERR, arg[3], false, lmp);
  eta_n = utils::numeric(FLERR, arg[4], false, lmp);
  const double nu_one = utils::numeric(FLERR, arg[5], false, lmp);
  mu = utils::numeric(FLERR, arg[6], false, lmp);
  xgammat = 1.0;
  coupled = 1;
  legacy_moduli = 0;

  if (parse_walls_and_options(narg, arg) != 1 || (wallstyle == WallStyle::kRegion) != region_style)
    error->all(FLERR, "Illegal fix {} command: give one wall: {}", style, syntax(region_style));
  check_parameters(e_one, nu_one);
  if (tsuji) {
    // damping tsuji: the second number is a coefficient of restitution.
    if (!(eta_n > 0.0 && eta_n <= 1.0))
      error->all(FLERR,
                 "Fix {}: with damping tsuji, the second number is the coefficient of "
                 "restitution, in (0, 1]",
                 style);
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
  if (history)
    for (int i = 0; i < atom->nlocal; i++)
      for (int k = 0; k < kHistSize; k++) history[i][k] = 0.0;

  dt = update->dt;
}

// The keywords after the four numbers: the wall (xplane|yplane|zplane lo
// hi, zcylinder radius, region ID) and the options; returns how many walls
// were given.
int FixWallGranSpinslide::parse_walls_and_options(int narg, char** arg) {
  int nwalls = 0;
  for (int iarg = 7; iarg < narg;) {
    const std::string key = arg[iarg];
    if (key == "xplane" || key == "yplane" || key == "zplane") {
      if (iarg + 2 >= narg)
        error->all(FLERR, "Illegal fix {} command: {} needs lo and hi", style, key);
      wallstyle = WallStyle::kPlane;
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
    if (iarg + 1 >= narg) error->all(FLERR, "Illegal fix {} command: {} needs a value", style, key);
    if (key == "zcylinder") {
      wallstyle = WallStyle::kZCylinder;
      cylradius = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      ++nwalls;
    } else if (key == "region") {
      wallstyle = WallStyle::kRegion;
      idregion = arg[iarg + 1];
      ++nwalls;
    } else {
      parse_option(key, arg[iarg + 1]);
    }
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
    if (coupled < 0) error->all(FLERR, "Illegal fix {} command: coupling {}", style, value);
  } else if (key == "damping") {
    tsuji = spinslide_lammps::either(value, {"tsuji"}, {"viscoelastic"});
    if (tsuji < 0)
      error->all(FLERR, "Fix {}: damping {}: viscoelastic (default) or tsuji", style, value);
  } else if (key == "moduli") {
    legacy_moduli = spinslide_lammps::either(value, {"legacy"}, {"exact"});
    if (legacy_moduli < 0) error->all(FLERR, "Illegal fix {} command: moduli {}", style, value);
  } else {
    error->all(FLERR, "Illegal fix {} command: unknown keyword {} ({})", style, key,
               syntax(wallstyle == WallStyle::kRegion));
  }
}

// The material and the walls, checked.
void FixWallGranSpinslide::check_parameters(double e_one, double nu_one) {
  if (!(e_one > 0.0)) error->all(FLERR, "Fix {}: E must be > 0", style);
  if (!(nu_one > -1.0 && nu_one <= 0.5))
    error->all(FLERR, "Fix {}: nu must be in (-1, 0.5]", style);
  if (!(eta_n >= 0.0) || !(mu >= 0.0) || !(xgammat >= 0.0))
    error->all(FLERR, "Fix {}: eta_n, mu and xgammat must be >= 0", style);
  if (wallstyle == WallStyle::kPlane) {
    if (!(lo < hi)) error->all(FLERR, "Fix {}: the walls need lo < hi", style);
    if (domain->periodicity[axis])
      error->all(FLERR, "Fix {}: no wall in a periodic dimension", style);
  } else if (wallstyle == WallStyle::kZCylinder) {
    if (!(cylradius > 0.0)) error->all(FLERR, "Fix {}: the cylinder's radius must be > 0", style);
    if (domain->xperiodic || domain->yperiodic)
      error->all(FLERR, "Fix {}: a zcylinder wall needs x and y not periodic", style);
  } else if (domain->find_region(idregion) < 0) {
    // (here, not in the region fix's constructor: an error after the base
    // registered its per-atom callbacks would fail to unregister them)
    error->all(FLERR, "Fix {}: region {} does not exist", style, idregion);
  }
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

spinslide_lammps::ContactLaw FixWallGranSpinslide::contact_law() const {
  spinslide_lammps::ContactLaw law;
  law.kn = kn;
  law.kt = kt;
  law.eta_n = eta_n;
  law.xgammat = xgammat;
  law.mu = mu;
  law.limit_damping = limit_damping != 0;
  law.tsuji = tsuji != 0;
  return law;
}

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

void FixWallGranSpinslide::apply_contact(int i, const WallTouch& touch, double* h,
                                         const spinslide_lammps::ContactLaw& law, bool advance) {
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
  torque[i][0] += cf.mt * nx;
  torque[i][1] += cf.mt * ny;
  torque[i][2] += cf.mt * nz;
}

/* ----------------------------------------------------------------------
   the planes: the signed distance from the nearer wall (positive above lo,
   negative below hi); the z cylinder: the vector from the nearest point of
   its surface, the curvature radius -2R inside it and 2R outside (LAMMPS'
   fix wall/gran convention, kept for identical results)
------------------------------------------------------------------------- */

void FixWallGranSpinslide::post_force(int /*vflag*/) {
  double** x = atom->x;
  const double* radius = atom->radius;
  const int* mask = atom->mask;
  const int nlocal = atom->nlocal;
  // setup() computes forces without advancing the springs
  const bool advance = update->setupflag == 0;
  const spinslide_lammps::ContactLaw law = contact_law();
  clear_statistics();

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double radi = radius[i];
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
      continue;
    }
    apply_contact(i, touch, h, law, advance);
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
