//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (../../README.md).
//
// An analysis plugin for the examples (docs/lammps_pile.md): the compute
//
//   compute ID group spinslide/contacts
//
// a local array with one row per sphere-sphere contact of
// pair_style granular/spinslide (both spheres in the group), columns
//   1  f = |F_t| / (mu N)       the friction force in units of its cap
//   2  t = |M| / (mu N a)       the twisting torque in the limit set's units
//   3  1 if at the friction limit (sliding), else 0
//   4  N = |F_n|                the normal force
//   5  a                        the patch radius
// computed as the pair style's next force computation would compute them at
// the current positions and velocities: the springs advanced by one step
// (on a copy of the contact history: the run is not changed).  Without the
// advance, a contact that slid in the last step sits exactly on the limit
// and its sliding flag would be decided by rounding.  It reads the pair
// style's protected state through member pointers and needs the plugin
// spinslideplugin.so loaded first; the pair style has no single() (so no
// compute pair/local), and this stands in for it until it has one.  Wall
// contacts (fix wall/gran/spinslide) are not included.

#include "lammpsplugin.h"
#include "version.h"

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "error.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "update.h"

#include "../../pair_granular_spinslide.h"
#include "../../spinslide_contact.h"

#include <cmath>

using namespace LAMMPS_NS;

namespace {

// Member pointers to the pair style's protected state (naming them through
// a derived class is allowed; nothing of this class is ever created).
struct PairAccess : PairGranularSpinslide {
  static constexpr auto history = &PairAccess::fix_history;
  static constexpr auto coupled_ = &PairAccess::coupled;
  static constexpr auto freeze_bit = &PairAccess::freeze_group_bit;
  static constexpr auto kn = &PairAccess::kn_hertz;
  static constexpr auto kt = &PairAccess::kt_mindlin;
  static constexpr auto eta = &PairAccess::eta_n;
  static constexpr auto xgt = &PairAccess::xgammat;
  static constexpr auto mu_ = &PairAccess::mu;
};

constexpr int kColumns = 5;

class ComputeSpinslideContacts : public Compute {
 public:
  ComputeSpinslideContacts(LAMMPS* lmp, int narg, char** arg) : Compute(lmp, narg, arg) {
    if (narg != 3) error->all(FLERR, "Illegal compute spinslide/contacts command");
    local_flag = 1;
    size_local_cols = kColumns;
    size_local_rows = 0;
  }
  ~ComputeSpinslideContacts() override { memory->destroy(rows); }

  void init() override {
    pair = force->pair_match("granular/spinslide", 1);
    if (pair == nullptr)
      error->all(FLERR, "compute spinslide/contacts needs pair_style granular/spinslide");
  }

