//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// fingerprint: prints, as exact hexadecimal floats, what the public API
// returns over a fixed grid of inputs: 𝓕, 𝓣 and derivatives in float, double
// and long double; every profile's force_torque and moments; the coupling
// inverses; terminal_motion; 360 throws (stop time, distance, angle, ε at the
// stop) and a trajectory; the contact law; the cylinder; the projections
// onto the limit set (2-D, and 3-D in a metric) and the impulse law, without
// a start and from the curve point of a neighbouring answer.  A refactor that
// must not change behaviour is checked by diffing this output before and
// after (docs/architecture.md, "Refactoring safely"):
//
//   ./build/release/tools/fingerprint > after.txt && diff before.txt after.txt
#include <spinslide/spinslide.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

// The named inputs (a, N, μ) of a contact, from plain numbers in this order.
spinslide::force_contact<double> contact_of(double radius, double normal, double mu) {
  return {spinslide::patch_radius<double>{radius}, spinslide::normal_force<double>{normal},
          spinslide::friction_coefficient<double>{mu}};
}

void put(const char* what, long double x) { std::printf("%s %La\n", what, x); }

const std::vector<double>& ratios() {
  static const std::vector<double> r = {0.0,   1e-300, 1e-9, 1e-3, 0.1,   0.5, 0.653, 0.999,   1.0,
                                        1.001, 1.5,    2.0,  7.5,  100.0, 1e9, 1e300, HUGE_VAL};
  return r;
}

template <class Real>
void disk(const char* type) {
  for (double e : ratios()) {
    const Real x = static_cast<Real>(e);
    std::printf("disk<%s> eps=%a\n", type, e);
    const auto ft = spinslide::force_torque(x);
    put(" force", spinslide::force(x));
    put(" torque", spinslide::torque(x));
    put(" pair.force", ft.force);
    put(" pair.torque", ft.torque);
    put(" force'", spinslide::force_derivative(x));
    put(" torque'", spinslide::torque_derivative(x));
  }
}

template <class Profile>
void profile(const std::string& name, const Profile& p, bool invert = true) {
  std::printf("profile %s\n", name.c_str());
  put(" <r>", p.mean_radius());
  put(" <1/r>", p.mean_inverse_radius());
  put(" <r2>", p.mean_square_radius());
  for (double e : ratios()) {
    const auto ft = p.force_torque(e);
    std::printf(" eps=%a %a %a %a %a\n", e, ft.force, ft.torque, p.force(e), p.torque(e));
  }
  if (!invert) return;
  for (double F : {0.0, 1e-6, 0.3, 0.8, 0.999})
    put(" ratio_from_force", spinslide::ratio_from_force(p, F));
  for (double f : {1.0, 0.7, 0.2, 1e-4}) {
    const double T = f * p.mean_radius();
    put(" ratio_from_torque", spinslide::ratio_from_torque(p, T));
    put(" force_at_torque", spinslide::force_at_torque(p, T));
  }
  put(" torque_at_force", spinslide::torque_at_force(p, 0.5));
  for (double g : {0.1, 0.3, 0.45, 0.5, 0.6, 1.0}) {
    try {
      const auto t = spinslide::terminal_motion(p, g);
      std::printf(" terminal gamma=%a %d %a\n", g, static_cast<int>(t.regime), t.ratio);
    } catch (const std::exception& ex) {
      std::printf(" terminal gamma=%a error %s\n", g, ex.what());
    }
    for (double e0 : {0.01, 1.0, 50.0}) {
      const auto t = spinslide::terminal_motion(p, g, e0);
      std::printf(" terminal gamma=%a eps=%a %d %a\n", g, e0, static_cast<int>(t.regime), t.ratio);
    }
    put(" ratio_flow", spinslide::ratio_flow(p, 0.4, g));
  }
}

template <class Profile>
void throws(const std::string& name, const Profile& p, int count) {
  std::printf("throws %s\n", name.c_str());
  const double gammas[] = {0.5, 0.3, 0.6, 2.0};
  for (int i = 0; i < count; ++i) {
    const double eps = std::pow(10.0, -3 + 6.0 * i / (count - 1));
    const double g = gammas[i % 4];
    const auto r = spinslide::simulate_throw(p, g, eps, 1.0);
    std::printf(" %a %a: %a %a %a %d %a\n", g, eps, r.time, r.distance, r.angle,
                static_cast<int>(r.terminal.regime), r.terminal.ratio);
  }
}

// The projections and the impulse law for a profile: the 2-D projection of
// C(ε) + 0.2(ε, 1) (and 0.5·C(ε), inside), the 3-D projection of the wrench
// 2(ε cos ε, ε sin ε, 1) in a coupled metric, and impulse_friction of the
// slips (ε cos ε, ε sin ε) with spin 1 and Λ = 1e-3 (and 1e3, sticking),
// each without a start and from the answer for a spin 1e-3 higher.
template <class Profile>
void projections(const std::string& name, const Profile& p) {
  using namespace spinslide;
  std::printf("projections %s\n", name.c_str());
  const planar_metric<double> w({{{2, 0.3, 0.2}, {0.3, 1.5, -0.1}, {0.2, -0.1, 3}}});
  for (int i = 0; i < 13; ++i) {
    const double e = std::pow(10.0, -3 + 0.5 * i);
    const auto c = p.force_torque(e);
    const auto flat = project_to_limit_set(p, c.force + 0.2 * e, c.torque + 0.2, 1.0);
    const auto inside = project_to_limit_set(p, 0.5 * c.force, 0.5 * c.torque, 1.0);
    std::printf(" 2d %a: %a %a %a %d %a\n", e, flat.force, flat.torque, flat.ratio,
                int(inside.sticking), inside.force);
    const tangent_wrench<double> z{2 * e * std::cos(e), 2 * e * std::sin(e), 2.0};
    const auto m = project_to_limit_set(p, z, w);
    std::printf(" 3d %a: %a %a %a %a\n", e, m.force[0], m.force[1], m.torque, m.ratio);
    const std::array<double, 2> v{e * std::cos(e), e * std::sin(e)};
    for (const double load : {1e-3, 1e3}) {
      const impulse_contact<double> k{patch_radius<double>{1}, normal_impulse<double>{load},
                                      friction_coefficient<double>{1}};
      const auto cold = impulse_friction(p, v, 1.0, w, k);
      const auto warm =
          impulse_friction(p, v, 1.0, w, k, impulse_friction(p, v, 1.001, w, k).curve());
      std::printf(" impulse %a %g: %a %a %a %a %d | %a %a %a %a\n", e, load, cold.force[0],
                  cold.force[1], cold.torque, cold.ratio, int(cold.sticking), warm.force[0],
                  warm.force[1], warm.torque, warm.ratio);
    }
  }
}

}  // namespace

