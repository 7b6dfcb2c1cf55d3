//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file granular_model.h
/// The contact law of one pair of materials (ContactLaw) and where it comes
/// from: the plugin's short form `E eta_n nu mu [options]` (read as the
/// model keywords it stands for), or the model
/// keywords of LAMMPS' `pair_style granular` (hooke, hertz, hertz/material,
/// dmt, jkr; damping; tangential linear_nohistory, linear_history, mindlin;
/// rolling sds; twisting marshall, sds; limit_damping), read in one place
/// for the pair style and the walls, checked, and turned into the
/// constants the force computation uses.  No LAMMPS header: the callers
/// report the messages.

#ifndef SPINSLIDE_LAMMPS_GRANULAR_MODEL_H
#define SPINSLIDE_LAMMPS_GRANULAR_MODEL_H

#include <cmath>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace spinslide_lammps {

/// The normal force: linear (Hooke), Hertz with a given stiffness, Hertz
/// from E and nu, and the adhesive Hertz models of Derjaguin-Muller-Toporov
/// and Johnson-Kendall-Roberts.
enum class NormalModel { kHooke, kHertz, kHertzMaterial, kDmt, kJkr };
/// What the normal damping coefficient multiplies: 1, m*, a m*
/// (viscoelastic) or sqrt(m* k_n a) (Tsuji).
enum class DampingModel { kVelocity, kMassVelocity, kViscoelastic, kTsuji };
/// The tangential force: viscous without a spring, a linear spring, or a
/// Mindlin spring (stiffness proportional to the patch radius a).
enum class TangentialModel { kLinearNoHistory, kLinearHistory, kMindlin };
/// The twisting torque: none, Marshall's spring (from the tangential one
/// and the patch), or a spring of its own (sds).
enum class TwistModel { kNone, kMarshall, kSds };
/// The pressure profile of the contact's patch, whose limit set the coupled
/// cap projects onto (spinslide's profiles; `profile` keyword): Hertz's
/// sphere (the default), the uniform disk, the ring (all pressure on the
/// rim), Boussinesq's flat punch and the uniform annulus b <= r/a <= 1.
enum class PatchProfile { kHertz, kDisk, kRing, kBoussinesq, kAnnulus };

/// The effective Young's modulus E* of two materials (Hertz).
inline double effective_youngs(double e1, double nu1, double e2, double nu2) {
  return 1 / ((1 - nu1 * nu1) / e1 + (1 - nu2 * nu2) / e2);
}
/// The effective shear modulus G* of two materials (Mindlin).
inline double effective_shear(double e1, double nu1, double e2, double nu2) {
  return 1 / ((2 * (2 - nu1) * (1 + nu1) / e1) + (2 * (2 - nu2) * (1 + nu2) / e2));
}

/// Tsuji's damping coefficient alpha for a coefficient of restitution e
/// (Tsuji, Tanaka and Ishida 1992, the polynomial fit LAMMPS' `damping
/// tsuji` uses), evaluated with the same products as LAMMPS' pair granular
/// (e^4 = (e e)(e e), e^5 = e e^4, e^6 = (e e) e^4), so that the two agree
/// to the last bit.
inline double tsuji_alpha(double e) {
  const double e2 = e * e, e3 = e2 * e, e4 = e2 * e2, e5 = e * e4, e6 = e2 * e4;
  return 1.2728 - 4.2783 * e + 11.087 * e2 - 22.348 * e3 + 27.467 * e4 - 18.022 * e5 + 4.8218 * e6;
}

/// The same fit with the powers by std::pow, as LAMMPS' fix wall/gran
/// evaluates it (the last bits may differ from tsuji_alpha; each reproduces
/// its own LAMMPS style).
inline double tsuji_alpha_by_pow(double e) {
  return 1.2728 - 4.2783 * e + 11.087 * std::pow(e, 2) - 22.348 * std::pow(e, 3) +
         27.467 * std::pow(e, 4) - 18.022 * std::pow(e, 5) + 4.8218 * std::pow(e, 6);
}

