//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The LAMMPS plugin's contact law per contact, in instructions (issue 41;
// docs/lammps.md, "Cost"): spinslide_lammps::contact_force, the whole law a
// pair or a wall runs for one touching contact (normal force, springs,
// friction), with the coupling off (LAMMPS' own arithmetic) and on (the
// coupled cap), for contacts that stick and contacts that slide.  Counted
// by tools/path_instructions.py under callgrind, as tools/path_instructions
// is, and held to law_instruction_budgets.txt by the test
// lammps.law_instructions; the unit is Hertz's force_torque (the plugin's
// default profile), counted here too.
//
// The law: Hertz/material (E = 1e5, ν = 0.3, damping 0.5), Mindlin,
// Marshall, μ = 0.5, as engines/lammps/examples/in.pour_ab.  The contacts:
// 64 pairs of spheres of diameter 1 (R* = 0.25) at overlap 1e-3, normal z,
// whose slips have ratios ε = |v|/(a|ω_n|) = 10^(−3 … 3):
//   sticking  slip speeds of 1e-7, so that the springs stay well inside the
//             inner triangle through every step counted;
//   warm      slip speeds of 1: every contact slides, each step from the
//             curve point its history kept from the step before (ten
//             steps before the count).
// Each case counts four steps of the 64 contacts; the program checks that
// every contact of a case stuck (or slid) at every one of them.
#include "spinslide_contact.h"

#include <valgrind/callgrind.h>

#include <spinslide/values/profile.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

using spinslide_lammps::ContactForce;
using spinslide_lammps::ContactLaw;
using spinslide_lammps::ContactState;
using spinslide_lammps::kHistSize;
using history = std::array<double, spinslide_lammps::kHistSize>;

constexpr int contacts = 64;
constexpr int repetitions = 4;
constexpr int warm_up = 10;
constexpr double dt = 1e-4;

template <class T>
T opaque(T v) {
  __asm__ volatile("" : "+m"(v));
  return v;
}

ContactLaw pour_law() {
  ContactLaw law;
  law.normal = spinslide_lammps::NormalModel::kHertzMaterial;
  law.youngs = 1e5;
  law.poisson = 0.3;
  law.damp = 0.5;
  law.tangential = spinslide_lammps::TangentialModel::kMindlin;
  law.kt_null = true;
  law.mu = 0.5;
  law.twist = spinslide_lammps::TwistModel::kMarshall;
  law.profile = spinslide_lammps::PatchProfile::kHertz;
  return spinslide_lammps::resolve(law, spinslide_lammps::Moduli::kExact, false);
}

// Contact i: slip speed `speed` along (cos i, sin i, 0), spin about the
// normal at the ratio 10^(−3 + 6i/63), no normal motion.
std::vector<ContactState> states(double speed) {
  std::vector<ContactState> v(contacts);
  for (int i = 0; i < contacts; ++i) {
    ContactState& s = v[std::size_t(i)];
    s = {};
    s.n[2] = 1;
    s.delta = 1e-3;
    s.reff = 0.25;
    s.meff = 0.25;
    const double a = std::sqrt(s.delta * s.reff), eps = std::pow(10.0, -3 + 6.0 * i / 63);
    s.vr[0] = speed * std::cos(i);
    s.vr[1] = speed * std::sin(i);
    s.twist_rate = speed / (a * eps);
    s.relrot[2] = s.twist_rate;
  }
  return v;
}

// Counts `repetitions` steps of every contact under `name`, after the
// warm-up steps; false unless every call's contact stuck (`stick`) or slid.
bool count(const std::string& name, const ContactLaw& law, bool coupled, bool stick) {
  const std::vector<ContactState> s = states(stick ? 1e-7 : 1.0);
  std::vector<history> h(contacts);
  for (history& x : h) x.fill(0.0);
  ContactForce out{};
  // LAMMPS' error handler: never called (every input is finite), opaque so
  // that the compiler does not see the null pointer.
  LAMMPS_NS::Error* const error = opaque<LAMMPS_NS::Error*>(nullptr);
  double sum = 0;
  bool as_meant = true;
  auto step = [&](int i) {
    spinslide_lammps::contact_force(law, s[std::size_t(i)], h[std::size_t(i)].data(), dt, true,
                                    coupled, error, "law_instructions", out);
    as_meant = as_meant && out.capped != stick;
    return out.fs[0] + out.mt;
  };
  for (int r = 0; r < warm_up; ++r)
    for (int i = 0; i < contacts; ++i) sum += step(i);
  as_meant = true;
  CALLGRIND_ZERO_STATS;
  for (int r = 0; r < repetitions; ++r)
    for (int i = 0; i < contacts; ++i) sum += step(opaque(i));
  CALLGRIND_DUMP_STATS_AT(name.c_str());
  std::printf("case %s %d %g\n", name.c_str(), contacts * repetitions, sum);
  if (!as_meant)
    std::printf("law_instructions: %s: a contact did not %s\n", name.c_str(),
                stick ? "stick" : "slide");
  return as_meant;
}

}  // namespace

int main() try {
  const ContactLaw law = pour_law();
  const spinslide::hertz<double> hertz;
  std::vector<double> eps;
  eps.reserve(contacts);
  for (int i = 0; i < contacts; ++i) eps.push_back(std::pow(10.0, -3 + 6.0 * i / 63));
  double sum = 0;
  // The unit and the bare loop, as tools/path_instructions counts them.
  CALLGRIND_ZERO_STATS;
  for (int r = 0; r < repetitions; ++r)
    for (int i = 0; i < contacts; ++i) sum += hertz.force_torque(eps[std::size_t(opaque(i))]).force;
  CALLGRIND_DUMP_STATS_AT("force_torque.hertz.double");
  std::printf("case force_torque.hertz.double %d %g\n", contacts * repetitions, sum);
  CALLGRIND_ZERO_STATS;
  for (int r = 0; r < repetitions; ++r)
    for (int i = 0; i < contacts; ++i) sum += eps[std::size_t(opaque(i))];
  CALLGRIND_DUMP_STATS_AT("loop.double");
  std::printf("case loop.double %d %g\n", contacts * repetitions, sum);
  bool ok = true;
  for (const bool coupled : {false, true})
    for (const bool stick : {true, false}) {
      const std::string name = std::string(coupled ? "lammps_coupled" : "lammps_uncoupled") +
                               ".hertz.double." + (stick ? "sticking" : "warm");
      ok = count(name, law, coupled, stick) && ok;
    }
  return ok ? 0 : 1;
} catch (const std::exception& e) {
  std::fprintf(stderr, "law_instructions: %s\n", e.what());
  return 1;
}
