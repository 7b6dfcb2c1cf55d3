//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// A coin (R = 12 mm, 2 mm thick, steel, γ = 1/2) thrown flat, sliding and
// spinning, on a wooden table (μ = 0.3) in Bullet 3 (double precision), in
// three models per throw:
//   native:  Bullet's own friction: friction μ per contact point, spinning
//            friction μ·(2/3)R (the torsional coefficient of a uniformly
//            pressed disk in pure spin) and a tiny rolling friction, without
//            which Bullet adds no spinning friction;
//   plug-in: spinslide::bullet::coupled_friction_solver (the exact impulse
//            law after Bullet's normal solve, uniform pressure, a = R);
//   exact:   spinslide::trajectory of the same throw (uniform disk, γ of the
//            Bullet coin).
// Then the cost per contact per step of the plug-in against native friction
// (many coins), and a billiard ball with side spin (Hertz law against
// Bullet's spinning friction).
//   ./build/release/engines/bullet/examples/bullet_coin/bullet_coin [output-directory]
// writes bullet_coin.csv and, with gnuplot, bullet_coin.png there; exits
// non-zero unless the plug-in meets the checks printed at the end.
#include <btBulletDynamicsCommon.h>
#include <spinslide/engines/bullet.hpp>
#include <spinslide/spinslide.hpp>

#include "gnuplot.hpp"
#include "scene.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace {

using bullet_scene::coin_radius;
using bullet_scene::g;
using bullet_scene::scene;
using model = bullet_scene::friction;

constexpr double pi = 3.14159265358979323846;
// The time step: friction changes a speed by μgΔt = 2.9e-5 m/s per step, below
// 1e-3 of the slowest start speed (0.10 m/s), so that the stop time is
// resolved to 2e-5 s, 0.1 % of the shortest stop (0.027 s).  ε is compared
// where the speed has fallen to 1e-2 of its start: at 1e-3 the stop is two
// or three steps away, and the discrete steps, not the law, decide ε there
// (issue 27: with the patch centre on the coin's axis ε tracks the exact
// one within 0.5 % from 0.5 down to 5e-3 of the start, and misses it by
// 2.8 % at 1e-3 on the throw (0.1, 1)).
constexpr double dt = 1e-5;

// The coin (scene.hpp: R = 12 mm, 2 mm thick, μ = 0.3), of steel.
constexpr double coin_thickness = 2 * bullet_scene::coin_half_thickness, steel = 7850,
                 mu = bullet_scene::coin_mu;

// The scenes (scene.hpp) have their table's top face centred here.
btVector3 table_top() { return btVector3(1, 1, 0); }

// A coin of `shape` in `s`, with the friction of the scene's model.
btRigidBody* add_coin(scene& s, btCylinderShapeZ& shape, double mass, const btVector3& origin) {
  btRigidBody* coin = s.add(&shape, mass, origin);
  bullet_scene::set_coin_friction(s, coin);
  return coin;
}

// One throw's time series and its summary in one model.
struct run_log {
  std::vector<double> t, v, rw;  // s, m/s, m/s (R|ω|)
  double slide_stop = -1, spin_stop = -1;
  std::vector<double> x, y;          // the centre of mass [m] (Bullet only)
  double eps_near_stop = NAN;        // v/(Rω) near the stop (see near_stop)
  double fraction = NAN;             // √(v² + (Rω)²) there, over its start value
  double peak_normal = 0;            // the largest summed normal force after the first steps, / mg
  int over = 0;                      // steps with a summed normal force above 1.05 mg
  int lost = 0;                      // steps with no normal impulse
  double peak_average = 0;           // the largest 1 ms average of the normal force, / mg
  double rise = 0;                   // the highest the centre of mass rose above its rest [m]
  double creep_v = 0, creep_rw = 0;  // the largest v and Rω after both stops
  double drift = 0;                  // how far the centre of mass moves after both stops [m]
};

struct throw_case {
  double v0s, w0s;  // v0*, ω0* (the library's units: v* = v/(μ√(gR)), ω* = ω√(R/g)/μ)
};

// The first time after which `x` stays below `threshold`; -1 if never.
double settle_time(const std::vector<double>& t, const std::vector<double>& x, double threshold) {
  double when = -1;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i] >= threshold)
      when = -1;
    else if (when < 0)
      when = t[i];
  }
  return when;
}

