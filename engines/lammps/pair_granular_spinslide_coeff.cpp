//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
// The settings and coefficients of the pair style granular/spinslide
// (pair_granular_spinslide.h): pair_style's keywords and pair_coeff's
// contact laws (the plugin's short form, LAMMPS' pair granular model
// keywords, LAMMPS' older styles), read through granular_model.h and
// legacy_contact.h.

#include "keywords.h"
#include "pair_granular_spinslide.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "utils.h"

#include "granular_model.h"
#include "legacy_contact.h"

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {

const char* const kCoeffSyntax =
    "pair_coeff I J E eta_n|e nu mu [xgammat x] [damping viscoelastic|tsuji] [limit_damping] "
    "[cutoff rc], or pair_coeff I J with LAMMPS' pair granular model keywords [cutoff rc]";

}  // namespace

/* ----------------------------------------------------------------------
   pair_style granular/spinslide [coupling yes|no] [twist_transfer symmetric|negate]
------------------------------------------------------------------------- */

void PairGranularSpinslide::settings(int narg, char** arg) {
  coupled = 1;
  twist_negate = 0;
  for (int iarg = 0; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Illegal pair_style granular/spinslide command: {} needs a value",
                 arg[iarg]);
    const std::string key = arg[iarg], value = arg[iarg + 1];
    if (key == "coupling") {
      coupled = spinslide_lammps::either(value, {"yes", "on"}, {"no", "off"});
      if (coupled < 0)
        error->all(FLERR, "Illegal pair_style granular/spinslide command: coupling {}", value);
    } else if (key == "twist_transfer") {
      twist_negate = spinslide_lammps::either(value, {"negate"}, {"symmetric"});
      if (twist_negate < 0)
        error->all(FLERR, "Illegal pair_style granular/spinslide command: twist_transfer {}",
                   value);
    } else {
      error->all(FLERR, "Illegal pair_style granular/spinslide command: unknown keyword {}", key);
    }
  }
}

/* ----------------------------------------------------------------------
   pair_coeff's words after I J: the short form E eta_n|e nu mu [xgammat x]
   [damping viscoelastic|tsuji] [limit_damping] [cutoff rc], or LAMMPS'
   pair granular model keywords [cutoff rc]
------------------------------------------------------------------------- */

spinslide_lammps::ContactLaw PairGranularSpinslide::read_law(int narg, char** arg, double& cutoff) {
  const std::vector<std::string> words(arg + 2, arg + narg);
  const bool short_form = utils::is_double(arg[2]);
  if (short_form && words.size() < 4)
    error->all(FLERR, "Incorrect args for pair coefficients: {}", kCoeffSyntax);
  const spinslide_lammps::NumberReader number = [this](const std::string& w) {
    return utils::numeric(FLERR, w.c_str(), false, lmp);
  };
  spinslide_lammps::ContactLaw law;
  std::vector<std::string> rest;
  const std::string why = spinslide_lammps::parse_lammps_model(
      short_form ? spinslide_lammps::expand_short_form(words) : words, number, law, rest);
  if (!why.empty()) error->all(FLERR, "pair_coeff granular/spinslide: {}", why);
  for (std::size_t k = 0; k < rest.size(); ++k) {
    if (rest[k] == "cutoff" && k + 1 < rest.size()) {
      cutoff = number(rest[++k]);
      // (LAMMPS' granular takes cutoff -1 for automatic; here the automatic
      // cutoff is the default, and a given one must be a distance.)
      if (!(cutoff > 0.0))
        error->all(FLERR,
                   "pair_coeff granular/spinslide: cutoff must be > 0 (leave it out for the "
                   "automatic cutoff, the contact distance of the largest spheres)");
      continue;
    }
    const std::string why = spinslide_lammps::unsupported_granular_keyword(rest[k]);
    if (!why.empty()) error->all(FLERR, "pair_coeff granular/spinslide: {}: {}", rest[k], why);
    error->all(FLERR, "Incorrect args for pair coefficients: unknown keyword {} ({})", rest[k],
               kCoeffSyntax);
  }
  return law;
}

void PairGranularSpinslide::coeff(int narg, char** arg) {
  if (narg < 3) error->all(FLERR, "Incorrect args for pair coefficients: {}", kCoeffSyntax);
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  double cut_one = -1.0;
  // LAMMPS' older styles (gran/hooke, gran/hooke/history, gran/hertz/history):
  // in their arithmetic with the coupling off, as their equivalent with
  // Marshall's twisting spring coupled (legacy_contact.h)
  spinslide_lammps::LegacyLaw legacy;
  if (utils::strmatch(arg[2], "^gran/")) {
    const std::vector<std::string> words(arg + 2, arg + narg);
    const std::string why = spinslide_lammps::parse_legacy(
        words,
        [this](const std::string& w) { return utils::numeric(FLERR, w.c_str(), false, lmp); },
        force->nktv2p, legacy);
    if (!why.empty()) error->all(FLERR, "pair_coeff granular/spinslide: {}", why);
  }
  const spinslide_lammps::ContactLaw read = legacy.model != spinslide_lammps::LegacyModel::kNone
                                                ? spinslide_lammps::modern_equivalent(legacy)
                                                : read_law(narg, arg, cut_one);
  if (coupled) legacy.model = spinslide_lammps::LegacyModel::kNone;
  const std::string why = spinslide_lammps::check_law(read);
  if (!why.empty()) error->all(FLERR, "pair_coeff granular/spinslide: {}", why);
  const spinslide_lammps::ContactLaw law =
      spinslide_lammps::resolve(read, spinslide_lammps::Moduli::kExact, false);
  // JKR: contacts last beyond touching, until the pull-off distance
  if (law.normal == spinslide_lammps::NormalModel::kJkr) beyond_contact = 1;

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      law_of(i, j) = law_of(j, i) = law;
      legacy_of(i, j) = legacy_of(j, i) = legacy;
      cutoff_type[i][j] = cutoff_type[j][i] = cut_one;
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}
