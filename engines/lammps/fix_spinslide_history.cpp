//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
// fix_spinslide_history.h says why this class exists.
#include "fix_spinslide_history.h"

#include "comm.h"
#include "update.h"

using namespace LAMMPS_NS;

FixSpinslideHistory::FixSpinslideHistory(LAMMPS* lmp, int narg, char** arg)
    : FixNeighHistory(lmp, narg, arg) {}

void FixSpinslideHistory::post_run() {
  FixNeighHistory::post_run();
  synced_step_ = update->ntimestep;
}

void FixSpinslideHistory::write_restart(FILE* fp) {
  const bool synced = update->whichflag == 0 && synced_step_ == update->ntimestep;
  if (!synced) {
    FixNeighHistory::write_restart(fp);  // copies, then writes the global record
    return;
  }
  // The global record, as FixNeighHistory writes it: no data.
  if (comm->me == 0) {
    int size = 0;
    fwrite(&size, sizeof(int), 1, fp);
  }
}