constexpr double stop_level = 1e-3;  // "stopped": below 1e-3 of the start value, and stays there
constexpr double eps_level = 1e-2;   // ε compared where the speed is 1e-2 of its start

// Near the stop: the first sample, both motions still on, whose speed
// √(v² + (Rω)²) is at most `level` of its start; if the steps jump past that
// level, the last such sample.  Sets the log's ε and speed fraction there.
void near_stop(run_log& log, double level) {
  const double start = std::hypot(log.v[0], log.rw[0]), tiny = 1e-12;
  for (std::size_t i = 0; i < log.v.size(); ++i) {
    if (log.v[i] <= tiny || log.rw[i] <= tiny) continue;
    const double s = std::hypot(log.v[i], log.rw[i]);
    log.fraction = s / start;
    log.eps_near_stop = log.v[i] / log.rw[i];
    if (s <= level * start) return;
  }
}

void summarize(run_log& log, double v0, double rw0, double level) {
  log.slide_stop = settle_time(log.t, log.v, level * v0);
  log.spin_stop = settle_time(log.t, log.rw, level * rw0);
  near_stop(log, eps_level);
  // After both stops, and a margin for the last steps below the thresholds.
  const double stop = std::max(log.slide_stop, log.spin_stop) * 1.05 + 0.001;
  std::size_t first = log.t.size();
  for (std::size_t i = 0; i < log.t.size(); ++i)
    if (log.slide_stop >= 0 && log.spin_stop >= 0 && log.t[i] > stop) {
      first = std::min(first, i);
      log.creep_v = std::max(log.creep_v, log.v[i]);
      log.creep_rw = std::max(log.creep_rw, log.rw[i]);
      if (!log.x.empty())
        log.drift =
            std::max(log.drift, std::hypot(log.x[i] - log.x[first], log.y[i] - log.y[first]));
    }
}

run_log run_bullet(model m, double v0, double w0, double duration) {
  scene s(m, table_top());
  btCylinderShapeZ shape(btVector3(coin_radius, coin_radius, coin_thickness / 2));
  const double mass = steel * pi * coin_radius * coin_radius * coin_thickness;
  btRigidBody* coin = add_coin(s, shape, mass, btVector3(0, 0, coin_thickness / 2));
  for (int i = 0; i < 300; ++i) s.step(dt);  // settle on the table
  coin->setLinearVelocity(btVector3(v0, 0, coin->getLinearVelocity().z()));
  coin->setAngularVelocity(btVector3(0, 0, w0));
  run_log log;
  const int steps = static_cast<int>(std::ceil(duration / dt));
  const double rest_height = static_cast<double>(coin->getCenterOfMassPosition().z());
  const auto window = static_cast<std::size_t>(std::lround(1e-3 / dt));  // 1 ms
  std::vector<double> normal;
  double window_sum = 0;
  for (int i = 0; i <= steps; ++i) {
    log.rise =
        std::max(log.rise, static_cast<double>(coin->getCenterOfMassPosition().z()) - rest_height);
    const btVector3 v = coin->getLinearVelocity();
    log.t.push_back(i * dt);
    log.v.push_back(std::hypot(v.x(), v.y()));
    log.rw.push_back(coin_radius * std::fabs(coin->getAngularVelocity().z()));
    log.x.push_back(coin->getCenterOfMassPosition().x());
    log.y.push_back(coin->getCenterOfMassPosition().y());
    if (i == steps) break;
    s.step(dt);
    const double n = s.contact_of(coin).first / (mass * g * dt);
    if (n <= 0) ++log.lost;
    if (i >= 5) log.peak_normal = std::max(log.peak_normal, n);
    if (i >= 5 && n > 1.05) ++log.over;
    normal.push_back(n);
    window_sum += n;
    if (normal.size() > window) window_sum -= normal[normal.size() - window - 1];
    if (normal.size() >= window)
      log.peak_average = std::max(log.peak_average, window_sum / static_cast<double>(window));
  }
  summarize(log, v0, coin_radius * w0, stop_level);
  return log;
}

