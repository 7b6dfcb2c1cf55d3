//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
/// \file fix_wall_gran_spinslide.h
/// The LAMMPS fix wall/gran/spinslide: granular walls (planes and a z
/// cylinder) with the contact law of the pair style granular/spinslide
/// (spinslide_contact.h), the wall a body of infinite mass of the spheres'
/// material.
///
///   fix ID group wall/gran/spinslide E eta_n nu mu [xgammat x] [limit_damping]
///       [damping viscoelastic|tsuji] [coupling yes|no] [moduli exact|legacy]
///       xplane|yplane|zplane lo hi  |  zcylinder radius
///   fix ID group wall/gran/spinslide granular <LAMMPS' model keywords> [coupling yes|no]
///       [moduli exact|legacy] xplane|yplane|zplane lo hi  |  zcylinder radius
///
/// lo, hi: the walls' positions (NULL: no wall on that side); radius: a
/// cylinder about the z axis through x = y = 0.  FixWallGranRegionSpinslide
/// (fix_wall_gran_region_spinslide.h) takes a region instead.
/// engines/lammps/README.md documents the syntax and the model.

#ifndef SPINSLIDE_LAMMPS_FIX_WALL_GRAN_SPINSLIDE_H
#define SPINSLIDE_LAMMPS_FIX_WALL_GRAN_SPINSLIDE_H

#include "fix.h"
#include "legacy_contact.h"
#include "spinslide_contact.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixWallGranSpinslide : public Fix {
 public:
  FixWallGranSpinslide(class LAMMPS*, int, char**);
  ~FixWallGranSpinslide() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  void reset_dt() override;
  double compute_vector(int) override;
  double memory_usage() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double*) override;
  int unpack_exchange(int, double*) override;
  int pack_restart(int, double*) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

  /// The global vector (`f_ID[k]`), summed over processes, of the last step:
  /// the contacts with the wall, those at the friction limit (sliding), the
  /// sum of the friction forces' magnitudes and of the twisting torques'.
  enum : int { kStatContacts = 0, kStatSliding, kStatForce, kStatTorque, kStatSize };

 protected:
  /// Which wall: a pair of planes, a z cylinder, or a region (the derived
  /// fix wall/gran/region/spinslide).
  enum class WallStyle { kPlane, kZCylinder, kRegion };

  /// Where sphere i touches a wall: the vector from the wall's nearest
  /// point to the centre and its squared length (as the wall computes it),
  /// the wall's radius of curvature there (0: flat; LAMMPS' sign
  /// convention, negative inside a concave wall) and the velocity of the
  /// wall's surface at the contact.
  struct WallTouch {
    double d[3];
    double rsq;
    double rwall;
    double vwall[3];
  };

  /// The words after the law: the wall (xplane|yplane|zplane lo hi,
  /// zcylinder radius, region ID) and the options; returns how many walls.
  int parse_walls_and_options(const std::vector<std::string>& words);
  void parse_option(const std::string& key, const std::string& value);
  void check_walls();
  /// What a step does before it looks at the atoms (a moving region: its
  /// velocities); nothing for the planes and the cylinder.
  virtual void begin_step();
  /// Sphere i (of the group) against the wall: its contacts applied, or
  /// forgotten when apart.
  virtual void touch_atom(int i, bool advance);
  /// Zeroes the statistics of the step (post_force's start).
  void clear_statistics();
  /// Sphere i's contact `touch` with history h (kHistSize values): the forces
  /// and torques added to i, the statistics counted.
  void apply_contact(int i, const WallTouch& touch, double* h, bool advance);
  void apply_legacy_contact(int i, const WallTouch& touch, double* h, bool advance);
  spinslide_lammps::ContactLaw read_law(int narg, char** arg, std::vector<std::string>& rest);

  WallStyle wallstyle = WallStyle::kPlane;
  int axis = 2;            // the planes' normal: 0 x, 1 y, 2 z
  double lo = 0.0;         // the lower plane (-1e20 for none)
  double hi = 0.0;         // the upper plane (+1e20 for none)
  double cylradius = 0.0;  // the z cylinder's radius
  std::string idregion;    // the region (wall/gran/region/spinslide)
  int coupled = 1;         // 1: the coupled cap (default); 0: independent caps
  int legacy_moduli = 0;   // 1: LAMMPS 2021 fix wall/gran's (4/3)E* and 8G*
  int legacy_slots = 0;    // region walls: 1 reproduces LAMMPS 2021's corner history mismatch
  int ninit = 0;           // how many times init() ran (moduli legacy, damping tsuji)
  int dropped = 0;         // restart records of another layout dropped on this rank

  spinslide_lammps::ContactLaw law;    // the wall's contact law, resolved
  spinslide_lammps::LegacyLaw legacy;  // LAMMPS' older style, if given one (coupling no)

  double dt = 0.0;
  double** history = nullptr;  // per atom: spinslide_lammps::kHistSize values

  double stats_local[kStatSize] = {0.0, 0.0, 0.0, 0.0};
  double stats_all[kStatSize] = {0.0, 0.0, 0.0, 0.0};
  int stats_reduced = 0;
};

}  // namespace LAMMPS_NS

#endif  // SPINSLIDE_LAMMPS_FIX_WALL_GRAN_SPINSLIDE_H
