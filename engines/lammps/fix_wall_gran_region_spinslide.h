//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
/// \file fix_wall_gran_region_spinslide.h
/// The LAMMPS fix wall/gran/region/spinslide: the surface of any LAMMPS
/// region (block, cylinder, cone, sphere, plane, prism, their unions and
/// intersections; moving and rotating as `region ... move|rotate` makes it)
/// as a granular wall with the contact law of fix wall/gran/spinslide.
///
///   fix ID group wall/gran/region/spinslide E eta_n nu mu [xgammat x] [limit_damping]
///       [damping viscoelastic|tsuji] [coupling yes|no] [moduli exact|legacy] region ID
///
/// A sphere touches as many of the region's faces as the region reports
/// (at most its `tmax`); each contact keeps its own history, found again
/// through the face's index from one step to the next.  The region's motion
/// is written to restart files, as LAMMPS' fix wall/gran/region does.

#ifndef SPINSLIDE_LAMMPS_FIX_WALL_GRAN_REGION_SPINSLIDE_H
#define SPINSLIDE_LAMMPS_FIX_WALL_GRAN_REGION_SPINSLIDE_H

#include "fix_wall_gran_spinslide.h"

namespace LAMMPS_NS {

class FixWallGranRegionSpinslide : public FixWallGranSpinslide {
 public:
  FixWallGranRegionSpinslide(class LAMMPS*, int, char**);
  ~FixWallGranRegionSpinslide() override;
  void init() override;
  double memory_usage() override;
  void write_restart(FILE*) override;
  void restart(char*) override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double*) override;
  int unpack_exchange(int, double*) override;
  int pack_restart(int, double*) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

 protected:
  /// The contacts' history slots of atom i matched to the region's `nc`
  /// contacts of this step (slot_of_contact[c]), by face index: a face
  /// touched again keeps its history, a new one starts unloaded, a face left
  /// is dropped.
  void match_contacts(int i, int nc);
  /// The per-atom values of atom i in buf (exchange, restart); returns how
  /// many.
  int pack_atom(int i, double* buf) const;
  /// Atom i's per-atom values from buf; returns how many were read.
  int unpack_atom(int i, const double* buf);

  static constexpr int kMaxSlots = 64;  // the most faces a sphere may touch at once

  class Region* region = nullptr;
  std::string region_style;  // the region's style and number of sub-regions when
  int nregion = 0;           // created, to notice a region redefined between runs
  int tmax = 0;              // the most faces a sphere can touch at once
  int motion_reset = 0;      // 1: a restart's region motion did not fit

  int* ncontact = nullptr;           // per atom: its contacts with the region
  int** walls = nullptr;             // per atom and contact: the face's index
  double*** history_many = nullptr;  // per atom and contact: kHistSize values
  int* slot_of_contact = nullptr;    // this step, per region contact: its slot
  bool moving = false;               // this step: the region moves (its velocities set)

  void begin_step() override;
  void touch_atom(int i, bool advance) override;
};

}  // namespace LAMMPS_NS

#endif  // SPINSLIDE_LAMMPS_FIX_WALL_GRAN_REGION_SPINSLIDE_H
