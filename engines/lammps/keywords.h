//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file keywords.h
/// The two-way keyword values of the plugin's commands (coupling yes|no,
/// twist_transfer symmetric|negate, moduli exact|legacy), read in one place,
/// and the message for LAMMPS' granular wall keywords that it does not take.

#ifndef SPINSLIDE_LAMMPS_KEYWORDS_H
#define SPINSLIDE_LAMMPS_KEYWORDS_H

#include <initializer_list>
#include <string>

namespace spinslide_lammps {

/// 1 if `value` is one of `one`, 0 if one of `zero`, −1 (an error for the
/// caller to report) otherwise.
inline int either(const std::string& value, std::initializer_list<const char*> one,
                  std::initializer_list<const char*> zero) {
  for (const char* v : one)
    if (value == v) return 1;
  for (const char* v : zero)
    if (value == v) return 0;
  return -1;
}

/// Why a keyword of LAMMPS' own granular commands is refused here, or an
/// empty string if `key` is not one of them: a user converting an input
/// reads what to do instead of "unknown keyword".
inline std::string unsupported_granular_keyword(const std::string& key) {
  if (key == "wiggle" || key == "shear")
    return "the plane and cylinder walls are fixed in space: move a region wall instead "
           "(fix wall/gran/region/spinslide with region ... move or rotate)";
  if (key == "contacts" || key == "temperature")
    return "per-contact output and heat conduction of fix wall/gran are not supported (f_ID "
           "gives the contact statistics)";
  return "";
}

}  // namespace spinslide_lammps

#endif  // SPINSLIDE_LAMMPS_KEYWORDS_H
