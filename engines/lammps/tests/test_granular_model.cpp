//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The LAMMPS plugin's contact law as read (engines/lammps/granular_model.h,
// no LAMMPS needed): LAMMPS' model keywords and the plugin's short form,
// the checks of bad input, the constants, the mixing of two types, and the
// JKR patch against the JKR relations it solves.
#include "granular_model.h"
#include "legacy_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using spinslide_lammps::ContactLaw;
using spinslide_lammps::DampingModel;
using spinslide_lammps::NormalModel;
using spinslide_lammps::TangentialModel;
using spinslide_lammps::TwistModel;

// Words of one string, split at spaces.
std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> out;
  std::string word;
  for (char c : text) {
    if (c == ' ') {
      if (!word.empty()) out.push_back(word);
      word.clear();
    } else {
      word += c;
    }
  }
  if (!word.empty()) out.push_back(word);
  return out;
}

double number(const std::string& w) {
  std::size_t used = 0;
  const double x = std::stod(w, &used);
  if (used != w.size()) throw std::invalid_argument(w);
  return x;
}

struct Parsed {
  ContactLaw law;
  std::vector<std::string> rest;
  std::string why;
};

Parsed parse(const std::string& text) {
  Parsed p;
  p.why = spinslide_lammps::parse_lammps_model(words(text), number, p.law, p.rest);
  return p;
}

TEST(GranularModel, ReadsLammpsKeywordsAndPassesTheRestOn) {
  const Parsed p = parse(
      "jkr 1000.0 50.0 0.3 10 tangential mindlin 800.0 1.0 0.5 rolling sds 500.0 200.0 0.5 "
      "twisting marshall damping mass_velocity region drum coupling no");
  ASSERT_EQ(p.why, "");
  EXPECT_EQ(p.law.normal, NormalModel::kJkr);
  EXPECT_EQ(p.law.youngs, 1000.0);
  EXPECT_EQ(p.law.damp, 50.0);
  EXPECT_EQ(p.law.poisson, 0.3);
  EXPECT_EQ(p.law.cohesion, 10.0);
  EXPECT_EQ(p.law.tangential, TangentialModel::kMindlin);
  EXPECT_FALSE(p.law.kt_null);
  EXPECT_EQ(p.law.kt, 800.0);
  EXPECT_EQ(p.law.xgammat, 1.0);
  EXPECT_EQ(p.law.mu, 0.5);
  EXPECT_TRUE(p.law.rolling);
  EXPECT_EQ(p.law.k_roll, 500.0);
  EXPECT_EQ(p.law.gamma_roll, 200.0);
  EXPECT_EQ(p.law.mu_roll, 0.5);
  EXPECT_EQ(p.law.twist, TwistModel::kMarshall);
  EXPECT_EQ(p.law.damping, DampingModel::kMassVelocity);
  EXPECT_EQ(p.rest, (std::vector<std::string>{"region", "drum", "coupling", "no"}));
  EXPECT_EQ(spinslide_lammps::check_law(p.law), "");
}

TEST(GranularModel, TwistingIsNoneUnlessGivenAsInLammps) {
  const Parsed p = parse("hertz 200.0 20.0 tangential linear_history 300.0 1.0 0.1");
  ASSERT_EQ(p.why, "");
  EXPECT_EQ(p.law.twist, TwistModel::kNone);
  EXPECT_FALSE(p.law.rolling);
  EXPECT_FALSE(p.law.couplable());
  EXPECT_EQ(p.law.damping, DampingModel::kViscoelastic);
}

TEST(GranularModel, TheShortFormIsHertzMindlinMarshall) {
  const Parsed s([] {
    Parsed p;
    p.why = spinslide_lammps::parse_lammps_model(
        spinslide_lammps::expand_short_form(words("1e5 1e3 0.3 0.5 xgammat 0.7 limit_damping")),
        number, p.law, p.rest);
    return p;
  }());
  const Parsed l = parse(
      "hertz/material 1e5 1e3 0.3 tangential mindlin NULL 0.7 0.5 twisting marshall "
      "limit_damping");
  ASSERT_EQ(s.why, "");
  ASSERT_EQ(l.why, "");
  EXPECT_EQ(s.law.normal, l.law.normal);
  EXPECT_EQ(s.law.youngs, l.law.youngs);
  EXPECT_EQ(s.law.damp, l.law.damp);
  EXPECT_EQ(s.law.poisson, l.law.poisson);
  EXPECT_TRUE(s.law.kt_null);
  EXPECT_EQ(s.law.xgammat, 0.7);
  EXPECT_EQ(s.law.mu, 0.5);
  EXPECT_EQ(s.law.twist, TwistModel::kMarshall);
  EXPECT_TRUE(s.law.limit_damping);
  EXPECT_TRUE(s.law.couplable());
  EXPECT_TRUE(s.rest.empty());
}