  void compute_local() override {
    invoked_local = update->ntimestep;
    auto* p = static_cast<PairGranularSpinslide*>(pair);
    FixNeighHistory* fix_history = p->*PairAccess::history;
    NeighList* list = p->list;
    if (fix_history == nullptr || list == nullptr)
      error->all(FLERR, "compute spinslide/contacts: the pair style is not set up (run 0 first)");
    const bool coupled = (p->*PairAccess::coupled_) != 0;
    const int freeze_bit = p->*PairAccess::freeze_bit;
    double** kn = p->*PairAccess::kn;
    double** kt = p->*PairAccess::kt;
    double** eta = p->*PairAccess::eta;
    double** xgt = p->*PairAccess::xgt;
    double** mu = p->*PairAccess::mu_;

    // the ghosts' positions and velocities of this step (as the next
    // step's communication will set them)
    comm->forward_comm();

    double** x = atom->x;
    double** v = atom->v;
    double** omega = atom->omega;
    const double* radius = atom->radius;
    const double* rmass = atom->rmass;
    const int* type = atom->type;
    const int* mask = atom->mask;
    int** firsttouch = fix_history->firstflag;
    double** firsthistory = fix_history->firstvalue;

    ncount = 0;
    for (int pass = 0; pass < 2; ++pass) {
      if (pass == 1) {
        if (ncount > nmax) {
          memory->destroy(rows);
          nmax = ncount;
          memory->create(rows, nmax, kColumns, "spinslide/contacts:rows");
        }
        array_local = rows;
        size_local_rows = ncount;
      }
      int n = 0;
      for (int ii = 0; ii < list->inum; ++ii) {
        const int i = list->ilist[ii];
        const int* jlist = list->firstneigh[i];
        for (int jj = 0; jj < list->numneigh[i]; ++jj) {
          const int j = jlist[jj] & NEIGHMASK;
          if (!firsttouch[i][jj]) continue;
          if (!(mask[i] & groupbit) || !(mask[j] & groupbit)) continue;
          const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
          const double rsq = dx * dx + dy * dy + dz * dz;
          const double radsum = radius[i] + radius[j];
          if (rsq >= radsum * radsum) continue;
          if (pass == 0) {
            ++n;
            continue;
          }
          const double r = std::sqrt(rsq);
          spinslide_lammps::ContactState s;
          s.n[0] = dx / r;
          s.n[1] = dy / r;
          s.n[2] = dz / r;
          s.delta = radsum - r;
          s.reff = radius[i] * radius[j] / radsum;
          double meff = rmass[i] * rmass[j] / (rmass[i] + rmass[j]);
          if (mask[i] & freeze_bit) meff = rmass[j];
          if (mask[j] & freeze_bit) meff = rmass[i];
          s.meff = meff;
          for (int k = 0; k < 3; ++k) {
            s.vr[k] = v[i][k] - v[j][k];
            s.wr[k] = radius[i] * omega[i][k] + radius[j] * omega[j][k];
          }
          s.twist_rate = (omega[i][0] - omega[j][0]) * s.n[0] +
                         (omega[i][1] - omega[j][1]) * s.n[1] +
                         (omega[i][2] - omega[j][2]) * s.n[2];
          const int it = type[i], jt = type[j];
          spinslide_lammps::ContactLaw law;
          law.kn = kn[it][jt];
          law.kt = kt[it][jt];
          law.eta_n = eta[it][jt];
          law.xgammat = xgt[it][jt];
          law.mu = mu[it][jt];
          double h[spinslide_lammps::kHistSize];
          for (int k = 0; k < spinslide_lammps::kHistSize; ++k)
            h[k] = firsthistory[i][spinslide_lammps::kHistSize * jj + k];
          spinslide_lammps::ContactForce cf;
          spinslide_lammps::contact_force(law, s, h, update->dt, true, coupled, error,
                                          "compute spinslide/contacts", cf);
          const double load = std::fabs(cf.fn);
          const double ft =
              std::sqrt(cf.fs[0] * cf.fs[0] + cf.fs[1] * cf.fs[1] + cf.fs[2] * cf.fs[2]);
          double* row = rows[n++];
          row[0] = load > 0 ? ft / (law.mu * load) : 0.0;
          row[1] = load > 0 ? std::fabs(cf.mt) / (law.mu * load * cf.a) : 0.0;
          row[2] = cf.capped ? 1.0 : 0.0;
          row[3] = load;
          row[4] = cf.a;
        }
      }
      ncount = n;
    }
  }

  double memory_usage() override { return static_cast<double>(nmax) * kColumns * sizeof(double); }

 private:
  Pair* pair = nullptr;
  double** rows = nullptr;
  int nmax = 0, ncount = 0;
};

void* create_compute(void* lmp, int argc, char** argv) {
  return new ComputeSpinslideContacts(static_cast<LAMMPS*>(lmp), argc, argv);
}

}  // namespace

extern "C" void lammpsplugin_init(void* lmp, void* handle, void* regfunc) {
  auto register_plugin = reinterpret_cast<lammpsplugin_regfunc>(regfunc);
  lammpsplugin_t plugin;
  plugin.version = LAMMPS_VERSION;
  plugin.style = "compute";
  plugin.name = "spinslide/contacts";
  plugin.info =
      "Per-contact friction of pair_style granular/spinslide (analysis) v" SPINSLIDE_VERSION;
  plugin.author = "the spinslide developers";
  plugin.creator.v2 = &create_compute;
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);
}
