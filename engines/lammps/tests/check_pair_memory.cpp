//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Checks the pair style granular/spinslide's memory_usage() against the
// arrays it allocates (lammps.pair_memory_usage, pair_memory.cmake): LAMMPS
// prints, at each run's setup, "Per MPI rank memory allocation (min/avg/max)
// = a | b | c Mbytes", the sum of every style's and fix's memory_usage().
// The same input (engines/lammps/tests/in.pair_memory) runs with 1 and with N atom
// types, with granular/spinslide and with LAMMPS' own pair_style granular
// (whose memory_usage() counts none of its per-type arrays: the control for
// whatever else in LAMMPS grows with the types).  The growth of
// granular/spinslide's figure from 1 to N types, less the control's, must
// be the growth of the arrays the pair allocates per type pair and per
// type, counted here from their element types, within the rounding of the
// four printed figures (4 significant digits each).
//
//   check_pair_memory N spinslide_1.log spinslide_N.log stock_1.log stock_N.log
#include "granular_model.h"
#include "legacy_contact.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

namespace {

// The figure LAMMPS printed first (the average over ranks) and half a unit
// of its last digit.
struct Printed {
  double mbytes = 0.0;
  double half_unit = 0.0;
};

bool read_printed(const std::string& path, Printed& out) {
  std::ifstream in(path);
  const std::string key = "Per MPI rank memory allocation (min/avg/max) = ";
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t at = line.find(key);
    if (at == std::string::npos) continue;
    // min | avg | max: the average
    const std::size_t bar = line.find('|', at);
    if (bar == std::string::npos) return false;
    const std::string avg = line.substr(bar + 1, line.find('|', bar + 1) - bar - 1);
    out.mbytes = std::strtod(avg.c_str(), nullptr);
    // 4 significant digits ({:.4} in LAMMPS' Output::memory_usage)
    const double exponent = std::floor(std::log10(out.mbytes));
    out.half_unit = 0.5 * std::pow(10.0, exponent - 3.0);
    return out.mbytes > 0.0;
  }
  return false;
}

// The bytes granular/spinslide allocates for n atom types, counted from
// pair_granular_spinslide.cpp's allocate(): setflag (int), cutsq and
// cutoff_type (double), (n + 1)^2 each with n + 1 row pointers (LAMMPS'
// memory->create); the laws and the older styles' laws, (n + 1)^2 each; the
// four radius arrays, n + 1 doubles each.
double allocated_bytes(int ntypes) {
  const double n1 = ntypes + 1;
  double bytes = n1 * n1 * sizeof(int) + n1 * sizeof(int*);
  bytes += 2 * (n1 * n1 * sizeof(double) + n1 * sizeof(double*));
  bytes += n1 * n1 * sizeof(spinslide_lammps::ContactLaw);
  bytes += n1 * n1 * sizeof(spinslide_lammps::LegacyLaw);
  bytes += 4 * n1 * sizeof(double);
  return bytes;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6) {
    std::cerr << "usage: check_pair_memory N spinslide_1.log spinslide_N.log stock_1.log "
                 "stock_N.log\n";
    return 2;
  }
  const int ntypes = std::atoi(argv[1]);
  Printed figures[4];
  for (int k = 0; k < 4; ++k) {
    if (!read_printed(argv[k + 2], figures[k])) {
      std::cerr << "check_pair_memory: no memory figure in " << argv[k + 2] << "\n";
      return 2;
    }
  }
  const double mb = 1024.0 * 1024.0;
  const double measured =
      (figures[1].mbytes - figures[0].mbytes) - (figures[3].mbytes - figures[2].mbytes);
  const double expected = (allocated_bytes(ntypes) - allocated_bytes(1)) / mb;
  double tolerance = 0.0;
  for (const Printed& p : figures) tolerance += p.half_unit;
  std::printf(
      "granular/spinslide: %.4g -> %.4g Mbytes from 1 to %d types; pair_style granular: %.4g -> "
      "%.4g\n",
      figures[0].mbytes, figures[1].mbytes, ntypes, figures[2].mbytes, figures[3].mbytes);
  std::printf(
      "growth less the control's: %.4f Mbytes; the arrays' growth: %.4f Mbytes (%.0f bytes); "
      "tolerance %.4f\n",
      measured, expected, expected * mb, tolerance);
  if (std::fabs(measured - expected) > tolerance) {
    std::printf("memory_usage() does not count the arrays the pair allocates\n");
    return 1;
  }
  std::printf("memory_usage() counts the arrays the pair allocates\n");
  return 0;
}