/// The contact law of one pair of materials (a type pair, or spheres
/// against a wall).  As read, `damp` is the damping coefficient (Tsuji: the
/// coefficient of restitution) and `kt_null` marks Mindlin's NULL (8 G*);
/// resolve() turns them into the constants of the force computation.
struct ContactLaw {
  NormalModel normal = NormalModel::kHertzMaterial;
  double kn = 0.0;        ///< hooke, hertz: k_n as given; the material models: (4/3) E*
  double youngs = 0.0;    ///< the material models: E
  double poisson = 0.0;   ///< the material models: nu
  double damp = 0.0;      ///< the normal damping coefficient (tsuji: alpha(e))
  double cohesion = 0.0;  ///< dmt, jkr: the surface energy
  DampingModel damping = DampingModel::kViscoelastic;
  bool limit_damping = false;  ///< the normal force not below 0
  TangentialModel tangential = TangentialModel::kMindlin;
  double kt = 0.0;       ///< linear_history: k_t; mindlin: k_t/a
  bool kt_null = true;   ///< mindlin NULL: k_t/a = 8 G* of the materials
  double xgammat = 1.0;  ///< gamma_t = xgammat gamma_n
  double mu = 0.0;       ///< the sliding friction coefficient
  bool rolling = false;  ///< rolling resistance (sds): a spring of its own, capped at mu_roll F_n
  double k_roll = 0.0, gamma_roll = 0.0, mu_roll = 0.0;
  TwistModel twist = TwistModel::kMarshall;
  double k_twist = 0.0, gamma_twist = 0.0, mu_twist = 0.0;  ///< sds only
  PatchProfile profile = PatchProfile::kHertz;              ///< the coupled cap's limit set
  double annulus_inner = 0.0;  ///< annulus: its inner radius over a, in [0, 1)

  /// Whether the normal model takes E and nu.
  bool material() const { return normal != NormalModel::kHooke && normal != NormalModel::kHertz; }
  /// Whether a tangential spring is kept (the coupled cap needs it).
  bool tangential_spring() const { return tangential != TangentialModel::kLinearNoHistory; }
  /// Whether the coupled cap applies: a tangential spring and Marshall's
  /// twisting spring.  Without a twisting torque there is nothing to couple.
  bool couplable() const { return tangential_spring() && twist == TwistModel::kMarshall; }
};

/// The constants of the JKR solution for the patch radius, as the doubles
/// LAMMPS 2021 uses (its decimal literals; 27 pi^2, 6 sqrt(6) and
/// 1/sqrt(6) each round to one ulp from the nearest double), so that the
/// coupling off reproduces it bit for bit.
constexpr double kPi = 3.14159265358979323846;
constexpr double k27PiSquared = 266.47931882941264802866;
constexpr double kThreeRoot3 = 5.19615242270663202362;
constexpr double kSixRoot6 = 14.69693845669906728801;
constexpr double kInvRoot6 = 0.40824829046386307274;

namespace detail {
// max(0, x) as LAMMPS' MAX(0, x) takes it (x for x = -0).
inline double max0(double x) { return 0.0 > x ? 0.0 : x; }

}  // namespace detail

/// The JKR patch radius a and elastic-adhesive normal force F at overlap
/// delta with effective radius R* (dr = delta R*), LAMMPS' closed form of
/// Johnson, Kendall and Roberts with the surface energy gamma (w = 2 gamma):
/// delta = a^2/R* - 2 sqrt(pi gamma a/E*), F = 4 E* a^3/(3 R*) - 4 sqrt(pi gamma E*) a^(3/2).
inline void jkr_patch(const ContactLaw& law, double reff, double dr, double& a, double& fne) {
  const double e = law.kn * 0.75;
  const double coh = law.cohesion;
  const double r2 = reff * reff;
  const double dr2 = dr * dr;
  const double t0 = coh * coh * r2 * r2 * e;
  const double t1 = k27PiSquared * t0;
  const double t2 = 8 * dr * dr2 * e * e * e;
  const double t3 = 4 * dr2 * e;
  const double sqrt1 = detail::max0(t0 * (t1 + 2 * t2));
  const double t4 = std::cbrt(t1 + t2 + kThreeRoot3 * kPi * std::sqrt(sqrt1));
  const double t5 = t3 / t4 + t4 / e;
  const double sqrt2 = detail::max0(2 * dr + t5);
  const double t6 = std::sqrt(sqrt2);
  const double sqrt3 = detail::max0(4 * dr - t5 + kSixRoot6 * coh * kPi * r2 / (e * t6));
  a = kInvRoot6 * (t6 + std::sqrt(sqrt3));
  const double a2 = a * a;
  const double knfac = law.kn * a;
  fne = knfac * a2 / reff - 2 * kPi * a2 * std::sqrt(4 * coh * e / (kPi * a));
}

