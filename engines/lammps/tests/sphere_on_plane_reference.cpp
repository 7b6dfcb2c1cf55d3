//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// spinslide's own integration of engines/lammps/examples/in.sphere_on_plane,
// independent of LAMMPS and of the plugin's code (issue 19: "a sphere sliding
// and spinning on a plane against spinslide's own integration of the same
// contact law: stop times within 1 %").
//
// One sphere (R = 0.5, m = pi/6, I = (2/5) m R^2) on the plane z = 0 under
// gravity g = 10 along -z, the wall of the same material (E = 1e5, nu = 0.3)
// and of infinite radius and mass: R* = R, m* = m, E* = E/(2(1 - nu^2)),
// G* = E/(4(2 - nu)(1 + nu)).  The contact law (engines/lammps/README.md,
// "The model"), with d = R - z the overlap and a = sqrt(R d):
//
//   normal     F_n = (4/3) E* a d - eta_n a m v_z            (Hertz, viscoelastic)
//   tangential F_t = -k_t xi - g_t v_t,   k_t = 8 G* a,  g_t = x_gt eta_n a m  (Mindlin)
//   twisting   M   = -k_w phi - g_w w_z,  k_w = k_t a^2/2, g_w = g_t a^2/2    (Marshall)
//
// v_t = v + w x (-R z) the slip of the contact point (the friction acts at the
// full radius R, as fix wall/gran's), xi and phi the springs, stretched by
// v_t dt and w_z dt each step.  The trial (F_t, M) is capped at the load
// mu |F_n| on the limit set of spinslide::hertz (coupling yes; or of the
// profile --profile names, as the input's `profile` keyword does) or of
// spinslide::uncoupled_caps(2/3) (coupling no: |F_t| <= mu N, |M| <= (2/3) a mu N),
// by spinslide::project_to_limit_set in the springs' energy metric (torque
// weight a^2 k_t/k_w = 2); when capped, the springs are rewritten so that
// spring + damping gives the capped friction.
//
// The rigid body is integrated with the semi-implicit (symplectic) Euler
// scheme, m dv/dt = F, I dw/dt = r x F + M z with r = -R z, at a step much
// smaller than LAMMPS' (default 1e-5 against 2e-4), the normal coordinate
// included.  As the LAMMPS input, the sphere is first set on the plane
// touching it and settles for one time unit, then its velocities are reset
// and it is thrown: v_x = 1 (sliding), w_z = 20 (spinning), or both.  A stop
// time is the first step at which the signed slip along x, v_x - R w_y, or
// the spin w_z is below 1e-3 (the input's rule).
//
//   sphere_on_plane_reference [dt] [--profile hertz|disk|ring|boussinesq|annulus b]
//                                               the stop times, coupling yes and no
//   sphere_on_plane_reference --convergence     the stop times for dt = 4e-5 ... 2.5e-6
#include <spinslide/contact/limit_set.hpp>
#include <spinslide/values/approximations.hpp>
#include <spinslide/values/contact_profile.hpp>
#include <spinslide/values/profile.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using vec3 = std::array<double, 3>;

// in.sphere_on_plane's parameters (units lj)
constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 0.5;
constexpr double kMass = kPi / 6;  // density 1
constexpr double kInertia = 0.4 * kMass * kRadius * kRadius;
constexpr double kYoung = 1e5;
constexpr double kPoisson = 0.3;
constexpr double kMu = 0.5;
constexpr double kGravity = 10.0;
constexpr double kEtaN = 1e3;
constexpr double kXGammaT = 1.0;
constexpr double kSettleTime = 1.0;  // 5000 steps of 2e-4 before the throw
constexpr double kSlipThreshold = 1e-3;
constexpr double kSpinThreshold = 1e-3;
constexpr double kMaxTime = 30.0;

// the sphere against a wall of its own material
constexpr double kEStar = kYoung / (2 * (1 - kPoisson * kPoisson));
constexpr double kGStar = kYoung / (4 * (2 - kPoisson) * (1 + kPoisson));
constexpr double kNormalStiffness = 4.0 / 3.0 * kEStar;  // F_n = kn d a
constexpr double kTangentialStiffness = 8 * kGStar;      // k_t = kt a