TEST(GranularModel, RefusesWhatItCannotReadWithAReason) {
  EXPECT_NE(parse("hertz/material 1e5 1e3").why, "");  // too few values
  EXPECT_NE(parse("hertz/material 1e5 1e3 0.3").why.find("tangential"), std::string::npos);
  EXPECT_NE(parse("hertz/material 1e5 1e3 0.3 tangential mindlin_rescale NULL 1 0.5")
                .why.find("mindlin_rescale"),
            std::string::npos);
  EXPECT_NE(parse("hooke 1e4 1 tangential linear_history 1e3 1 0.5 damping soft").why, "");
  EXPECT_NE(parse("hooke 1e4 1 tangential linear_history 1e3 1 0.5 rolling hard 1 1 1").why, "");
  EXPECT_NE(parse("hooke 1e4 1 tangential linear_history 1e3 1 0.5 twisting sds 1 1").why, "");
}

TEST(GranularModel, ChecksTheNumbersAndTheCombinations) {
  const auto why = [](const std::string& text) {
    const Parsed p = parse(text);
    EXPECT_EQ(p.why, "") << text;
    return spinslide_lammps::check_law(p.law);
  };
  EXPECT_NE(why("hertz/material -1 1e3 0.3 tangential mindlin NULL 1 0.5"), "");
  EXPECT_NE(why("hertz/material 1e5 1e3 0.6 tangential mindlin NULL 1 0.5"), "");
  EXPECT_NE(why("hertz/material 1e5 1e3 0.3 tangential mindlin NULL 1 -0.5"), "");
  EXPECT_NE(why("hertz/material 1e5 1.5 0.3 tangential mindlin NULL 1 0.5 damping tsuji"), "");
  EXPECT_NE(why("hooke 1e4 1 tangential mindlin NULL 1 0.5"), "");  // NULL needs E, nu
  EXPECT_NE(why("hooke 1e4 1 tangential linear_nohistory 1 0.5 twisting marshall"), "");
  EXPECT_NE(why("dmt 1e5 1e3 0.3 5 tangential mindlin NULL 1 0.5 limit_damping"), "");
  EXPECT_NE(why("hooke 1e4 1 tangential linear_history 1e3 1 0.5 rolling sds 0 1 1"), "");
  EXPECT_EQ(why("hooke 1e4 1 tangential linear_nohistory 1 0.5 twisting sds 1 1 1"), "");
}

TEST(GranularModel, ReadsThePatchProfile) {
  using spinslide_lammps::PatchProfile;
  const std::string law = "hertz/material 1e5 1e3 0.3 tangential mindlin NULL 1 0.5 ";
  EXPECT_EQ(parse(law + "twisting marshall").law.profile, PatchProfile::kHertz);  // default
  const Parsed ring = parse(law + "profile ring twisting marshall coupling yes");
  ASSERT_EQ(ring.why, "");
  EXPECT_EQ(ring.law.profile, PatchProfile::kRing);
  EXPECT_EQ(ring.law.twist, TwistModel::kMarshall);
  EXPECT_EQ(ring.rest, (std::vector<std::string>{"coupling", "yes"}));
  EXPECT_EQ(parse(law + "profile disk").law.profile, PatchProfile::kDisk);
  EXPECT_EQ(parse(law + "profile boussinesq").law.profile, PatchProfile::kBoussinesq);
  const Parsed annulus = parse(law + "profile annulus 0.25 cutoff 2");
  ASSERT_EQ(annulus.why, "");
  EXPECT_EQ(annulus.law.profile, PatchProfile::kAnnulus);
  EXPECT_EQ(annulus.law.annulus_inner, 0.25);
  EXPECT_EQ(annulus.rest, (std::vector<std::string>{"cutoff", "2"}));
  EXPECT_EQ(spinslide_lammps::check_law(annulus.law), "");
  // in the short form too, after the four numbers
  Parsed s;
  s.why = spinslide_lammps::parse_lammps_model(
      spinslide_lammps::expand_short_form(words("1e5 1e3 0.3 0.5 profile ring")), number, s.law,
      s.rest);
  ASSERT_EQ(s.why, "");
  EXPECT_EQ(s.law.profile, PatchProfile::kRing);
  // refused, saying why
  EXPECT_NE(parse(law + "profile square").why.find("square"), std::string::npos);
  EXPECT_NE(parse(law + "profile").why, "");
  EXPECT_NE(parse(law + "profile annulus").why.find("annulus"), std::string::npos);
  EXPECT_NE(spinslide_lammps::check_law(parse(law + "profile annulus 1").law), "");
  EXPECT_NE(spinslide_lammps::check_law(parse(law + "profile annulus -0.1").law), "");
  // types of different profiles do not mix
  EXPECT_FALSE(spinslide_lammps::same_forms(ring.law, annulus.law));
  EXPECT_FALSE(spinslide_lammps::same_forms(annulus.law, parse(law + "profile annulus 0.5").law));
}

