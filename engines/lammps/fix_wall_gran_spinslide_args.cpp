//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
//  The plugin binary built from this file includes LAMMPS headers and runs
//  inside LAMMPS, which is GPL-2.0: the binary is GPL-2.0 (README.md).
//
// The command of the fix wall/gran/spinslide (fix_wall_gran_spinslide.h,
// README.md): its constructor, which reads the contact law (the short
// form, `granular` and LAMMPS' model keywords, or one of LAMMPS' older
// styles), the wall and the options, and checks them.  The contacts and
// the per-atom history are in fix_wall_gran_spinslide.cpp.

#include "fix_wall_gran_spinslide.h"
#include "keywords.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "update.h"
#include "utils.h"

#include "granular_model.h"
#include "legacy_contact.h"
#include "spinslide_contact.h"

#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

using spinslide_lammps::kHistSize;

namespace {

// A wall given as NULL sits this far away.
constexpr double kFarAway = 1.0e20;

// The command's syntax, for messages.
std::string syntax(bool region_style) {
  return std::string(region_style ? "fix ID group wall/gran/region/spinslide"
                                  : "fix ID group wall/gran/spinslide") +
         " E eta_n|e nu mu [xgammat x] [damping viscoelastic|tsuji] [limit_damping] | granular "
         "<LAMMPS' model keywords>, then [coupling yes|no] [moduli exact|legacy] " +
         (region_style ? "region ID" : "xplane|yplane|zplane lo hi | zcylinder radius");
}

}  // namespace

/* ---------------------------------------------------------------------- */

FixWallGranSpinslide::FixWallGranSpinslide(LAMMPS* lmp, int narg, char** arg)
    : Fix(lmp, narg, arg) {
  const bool region_style = utils::strmatch(style, "region");
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR,
               "Fix {} requires atom attributes radius, rmass, omega, torque (atom_style sphere)",
               style);
  for (int iarg = 3; iarg < narg; iarg++)
    if (strcmp(arg[iarg], "region") == 0 && !region_style)
      error->all(FLERR, "Fix {}: region: a region wall is fix wall/gran/region/spinslide", style);
  if (narg < 6) error->all(FLERR, "Illegal fix {} command: {}", style, syntax(region_style));

  std::vector<std::string> rest;
  const spinslide_lammps::ContactLaw read = read_law(narg, arg, rest);
  std::string why = spinslide_lammps::check_law(read);
  if (why.empty() && read.normal == spinslide_lammps::NormalModel::kJkr)
    why =
        "jkr walls are not supported (LAMMPS 29 Sep 2021's fix wall/gran takes a pull-off "
        "distance of the wrong sign and scale, which the plugin does not reproduce); use dmt "
        "or hertz/material for the wall";
  if (!why.empty()) error->all(FLERR, "Fix {}: {}", style, why);

  if (parse_walls_and_options(rest) != 1 || (wallstyle == WallStyle::kRegion) != region_style)
    error->all(FLERR, "Illegal fix {} command: give one wall: {}", style, syntax(region_style));
  check_walls();
  // coupled, LAMMPS' older styles run as their equivalent with Marshall's
  // twisting spring (legacy_contact.h)
  if (coupled) legacy.model = spinslide_lammps::LegacyModel::kNone;
  if (coupled && read.twist == spinslide_lammps::TwistModel::kSds)
    error->all(FLERR,
               "Fix {}: coupling yes needs twisting marshall: the coupled cap takes the "
               "twisting limit from the contact patch; give twisting marshall, or coupling no",
               style);
  // legacy: LAMMPS 29 Sep 2021 fix wall/gran's constants of the material
  // models, (4/3)E/(2(1-nu)) with 4/3 to 16 digits and E(2-nu)(1+nu)/4, for
  // A/B runs; exact: the sphere against a wall of its own material.
  law = spinslide_lammps::resolve(
      read,
      legacy_moduli ? spinslide_lammps::Moduli::kLegacyWall : spinslide_lammps::Moduli::kExact,
      true);

  create_attribute = 1;
  restart_peratom = 1;
  vector_flag = 1;
  size_vector = kStatSize;
  global_freq = 1;
  extvector = 1;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  if (history)
    for (int i = 0; i < atom->nlocal; i++)
      for (int k = 0; k < kHistSize; k++) history[i][k] = 0.0;

  dt = update->dt;
}