vec3 cross(const vec3& p, const vec3& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
double dot(const vec3& p, const vec3& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }

struct sphere {
  vec3 x{0.0, 0.0, kRadius};  // centre
  vec3 v{};                   // velocity
  vec3 w{};                   // spin
};

// The contact's history: the tangential spring, the twisting spring and the
// last ratio eps of the limit set (a warm start only).
struct history {
  vec3 xi{};
  double phi = 0.0;
  double ratio = 0.0;
};

struct wrench {
  vec3 force{};
  vec3 torque{};
  double load = 0.0;  // |F_n|
};

// The springs' stiffnesses and damping at patch radius a.
struct springs {
  double kt, gt, kw, gw;
};

// Caps the trial (force, torque) on mu_load * L (L the profile's limit set,
// mu_load = mu |F_n|) in the springs' energy metric, and rewrites the springs.
template <class Profile>
void cap_friction(const Profile& profile, double mu_load, double a, const springs& k,
                  const vec3& slip, double twist_rate, history& h, vec3& force, double& torque) {
  const double fmag = std::sqrt(dot(force, force));
  if (fmag == 0.0 && torque == 0.0) return;
  const double f = fmag / mu_load;
  const double t = std::fabs(torque) / (mu_load * a);
  const spinslide::friction_result<double, double> p = spinslide::project_to_limit_set(
      profile, f, t, a * a * k.kt / k.kw, spinslide::curve_point<double>{h.ratio});
  if (p.sticking) return;
  if (!std::isnan(p.ratio)) h.ratio = p.ratio;
  const double scale = fmag > 0.0 ? p.force * mu_load / fmag : 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    force[i] *= scale;
    h.xi[i] = -(force[i] + k.gt * slip[i]) / k.kt;
  }
  torque = std::copysign(p.torque * mu_load * a, torque);
  h.phi = -(torque + k.gw * twist_rate) / k.kw;
}

// The wall's force and torque on the sphere (about its centre), advancing the
// springs by dt.
template <class Profile>
wrench wall_contact(const Profile& profile, const sphere& s, history& h, double dt) {
  wrench out;
  const vec3 n{0.0, 0.0, 1.0};  // from the wall to the centre
  const double overlap = kRadius - s.x[2];
  if (overlap < 0.0) {
    h = history{};
    return out;
  }
  const double a = std::sqrt(kRadius * overlap);
  const double vn = dot(s.v, n);
  const double fn = kNormalStiffness * overlap * a - kEtaN * a * kMass * vn;
  out.load = std::fabs(fn);

  const vec3 arm{-kRadius * n[0], -kRadius * n[1], -kRadius * n[2]};  // centre to contact
  const vec3 spin_part = cross(s.w, arm);
  vec3 slip{};
  for (std::size_t i = 0; i < 3; ++i) slip[i] = s.v[i] - vn * n[i] + spin_part[i];
  const double twist_rate = dot(s.w, n);

  springs k{};
  k.kt = kTangentialStiffness * a;
  k.gt = kXGammaT * kEtaN * a * kMass;
  k.kw = 0.5 * k.kt * a * a;
  k.gw = 0.5 * k.gt * a * a;

  // the plane does not turn: xi stays in it
  for (std::size_t i = 0; i < 3; ++i) h.xi[i] += slip[i] * dt;
  h.phi += twist_rate * dt;
  vec3 friction{};
  for (std::size_t i = 0; i < 3; ++i) friction[i] = -k.kt * h.xi[i] - k.gt * slip[i];
  double twist = -k.kw * h.phi - k.gw * twist_rate;
  if (out.load > 0.0) {
    cap_friction(profile, kMu * out.load, a, k, slip, twist_rate, h, friction, twist);
  }

  const vec3 lever = cross(arm, friction);
  for (std::size_t i = 0; i < 3; ++i) {
    out.force[i] = fn * n[i] + friction[i];
    out.torque[i] = lever[i] + twist * n[i];
  }
  return out;
}

// One step of the semi-implicit Euler scheme; returns the wall's load.
template <class Profile>
double step(const Profile& profile, sphere& s, history& h, double dt) {
  const wrench c = wall_contact(profile, s, h, dt);
  for (std::size_t i = 0; i < 3; ++i) {
    const double gravity = i == 2 ? -kMass * kGravity : 0.0;
    s.v[i] += dt * (c.force[i] + gravity) / kMass;
    s.w[i] += dt * c.torque[i] / kInertia;
    s.x[i] += dt * s.v[i];
  }
  return c.load;
}

