//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
// fix_spinslide_history.h says why this class exists.
#include "fix_spinslide_history.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "my_page.h"
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

void FixSpinslideHistory::unpack_restart(int nlocal, int nth) {
  const double* extra = atom->extra[nlocal];
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[m]);
  // the record: its length, the partners' count, then per partner its ID
  // and dnum values
  const int length = static_cast<int>(extra[m]);
  const int count = static_cast<int>(extra[m + 1]);
  if (count >= 0 && length == 2 + count * (dnum + 1)) {
    FixNeighHistory::unpack_restart(nlocal, nth);
    return;
  }
  if (ipage_atom == nullptr) allocate_pages();
  npartner[nlocal] = 0;
  partner[nlocal] = ipage_atom->get(0);
  valuepartner[nlocal] = dpage_atom->get(0);
  ++dropped_;
}

void FixSpinslideHistory::init() {
  FixNeighHistory::init();
  int dropped = 0;
  MPI_Allreduce(&dropped_, &dropped, 1, MPI_INT, MPI_SUM, world);
  if (dropped > 0 && comm->me == 0)
    error->warning(FLERR,
                   "Pair granular/spinslide: the restart file's contact history of {} atoms has "
                   "another layout (an earlier plugin's): dropped, their contacts start with "
                   "unloaded springs",
                   dropped);
  dropped_ = 0;
}
