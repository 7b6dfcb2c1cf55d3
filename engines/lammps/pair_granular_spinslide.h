//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
/// \file pair_granular_spinslide.h
/// The LAMMPS pair style granular/spinslide: Hertz contacts between spheres
/// (material constants, viscoelastic normal damping), a Mindlin tangential
/// spring and a Marshall twisting spring, whose force and torque are capped
/// together on spinslide's exact Hertz limit set (Coulomb-Contensou
/// friction), or independently (`coupling no`) as pair_style granular does.
///
///   pair_style granular/spinslide [coupling yes|no] [twist_transfer symmetric|negate]
///   pair_coeff I J E eta_n nu mu [xgammat x] [damping viscoelastic|tsuji] [limit_damping]
///              [cutoff rc]
///   pair_coeff I J <LAMMPS pair granular model keywords> [cutoff rc]
///
/// Restart files carry the settings and every type pair's coefficients
/// (pair_granular_spinslide_restart.cpp, law_record.h): read_restart
/// restores the pair without pair_style or pair_coeff.
///
/// engines/lammps/README.md documents the models and the syntax.

#ifndef SPINSLIDE_LAMMPS_PAIR_GRANULAR_SPINSLIDE_H
#define SPINSLIDE_LAMMPS_PAIR_GRANULAR_SPINSLIDE_H

#include "legacy_contact.h"
#include "pair.h"
#include "spinslide_contact.h"

#include <boost/config.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class PairGranularSpinslide : public Pair {
 public:
  explicit PairGranularSpinslide(class LAMMPS*);
  ~PairGranularSpinslide() override;
  void compute(int, int) override;
  void settings(int, char**) override;
  void coeff(int, char**) override;
  void init_style() override;
  void write_restart(FILE*) override;
  void read_restart(FILE*) override;
  void write_restart_settings(FILE*) override;
  void read_restart_settings(FILE*) override;
  double init_one(int, int) override;
  void reset_dt() override;
  double memory_usage() override;
  double atom2cut(int) override;
  double radii2cut(double, double) override;
  void transfer_history(double*, double*) override;
  double single(int, int, int, int, double, double, double, double&) override;

  /// The extra quantities of the last force computation, on this process
  /// (`compute ID all pair granular/spinslide` sums them over processes):
  /// contacts, contacts at the friction limit (sliding), the sum of the
  /// friction forces' magnitudes and of the twisting torques' magnitudes.
  enum : int { kExtraContacts = 0, kExtraSliding, kExtraForce, kExtraTorque, kExtraSize };
  /// The extra quantities of single() (compute pair/local p1 ... p8):
  /// the friction force (x, y, z) and its magnitude, the twisting torque,
  /// the contact's ratio eps, 1 if sliding, 1 if in contact.
  enum : int { kSingleSize = 8 };

 protected:
  void allocate();
  void read_type_pair(FILE* fp, int i, int j);
  spinslide_lammps::ContactLaw read_law(int narg, char** arg, double& cutoff);
  // A touching pair's path, always inlined into compute() (and single()),
  // as stock's pair granular computes it all in its loop: defined in
  // pair_granular_spinslide_compute.cpp, the one file that calls them.
  BOOST_FORCEINLINE spinslide_lammps::ContactState contact_state(int i, int j, double r) const;
  BOOST_FORCEINLINE void apply_forces(int i, int j, const spinslide_lammps::ContactLaw& law,
                                      const spinslide_lammps::ContactState& state,
                                      const spinslide_lammps::ContactForce& cf, bool on_j,
                                      double fij[3]);
  const spinslide_lammps::ContactLaw& contact_law(int itype, int jtype) const;
  spinslide_lammps::ContactLaw& law_of(int itype, int jtype);
  spinslide_lammps::LegacyLaw& legacy_of(int itype, int jtype);
  BOOST_FORCEINLINE bool one_pair(int i, int j, int& touch, double* history, bool advance,
                                  spinslide_lammps::ContactForce& cf, double fij[3]);
  spinslide_lammps::LegacyForce legacy_contact(int i, int j,
                                               const spinslide_lammps::LegacyLaw& legacy,
                                               double* history, bool advance) const;
  spinslide_lammps::ContactForce legacy_pair(int i, int j,
                                             const spinslide_lammps::LegacyLaw& legacy,
                                             double* history, bool advance, double fij[3]);
  double dt = 0.0;
  int coupled = 1;       // 1: the coupled cap (default); 0: independent caps
  int twist_negate = 0;  // 1: the twist spring flips sign when a contact changes owner
  int freeze_group_bit = 0;

  class FixNeighHistory* fix_history = nullptr;
  std::string id_dummy, id_history;

  // per type pair (i (ntypes + 1) + j): the contact law, resolved
  std::vector<spinslide_lammps::ContactLaw> laws;
  // ... and LAMMPS' older style, if the type pair was given one (coupling no)
  std::vector<spinslide_lammps::LegacyLaw> legacy_laws;
  double** cutoff_type = nullptr;  // the given cutoff (-1: automatic)

  double *onerad_dynamic = nullptr, *onerad_frozen = nullptr;
  double *maxrad_dynamic = nullptr, *maxrad_frozen = nullptr;
};

}  // namespace LAMMPS_NS

#endif  // SPINSLIDE_LAMMPS_PAIR_GRANULAR_SPINSLIDE_H