struct throw_kind {
  const char* label;
  double vx;
  double wz;
};
constexpr std::array<throw_kind, 3> kThrows{{{"sliding:             ", 1.0, 0.0},
                                             {"spinning:            ", 0.0, 20.0},
                                             {"sliding and spinning:", 1.0, 20.0}}};

struct stop_times {
  double sliding = -1.0;  // -1: not within kMaxTime
  double spinning = -1.0;
  double settled_overlap = 0.0;
  double load_deviation = 0.0;  // max |N/(mg) - 1| after the throw
};

// Records the first time each quantity is below its threshold; true when both are.
bool record_stops(const sphere& s, double t, stop_times& out) {
  if (out.sliding < 0.0 && s.v[0] - kRadius * s.w[1] < kSlipThreshold) out.sliding = t;
  if (out.spinning < 0.0 && s.w[2] < kSpinThreshold) out.spinning = t;
  return out.sliding >= 0.0 && out.spinning >= 0.0;
}

template <class Profile>
stop_times throw_sphere(const Profile& profile, const throw_kind& kind, double dt) {
  sphere s;
  history h;
  const long settle_steps = std::lround(kSettleTime / dt);
  for (long i = 0; i < settle_steps; ++i) step(profile, s, h, dt);
  stop_times out;
  out.settled_overlap = kRadius - s.x[2];
  // the throw: the velocities are reset, the contact's history kept
  s.v = {kind.vx, 0.0, 0.0};
  s.w = {0.0, 0.0, kind.wz};
  const long max_steps = std::lround(kMaxTime / dt);
  for (long i = 0; i <= max_steps; ++i) {
    if (record_stops(s, static_cast<double>(i) * dt, out)) break;
    const double load = step(profile, s, h, dt);
    out.load_deviation = std::fmax(out.load_deviation, std::fabs(load / (kMass * kGravity) - 1));
  }
  return out;
}

// The stop times of the three throws, with one profile.
template <class Profile>
std::array<stop_times, 3> throw_all(const Profile& profile, double dt) {
  std::array<stop_times, 3> out{};
  for (std::size_t i = 0; i < kThrows.size(); ++i) out[i] = throw_sphere(profile, kThrows[i], dt);
  return out;
}

// in.sphere_on_plane's printed lines, for the test's parser.
void print_block(const char* coupling, double dt, const std::array<stop_times, 3>& t) {
  std::printf(
      "coupling %s: stop times after the throw (slip_x < %g, w_z < %g; -1: not within t = %g; "
      "reference, dt = %g)\n",
      coupling, kSlipThreshold, kSpinThreshold, kMaxTime, dt);
  for (std::size_t i = 0; i < kThrows.size(); ++i) {
    std::printf("  sphere %zu, %s sliding stops at t = %.6f, spinning at t = %.6f\n", i + 1,
                kThrows[i].label, t[i].sliding, t[i].spinning);
  }
}

// The rigid reduced models where they apply, and the normal contact's state.
void print_sanity(double dt, double top, const std::array<stop_times, 3>& coupled,
                  const std::array<stop_times, 3>& uncoupled) {
  const double weight = kMass * kGravity;
  const double overlap = std::pow(weight / (kNormalStiffness * std::sqrt(kRadius)), 2.0 / 3.0);
  const double a = std::sqrt(kRadius * overlap);
  const double spin_coupled = kThrows[1].wz * kInertia / (kMu * weight * a * top);
  const double spin_uncoupled = kThrows[1].wz * kInertia / (kMu * weight * a * (2.0 / 3.0));
  const double slide = 2 * kThrows[0].vx / (7 * kMu * kGravity);
  std::printf("sanity (dt = %g):\n", dt);
  std::printf("  static Hertz overlap %.9g, a = %.9g; settled overlap %.9g (rel. %.2g)\n", overlap,
              a, coupled[0].settled_overlap, coupled[0].settled_overlap / overlap - 1);
  double deviation = 0.0;
  for (std::size_t i = 0; i < kThrows.size(); ++i) {
    deviation =
        std::fmax(deviation, std::fmax(coupled[i].load_deviation, uncoupled[i].load_deviation));
  }
  std::printf("  normal load after the throws: max |N/(mg) - 1| = %.2g\n", deviation);
  std::printf(
      "  rigid Coulomb sliding 2 v0/(7 mu g) = %.6f; integrated: %.6f (coupled), %.6f "
      "(uncoupled)\n",
      slide, coupled[0].sliding, uncoupled[0].sliding);
  std::printf(
      "  rigid pure spin w0 I/(mu m g a T(0)): coupled, T(0) = %.6f: %.6f; integrated "
      "%.6f (rel. %.2g)\n",
      top, spin_coupled, coupled[1].spinning, coupled[1].spinning / spin_coupled - 1);
  std::printf("  rigid pure spin, uncoupled, T(0) = 2/3: %.6f; integrated %.6f (rel. %.2g)\n",
              spin_uncoupled, uncoupled[1].spinning, uncoupled[1].spinning / spin_uncoupled - 1);
}

