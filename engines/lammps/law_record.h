//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file law_record.h
/// One type pair's coefficients as the pair style granular/spinslide writes
/// them to a restart file: its contact law as resolved (ContactLaw), LAMMPS'
/// older style if it was given one (LegacyLaw) and its cutoff, as a record of
/// kLawRecordSize doubles in a fixed order (enumerations and flags as small
/// whole numbers, which doubles hold exactly).  The restart section starts
/// with kRestartMagic and kRestartLayout, which the reader checks before it
/// reads anything else (pair_granular_spinslide_restart.cpp).  No LAMMPS
/// header: the unit tests pack and unpack records without LAMMPS.

#ifndef SPINSLIDE_LAMMPS_LAW_RECORD_H
#define SPINSLIDE_LAMMPS_LAW_RECORD_H

#include "granular_model.h"
#include "legacy_contact.h"

#include <cstddef>
#include <string>

namespace spinslide_lammps {

/// The first int of the pair's restart section: "SPSL" read as a
/// big-endian int.  Anything else there was not written by this plugin.
constexpr int kRestartMagic = 0x5350534C;
/// The layout of the section after the magic (the second int).  2: the
/// settings (coupled, twist_negate as ints), the number of types and the
/// record size (ints), then per type pair I <= J its setflag (int) and, if
/// set, its record (kLawRecordSize doubles).  A reader refuses any other
/// layout.  (Layout 1, of the unreleased plugin before the `profile`
/// keyword, had no profile in its records; plugins before it, version
/// 0.1.0, wrote no pair section: LAMMPS then asks for pair_style and
/// pair_coeff after read_restart.)
constexpr int kRestartLayout = 2;

namespace detail {

// The law's numbers, in the record's order (after its 8 enumerations and
// flags); pack and unpack walk the same lists.
constexpr double ContactLaw::*kLawNumbers[] = {
    &ContactLaw::kn,          &ContactLaw::youngs,   &ContactLaw::poisson,
    &ContactLaw::damp,        &ContactLaw::cohesion, &ContactLaw::kt,
    &ContactLaw::xgammat,     &ContactLaw::mu,       &ContactLaw::k_roll,
    &ContactLaw::gamma_roll,  &ContactLaw::mu_roll,  &ContactLaw::k_twist,
    &ContactLaw::gamma_twist, &ContactLaw::mu_twist, &ContactLaw::annulus_inner};
constexpr double LegacyLaw::*kLegacyNumbers[] = {&LegacyLaw::kn, &LegacyLaw::kt, &LegacyLaw::gamman,
                                                 &LegacyLaw::gammat, &LegacyLaw::xmu};
constexpr std::size_t kLawFlags = 8;     // normal, damping, tangential, twist, 3 flags, profile
constexpr std::size_t kLegacyFlags = 2;  // model, limit_damping
constexpr std::size_t kNumLaw = sizeof(kLawNumbers) / sizeof(kLawNumbers[0]);
constexpr std::size_t kNumLegacy = sizeof(kLegacyNumbers) / sizeof(kLegacyNumbers[0]);

// A whole number in [0, max] from the record, or -1.
inline int small_whole(double x, int max) {
  if (!(x >= 0.0 && x <= max)) return -1;
  const int k = static_cast<int>(x);
  return static_cast<double>(k) == x ? k : -1;
}

}  // namespace detail

/// The doubles of one type pair's record.
constexpr std::size_t kLawRecordSize =
    detail::kLawFlags + detail::kNumLaw + detail::kLegacyFlags + detail::kNumLegacy + 1;

/// One type pair's record: `law` (resolved), `legacy` and the cutoff, into
/// record[0, kLawRecordSize).
inline void pack_law(const ContactLaw& law, const LegacyLaw& legacy, double cutoff,
                     double* record) {
  std::size_t k = 0;
  record[k++] = static_cast<int>(law.normal);
  record[k++] = static_cast<int>(law.damping);
  record[k++] = static_cast<int>(law.tangential);
  record[k++] = static_cast<int>(law.twist);
  record[k++] = law.limit_damping ? 1.0 : 0.0;
  record[k++] = law.kt_null ? 1.0 : 0.0;
  record[k++] = law.rolling ? 1.0 : 0.0;
  record[k++] = static_cast<int>(law.profile);
  for (double ContactLaw::*member : detail::kLawNumbers) record[k++] = law.*member;
  record[k++] = static_cast<int>(legacy.model);
  record[k++] = legacy.limit_damping ? 1.0 : 0.0;
  for (double LegacyLaw::*member : detail::kLegacyNumbers) record[k++] = legacy.*member;
  record[k] = cutoff;
}

/// The law, older style and cutoff of one record; an error message if the
/// record holds a value no law has (an enumeration or flag out of range), or
/// an empty string.
inline std::string unpack_law(const double* record, ContactLaw& law, LegacyLaw& legacy,
                              double& cutoff) {
  law = ContactLaw{};
  legacy = LegacyLaw{};
  const int normal = detail::small_whole(record[0], static_cast<int>(NormalModel::kJkr));
  const int damping = detail::small_whole(record[1], static_cast<int>(DampingModel::kTsuji));
  const int tangential =
      detail::small_whole(record[2], static_cast<int>(TangentialModel::kMindlin));
  const int twist = detail::small_whole(record[3], static_cast<int>(TwistModel::kSds));
  const int flags[3] = {detail::small_whole(record[4], 1), detail::small_whole(record[5], 1),
                        detail::small_whole(record[6], 1)};
  const int profile = detail::small_whole(record[7], static_cast<int>(PatchProfile::kAnnulus));
  const std::size_t at_legacy = detail::kLawFlags + detail::kNumLaw;
  const int model =
      detail::small_whole(record[at_legacy], static_cast<int>(LegacyModel::kHertzHistory));
  const int legacy_limit = detail::small_whole(record[at_legacy + 1], 1);
  if (normal < 0 || damping < 0 || tangential < 0 || twist < 0 || flags[0] < 0 || flags[1] < 0 ||
      flags[2] < 0 || profile < 0 || model < 0 || legacy_limit < 0)
    return "a type pair's record holds a model number no law has (a damaged file?)";
  law.normal = static_cast<NormalModel>(normal);
  law.damping = static_cast<DampingModel>(damping);
  law.tangential = static_cast<TangentialModel>(tangential);
  law.twist = static_cast<TwistModel>(twist);
  law.limit_damping = flags[0] == 1;
  law.kt_null = flags[1] == 1;
  law.rolling = flags[2] == 1;
  law.profile = static_cast<PatchProfile>(profile);
  std::size_t k = detail::kLawFlags;
  for (double ContactLaw::*member : detail::kLawNumbers) law.*member = record[k++];
  legacy.model = static_cast<LegacyModel>(model);
  legacy.limit_damping = legacy_limit == 1;
  k = at_legacy + detail::kLegacyFlags;
  for (double LegacyLaw::*member : detail::kLegacyNumbers) legacy.*member = record[k++];
  cutoff = record[k];
  return "";
}

}  // namespace spinslide_lammps

#endif  // SPINSLIDE_LAMMPS_LAW_RECORD_H