/// Whether a pair at squared distance rsq touches: within r_i + r_j, or,
/// for JKR, a pair that touched until the pull-off distance (LAMMPS' pair
/// granular's criterion).
inline bool pair_touching(const ContactLaw& law, double rsq, double radsum, double reff,
                          bool touched) {
  if (law.normal != NormalModel::kJkr || !touched) return rsq < radsum * radsum;
  const double e = law.kn * 0.75;
  const double a = std::cbrt(9.0 * kPi * law.cohesion * (reff * reff) / (4 * e));
  const double delta_pulloff = a * a / reff - 2 * std::sqrt(kPi * law.cohesion * a / e);
  const double dist_pulloff = radsum - delta_pulloff;
  return rsq < dist_pulloff * dist_pulloff;
}

/// The overlap at which a JKR pair of radii r_i, r_j separates (negative:
/// a gap; 0 for other models), as LAMMPS' pulloff_distance, for the
/// neighbor cutoff.
inline double pulloff_distance(const ContactLaw& law, double radi, double radj) {
  const double reff = radi * radj / (radi + radj);
  if (law.normal != NormalModel::kJkr || !(reff > 0.0)) return 0.0;
  const double e = law.kn * 0.75;
  const double a = std::cbrt(9 * kPi * law.cohesion * reff * reff / (4 * e));
  return a * a / reff - 2 * std::sqrt(kPi * law.cohesion * a / e);
}

/// Where the constants of the material models come from.
enum class Moduli {
  kExact,       ///< (4/3) E* and 8 G* of the two materials
  kLegacyWall,  ///< LAMMPS 29 Sep 2021 fix wall/gran's: (4/3)E/(2(1-nu)), E(2-nu)(1+nu)/4
};

/// Reads numbers for the parser (the caller's, e.g. LAMMPS' utils::numeric).
using NumberReader = std::function<double(const std::string&)>;