// The profile --profile names (Hertz's without it), or an error.
spinslide::contact_profile<double> named_profile(const std::vector<std::string>& args) {
  if (args.empty() || args[0] == "hertz") return spinslide::hertz<double>{};
  if (args[0] == "disk") return spinslide::uniform_disk<double>{};
  if (args[0] == "ring") return spinslide::ring<double>{};
  if (args[0] == "boussinesq") return spinslide::boussinesq<double>{};
  if (args[0] == "annulus" && args.size() == 2)
    return spinslide::annulus<double>{std::strtod(args[1].c_str(), nullptr)};
  throw std::invalid_argument("--profile: hertz, disk, ring, boussinesq or annulus b");
}

void run(double dt, const spinslide::contact_profile<double>& profile) {
  const spinslide::uncoupled_caps<double> caps(2.0 / 3.0);
  const auto [coupled, top] = profile.visit([&](const auto& p) {
    return std::make_pair(throw_all(p, dt), p.mean_radius());  // T(0) = mean radius
  });
  const std::array<stop_times, 3> uncoupled = throw_all(caps, dt);
  print_block("yes", dt, coupled);
  print_block("no", dt, uncoupled);
  print_sanity(dt, top, coupled, uncoupled);
}

void convergence() {
  const spinslide::hertz<double> hertz;
  const spinslide::uncoupled_caps<double> caps(2.0 / 3.0);
  std::printf("%-8s %-9s %10s %10s %10s %10s\n", "dt", "coupling", "1 slide", "2 spin", "3 slide",
              "3 spin");
  for (const double dt : {4e-5, 2e-5, 1e-5, 5e-6, 2.5e-6}) {
    const std::array<stop_times, 3> c = throw_all(hertz, dt);
    const std::array<stop_times, 3> u = throw_all(caps, dt);
    std::printf("%-8g %-9s %10.6f %10.6f %10.6f %10.6f\n", dt, "yes", c[0].sliding, c[1].spinning,
                c[2].sliding, c[2].spinning);
    std::printf("%-8g %-9s %10.6f %10.6f %10.6f %10.6f\n", dt, "no", u[0].sliding, u[1].spinning,
                u[2].sliding, u[2].spinning);
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (!args.empty() && args[0] == "--convergence") {
      convergence();
      return 0;
    }
    std::vector<std::string> profile_args;
    std::size_t n = args.size();
    for (std::size_t i = 0; i < args.size(); ++i) {
      if (args[i] == "--profile") {
        profile_args.assign(args.begin() + static_cast<std::ptrdiff_t>(i) + 1, args.end());
        n = i;
        break;
      }
    }
    const double dt = n == 0 ? 1e-5 : std::strtod(args[0].c_str(), nullptr);
    if (n > 1 || !(dt > 0.0 && dt <= 1e-3) || (n < args.size() && profile_args.empty())) {
      std::fprintf(stderr,
                   "usage: sphere_on_plane_reference [dt in (0, 1e-3]] [--profile hertz|disk|"
                   "ring|boussinesq|annulus b] | --convergence\n");
      return 2;
    }
    run(dt, named_profile(profile_args));
    return 0;
  } catch (const std::exception& e) {  // a failed projection (a domain error)
    std::fprintf(stderr, "sphere_on_plane_reference: %s\n", e.what());
    return 1;
  }
}
