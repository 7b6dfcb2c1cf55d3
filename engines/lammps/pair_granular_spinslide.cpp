//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
// The pair style granular/spinslide (pair_granular_spinslide.h, README.md).
//
// Per contact and step, for spheres i and j with unit normal n (from j to i),
// overlap d = r_i + r_j - |x_i - x_j|, R* = r_i r_j/(r_i + r_j),
// m* = m_i m_j/(m_i + m_j) and patch radius a = sqrt(R* d):
//
//   normal     F_n = (4/3) E* d a - eta_n a m* v_n       (Hertz, viscoelastic damping)
//   tangential F_t = -k_t xi - x_gt eta_n a m* v_t,      k_t = 8 G* a   (Mindlin)
//   twisting   M   = -k_w phi - (x_gt eta_n a m* a^2/2) w_n,  k_w = k_t a^2/2 (Marshall)
//
// with xi the tangential spring (kept in the contact's tangent plane, its
// length preserved when the plane turns), phi the twisting spring, v_t the
// slip velocity at the contact and w_n the relative spin about n.  The
// springs are stretched by v_t dt and w_n dt each step.  The trial friction
// (F_t, M) is then capped at the load mu |F_n|:
//
//   coupling no:  |F_t| <= mu |F_n| and |M| <= (2/3) a mu |F_n| separately, as
//                 pair_style granular's `tangential mindlin NULL x_gt mu
//                 twisting marshall` (the same arithmetic, step for step);
//   coupling yes: (F_t, M) in mu |F_n| L, L spinslide's exact limit set of a
//                 Hertzian patch (Coulomb-Contensou): outside it, the trial
//                 is replaced by its nearest point of mu |F_n| L in the
//                 springs' energy metric |dF|^2/k_t + |dM|^2/k_w.
//
// When capped, the springs are rewritten so that spring + damping equals the
// capped friction (as pair_style granular does for its independent caps).

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
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

#include <spinslide/limit_set.hpp>
#include <spinslide/profile.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <limits>
#include <string>

using namespace LAMMPS_NS;

namespace {

// A spring's trial state is turned into the contact's plane only when its
// normal component matters against the friction limit (relative threshold).
constexpr double kFrameTolerance = 1e-10;

// The springs' energy metric in the limit set's units (F/(mu N), M/(mu N a))
// weighs the torque by a^2 k_t / k_w, which Marshall's k_w = k_t a^2/2 makes 2.
constexpr double kTorqueWeight = 2.0;

// The effective moduli of two materials (Hertz, Mindlin).
double effective_youngs(double e1, double nu1, double e2, double nu2) {
  return 1 / ((1 - nu1 * nu1) / e1 + (1 - nu2 * nu2) / e2);
}
double effective_shear(double e1, double nu1, double e2, double nu2) {
  return 1 / ((2 * (2 - nu1) * (1 + nu1) / e1) + (2 * (2 - nu2) * (1 + nu2) / e2));
}

const spinslide::hertz<double> hertz_patch{};

}  // namespace

/* ---------------------------------------------------------------------- */

PairGranularSpinslide::PairGranularSpinslide(LAMMPS* lmp) : Pair(lmp) {
  single_enable = 0;
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
  // input defines afterwards).
  id_dummy = "SPINSLIDE_HISTORY_DUMMY" + std::to_string(instance_me);
  id_history = "SPINSLIDE_HISTORY" + std::to_string(instance_me);
  modify->add_fix(id_dummy + " all DUMMY");
}

/* ---------------------------------------------------------------------- */

PairGranularSpinslide::~PairGranularSpinslide() {
  delete[] pvector;
  pvector = nullptr;
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
    memory->destroy(youngs);
    memory->destroy(poisson);
    memory->destroy(eta_n);
    memory->destroy(mu);
    memory->destroy(xgammat);
    memory->destroy(cutoff_type);
    memory->destroy(kn_hertz);
    memory->destroy(kt_mindlin);
    delete[] onerad_dynamic;
    delete[] onerad_frozen;
    delete[] maxrad_dynamic;
    delete[] maxrad_frozen;
  }
}

/* ----------------------------------------------------------------------
   the friction, independent caps (pair_style granular's mindlin + marshall)
------------------------------------------------------------------------- */

