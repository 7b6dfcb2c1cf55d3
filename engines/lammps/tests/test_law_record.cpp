//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The LAMMPS plugin's restart record of one type pair
// (engines/lammps/law_record.h, no LAMMPS needed): every field of the law,
// the older style's law and the cutoff comes back as it was written, to the
// bit; a record holding a value no law has is refused; layout 2's size is
// fixed.
#include "granular_model.h"
#include "law_record.h"
#include "legacy_contact.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <string>

namespace {

using spinslide_lammps::ContactLaw;
using spinslide_lammps::kLawRecordSize;
using spinslide_lammps::LegacyLaw;
using Record = std::array<double, kLawRecordSize>;

// A law whose every field differs from its default, the numbers each other
// too (and not short decimals: their last bits must survive).
ContactLaw unusual_law() {
  ContactLaw law;
  law.normal = spinslide_lammps::NormalModel::kJkr;
  law.kn = 1.0 / 3.0;
  law.youngs = 2.0 / 3.0;
  law.poisson = 0.1 / 3.0;
  law.damp = 4.0 / 7.0;
  law.cohesion = 5.0 / 7.0;
  law.damping = spinslide_lammps::DampingModel::kTsuji;
  law.limit_damping = true;
  law.tangential = spinslide_lammps::TangentialModel::kLinearHistory;
  law.kt = 6.0 / 7.0;
  law.kt_null = false;
  law.xgammat = 1.0 / 11.0;
  law.mu = 2.0 / 11.0;
  law.rolling = true;
  law.k_roll = 3.0 / 11.0;
  law.gamma_roll = 4.0 / 11.0;
  law.mu_roll = 5.0 / 11.0;
  law.twist = spinslide_lammps::TwistModel::kSds;
  law.k_twist = 6.0 / 11.0;
  law.gamma_twist = 7.0 / 11.0;
  law.mu_twist = 8.0 / 11.0;
  law.profile = spinslide_lammps::PatchProfile::kAnnulus;
  law.annulus_inner = 9.0 / 11.0;
  return law;
}

// Whether two records hold the same bits.
bool same_bits(const Record& a, const Record& b) {
  for (std::size_t k = 0; k < a.size(); ++k) {
    std::uint64_t x = 0, y = 0;
    std::memcpy(&x, &a[k], sizeof(x));
    std::memcpy(&y, &b[k], sizeof(y));
    if (x != y) return false;
  }
  return true;
}

LegacyLaw unusual_legacy() {
  LegacyLaw legacy;
  legacy.model = spinslide_lammps::LegacyModel::kHertzHistory;
  legacy.kn = 1.0 / 13.0;
  legacy.kt = 2.0 / 13.0;
  legacy.gamman = 3.0 / 13.0;
  legacy.gammat = 4.0 / 13.0;
  legacy.xmu = 5.0 / 13.0;
  legacy.limit_damping = true;
  return legacy;
}

TEST(LawRecord, EveryFieldComesBackToTheBit) {
  const ContactLaw law = unusual_law();
  const LegacyLaw legacy = unusual_legacy();
  Record record{};
  spinslide_lammps::pack_law(law, legacy, 1.0 / 17.0, record.data());
  ContactLaw read;
  LegacyLaw read_legacy;
  double cutoff = 0.0;
  ASSERT_EQ(spinslide_lammps::unpack_law(record.data(), read, read_legacy, cutoff), "");
  EXPECT_EQ(read.normal, law.normal);
  EXPECT_EQ(read.kn, law.kn);
  EXPECT_EQ(read.youngs, law.youngs);
  EXPECT_EQ(read.poisson, law.poisson);
  EXPECT_EQ(read.damp, law.damp);
  EXPECT_EQ(read.cohesion, law.cohesion);
  EXPECT_EQ(read.damping, law.damping);
  EXPECT_EQ(read.limit_damping, law.limit_damping);
  EXPECT_EQ(read.tangential, law.tangential);
  EXPECT_EQ(read.kt, law.kt);
  EXPECT_EQ(read.kt_null, law.kt_null);
  EXPECT_EQ(read.xgammat, law.xgammat);
  EXPECT_EQ(read.mu, law.mu);
  EXPECT_EQ(read.rolling, law.rolling);
  EXPECT_EQ(read.k_roll, law.k_roll);
  EXPECT_EQ(read.gamma_roll, law.gamma_roll);
  EXPECT_EQ(read.mu_roll, law.mu_roll);
  EXPECT_EQ(read.twist, law.twist);
  EXPECT_EQ(read.k_twist, law.k_twist);
  EXPECT_EQ(read.gamma_twist, law.gamma_twist);
  EXPECT_EQ(read.mu_twist, law.mu_twist);
  EXPECT_EQ(read.profile, law.profile);
  EXPECT_EQ(read.annulus_inner, law.annulus_inner);
  EXPECT_EQ(read_legacy.model, legacy.model);
  EXPECT_EQ(read_legacy.kn, legacy.kn);
  EXPECT_EQ(read_legacy.kt, legacy.kt);
  EXPECT_EQ(read_legacy.gamman, legacy.gamman);
  EXPECT_EQ(read_legacy.gammat, legacy.gammat);
  EXPECT_EQ(read_legacy.xmu, legacy.xmu);
  EXPECT_EQ(read_legacy.limit_damping, legacy.limit_damping);
  EXPECT_EQ(cutoff, 1.0 / 17.0);
  // and it packs into the same record again
  Record again{};
  spinslide_lammps::pack_law(read, read_legacy, cutoff, again.data());
  EXPECT_TRUE(same_bits(record, again));
}

TEST(LawRecord, TheDefaultsComeBackToo) {
  Record record{};
  spinslide_lammps::pack_law(ContactLaw{}, LegacyLaw{}, -1.0, record.data());
  ContactLaw read = unusual_law();
  LegacyLaw read_legacy = unusual_legacy();
  double cutoff = 0.0;
  ASSERT_EQ(spinslide_lammps::unpack_law(record.data(), read, read_legacy, cutoff), "");
  Record again{};
  spinslide_lammps::pack_law(read, read_legacy, cutoff, again.data());
  EXPECT_TRUE(same_bits(record, again));
  EXPECT_EQ(read.normal, spinslide_lammps::NormalModel::kHertzMaterial);
  EXPECT_TRUE(read.kt_null);
  EXPECT_EQ(read.profile, spinslide_lammps::PatchProfile::kHertz);
  EXPECT_EQ(read_legacy.model, spinslide_lammps::LegacyModel::kNone);
  EXPECT_EQ(cutoff, -1.0);
}

TEST(LawRecord, RefusesAValueNoLawHas) {
  Record good{};
  spinslide_lammps::pack_law(unusual_law(), unusual_legacy(), 1.0, good.data());
  // the normal model, the twisting model, a flag, the profile, the older
  // style's model
  const std::size_t legacy_model = kLawRecordSize - 8;
  const std::array<std::size_t, 5> slots = {0, 3, 5, 7, legacy_model};
  for (std::size_t slot : slots) {
    for (double bad : {-1.0, 0.5, 99.0}) {
      Record record = good;
      record[slot] = bad;
      ContactLaw law;
      LegacyLaw legacy;
      double cutoff = 0.0;
      EXPECT_NE(spinslide_lammps::unpack_law(record.data(), law, legacy, cutoff), "")
          << "slot " << slot << " = " << bad;
    }
  }
}

TEST(LawRecord, LayoutTwoHasThirtyOneNumbers) {
  // Layout 2 as written by the plugin: 8 + 15 numbers of the law (layout 1
  // had no profile: 7 + 14), 2 + 5 of the older style's, the cutoff.  A
  // record of another size needs another layout number (kRestartLayout), so
  // that older plugins refuse it.
  EXPECT_EQ(kLawRecordSize, 31u);
  EXPECT_EQ(spinslide_lammps::kRestartLayout, 2);
  EXPECT_EQ(spinslide_lammps::kRestartMagic, 0x5350534C);
}

}  // namespace