namespace detail {

// The tokens of one model keyword and its values: tokens[i] is the keyword.
struct TokenCursor {
  const std::vector<std::string>& tokens;
  std::size_t i;
  bool has(std::size_t n) const { return i + n < tokens.size(); }
  const std::string& at(std::size_t n) const { return tokens[i + n]; }
};

inline std::string parse_normal(TokenCursor& c, const NumberReader& number, ContactLaw& law) {
  const std::string& key = c.at(0);
  const bool adhesive = key == "dmt" || key == "jkr";
  const bool material = adhesive || key == "hertz/material";
  const std::size_t n = adhesive ? 4 : (material ? 3 : 2);
  if (!c.has(n)) return key + " needs " + std::to_string(n) + " values";
  law.normal = key == "hooke"   ? NormalModel::kHooke
               : key == "hertz" ? NormalModel::kHertz
               : key == "dmt"   ? NormalModel::kDmt
               : key == "jkr"   ? NormalModel::kJkr
                                : NormalModel::kHertzMaterial;
  if (material) {
    law.youngs = number(c.at(1));
    law.poisson = number(c.at(3));
  } else {
    law.kn = number(c.at(1));
  }
  law.damp = number(c.at(2));
  if (adhesive) law.cohesion = number(c.at(4));
  c.i += n + 1;
  return "";
}

inline std::string parse_tangential(TokenCursor& c, const NumberReader& number, ContactLaw& law) {
  if (!c.has(1)) return "tangential needs a model";
  const std::string& model = c.at(1);
  if (model == "linear_nohistory") {
    if (!c.has(3)) return "tangential linear_nohistory needs xgammat and mu";
    law.tangential = TangentialModel::kLinearNoHistory;
    law.kt = 0.0;
    law.kt_null = false;
    law.xgammat = number(c.at(2));
    law.mu = number(c.at(3));
    c.i += 4;
    return "";
  }
  if (model != "linear_history" && model != "mindlin")
    return "tangential " + model +
           ": the plugin has linear_nohistory, linear_history and mindlin (not the rescale and "
           "force variants)";
  if (!c.has(4)) return "tangential " + model + " needs kt, xgammat and mu";
  law.tangential = model == "mindlin" ? TangentialModel::kMindlin : TangentialModel::kLinearHistory;
  law.kt_null = c.at(2) == "NULL" && model == "mindlin";
  law.kt = law.kt_null ? 0.0 : number(c.at(2));
  law.xgammat = number(c.at(3));
  law.mu = number(c.at(4));
  c.i += 5;
  return "";
}

// rolling sds kR gammaR muR | none; twisting marshall | sds kT gammaT muT | none
inline std::string parse_spin_model(TokenCursor& c, const NumberReader& number, ContactLaw& law) {
  const std::string& key = c.at(0);
  if (!c.has(1)) return key + " needs a model";
  const std::string& model = c.at(1);
  if (model == "none" || (key == "twisting" && model == "marshall")) {
    if (key == "rolling") law.rolling = false;
    if (key == "twisting") law.twist = model == "none" ? TwistModel::kNone : TwistModel::kMarshall;
    c.i += 2;
    return "";
  }
  if (model != "sds")
    return key + " " + model + ": " + key + (key == "rolling" ? " sds|none" : " marshall|sds|none");
  if (!c.has(4)) return key + " sds needs a stiffness, a damping and a friction coefficient";
  const double k = number(c.at(2)), g = number(c.at(3)), m = number(c.at(4));
  if (key == "rolling") {
    law.rolling = true;
    law.k_roll = k, law.gamma_roll = g, law.mu_roll = m;
  } else {
    law.twist = TwistModel::kSds;
    law.k_twist = k, law.gamma_twist = g, law.mu_twist = m;
  }
  c.i += 5;
  return "";
}

// profile hertz|disk|ring|boussinesq|annulus b (the plugin's own keyword)
inline std::string parse_profile(TokenCursor& c, const NumberReader& number, ContactLaw& law) {
  if (!c.has(1)) return "profile needs a model: hertz, disk, ring, boussinesq or annulus b";
  const std::string& model = c.at(1);
  law.annulus_inner = 0.0;
  if (model == "annulus") {
    if (!c.has(2)) return "profile annulus needs b, its inner radius over the patch radius";
    law.profile = PatchProfile::kAnnulus;
    law.annulus_inner = number(c.at(2));
    c.i += 3;
    return "";
  }
  if (model == "hertz")
    law.profile = PatchProfile::kHertz;
  else if (model == "disk")
    law.profile = PatchProfile::kDisk;
  else if (model == "ring")
    law.profile = PatchProfile::kRing;
  else if (model == "boussinesq")
    law.profile = PatchProfile::kBoussinesq;
  else
    return "profile " + model + ": hertz, disk, ring, boussinesq or annulus b";
  c.i += 2;
  return "";
}

inline std::string parse_damping(TokenCursor& c, ContactLaw& law) {
  if (!c.has(1)) return "damping needs a model";
  const std::string& model = c.at(1);
  if (model == "velocity")
    law.damping = DampingModel::kVelocity;
  else if (model == "mass_velocity")
    law.damping = DampingModel::kMassVelocity;
  else if (model == "viscoelastic")
    law.damping = DampingModel::kViscoelastic;
  else if (model == "tsuji")
    law.damping = DampingModel::kTsuji;
  else
    return "damping " + model + ": velocity, mass_velocity, viscoelastic or tsuji";
  c.i += 2;
  return "";
}

}  // namespace detail