// The contact law's words: one of LAMMPS' older styles (hooke,
// hooke/history, hertz/history and their six numbers, as fix wall/gran
// takes them), LAMMPS' model keywords after `granular`, or the short form.
// The words after the law go into rest.
spinslide_lammps::ContactLaw FixWallGranSpinslide::read_law(int narg, char** arg,
                                                            std::vector<std::string>& rest) {
  const bool region_style = wallstyle == WallStyle::kRegion || utils::strmatch(style, "region");
  const spinslide_lammps::NumberReader number = [this](const std::string& w) {
    return utils::numeric(FLERR, w.c_str(), false, lmp);
  };
  const std::string first = arg[3];
  std::string why;
  spinslide_lammps::ContactLaw read;
  if (first == "hooke" || first == "hooke/history" || first == "hertz/history") {
    const int n = narg > 10 && strcmp(arg[10], "limit_damping") == 0 ? 8 : 7;
    if (narg < 3 + n)
      error->all(FLERR, "Illegal fix {} command: {} needs kn kt gamman gammat xmu dampflag", style,
                 first);
    why = spinslide_lammps::parse_legacy(std::vector<std::string>(arg + 3, arg + 3 + n), number,
                                         force->nktv2p, legacy);
    rest.assign(arg + 3 + n, arg + narg);
    read = spinslide_lammps::modern_equivalent(legacy);
  } else {
    const bool lammps_form = first == "granular";
    const std::vector<std::string> words(arg + (lammps_form ? 4 : 3), arg + narg);
    if (!lammps_form && (words.size() < 4 || !utils::is_double(arg[3])))
      error->all(FLERR, "Illegal fix {} command: {}", style, syntax(region_style));
    why = spinslide_lammps::parse_lammps_model(
        lammps_form ? words : spinslide_lammps::expand_short_form(words), number, read, rest);
  }
  if (!why.empty()) error->all(FLERR, "Fix {}: {}", style, why);
  return read;
}

// The keywords after the four numbers: the wall (xplane|yplane|zplane lo
// hi, zcylinder radius, region ID) and the options; returns how many walls
// were given.
int FixWallGranSpinslide::parse_walls_and_options(const std::vector<std::string>& words) {
  int nwalls = 0;
  const auto value = [&](std::size_t k) -> double {
    return words[k] == "NULL" ? 0.0 : utils::numeric(FLERR, words[k].c_str(), false, lmp);
  };
  for (std::size_t k = 0; k < words.size();) {
    const std::string& key = words[k];
    const std::string why = spinslide_lammps::unsupported_granular_keyword(key);
    if (!why.empty()) error->all(FLERR, "Fix {}: {}: {}", style, key, why);
    if (key == "xplane" || key == "yplane" || key == "zplane") {
      if (k + 2 >= words.size())
        error->all(FLERR, "Illegal fix {} command: {} needs lo and hi", style, key);
      wallstyle = WallStyle::kPlane;
      axis = key[0] - 'x';
      lo = words[k + 1] == "NULL" ? -kFarAway : value(k + 1);
      hi = words[k + 2] == "NULL" ? kFarAway : value(k + 2);
      ++nwalls;
      k += 3;
      continue;
    }
    if (k + 1 >= words.size())
      error->all(FLERR, "Illegal fix {} command: {} needs a value ({})", style, key,
                 syntax(wallstyle == WallStyle::kRegion));
    if (key == "zcylinder") {
      wallstyle = WallStyle::kZCylinder;
      cylradius = value(k + 1);
      ++nwalls;
    } else if (key == "region") {
      wallstyle = WallStyle::kRegion;
      idregion = words[k + 1];
      ++nwalls;
    } else {
      parse_option(key, words[k + 1]);
    }
    k += 2;
  }
  return nwalls;
}

// One option keyword and its value.
void FixWallGranSpinslide::parse_option(const std::string& key, const std::string& value) {
  if (key == "coupling") {
    coupled = spinslide_lammps::either(value, {"yes", "on"}, {"no", "off"});
    if (coupled < 0) error->all(FLERR, "Illegal fix {} command: coupling {}", style, value);
  } else if (key == "slots") {
    legacy_slots = spinslide_lammps::either(value, {"legacy"}, {"exact"});
    if (legacy_slots < 0) error->all(FLERR, "Illegal fix {} command: slots {}", style, value);
  } else if (key == "moduli") {
    legacy_moduli = spinslide_lammps::either(value, {"legacy"}, {"exact"});
    if (legacy_moduli < 0) error->all(FLERR, "Illegal fix {} command: moduli {}", style, value);
  } else {
    error->all(FLERR, "Illegal fix {} command: unknown keyword {} ({})", style, key,
               syntax(wallstyle == WallStyle::kRegion));
  }
}

// The walls, checked.
void FixWallGranSpinslide::check_walls() {
  if (legacy_slots && wallstyle != WallStyle::kRegion)
    error->all(FLERR, "Fix {}: slots is a keyword of region walls", style);
  if (wallstyle == WallStyle::kPlane) {
    if (!(lo < hi)) error->all(FLERR, "Fix {}: the walls need lo < hi", style);
    if (domain->periodicity[axis])
      error->all(FLERR, "Fix {}: no wall in a periodic dimension", style);
  } else if (wallstyle == WallStyle::kZCylinder) {
    if (!(cylradius > 0.0)) error->all(FLERR, "Fix {}: the cylinder's radius must be > 0", style);
    if (domain->xperiodic || domain->yperiodic)
      error->all(FLERR, "Fix {}: a zcylinder wall needs x and y not periodic", style);
  } else if (domain->find_region(idregion) < 0) {
    // (here, not in the region fix's constructor: an error after the base
    // registered its per-atom callbacks would fail to unregister them)
    error->all(FLERR, "Fix {}: region {} does not exist", style, idregion);
  }
}