bool PairGranularSpinslide::friction_uncoupled(double* h, const double* vtr, double twist_rate,
                                               double kt, double damp_t, double k_tw,
                                               double damp_tw, double fscrit, double mtcrit,
                                               double* fs, double& mt) const {
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
    // pair_style granular caps against the spin's direction, not the trial's
    const double spin_sign = (twist_rate > 0) - (twist_rate < 0);
    h[kHistTwist] = 1.0 / k_tw * (mtcrit * spin_sign - damp_tw * twist_rate);
    mt = -mtcrit * spin_sign;
  }
  return capped;
}

/* ----------------------------------------------------------------------
   the friction, capped together on spinslide's Hertz limit set
------------------------------------------------------------------------- */

bool PairGranularSpinslide::friction_coupled(double* h, const double* vtr, double twist_rate,
                                             double kt, double damp_t, double k_tw, double damp_tw,
                                             double load, double a, double* fs, double& mt) const {
  // the trial: springs + damping
  fs[0] = -kt * h[0] - damp_t * vtr[0];
  fs[1] = -kt * h[1] - damp_t * vtr[1];
  fs[2] = -kt * h[2] - damp_t * vtr[2];
  mt = -k_tw * h[kHistTwist] - damp_tw * twist_rate;
  const double fmag = std::sqrt(fs[0] * fs[0] + fs[1] * fs[1] + fs[2] * fs[2]);
  const double tmag = std::fabs(mt);
  if (fmag == 0.0 && tmag == 0.0) return false;

  // The trial in the limit set's units, f = |F|/(mu N), t = |M|/(mu N a).
  // The metric diag(1/k_t, 1/k_t, 1/k_w) is isotropic in the tangent plane,
  // so the nearest point keeps the force's direction and the torque's sign:
  // the 3-D projection reduces to the one on the magnitudes (f, t) with
  // torque weight a^2 k_t/k_w = 2 (docs/contact.md; spring_friction.hpp).
  double fscale = 0.0, mcap = 0.0;
  bool capped;
  if (load > 0.0) {
    const double f = fmag / load, t = tmag / (load * a);
    if (!std::isfinite(f) || !std::isfinite(t)) {
      capped = true;  // a vanishing load against a finite trial: no friction
    } else {
      spinslide::limit_projection<double> p;
      try {
        p = spinslide::project_to_limit_set(hertz_patch, f, t, kTorqueWeight,
                                            spinslide::starting_ratio<double>{h[kHistRatio]});
      } catch (std::exception& e) {
        error->one(FLERR, "pair granular/spinslide: the projection failed: {}", e.what());
      }
      if (p.sticking) return false;
      capped = true;
      fscale = fmag > 0.0 ? p.force * load / fmag : 0.0;
      mcap = std::copysign(p.torque * load * a, mt);
      if (!std::isnan(p.ratio)) h[kHistRatio] = p.ratio;
    }
  } else {
    capped = true;  // no load, no friction
  }

  // slip: the capped friction, and the springs that give it with the damping
  fs[0] *= fscale;
  fs[1] *= fscale;
  fs[2] *= fscale;
  mt = mcap;
  for (int k = 0; k < 3; ++k) h[k] = -(fs[k] + damp_t * vtr[k]) / kt;
  h[kHistTwist] = -(mt + damp_tw * twist_rate) / k_tw;
  return capped;
}

/* ---------------------------------------------------------------------- */