TEST(GranularModel, ResolvesTheMaterialConstants) {
  const double e = 1e5, nu = 0.3;
  const Parsed p = parse("hertz/material 1e5 0.8 0.3 tangential mindlin NULL 1 0.5 damping tsuji");
  ASSERT_EQ(p.why, "");
  const ContactLaw exact =
      spinslide_lammps::resolve(p.law, spinslide_lammps::Moduli::kExact, false);
  // one material: E* = E/(2(1 - nu^2)), G* = E/(4(2 - nu)(1 + nu))
  EXPECT_NEAR(exact.kn, 4.0 / 3.0 * e / (2 * (1 - nu * nu)), 1e-10 * exact.kn);
  EXPECT_NEAR(exact.kt, 8 * e / (4 * (2 - nu) * (1 + nu)), 1e-10 * exact.kt);
  // Not bit for bit: clang folds a call with a constant argument with fused
  // multiply-adds (llvm.fmuladd), where the call at run time, on a target
  // without FMA, multiplies and adds.  The fit cancels: its terms at e = 0.8
  // sum to 42 in magnitude for a value of 0.11, so a rounding of each of its
  // 7 terms moves it by up to 7 * 42 * 2.2e-16 = 6.5e-14 (seen: 1.2e-15).
  const double fit_rounding = 1e-13;
  EXPECT_NEAR(exact.damp, spinslide_lammps::tsuji_alpha(0.8), fit_rounding);
  const ContactLaw legacy =
      spinslide_lammps::resolve(p.law, spinslide_lammps::Moduli::kLegacyWall, true);
  EXPECT_NEAR(legacy.kn, 4.0 / 3.0 * e / (2 * (1 - nu)), 1e-14 * legacy.kn);
  EXPECT_NEAR(legacy.kt, e * (2 - nu) * (1 + nu) / 4, 1e-14 * legacy.kt);
  EXPECT_NEAR(legacy.damp, spinslide_lammps::tsuji_alpha_by_pow(0.8), fit_rounding);
  // Tsuji's fit: alpha(1) is 3e-4 (its coefficients sum), alpha falls with e
  EXPECT_NEAR(spinslide_lammps::tsuji_alpha(1.0), 3e-4, 1e-12);
  EXPECT_GT(spinslide_lammps::tsuji_alpha(0.5), spinslide_lammps::tsuji_alpha(0.9));
}

