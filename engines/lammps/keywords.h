//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file keywords.h
/// The two-way keyword values of the plugin's commands (coupling yes|no,
/// twist_transfer symmetric|negate, moduli exact|legacy), read in one place.

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

}  // namespace spinslide_lammps

#endif  // SPINSLIDE_LAMMPS_KEYWORDS_H