void PairGranularSpinslide::compute(int eflag, int vflag) {
  ev_init(eflag, vflag);
  for (int k = 0; k < nextra; ++k) pvector[k] = 0.0;

  double** x = atom->x;
  double** v = atom->v;
  double** f = atom->f;
  double** omega = atom->omega;
  double** torque = atom->torque;
  const double* radius = atom->radius;
  const double* rmass = atom->rmass;
  const int* type = atom->type;
  const int* mask = atom->mask;
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
  double ncontacts = 0.0, nsliding = 0.0, sum_force = 0.0, sum_torque = 0.0;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int itype = type[i];
    const double xi = x[i][0], yi = x[i][1], zi = x[i][2];
    const double radi = radius[i];
    int* touch = firsttouch[i];
    double* allhistory = firsthistory[i];
    const int* jlist = firstneigh[i];
    const int jnum = numneigh[i];

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = xi - x[j][0];
      const double dely = yi - x[j][1];
      const double delz = zi - x[j][2];
      const int jtype = type[j];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const double radj = radius[j];
      const double radsum = radi + radj;
      double* history = &allhistory[kHistSize * jj];

      if (rsq >= radsum * radsum) {
        // apart: forget the contact
        touch[jj] = 0;
        for (int k = 0; k < kHistSize; ++k) history[k] = 0.0;
        continue;
      }
      touch[jj] = 1;

      const double r = std::sqrt(rsq);
      const double rinv = 1.0 / r;
      const double nx = delx * rinv, ny = dely * rinv, nz = delz * rinv;

      // relative velocity of i's centre against j's, and its normal part
      const double vr1 = v[i][0] - v[j][0];
      const double vr2 = v[i][1] - v[j][1];
      const double vr3 = v[i][2] - v[j][2];
      const double vnnr = vr1 * nx + vr2 * ny + vr3 * nz;

      double meff = rmass[i] * rmass[j] / (rmass[i] + rmass[j]);
      if (mask[i] & freeze_group_bit) meff = rmass[j];
      if (mask[j] & freeze_group_bit) meff = rmass[i];

      // Hertz with viscoelastic damping
      const double reff = radi * radj / radsum;
      const double delta = radsum - r;
      const double a = std::sqrt(delta * reff);
      const double fn_elastic = kn_hertz[itype][jtype] * delta * a;
      const double damp_n = eta_n[itype][jtype] * (a * meff);
      const double fn = fn_elastic + (-damp_n * vnnr);
      const double load_n = std::fabs(fn);
      const double fscrit = mu[itype][jtype] * load_n;

      // slip velocity at the contact point: tangential relative velocity
      // minus the surfaces' rotation (r_i w_i + r_j w_j) x n
      const double vt1 = vr1 - nx * vnnr;
      const double vt2 = vr2 - ny * vnnr;
      const double vt3 = vr3 - nz * vnnr;
      const double wr1 = radi * omega[i][0] + radj * omega[j][0];
      const double wr2 = radi * omega[i][1] + radj * omega[j][1];
      const double wr3 = radi * omega[i][2] + radj * omega[j][2];
      double vtr[3];
      vtr[0] = vt1 - (nz * wr2 - ny * wr3);
      vtr[1] = vt2 - (nx * wr3 - nz * wr1);
      vtr[2] = vt3 - (ny * wr1 - nx * wr2);

      // Mindlin and Marshall springs and their damping
      const double kt = kt_mindlin[itype][jtype] * a;
      const double damp_t = xgammat[itype][jtype] * damp_n;
      const double k_tw = 0.5 * kt * a * a;
      const double damp_tw = 0.5 * damp_t * a * a;
      const double twist_rate = (omega[i][0] - omega[j][0]) * nx +
                                (omega[i][1] - omega[j][1]) * ny + (omega[i][2] - omega[j][2]) * nz;

      if (advance) {
        // Keep the tangential spring in the tangent plane as the contact
        // turns: drop its normal part and restore its length.
        const double hn = history[0] * nx + history[1] * ny + history[2] * nz;
        if (std::fabs(hn) * kt > kFrameTolerance * fscrit) {
          const double len = std::sqrt(history[0] * history[0] + history[1] * history[1] +
                                       history[2] * history[2]);
          history[0] -= hn * nx;
          history[1] -= hn * ny;
          history[2] -= hn * nz;
          const double plen = std::sqrt(history[0] * history[0] + history[1] * history[1] +
                                        history[2] * history[2]);
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

      double fs[3], mt;
      bool capped;
      if (coupled) {
        capped = friction_coupled(history, vtr, twist_rate, kt, damp_t, k_tw, damp_tw, fscrit, a,
                                  fs, mt);
      } else {
        const double mtcrit = (2.0 / 3.0) * a * mu[itype][jtype] * load_n;
        capped = friction_uncoupled(history, vtr, twist_rate, kt, damp_t, k_tw, damp_tw, fscrit,
                                    mtcrit, fs, mt);
      }

      if (tally) {
        ncontacts += 1.0;
        if (capped) nsliding += 1.0;
        sum_force += std::sqrt(fs[0] * fs[0] + fs[1] * fs[1] + fs[2] * fs[2]);
        sum_torque += std::fabs(mt);
      }

      // forces and torques: the friction acts at the contact point, at
      // r - d/2 from each centre; the twisting torque about n
      const double fx = nx * fn + fs[0];
      const double fy = ny * fn + fs[1];
      const double fz = nz * fn + fs[2];
      f[i][0] += fx;
      f[i][1] += fy;
      f[i][2] += fz;

      const double tor1 = ny * fs[2] - nz * fs[1];
      const double tor2 = nz * fs[0] - nx * fs[2];
      const double tor3 = nx * fs[1] - ny * fs[0];
      const double arm_i = radi - 0.5 * delta;
      torque[i][0] -= arm_i * tor1;
      torque[i][1] -= arm_i * tor2;
      torque[i][2] -= arm_i * tor3;
      const double tw1 = mt * nx, tw2 = mt * ny, tw3 = mt * nz;
      torque[i][0] += tw1;
      torque[i][1] += tw2;
      torque[i][2] += tw3;

      if (newton_pair || j < nlocal) {
        f[j][0] -= fx;
        f[j][1] -= fy;
        f[j][2] -= fz;
        const double arm_j = radj - 0.5 * delta;
        torque[j][0] -= arm_j * tor1;
        torque[j][1] -= arm_j * tor2;
        torque[j][2] -= arm_j * tor3;
        torque[j][0] -= tw1;
        torque[j][1] -= tw2;
        torque[j][2] -= tw3;
      }
      if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fx, fy, fz, delx, dely, delz);
    }
  }
  pvector[kExtraContacts] = ncontacts;
  pvector[kExtraSliding] = nsliding;
  pvector[kExtraForce] = sum_force;
  pvector[kExtraTorque] = sum_torque;
}