// The exact throw sampled at the same times (SI), from spinslide::trajectory.
run_log run_exact(double gamma, double v0, double w0, double duration) {
  const spinslide::si_units<double> u{coin_radius, mu, g};
  std::vector<double> times;
  const int steps = static_cast<int>(std::ceil(duration / dt));
  for (int i = 0; i <= steps; ++i) times.push_back(i * dt / u.time_unit());
  const auto samples = spinslide::trajectory(spinslide::uniform_disk<>(), gamma,
                                             v0 / u.velocity_unit(), w0 / u.spin_unit(), times);
  run_log log;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    log.t.push_back(static_cast<double>(i) * dt);
    log.v.push_back(samples[i].speed * u.velocity_unit());
    log.rw.push_back(coin_radius * samples[i].spin * u.spin_unit());
  }
  summarize(log, v0, coin_radius * w0, stop_level);
  log.peak_normal = log.peak_average = 1;
  return log;
}

// The exact ε where the speed √(v² + (Rω)²) has fallen to `fraction` of its
// start (sampled on a logarithmic grid of the time left before the stop).
double exact_ratio_at(double gamma, double v0, double w0, double stop, double fraction) {
  const spinslide::si_units<double> u{coin_radius, mu, g};
  const double v0s = v0 / u.velocity_unit(), w0s = w0 / u.spin_unit();
  const double ts = stop / u.time_unit();
  std::vector<double> times;
  // 0.5 % steps of the time left: ε changes by less than 0.2 % per sample.
  for (int k = 0; k <= 5000; ++k) times.push_back(ts * (1 - std::pow(10.0, -k / 500.0)));
  const auto samples = spinslide::trajectory(spinslide::uniform_disk<>(), gamma, v0s, w0s, times);
  const double start = std::hypot(v0s, w0s * u.spin_unit() * coin_radius / u.velocity_unit());
  for (const auto& m : samples) {
    const double s = std::hypot(m.speed, m.spin * u.spin_unit() * coin_radius / u.velocity_unit());
    if (m.speed > 0 && m.spin > 0 && s <= fraction * start) return m.ratio;
  }
  return NAN;
}

// Seconds per step of `steps` steps of `coins` coins thrown in a grid (best
// of three runs) and the contacts per step.
std::pair<double, double> time_steps(model m, int coins, int steps) {
  double best = INFINITY, contacts = 0;
  for (int repeat = 0; repeat < 3; ++repeat) {
    scene s(m, table_top());
    btCylinderShapeZ shape(btVector3(coin_radius, coin_radius, coin_thickness / 2));
    const double mass = steel * pi * coin_radius * coin_radius * coin_thickness;
    std::vector<btRigidBody*> all;
    const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(coins))));
    for (int i = 0; i < coins; ++i) {
      btRigidBody* c = add_coin(s, shape, mass,
                                btVector3(0.2 * (i % side), 0.2 * (i / side), coin_thickness / 2));
      all.push_back(c);
    }
    for (int i = 0; i < 100; ++i) s.step(dt);
    for (std::size_t i = 0; i < all.size(); ++i) {
      all[i]->setLinearVelocity(btVector3(0.1 + 0.001 * static_cast<double>(i), 0.05, 0));
      all[i]->setAngularVelocity(btVector3(0, 0, 10.0 - 0.05 * static_cast<double>(i)));
    }
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) s.step(dt);
    const auto stop = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double>(stop - start).count() / steps);
    contacts = coins;
  }
  return {best, contacts};
}

// The billiard ball: R = 28.6 mm, m = 0.17 kg, μ = 0.2 on cloth, sliding at
// 1 m/s without rolling and spinning about the vertical at 20 rad/s.
struct ball_log {
  double roll_time = -1;        // when the contact point stops slipping (< 1 mm/s)
  double spin_at_roll = NAN;    // ω_z then
  double spin_stop = -1;        // when |ω_z| < 0.02 rad/s
  double raw_hertz_radius = 0;  // √(R*δ) from Bullet's penetration, largest seen
  std::vector<double> t, wz, slip;
  double spin_end = NAN;  // ω_z at the end
};

constexpr double ball_radius = 0.0286, ball_mass = 0.17, ball_mu = 0.2;
// The patch: a stated value (Bullet's √(R*δ) is about 1e-7 m, printed).
constexpr double ball_patch = 1e-3;
constexpr double ball_dt = 1e-4;  // s (the ball's motion takes seconds)