/// Reads LAMMPS' `pair_style granular` model keywords and the plugin's
/// `profile` from `tokens` into `law` (twisting defaults to none, as in
/// LAMMPS; the profile to Hertz's); the tokens it does not
/// know are appended to `rest`, in order, for the caller (a wall's
/// geometry, the plugin's own options).  Returns an error message, or an
/// empty string.
inline std::string parse_lammps_model(const std::vector<std::string>& tokens,
                                      const NumberReader& number, ContactLaw& law,
                                      std::vector<std::string>& rest) {
  law = ContactLaw{};
  law.twist = TwistModel::kNone;
  bool normal = false, tangential = false;
  detail::TokenCursor c{tokens, 0};
  while (c.i < tokens.size()) {
    const std::string& key = c.at(0);
    std::string why;
    if (key == "hooke" || key == "hertz" || key == "hertz/material" || key == "dmt" ||
        key == "jkr") {
      why = detail::parse_normal(c, number, law);
      normal = true;
    } else if (key == "tangential") {
      why = detail::parse_tangential(c, number, law);
      tangential = true;
    } else if (key == "rolling" || key == "twisting") {
      why = detail::parse_spin_model(c, number, law);
    } else if (key == "damping") {
      why = detail::parse_damping(c, law);
    } else if (key == "profile") {
      why = detail::parse_profile(c, number, law);
    } else if (key == "limit_damping") {
      law.limit_damping = true;
      ++c.i;
    } else {
      rest.push_back(key);
      ++c.i;
    }
    if (!why.empty()) return why;
  }
  if (!normal || !tangential) return "give a normal model and a tangential model";
  return "";
}

/// The plugin's short form `E eta_n nu mu [xgammat x] [keywords...]` in
/// LAMMPS' model keywords: `hertz/material E eta_n nu tangential mindlin
/// NULL x mu twisting marshall [keywords...]` (x = 1 unless given).  The
/// first four words must be there.
inline std::vector<std::string> expand_short_form(const std::vector<std::string>& words) {
  std::string xgammat = "1.0";
  std::vector<std::string> after;
  for (std::size_t k = 4; k < words.size(); ++k) {
    if (words[k] == "xgammat" && k + 1 < words.size()) {
      xgammat = words[++k];
      continue;
    }
    after.push_back(words[k]);
  }
  std::vector<std::string> tokens = {"hertz/material", words[0],   words[1],  words[2],
                                     "tangential",     "mindlin",  "NULL",    xgammat,
                                     words[3],         "twisting", "marshall"};
  tokens.insert(tokens.end(), after.begin(), after.end());
  return tokens;
}

/// Why `law` (as read) cannot be used, or an empty string: the ranges of
/// its numbers and the combinations the force computation cannot take.
inline std::string check_law(const ContactLaw& law) {
  if (law.material() && !(law.youngs > 0.0)) return "E must be > 0";
  if (law.material() && !(law.poisson > -1.0 && law.poisson <= 0.5))
    return "nu must be in (-1, 0.5]";
  if (!law.material() && !(law.kn > 0.0)) return "the normal stiffness must be > 0";
  if (law.damping == DampingModel::kTsuji && !(law.damp > 0.0 && law.damp <= 1.0))
    return "with damping tsuji, the damping number is the coefficient of restitution, in (0, 1]";
  if (!(law.damp >= 0.0) || !(law.mu >= 0.0) || !(law.xgammat >= 0.0))
    return "the damping, mu and xgammat must be >= 0";
  if (!law.material() && law.kt_null) return "tangential mindlin NULL needs E and nu";
  if (law.tangential_spring() && !law.kt_null && !(law.kt > 0.0))
    return "the tangential stiffness must be > 0";
  if (law.normal == NormalModel::kJkr || law.normal == NormalModel::kDmt) {
    if (!(law.cohesion >= 0.0)) return "the surface energy must be >= 0";
    if (law.limit_damping) return "limit_damping does not go with jkr or dmt (as in LAMMPS)";
  }
  if (law.twist == TwistModel::kMarshall && !law.tangential_spring())
    return "twisting marshall needs a tangential spring (linear_history or mindlin)";
  if (law.rolling && !(law.k_roll > 0.0 && law.gamma_roll >= 0.0 && law.mu_roll >= 0.0))
    return "rolling sds needs a stiffness > 0, a damping and a friction coefficient >= 0";
  if (law.twist == TwistModel::kSds &&
      !(law.k_twist > 0.0 && law.gamma_twist >= 0.0 && law.mu_twist >= 0.0))
    return "twisting sds needs a stiffness > 0, a damping and a friction coefficient >= 0";
  if (law.profile == PatchProfile::kAnnulus &&
      !(law.annulus_inner >= 0.0 && law.annulus_inner < 1.0))
    return "profile annulus needs b in [0, 1)";
  return "";
}