TEST(GranularModel, MixesTwoTypes) {
  const auto resolved = [](const std::string& text) {
    const Parsed p = parse(text);
    EXPECT_EQ(p.why, "");
    return spinslide_lammps::resolve(p.law, spinslide_lammps::Moduli::kExact, false);
  };
  const ContactLaw a = resolved("hertz/material 1e5 100 0.3 tangential mindlin NULL 1 0.4");
  const ContactLaw b = resolved("hertz/material 4e5 400 0.2 tangential mindlin NULL 1 0.9");
  ASSERT_TRUE(spinslide_lammps::same_forms(a, b));
  const ContactLaw m = spinslide_lammps::mix(a, b);
  EXPECT_NEAR(m.kn, 4.0 / 3.0 / ((1 - 0.09) / 1e5 + (1 - 0.04) / 4e5), 1e-10 * m.kn);
  EXPECT_NEAR(m.kt, 8.0 / (2 * 1.7 * 1.3 / 1e5 + 2 * 1.8 * 1.2 / 4e5), 1e-10 * m.kt);
  EXPECT_NEAR(m.damp, 200.0, 1e-12);
  EXPECT_NEAR(m.mu, 0.6, 1e-15);
  // the same type with itself is itself
  const ContactLaw s = spinslide_lammps::mix(a, a);
  EXPECT_NEAR(s.kn, a.kn, 1e-12 * a.kn);
  EXPECT_NEAR(s.kt, a.kt, 1e-12 * a.kt);
  const ContactLaw c = resolved("hooke 1e4 1 tangential linear_history 1e3 1 0.5");
  EXPECT_FALSE(spinslide_lammps::same_forms(a, c));
}

// The JKR patch against the relations it solves (surface energy gamma,
// w = 2 gamma): delta = a^2/R - 2 sqrt(pi gamma a/E*) and
// F = 4 E* a^3/(3 R) - 4 sqrt(pi gamma E*) a^(3/2).
TEST(GranularModel, JkrPatchSolvesTheJkrRelations) {
  const Parsed p = parse("jkr 1e5 0 0.3 10 tangential mindlin NULL 1 0.5");
  ASSERT_EQ(p.why, "");
  const ContactLaw law = spinslide_lammps::resolve(p.law, spinslide_lammps::Moduli::kExact, false);
  const double estar = 0.75 * law.kn, gamma = law.cohesion, pi = std::acos(-1.0);
  for (const double reff : {0.125, 0.25, 0.5}) {
    for (const double delta : {-0.002, 0.0, 1e-4, 1e-3, 1e-2, 5e-2}) {
      double a = 0.0, f = 0.0;
      spinslide_lammps::jkr_patch(law, reff, delta * reff, a, f);
      const double delta_jkr = a * a / reff - 2 * std::sqrt(pi * gamma * a / estar);
      const double f_jkr =
          4 * estar * a * a * a / (3 * reff) - 4 * std::sqrt(pi * gamma * estar) * std::pow(a, 1.5);
      EXPECT_NEAR(delta_jkr, delta, 1e-9 * reff) << "R " << reff << " delta " << delta;
      EXPECT_NEAR(f_jkr, f, 1e-9 * std::fabs(f) + 1e-12) << "R " << reff << " delta " << delta;
    }
    // At LAMMPS' pull-off overlap (the force-controlled one, a^3 = 9 pi
    // gamma R^2/(4 E*)) the force is the pull-off force -3 pi gamma R.
    const double pulloff = spinslide_lammps::pulloff_distance(law, 2 * reff, 2 * reff);
    double a = 0.0, f = 0.0;
    spinslide_lammps::jkr_patch(law, reff, pulloff * reff, a, f);
    EXPECT_NEAR(f, -3 * pi * gamma * reff, 1e-8 * 3 * pi * gamma * reff);
    EXPECT_LT(pulloff, 0.0);
    // touching pairs hold until that overlap, new ones touch at contact
    const double radsum = 4 * reff;
    const double inside = radsum - pulloff * 0.999, outside = radsum - pulloff * 1.001;
    EXPECT_TRUE(spinslide_lammps::pair_touching(law, inside * inside, radsum, reff, true));
    EXPECT_FALSE(spinslide_lammps::pair_touching(law, outside * outside, radsum, reff, true));
    EXPECT_FALSE(spinslide_lammps::pair_touching(law, inside * inside, radsum, reff, false));
  }
}