ball_log run_ball(model m) {
  scene s(m, table_top());
  btSphereShape shape(ball_radius);
  btRigidBody* ball = s.add(&shape, ball_mass, btVector3(0, 0, ball_radius));
  if (m == model::native) {
    ball->setFriction(ball_mu);
    // The torsional coefficient of Hertz pressure in pure spin, 𝓣(0)a = (3π/16)a.
    ball->setSpinningFriction(ball_mu * 3 * pi / 16 * ball_patch);
    ball->setRollingFriction(1e-9);
  } else {
    s.plugin().couple(
        ball, s.table(),
        spinslide::pair_friction(
            spinslide::hertz<>(),
            spinslide::hertz_radius(ball_radius, spinslide::patch_radius<double>{ball_patch}),
            spinslide::friction_coefficient<double>{ball_mu}));
  }
  for (int i = 0; i < 300; ++i) s.step(ball_dt);
  ball->setLinearVelocity(btVector3(1.0, 0, ball->getLinearVelocity().z()));
  ball->setAngularVelocity(btVector3(0, 0, 20.0));
  ball_log log;
  const int steps = static_cast<int>(8.0 / ball_dt);
  for (int i = 0; i <= steps; ++i) {
    const btVector3 c = ball->getVelocityInLocalPoint(btVector3(0, 0, -ball_radius));
    const double slip = std::hypot(c.x(), c.y()), wz = ball->getAngularVelocity().z();
    const double t = i * ball_dt;
    if (i % 50 == 0) {
      log.t.push_back(t);
      log.wz.push_back(wz);
      log.slip.push_back(slip);
    }
    if (log.roll_time < 0 && slip < 1e-3) {
      log.roll_time = t;
      log.spin_at_roll = wz;
    }
    if (log.spin_stop < 0 && std::fabs(wz) < 0.02) log.spin_stop = t;
    log.spin_end = wz;
    if (i == steps) break;
    s.step(ball_dt);
    log.raw_hertz_radius =
        std::max(log.raw_hertz_radius, std::sqrt(ball_radius * s.contact_of(ball).second));
  }
  return log;
}

