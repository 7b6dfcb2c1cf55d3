//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
// The contact history of pair granular/spinslide: LAMMPS' FixNeighHistory,
// but for one defect of its write_restart (LAMMPS 29 Sep 2021, found in issue
// 30).  After a run, post_run() has already copied the history from the
// neighbor list into the per-atom arrays; write_restart() does it again, after
// the write_restart command has exchanged the atoms and rebuilt the ghosts,
// through the old neighbor list, whose ghost indices no longer mean the same
// atoms.  The history of every contact across a periodic boundary (or between
// MPI ranks) is then scrambled: in the file, and in the run that continues.
// Measured on engines/lammps/examples/in.restart in a periodic box: 50 of 384
// spheres' forces differ at the first step after the restart, and as many
// in a run that only wrote a restart and went on; LAMMPS' own pair granular
// shows the same (42).  Here write_restart() skips the copy when post_run()
// made it at this step outside a run; during a run (the restart command's
// periodic files) it copies as LAMMPS does, through the current list.
//
// It also checks each atom's restart record against its own length: a file
// whose history has another number of values per contact (written by an
// earlier plugin whose history was shorter) would otherwise be read as
// garbage.  Such records are dropped, with a warning: those contacts start
// with unloaded springs.
#ifndef SPINSLIDE_LAMMPS_FIX_SPINSLIDE_HISTORY_H
#define SPINSLIDE_LAMMPS_FIX_SPINSLIDE_HISTORY_H

#include "fix_neigh_history.h"

namespace LAMMPS_NS {

class FixSpinslideHistory : public FixNeighHistory {
 public:
  FixSpinslideHistory(class LAMMPS* lmp, int narg, char** arg);
  void post_run() override;
  void write_restart(FILE* fp) override;
  void unpack_restart(int nlocal, int nth) override;
  void init() override;

 private:
  bigint synced_step_ = -1;  // the step post_run() copied the history at
  int dropped_ = 0;          // restart records of another layout dropped on this rank
};

}  // namespace LAMMPS_NS

#endif  // SPINSLIDE_LAMMPS_FIX_SPINSLIDE_HISTORY_H