/* ---------------------------------------------------------------------- */

void PairGranularSpinslide::allocate() {
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) setflag[i][j] = 0;
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  memory->create(youngs, n + 1, n + 1, "pair:youngs");
  memory->create(poisson, n + 1, n + 1, "pair:poisson");
  memory->create(eta_n, n + 1, n + 1, "pair:eta_n");
  memory->create(mu, n + 1, n + 1, "pair:mu");
  memory->create(xgammat, n + 1, n + 1, "pair:xgammat");
  memory->create(cutoff_type, n + 1, n + 1, "pair:cutoff_type");
  memory->create(kn_hertz, n + 1, n + 1, "pair:kn_hertz");
  memory->create(kt_mindlin, n + 1, n + 1, "pair:kt_mindlin");
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
      if (value == "yes" || value == "on")
        coupled = 1;
      else if (value == "no" || value == "off")
        coupled = 0;
      else
        error->all(FLERR, "Illegal pair_style granular/spinslide command: coupling {}", value);
    } else if (key == "twist_transfer") {
      if (value == "symmetric")
        twist_negate = 0;
      else if (value == "negate")
        twist_negate = 1;
      else
        error->all(FLERR, "Illegal pair_style granular/spinslide command: twist_transfer {}",
                   value);
    } else {
      error->all(FLERR, "Illegal pair_style granular/spinslide command: unknown keyword {}", key);
    }
  }
}

/* ----------------------------------------------------------------------
   pair_coeff I J E eta_n nu mu [xgammat x] [cutoff rc]
------------------------------------------------------------------------- */