// One throw in the three models: its rows of the table, its block of the
// CSV (gnuplot index `index`), and whether the plug-in passed its checks.
bool run_throw(const throw_case& c, double gamma, int index, FILE* f) {
  const spinslide::si_units<double> u{coin_radius, mu, g};
  const double v0 = c.v0s * u.velocity_unit(), w0 = c.w0s * u.spin_unit();
  const auto exact_stop = spinslide::simulate_throw_si(
      spinslide::uniform_disk<>(), spinslide::disk_radius{coin_radius},
      spinslide::friction_coefficient{mu}, spinslide::gravity{g}, gamma,
      spinslide::initial_speed{v0}, spinslide::initial_spin{w0});
  const double duration = 1.3 * exact_stop.time + 0.02;
  const run_log logs[3] = {run_bullet(model::native, v0, w0, duration),
                           run_bullet(model::plugin, v0, w0, duration),
                           run_exact(gamma, v0, w0, duration)};
  const char* names[3] = {"native", "plug-in", "exact"};
  const run_log& p = logs[1];
  const run_log& e = logs[2];
  // The exact ε at the plug-in's speed fraction near the stop.
  const double exact_eps = exact_ratio_at(gamma, v0, w0, exact_stop.time, p.fraction);
  for (int k = 0; k < 3; ++k) {
    const run_log& l = logs[k];
    const std::string label =
        k == 0 ? std::to_string(c.v0s).substr(0, 3) + "," + std::to_string(c.w0s).substr(0, 3) : "";
    std::printf(
        "%-8s %-8s %9.5f %9.5f %9.5f %8.4f %8.1e %6.3f %5d %6.3f %8.1e %5d %9.1e %9.1e %9.1e\n",
        label.c_str(), names[k], l.slide_stop, l.spin_stop, exact_stop.time,
        k == 2 ? exact_eps : l.eps_near_stop, k == 2 ? p.fraction : l.fraction, l.peak_normal,
        l.over, l.peak_average, l.rise, l.lost, l.creep_v, l.creep_rw, l.drift);
  }
  // The plug-in's checks against the exact throw.
  const double creep_bound = 1e-6;  // m/s
  const bool time_ok = std::fabs(p.slide_stop / e.slide_stop - 1) <= 0.01 &&
                       std::fabs(p.spin_stop / e.spin_stop - 1) <= 0.01;
  const bool eps_ok = std::fabs(p.eps_near_stop / exact_eps - 1) <= 0.01;
  // No lift-off: contact in every step, the normal force over any 1 ms
  // within 5 % of mg, and the coin never 1 μm above its rest.  (Single steps
  // reach 1.7 mg, natively too: Bullet replaces the cylinder's manifold
  // points under the spinning coin and the impulses shift between them.)
  const bool contact_ok = p.lost == 0 && std::fabs(p.peak_average - 1) <= 0.05 && p.rise <= 1e-6;
  const bool creep_ok = p.creep_v <= creep_bound && p.creep_rw <= creep_bound;
  std::printf(
      "%-8s plug-in vs exact: slide stop %+.2f%%, spin stop %+.2f%%, eps %+.2f%% (terminal "
      "ratio %.4f); checks: time %s, eps %s, normal force %s, no creep %s\n",
      "", 100 * (p.slide_stop / e.slide_stop - 1), 100 * (p.spin_stop / e.spin_stop - 1),
      100 * (p.eps_near_stop / exact_eps - 1), exact_stop.terminal.ratio, time_ok ? "yes" : "NO",
      eps_ok ? "yes" : "NO", contact_ok ? "yes" : "NO", creep_ok ? "yes" : "NO");
  const bool passed = time_ok && eps_ok && contact_ok && creep_ok;
  for (std::size_t i = 0; i < e.t.size(); ++i) {
    std::fprintf(f, "%d %.5f", index, e.t[i]);
    for (const run_log& l : logs)
      std::fprintf(f, " %.6e %.6e %.6e", l.v[i], l.rw[i],
                   l.rw[i] > 0 ? l.v[i] / l.rw[i] : (l.v[i] > 0 ? INFINITY : NAN));
    std::fprintf(f, "\n");
  }
  std::fprintf(f, "\n\n");
  return passed;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : ".";
  const throw_case throws[] = {{1, 1}, {1, 0.1}, {0.1, 1}, {2, 3}};
  const spinslide::si_units<double> u{coin_radius, mu, g};
  const double mass = steel * pi * coin_radius * coin_radius * coin_thickness;
  btCylinderShapeZ probe(btVector3(coin_radius, coin_radius, coin_thickness / 2));
  btVector3 inertia;
  probe.calculateLocalInertia(mass, inertia);
  const double gamma = inertia.z() / (mass * coin_radius * coin_radius);
  std::printf(
      "coin: R = %.0f mm, %.0f mm thick, m = %.2f g, gamma = I/(mR^2) = %.4f, mu = %.2f, dt = "
      "%.0e s\n"
      "units: v* = v/(mu sqrt(gR)) (%.4f m/s), omega* = omega sqrt(R/g)/mu (%.3f rad/s), t* = "
      "t sqrt(g/R) (%.4f s)\n"
      "stopped: below 1e-3 of the start value for good; eps = v/(R omega) at the first step "
      "with s = sqrt(v^2 + (R omega)^2) <= 1e-2 s0 (else the last step before the stop), the "
      "exact one at the same s/s0\nN/mg: the largest summed normal force per step after the "
      "first 5 steps; >1.05: steps above 1.05 mg; 1ms N: the largest 1 ms average of N/mg; rise: "
      "the highest the centre rose above its rest; after: the largest speeds and the drift of the "
      "centre of mass after both stops\n\n",
      coin_radius * 1e3, coin_thickness * 1e3, mass * 1e3, gamma, mu, dt, u.velocity_unit(),
      u.spin_unit(), u.time_unit());

  const std::string csv = out + "/bullet_coin.csv";
  FILE* f = spinslide_examples::open_output(csv, "bullet_coin");
  if (!f) return 1;
  std::fprintf(f,
               "# throw t  native: v R*omega eps  plug-in: v R*omega eps  exact: v R*omega eps "
               "(SI; gnuplot index = throw)\n");
  std::printf("%-8s %-8s %9s %9s %9s %8s %8s %6s %5s %6s %8s %5s %9s %9s %9s\n", "v0*,w0*", "model",
              "slide [s]", "spin [s]", "exact [s]", "eps", "at s/s0", "N/mg", ">1.05", "1ms N",
              "rise [m]", "lost", "v after", "Rw after", "drift [m]");
  bool ok = true;
  int index = 0;
  for (const throw_case& c : throws) {
    ok = run_throw(c, gamma, index, f) && ok;
    ++index;
  }
  std::fclose(f);

  // Cost: many coins, each its own contact with the table.
  const int coins = 64, timed = 2000;
  const auto native_cost = time_steps(model::native, coins, timed);
  const auto plugin_cost = time_steps(model::plugin, coins, timed);
  std::printf(
      "\ncost (%d coins sliding and spinning, %d steps, best of 3): native %.3f us per step "
      "(%.1f ns per contact), plug-in %.3f us per step (%.1f ns per contact); the plug-in adds "
      "%.1f ns per contact per step (%.2fx)\n",
      coins, timed, native_cost.first * 1e6, native_cost.first / native_cost.second * 1e9,
      plugin_cost.first * 1e6, plugin_cost.first / plugin_cost.second * 1e9,
      (plugin_cost.first - native_cost.first) / plugin_cost.second * 1e9,
      plugin_cost.first / native_cost.first);

  // The billiard ball.
  const ball_log bn = run_ball(model::native), bp = run_ball(model::plugin);
  std::printf(
      "\nbilliard ball (R = %.1f mm, m = %.2f kg, mu = %.1f, patch a = %.1f mm; Bullet's "
      "sqrt(R* delta) reached only %.2e m), v0 = 1 m/s sliding, side spin 20 rad/s:\n",
      ball_radius * 1e3, ball_mass, ball_mu, ball_patch * 1e3,
      std::max(bn.raw_hertz_radius, bp.raw_hertz_radius));
  auto ball_line = [](const char* name, const ball_log& b) {
    std::printf(
        "  %-28s rolls at %.4f s with side spin %.3f rad/s (lost %.3f rad/s while sliding, "
        "%.2f rad/s^2); side spin stops at %.3f s (-1: not within 8 s; %.3f rad/s then)\n",
        name, b.roll_time, b.spin_at_roll, 20.0 - b.spin_at_roll,
        (20.0 - b.spin_at_roll) / b.roll_time, b.spin_stop, b.spin_end);
  };
  ball_line("native (spinning friction):", bn);
  ball_line("plug-in (Hertz, coupled):", bp);

  const bool figure = spinslide_examples::plot(
      out, "bullet_coin.gp",
      "set terminal pngcairo size 1600,1000 font ',10'\n"
      "set output 'bullet_coin.png'\n"
      "set multiplot layout 3,4 title 'Coin in Bullet: native friction (red), spinslide plug-in "
      "(black), exact (blue dashed)'\n"
      "titles = \"'(1,1)' '(1,0.1)' '(0.1,1)' '(2,3)'\"\n"
      "set xlabel 't [s]'\n"
      "do for [i=0:3] { set title sprintf('v [m/s], (v0*,w0*) = %s', word(titles, i+1)); unset "
      "logscale y; set yrange [*:*]\n"
      "  plot 'bullet_coin.csv' index i u 2:3 w l lc 'red' t 'native', '' index i u 2:6 w l lw 2 "
      "lc 'black' t 'plug-in', '' index i u 2:9 w l dt 2 lw 2 lc 'blue' t 'exact' }\n"
      "do for [i=0:3] { set title sprintf('R omega [m/s], %s', word(titles, i+1))\n"
      "  plot 'bullet_coin.csv' index i u 2:4 w l lc 'red' t 'native', '' index i u 2:7 w l lw 2 "
      "lc 'black' t 'plug-in', '' index i u 2:10 w l dt 2 lw 2 lc 'blue' t 'exact' }\n"
      "do for [i=0:3] { set title sprintf('eps = v/(R omega), %s', word(titles, i+1)); set "
      "logscale y; set yrange [0.01:100]\n"
      "  plot 'bullet_coin.csv' index i u 2:($3 > 1e-5 && $4 > 1e-5 ? $5 : 1/0) w l lc 'red' t "
      "'native', '' index i u 2:($6 > 1e-5 && $7 > 1e-5 ? $8 : 1/0) w l lw 2 lc 'black' t "
      "'plug-in', '' index i u 2:($9 > 1e-5 && $10 > 1e-5 ? $11 : 1/0) w l dt 2 lw 2 lc 'blue' "
      "t 'exact' }\n"
      "unset multiplot\n");
  if (figure)
    std::printf("\nwrote %s/bullet_coin.csv and %s/bullet_coin.png\n", out.c_str(), out.c_str());
  else
    std::printf("\nwrote %s/bullet_coin.csv (no gnuplot: no figure)\n", out.c_str());
  std::printf("plug-in checks: %s\n", ok ? "all passed" : "FAILED");
  return ok ? 0 : 1;
}