// LAMMPS' older styles: their numbers as those styles resolve them.
TEST(LegacyModel, ReadsTheOlderStylesNumbers) {
  spinslide_lammps::LegacyLaw law;
  ASSERT_EQ(spinslide_lammps::parse_legacy(words("gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0"),
                                           number, 1.0, law),
            "");
  EXPECT_EQ(law.model, spinslide_lammps::LegacyModel::kHookeHistory);
  EXPECT_EQ(law.kt, 2000.0 * 2.0 / 7.0);  // NULL: 2 kn/7
  EXPECT_EQ(law.gammat, 0.0);             // dampflag 0
  ASSERT_EQ(spinslide_lammps::parse_legacy(
                words("hertz/history 4000 1000 100 NULL 0.5 1 limit_damping"), number, 2.0, law),
            "");
  EXPECT_EQ(law.model, spinslide_lammps::LegacyModel::kHertzHistory);
  EXPECT_EQ(law.kn, 2000.0);  // divided by nktv2p
  EXPECT_EQ(law.kt, 500.0);
  EXPECT_EQ(law.gammat, 50.0);  // NULL: gamman/2
  EXPECT_TRUE(law.limit_damping);
  const spinslide_lammps::LegacyLaw hertz = law;
  EXPECT_NE(spinslide_lammps::parse_legacy(words("gran/hooke 1 1 1 1 0.5"), number, 1.0, law), "");
  EXPECT_NE(spinslide_lammps::parse_legacy(words("gran/hooke 1 1 1 1 0.5 2"), number, 1.0, law),
            "");
  EXPECT_NE(spinslide_lammps::parse_legacy(words("gran/soft 1 1 1 1 0.5 1"), number, 1.0, law), "");
  // coupled: the same contact in the newer keywords, with Marshall's spring
  const ContactLaw modern = spinslide_lammps::modern_equivalent(hertz);
  EXPECT_EQ(modern.normal, NormalModel::kHertz);
  EXPECT_EQ(modern.damping, DampingModel::kViscoelastic);
  EXPECT_EQ(modern.tangential, TangentialModel::kMindlin);
  EXPECT_EQ(modern.xgammat, 0.5);
  EXPECT_EQ(modern.twist, TwistModel::kMarshall);
  EXPECT_EQ(spinslide_lammps::check_law(modern), "");
}

// The older styles' forces against the contact laws they implement: a
// sphere pair at overlap d approaching at v_n and sliding at v_t.
TEST(LegacyModel, ForcesAreTheContactLaw) {
  spinslide_lammps::LegacyLaw law;
  const double kn = 2000.0, kt = 600.0, gn = 50.0, gt = 20.0, mu = 0.5;
  for (const char* model : {"gran/hooke/history", "gran/hertz/history"}) {
    ASSERT_EQ(spinslide_lammps::parse_legacy(words(std::string(model) + " 2000 600 50 20 0.5 1"),
                                             number, 1.0, law),
              "");
    const bool hertz = std::string(model) == "gran/hertz/history";
    spinslide_lammps::LegacyContact c{};
    const double d = 0.01, r = 2.0 - d, reff = 0.5, meff = 0.25, vn = -0.1, vt = 0.02;
    c.del[0] = r;  // along x; the partner approaches along -x relative
    c.rsq = r * r;
    c.radsum = 2.0;
    c.polyhertz = std::sqrt(d * reff);
    c.vr[0] = vn;
    c.vr[1] = vt;
    c.meff = meff;
    double shear[3] = {0.0, 0.0, 0.0};
    const double dt = 1e-4;
    const spinslide_lammps::LegacyForce lf =
        spinslide_lammps::legacy_force(law, c, shear, dt, true, false);
    const double* f = lf.f;
    const double* tor = lf.tor;
    const bool capped = lf.capped;
    const double scale = hertz ? std::sqrt(d * reff) : 1.0;
    EXPECT_NEAR(f[0], scale * (kn * d - meff * gn * vn), 1e-12) << model;
    EXPECT_NEAR(f[1], -scale * (kt * vt * dt + meff * gt * vt), 1e-12) << model;
    EXPECT_NEAR(shear[1], vt * dt, 1e-18) << model;
    EXPECT_FALSE(capped) << model;
    // torque: r_i (n x F_t) taken off; here n = x, F_t along y
    EXPECT_NEAR(tor[2], f[1], 1e-12) << model;
    // a fast slip is capped at mu |F_n|
    c.vr[1] = 100.0;
    double shear2[3] = {0.0, 0.0, 0.0};
    const spinslide_lammps::LegacyForce fast =
        spinslide_lammps::legacy_force(law, c, shear2, dt, true, false);
    EXPECT_TRUE(fast.capped) << model;
    EXPECT_NEAR(std::fabs(fast.f[1]), mu * std::fabs(fast.f[0]), 1e-12 * std::fabs(fast.f[0]))
        << model;
  }
}

}  // namespace