int main() {
  using namespace spinslide;
  disk<float>("float");
  disk<double>("double");
  disk<long double>("long double");
  put("terminal_ratio", terminal_ratio());
  put("stop_time(1, 1)", stop_time(1.0, 1.0));
  put("stop_time(0.3, 2)", stop_time(0.3, 2.0));

  profile("uniform_disk", uniform_disk<>());
  profile("annulus(0.125)", annulus<>(0.125));
  profile("annulus(0.7)", annulus<>(0.7));
  profile("ring", ring<>());
  profile("hertz", hertz<>());
  profile("boussinesq", boussinesq<>());
  profile("scaled(disk, 0.5)", scaled<uniform_disk<>>(uniform_disk<>(), 0.5));
  profile("weighted_sum",
          weighted_sum({0.6, 0.4}, scaled<uniform_disk<>>(uniform_disk<>(), 0.5), annulus<>(0.5)));
  profile("radial(1-r)", radial_profile([](double r) { return 1 - r; }, 0.1));
  profile("uncoupled_caps", uncoupled_caps<>(), false);
  profile("elliptic", elliptic_limit_surface<>());
  profile("pade", pade_approximation<>::matching(hertz<>()));
  const tabulated_profile<> table{hertz<>()};
  profile("tabulated(hertz)", table);
  projections("uniform_disk", uniform_disk<>());
  projections("hertz", hertz<>());
  projections("boussinesq", boussinesq<>());
  projections("tabulated(hertz)", table);
  projections("annulus(0.5)", annulus<>(0.5));

  throws("uniform_disk", uniform_disk<>(), 80);
  throws("annulus(0.125)", annulus<>(0.125), 40);
  throws("ring", ring<>(), 40);
  throws("elliptic", elliptic_limit_surface<>(), 40);
  throws("pade", pade_approximation<>(), 40);
  throws("uncoupled_caps", uncoupled_caps<>(), 40);
  throws("tabulated(hertz)", table, 40);
  throws("boussinesq", boussinesq<>(), 20);
  throws("hertz", hertz<>(), 20);
  put("stop_time(hertz)", stop_time(hertz<>(), 0.4, 1.0, 2.0));
  const auto si = simulate_throw_si(uniform_disk<>(), disk_radius{0.06}, friction_coefficient{0.2},
                                    gravity{9.81}, 0.5, initial_speed{1.0}, initial_spin{20.0});
  std::printf("si %a %a %a\n", si.time, si.distance, si.angle);
  for (const auto& m :
       trajectory(uniform_disk<>(), 0.5, 2.0, 1.0, {0.0, 0.1, 0.5, 1.0, 1.5, 100.0}))
    std::printf("trajectory %a %a %a %a %a %a\n", m.time, m.speed, m.spin, m.ratio, m.distance,
                m.angle);
  const tabulated_throw<uniform_disk<>> tt{uniform_disk<>(), 0.4};
  for (double e : {0.0, 0.01, 1.0, 30.0})
    std::printf("tabulated_throw %a %a\n", tt.stop_time(e, 1.0), tt.distance(e, 1.0));

  const contact_law<hertz<>> law(hertz<>(), velocity_scale<double>{1e-3});
  for (double v : {0.0, 1e-5, 0.01, 1.0}) {
    const auto f2 = law(std::array<double, 2>{v, -0.5 * v}, 3.0, contact_of(0.01, 10.0, 0.3));
    const auto f3 =
        law(std::array<double, 3>{v, 0.2, 0.1}, std::array<double, 3>{0.0, 1.0, 2.0},
            contact_normal{std::array<double, 3>{0.0, 0.0, 1.0}}, contact_of(0.01, 10.0, 0.3));
    std::printf("contact %a %a %a | %a %a %a %a %a %a\n", f2.force[0], f2.force[1], f2.torque,
                f3.force[0], f3.force[1], f3.force[2], f3.torque[0], f3.torque[1], f3.torque[2]);
  }
  const auto cf = contact_friction(std::array<double, 2>{0.3, 0.1}, 5.0, contact_of(0.06, 1.0, 0.2),
                                   velocity_scale<double>{1e-6});
  std::printf("contact_friction %a %a %a\n", cf.force[0], cf.force[1], cf.torque);
  for (double e : {0.0, 0.5, 2.0}) {
    const auto c = tilted_cylinder_friction(e, 0.05, 0.06, 0.2);
    std::printf("cylinder %a %a %a %a %a\n", c.force[0], c.force[1], c.torque, c.centre[0],
                c.centre[1]);
  }
}
