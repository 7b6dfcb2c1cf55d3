//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
// The pair style granular/spinslide's section of a restart file
// (pair_granular_spinslide.h; law_record.h gives the layout): the settings
// of pair_style and every type pair's coefficients as pair_coeff set them,
// so that read_restart restores the pair without pair_style or pair_coeff.
// Rank 0 writes and reads; what it reads is broadcast.
//
// The section starts with a magic number and the layout's number, checked
// before anything else is read: a section of another layout (a newer
// plugin's) or not written by this plugin is refused with a message, never
// misread.  The plugin of version 0.1.0 wrote no section (restartinfo 0):
// LAMMPS then logs "pair style granular/spinslide stores no restart info"
// and requires pair_style and pair_coeff after read_restart, as before.

#include "pair_granular_spinslide.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "utils.h"

#include "granular_model.h"
#include "law_record.h"
#include "legacy_contact.h"

#include <cstdio>
#include <string>

using namespace LAMMPS_NS;

/* ----------------------------------------------------------------------
   rank 0 writes: the magic, the layout, then the settings
------------------------------------------------------------------------- */

void PairGranularSpinslide::write_restart_settings(FILE* fp) {
  const int head[4] = {spinslide_lammps::kRestartMagic, spinslide_lammps::kRestartLayout, coupled,
                       twist_negate};
  fwrite(head, sizeof(int), 4, fp);
}

/* ----------------------------------------------------------------------
   rank 0 reads the magic and the layout, which every rank checks; then the
   settings
------------------------------------------------------------------------- */

void PairGranularSpinslide::read_restart_settings(FILE* fp) {
  int head[2] = {0, 0};
  if (comm->me == 0) utils::sfread(FLERR, head, sizeof(int), 2, fp, nullptr, error);
  MPI_Bcast(head, 2, MPI_INT, 0, world);
  if (head[0] != spinslide_lammps::kRestartMagic)
    error->all(FLERR,
               "Pair granular/spinslide: the restart file's pair section does not start with "
               "granular/spinslide's marker: it was not written by this plugin's restart code "
               "(a damaged file, or another program's); it cannot be read");
  if (head[1] != spinslide_lammps::kRestartLayout)
    error->all(FLERR,
               "Pair granular/spinslide: the restart file's pair section has layout {}, this "
               "plugin reads layout {} only (the file was written by {} plugin): read it with "
               "the plugin version that wrote it",
               head[1], spinslide_lammps::kRestartLayout,
               head[1] > spinslide_lammps::kRestartLayout ? "a newer" : "another");
  int settings[2] = {0, 0};
  if (comm->me == 0) utils::sfread(FLERR, settings, sizeof(int), 2, fp, nullptr, error);
  MPI_Bcast(settings, 2, MPI_INT, 0, world);
  if ((settings[0] != 0 && settings[0] != 1) || (settings[1] != 0 && settings[1] != 1))
    error->all(FLERR,
               "Pair granular/spinslide: the restart file's settings are not 0 or 1 (coupling "
               "{}, twist_transfer {}): a damaged file",
               settings[0], settings[1]);
  coupled = settings[0];
  twist_negate = settings[1];
}

/* ----------------------------------------------------------------------
   rank 0 writes: the settings, the number of types and the record size,
   then for each type pair I <= J its setflag and, if set, its record (the
   mixed pairs are mixed again by init_one)
------------------------------------------------------------------------- */

void PairGranularSpinslide::write_restart(FILE* fp) {
  write_restart_settings(fp);
  const int ntypes = atom->ntypes;
  const int sizes[2] = {ntypes, static_cast<int>(spinslide_lammps::kLawRecordSize)};
  fwrite(sizes, sizeof(int), 2, fp);
  double record[spinslide_lammps::kLawRecordSize];
  for (int i = 1; i <= ntypes; i++) {
    for (int j = i; j <= ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j] == 0) continue;
      spinslide_lammps::pack_law(law_of(i, j), legacy_of(i, j), cutoff_type[i][j], record);
      fwrite(record, sizeof(double), spinslide_lammps::kLawRecordSize, fp);
    }
  }
}

/* ----------------------------------------------------------------------
   rank 0 reads what write_restart wrote and broadcasts it; every rank
   checks it
------------------------------------------------------------------------- */

void PairGranularSpinslide::read_restart(FILE* fp) {
  read_restart_settings(fp);
  if (!allocated) allocate();
  const int ntypes = atom->ntypes;
  int sizes[2] = {0, 0};
  if (comm->me == 0) utils::sfread(FLERR, sizes, sizeof(int), 2, fp, nullptr, error);
  MPI_Bcast(sizes, 2, MPI_INT, 0, world);
  if (sizes[0] != ntypes || sizes[1] != static_cast<int>(spinslide_lammps::kLawRecordSize))
    error->all(FLERR,
               "Pair granular/spinslide: the restart file's pair section is for {} atom types "
               "with {} numbers per type pair, not {} and {}: a damaged file",
               sizes[0], sizes[1], ntypes, spinslide_lammps::kLawRecordSize);
  for (int i = 1; i <= ntypes; i++)
    for (int j = i; j <= ntypes; j++) read_type_pair(fp, i, j);
}

// Type pair (i, j)'s setflag and, if set, its record.
void PairGranularSpinslide::read_type_pair(FILE* fp, int i, int j) {
  if (comm->me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
  MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
  if (setflag[i][j] == 0) return;
  double record[spinslide_lammps::kLawRecordSize];
  if (comm->me == 0)
    utils::sfread(FLERR, record, sizeof(double), spinslide_lammps::kLawRecordSize, fp, nullptr,
                  error);
  MPI_Bcast(record, static_cast<int>(spinslide_lammps::kLawRecordSize), MPI_DOUBLE, 0, world);
  spinslide_lammps::ContactLaw law;
  spinslide_lammps::LegacyLaw legacy;
  double cutoff = -1.0;
  const std::string why = spinslide_lammps::unpack_law(record, law, legacy, cutoff);
  if (!why.empty())
    error->all(FLERR, "Pair granular/spinslide: the restart file's types {} {}: {}", i, j, why);
  law_of(i, j) = law_of(j, i) = law;
  legacy_of(i, j) = legacy_of(j, i) = legacy;
  cutoff_type[i][j] = cutoff_type[j][i] = cutoff;
  // JKR: contacts last beyond touching, until the pull-off distance (coeff)
  if (law.normal == spinslide_lammps::NormalModel::kJkr) beyond_contact = 1;
}
