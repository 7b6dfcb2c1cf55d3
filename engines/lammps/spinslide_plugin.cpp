//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
// Registers the pair style granular/spinslide, the fix wall/gran/spinslide
// and the pair's history fix NEIGH_HISTORY/SPINSLIDE with LAMMPS' plugin
// loader:
//   plugin load /path/to/spinslideplugin.so

#include "lammpsplugin.h"
#include "version.h"

#include "fix_spinslide_history.h"
#include "fix_wall_gran_region_spinslide.h"
#include "fix_wall_gran_spinslide.h"
#include "pair_granular_spinslide.h"

using namespace LAMMPS_NS;

namespace {

void* create_pair_granular_spinslide(void* lmp) {
  return new PairGranularSpinslide(static_cast<LAMMPS*>(lmp));
}

void* create_fix_wall_gran_spinslide(void* lmp, int argc, char** argv) {
  return new FixWallGranSpinslide(static_cast<LAMMPS*>(lmp), argc, argv);
}

void* create_fix_wall_gran_region_spinslide(void* lmp, int argc, char** argv) {
  return new FixWallGranRegionSpinslide(static_cast<LAMMPS*>(lmp), argc, argv);
}

void* create_fix_spinslide_history(void* lmp, int argc, char** argv) {
  return new FixSpinslideHistory(static_cast<LAMMPS*>(lmp), argc, argv);
}

}  // namespace

extern "C" void lammpsplugin_init(void* lmp, void* handle, void* regfunc) {
  auto register_plugin = reinterpret_cast<lammpsplugin_regfunc>(regfunc);
  lammpsplugin_t plugin;
  plugin.version = LAMMPS_VERSION;
  plugin.style = "pair";
  plugin.name = "granular/spinslide";
  plugin.info =
      "Hertz-Mindlin-Marshall granular contacts with coupled sliding and twisting "
      "friction (spinslide, Coulomb-Contensou) v" SPINSLIDE_VERSION;
  plugin.author = "the spinslide developers";
  plugin.creator.v1 = &create_pair_granular_spinslide;
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "fix";
  plugin.name = "wall/gran/spinslide";
  plugin.info =
      "Granular plane and z-cylinder walls with the Hertz-Mindlin-Marshall contacts of "
      "granular/spinslide (spinslide, Coulomb-Contensou) v" SPINSLIDE_VERSION;
  plugin.creator.v2 = &create_fix_wall_gran_spinslide;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "wall/gran/region/spinslide";
  plugin.info =
      "Granular walls on any region's surface, moving and rotating, with the contacts of "
      "granular/spinslide (spinslide, Coulomb-Contensou) v" SPINSLIDE_VERSION;
  plugin.creator.v2 = &create_fix_wall_gran_region_spinslide;
  (*register_plugin)(&plugin, lmp);

  // The pair style's own history fix (fix_spinslide_history.h); not for inputs.
  plugin.name = "NEIGH_HISTORY/SPINSLIDE";
  plugin.info = "Contact history of pair granular/spinslide (internal) v" SPINSLIDE_VERSION;
  plugin.creator.v2 = &create_fix_spinslide_history;
  (*register_plugin)(&plugin, lmp);
}