/// The constants of `law` (as read and checked): the material models' k_n
/// and Mindlin's NULL stiffness from E and nu (as `moduli` says), Tsuji's
/// alpha from the coefficient of restitution (by products for the pair
/// style, by std::pow for a wall, as LAMMPS evaluates each).
inline ContactLaw resolve(ContactLaw law, Moduli moduli, bool alpha_by_pow) {
  const double e = law.youngs, nu = law.poisson;
  if (law.material()) {
    law.kn = moduli == Moduli::kExact ? 4.0 / 3.0 * effective_youngs(e, nu, e, nu)
                                      : e / (2 * (1 - nu)) * 1.333333333333333;
  }
  if (law.kt_null) {
    law.kt =
        moduli == Moduli::kExact ? 8 * effective_shear(e, nu, e, nu) : e / 4 * (2 - nu) * (1 + nu);
  }
  if (law.damping == DampingModel::kTsuji)
    law.damp = alpha_by_pow ? tsuji_alpha_by_pow(law.damp) : tsuji_alpha(law.damp);
  return law;
}

/// Whether two laws have the same functional forms, so that a mixed type
/// pair can be made of them.
inline bool same_forms(const ContactLaw& a, const ContactLaw& b) {
  return a.normal == b.normal && a.damping == b.damping && a.tangential == b.tangential &&
         a.rolling == b.rolling && a.twist == b.twist && a.kt_null == b.kt_null &&
         a.profile == b.profile && a.annulus_inner == b.annulus_inner;
}

/// The law of two types of the same forms (resolved, exact moduli): E* and
/// G* of the two materials, the geometric means of the other numbers (of
/// Tsuji's alphas, as LAMMPS); limit_damping if either has it.  (LAMMPS
/// 2021's pair granular leaves out the 4/3 of the mixed k_n; this does
/// not.)
inline ContactLaw mix(const ContactLaw& a, const ContactLaw& b) {
  const auto geom = [](double x, double y) { return std::sqrt(x * y); };
  ContactLaw m = a;
  if (a.material()) {
    m.kn = 4.0 / 3.0 * effective_youngs(a.youngs, a.poisson, b.youngs, b.poisson);
  } else {
    m.kn = geom(a.kn, b.kn);
  }
  m.damp = geom(a.damp, b.damp);
  m.cohesion = geom(a.cohesion, b.cohesion);
  m.kt =
      a.kt_null ? 8 * effective_shear(a.youngs, a.poisson, b.youngs, b.poisson) : geom(a.kt, b.kt);
  m.xgammat = geom(a.xgammat, b.xgammat);
  m.mu = geom(a.mu, b.mu);
  m.k_roll = geom(a.k_roll, b.k_roll);
  m.gamma_roll = geom(a.gamma_roll, b.gamma_roll);
  m.mu_roll = geom(a.mu_roll, b.mu_roll);
  m.k_twist = geom(a.k_twist, b.k_twist);
  m.gamma_twist = geom(a.gamma_twist, b.gamma_twist);
  m.mu_twist = geom(a.mu_twist, b.mu_twist);
  m.limit_damping = a.limit_damping || b.limit_damping;
  return m;
}

}  // namespace spinslide_lammps

#endif  // SPINSLIDE_LAMMPS_GRANULAR_MODEL_H