void PairGranularSpinslide::coeff(int narg, char** arg) {
  if (narg < 6)
    error->all(FLERR,
               "Incorrect args for pair coefficients: "
               "pair_coeff I J E eta_n nu mu [xgammat x] [cutoff rc]");
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  const double e_one = utils::numeric(FLERR, arg[2], false, lmp);
  const double eta_one = utils::numeric(FLERR, arg[3], false, lmp);
  const double nu_one = utils::numeric(FLERR, arg[4], false, lmp);
  const double mu_one = utils::numeric(FLERR, arg[5], false, lmp);
  double xgt_one = 1.0, cut_one = -1.0;
  for (int iarg = 6; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Incorrect args for pair coefficients: {} needs a value", arg[iarg]);
    if (strcmp(arg[iarg], "xgammat") == 0)
      xgt_one = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    else if (strcmp(arg[iarg], "cutoff") == 0)
      cut_one = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    else
      error->all(FLERR, "Incorrect args for pair coefficients: unknown keyword {}", arg[iarg]);
  }
  if (!(e_one > 0.0)) error->all(FLERR, "pair_coeff granular/spinslide: E must be > 0");
  if (!(nu_one > -1.0 && nu_one <= 0.5))
    error->all(FLERR, "pair_coeff granular/spinslide: nu must be in (-1, 0.5]");
  if (!(eta_one >= 0.0) || !(mu_one >= 0.0) || !(xgt_one >= 0.0))
    error->all(FLERR, "pair_coeff granular/spinslide: eta_n, mu and xgammat must be >= 0");

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      youngs[i][j] = youngs[j][i] = e_one;
      poisson[i][j] = poisson[j][i] = nu_one;
      eta_n[i][j] = eta_n[j][i] = eta_one;
      mu[i][j] = mu[j][i] = mu_one;
      xgammat[i][j] = xgammat[j][i] = xgt_one;
      cutoff_type[i][j] = cutoff_type[j][i] = cut_one;
      kn_hertz[i][j] = kn_hertz[j][i] = 4.0 / 3.0 * effective_youngs(e_one, nu_one, e_one, nu_one);
      kt_mindlin[i][j] = kt_mindlin[j][i] = 8 * effective_shear(e_one, nu_one, e_one, nu_one);
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
        id_dummy, id_history + " all NEIGH_HISTORY " + std::to_string(int(kHistSize)), 1));
    if (fix_history == nullptr)
      error->all(FLERR, "Pair granular/spinslide could not create its history fix");
    fix_history->pair = this;
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
    // means of the damping, friction and tangential damping ratios
    const double ei = youngs[i][i], ej = youngs[j][j];
    const double nui = poisson[i][i], nuj = poisson[j][j];
    kn_hertz[i][j] = kn_hertz[j][i] = 4.0 / 3.0 * effective_youngs(ei, nui, ej, nuj);
    kt_mindlin[i][j] = kt_mindlin[j][i] = 8 * effective_shear(ei, nui, ej, nuj);
    eta_n[i][j] = eta_n[j][i] = std::sqrt(eta_n[i][i] * eta_n[j][j]);
    mu[i][j] = mu[j][i] = std::sqrt(mu[i][i] * mu[j][j]);
    xgammat[i][j] = xgammat[j][i] = std::sqrt(xgammat[i][i] * xgammat[j][j]);
    cutoff_type[i][j] = cutoff_type[j][i] = -1.0;
  }

  if (cutoff_type[i][j] > 0.0) return cutoff_type[i][j];

  // No cutoff given: contact distance of the largest spheres of the two
  // types (dynamic with dynamic or frozen); if a type has no sphere yet,
  // the largest contact distance of any.
  const bool known = (maxrad_dynamic[i] > 0.0 && maxrad_dynamic[j] > 0.0) ||
                     (maxrad_dynamic[i] > 0.0 && maxrad_frozen[j] > 0.0) ||
                     (maxrad_frozen[i] > 0.0 && maxrad_dynamic[j] > 0.0);
  if (known) {
    double cut = maxrad_dynamic[i] + maxrad_dynamic[j];
    cut = std::max(cut, maxrad_frozen[i] + maxrad_dynamic[j]);
    cut = std::max(cut, maxrad_dynamic[i] + maxrad_frozen[j]);
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
   convention); the ratio does not
------------------------------------------------------------------------- */

void PairGranularSpinslide::transfer_history(double* source, double* target) {
  target[kHistShear + 0] = -source[kHistShear + 0];
  target[kHistShear + 1] = -source[kHistShear + 1];
  target[kHistShear + 2] = -source[kHistShear + 2];
  target[kHistTwist] = twist_negate ? -source[kHistTwist] : source[kHistTwist];
  target[kHistRatio] = source[kHistRatio];
}
