//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The paper's disk thrown sliding and spinning in MuJoCo, side by side:
//   MuJoCo's own friction (a cylinder; condim 3, 4 and 6; elliptic and
//   pyramidal cones; torsional coefficient (2/3)μR),
//   spinslide inside MuJoCo (frictionless contacts, condim 1, and
//   spinslide::mujoco::coupled_friction), and
//   the exact motion from spinslide's own integration.
// For each throw (v0*, ω0*) = (1, 1), (1, 0.1), (0.1, 1), (2, 3) it prints
// the slide-stop and spin-stop times, ε near the stop, the peak normal force
// and the steps with a lost contact, writes mujoco_disk.csv, mujoco_disk.md
// (the table of docs/engines.md) and, with gnuplot, mujoco_disk.png, and
// exits non-zero unless spinslide in MuJoCo stops within 1 % of the exact
// stop, with ε within 2 % of the exact one, without lift-off, creep or
// chatter.
//   ./build/release/engines/mujoco/examples/mujoco_disk/mujoco_disk [output-directory]
#include <spinslide/engines/mujoco.hpp>
#include <spinslide/spinslide.hpp>

#include "gnuplot.hpp"
#include "scene.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace {

using mujoco_scene::friction_model;

// v and Rω of the disk at each step after the throw, with the contacts.
struct record {
  std::vector<double> time, speed, rim;
  std::vector<double> normal;  // summed normal force / (m g)
  std::vector<int> contacts;   // disk-floor contacts
  double seconds_per_step = 0;
  int contacts_at_rest = 0;
};

// What the table shows of one run.
struct summary {
  double slide_stop, spin_stop;  // s (NaN: still moving at the end)
  double ratio_1e2, ratio_1e3;   // ε where v + Rω first falls below 1e-2, 1e-3 of the start
  double peak_normal;            // max N/(mg) after the throw
  int lost_steps;                // steps with fewer contacts than at rest
  int airborne_steps;            // steps without any contact
  double after_stop;             // max(v, Rω) from 10 ms after the exact stop on [m/s]
};

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The first sample from which `x` stays below `threshold`.
double settles_below(const std::vector<double>& t, const std::vector<double>& x, double threshold) {
  for (std::size_t i = x.size(); i-- > 0;)
    if (x[i] >= threshold) return i + 1 < t.size() ? t[i + 1] : nan;
  return t.empty() ? nan : t.front();
}

// ε = v/(Rω) at the first sample where v + Rω < fraction × (v0 + Rω0).
double ratio_at(const record& r, double fraction, double scale) {
  for (std::size_t i = 0; i < r.time.size(); ++i)
    if (r.speed[i] + r.rim[i] < fraction * scale) return r.speed[i] / r.rim[i];
  return nan;
}

summary summarize(const record& r, double scale, double exact_stop) {
  summary s{settles_below(r.time, r.speed, 1e-4 * scale),
            settles_below(r.time, r.rim, 1e-4 * scale),
            ratio_at(r, 1e-2, scale),
            ratio_at(r, 1e-3, scale),
            0,
            0,
            0,
            0};
  for (std::size_t i = 0; i < r.time.size(); ++i) {
    if (r.time[i] > exact_stop + 0.01)
      s.after_stop = std::fmax(s.after_stop, std::fmax(r.speed[i], r.rim[i]));
    if (r.normal.empty()) continue;
    s.peak_normal = std::fmax(s.peak_normal, r.normal[i]);
    if (r.contacts[i] < r.contacts_at_rest) ++s.lost_steps;
    if (r.contacts[i] == 0) ++s.airborne_steps;
  }
  return s;
}

struct disk_contacts {
  int count = 0;
  double normal = 0;
};

disk_contacts floor_contacts(const mjModel* m, const mjData* d) {
  disk_contacts c;
  for (int i = 0; i < d->ncon; ++i) {
    if (d->contact[i].efc_address < 0) continue;
    mjtNum f[6];
    mj_contactForce(m, d, i, f);
    ++c.count;
    c.normal += f[0];
  }
  return c;
}

// Runs one throw in MuJoCo for `duration` seconds; spinslide's friction when
// the model is frictionless.
record run(const friction_model& fm, double v0, double omega0, double duration,
           double dt = mujoco_scene::time_step) {
  const auto model = mujoco_scene::load(mujoco_scene::disk_xml(fm, dt));
  const mujoco_scene::data_ptr data(mj_makeData(model.get()));
  mjModel* m = model.get();
  mjData* d = data.get();
  std::unique_ptr<spinslide::mujoco::coupled_friction> coupled;
  if (fm.condim == 1) {
    coupled = std::make_unique<spinslide::mujoco::coupled_friction>(m);
    coupled->couple(
        spinslide::mujoco::geom_name{"disk"}, spinslide::mujoco::geom_name{"floor"},
        spinslide::pair_friction(spinslide::uniform_disk<>(),
                                 spinslide::patch_radius<double>{mujoco_scene::radius},
                                 spinslide::friction_coefficient<double>{mujoco_scene::friction}));
  }
  auto step = [&] {
    if (coupled)
      coupled->step(d);
    else
      mj_step(m, d);
  };
  mujoco_scene::settle_and_throw(m, d, v0, omega0, step);
  const double weight = mujoco_scene::mass * mujoco_scene::gravity;
  record r;
  r.contacts_at_rest = floor_contacts(m, d).count;
  const auto steps = static_cast<int>(std::lround(duration / m->opt.timestep));
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < steps; ++i) {
    const auto motion = mujoco_scene::disk_patch_motion(d);
    const disk_contacts c = floor_contacts(m, d);
    r.time.push_back(d->time);
    r.speed.push_back(motion.speed);
    r.rim.push_back(mujoco_scene::radius * std::fabs(motion.spin));
    r.normal.push_back(c.normal / weight);
    r.contacts.push_back(c.count);
    step();
  }
  r.seconds_per_step =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps;
  return r;
}

// The exact motion at the same times.
struct throw_case {
  double v0s, w0s;  // dimensionless start
};

record exact_record(double gamma, const throw_case& c, const std::vector<double>& times) {
  const spinslide::si_units<double> u{mujoco_scene::radius, mujoco_scene::friction,
                                      mujoco_scene::gravity};
  std::vector<double> scaled;
  for (const double t : times) scaled.push_back(t / u.time_unit());
  const auto samples =
      spinslide::trajectory(spinslide::uniform_disk<>(), gamma, c.v0s, c.w0s, scaled);
  record r;
  r.time = times;
  for (const auto& s : samples) {
    r.speed.push_back(s.speed * u.velocity_unit());
    r.rim.push_back(s.spin * u.spin_unit() * mujoco_scene::radius);
  }
  return r;
}

const friction_model spinslide_model{"spinslide in MuJoCo", 1, "elliptic"};
const std::vector<friction_model> native_models{
    {"MuJoCo condim 3, elliptic", 3, "elliptic"},   {"MuJoCo condim 4, elliptic", 4, "elliptic"},
    {"MuJoCo condim 6, elliptic", 6, "elliptic"},   {"MuJoCo condim 3, pyramidal", 3, "pyramidal"},
    {"MuJoCo condim 4, pyramidal", 4, "pyramidal"}, {"MuJoCo condim 6, pyramidal", 6, "pyramidal"}};

std::string format_time(double t) {
  char b[32];
  if (std::isnan(t)) return "no stop";
  std::snprintf(b, sizeof b, "%.1f", 1e3 * t);
  return b;
}

struct outputs {
  FILE* table;
  FILE* csv;
};
struct cost_totals {
  double native = 0, spinslide = 0;  // seconds per step, summed over the throws
  int throws = 0;
};

void print_row(const outputs& o, const throw_case& c, const char* name, const summary& s,
               bool engine) {
  auto number = [](const char* format, double x) {
    char b[32];
    std::snprintf(b, sizeof b, format, x);
    return std::string(b);
  };
  std::fprintf(o.table, "| (%g, %g) | %s | %s | %s | %.4g | %.4g | %s | %s | %s | %s |\n", c.v0s,
               c.w0s, name, format_time(s.slide_stop).c_str(), format_time(s.spin_stop).c_str(),
               s.ratio_1e2, s.ratio_1e3, engine ? number("%.3f", s.peak_normal).c_str() : "1",
               engine ? std::to_string(s.lost_steps).c_str() : "0",
               engine ? std::to_string(s.airborne_steps).c_str() : "0",
               engine ? number("%.1e", s.after_stop).c_str() : "0");
  std::printf(
      "  %-36s slide %7s ms  spin %7s ms  eps(1e-2) %.4f  eps(1e-3) %9.4f  peak N/mg %.3f  "
      "lost %4d  airborne %3d  after %.1e m/s\n",
      name, format_time(s.slide_stop).c_str(), format_time(s.spin_stop).c_str(), s.ratio_1e2,
      s.ratio_1e3, engine ? s.peak_normal : 1.0, s.lost_steps, s.airborne_steps, s.after_stop);
}

bool within(double x, double reference, double tolerance) {
  return std::fabs(x / reference - 1) <= tolerance;
}

// Runs one throw in every model; prints and writes its rows; true if
// spinslide in MuJoCo passes its checks.
bool compare_throw(const throw_case& c, std::size_t index, double gamma, const outputs& o,
                   cost_totals& cost) {
  const spinslide::si_units<double> u{mujoco_scene::radius, mujoco_scene::friction,
                                      mujoco_scene::gravity};
  const double v0 = c.v0s * u.velocity_unit(), w0 = c.w0s * u.spin_unit();
  const double scale = v0 + mujoco_scene::radius * w0;
  const double stop = spinslide::simulate_throw_si(
                          spinslide::uniform_disk<>(), spinslide::disk_radius{mujoco_scene::radius},
                          spinslide::friction_coefficient{mujoco_scene::friction},
                          spinslide::gravity{mujoco_scene::gravity}, gamma,
                          spinslide::initial_speed{v0}, spinslide::initial_spin{w0})
                          .time;
  const double duration = stop + 0.15;
  std::vector<record> runs{run(spinslide_model, v0, w0, duration)};
  for (const auto& f : native_models) runs.push_back(run(f, v0, w0, duration));
  const record fine = run(spinslide_model, v0, w0, duration, mujoco_scene::time_step / 10);
  // The exact motion: at the engine's samples for the figure, and every
  // 0.1 us over the last 20 ms for ε near the stop.
  const record exact = exact_record(gamma, c, runs.front().time);
  std::vector<double> dense;
  for (int i = 0; i <= 200000; ++i) dense.push_back(stop - 0.02 + 1e-7 * i);
  summary se = summarize(exact_record(gamma, c, dense), scale, stop);
  se.slide_stop = se.spin_stop = stop;
  std::printf("throw (v0*, w0*) = (%g, %g): v0 = %.4f m/s, omega0 = %.3f rad/s\n", c.v0s, c.w0s, v0,
              w0);
  print_row(o, c, "exact (spinslide)", se, false);
  const summary sp = summarize(runs[0], scale, stop);
  print_row(o, c, spinslide_model.name, sp, true);
  const summary sf = summarize(fine, scale, stop);
  print_row(o, c, "spinslide in MuJoCo, step 1e-5 s", sf, true);
  for (std::size_t i = 0; i < native_models.size(); ++i)
    print_row(o, c, native_models[i].name, summarize(runs[i + 1], scale, stop), true);
  const bool ok = within(sp.slide_stop, stop, 0.01) && within(sp.spin_stop, stop, 0.01) &&
                  within(sp.ratio_1e2, se.ratio_1e2, 0.02) && sp.peak_normal <= 1.05 &&
                  sp.airborne_steps == 0 && sp.after_stop <= 1e-6 * scale &&
                  within(sf.ratio_1e3, se.ratio_1e3, 0.02);
  std::printf(
      "  check: spinslide in MuJoCo stops within 1 %% of exact, eps within 2 %% at 1e-2 of the "
      "start (step 1e-4 s) and at 1e-3 (step 1e-5 s), no lift-off, no creep: %s\n",
      ok ? "yes" : "NO");
  cost.spinslide += runs[0].seconds_per_step;
  cost.native += runs[2].seconds_per_step;  // condim 4, elliptic
  ++cost.throws;
  for (std::size_t i = 0; i < exact.time.size(); i += 10) {
    std::fprintf(o.csv, "%zu %.5f %.6e %.6e", index, exact.time[i], exact.speed[i], exact.rim[i]);
    for (const auto& r : runs) std::fprintf(o.csv, " %.6e %.6e", r.speed[i], r.rim[i]);
    std::fprintf(o.csv, "\n");
  }
  std::fprintf(o.csv, "\n\n");
  return ok;
}

// The billiard ball (R = 28.6 mm, 0.17 kg, μ = 0.2 on cloth) thrown sliding at
// 1 m/s with side spin 20 rad/s about the vertical, for 1 s.
struct ball_log {
  std::vector<double> time, slip, spin;  // contact slip speed [m/s], side spin [rad/s]
  double rolls_at = nan;                 // first time the slip is below 1e-4 m/s
  double spin_at_roll = nan;             // side spin then
  double patch = nan;                    // the plug-in's patch radius at rest [m]
};

constexpr double ball_radius = 0.0286, ball_mass = 0.17, ball_mu = 0.2;

std::string ball_xml(int condim, double torsional) {
  char xml[700];
  std::snprintf(xml, sizeof xml,
                "<mujoco><option timestep='1e-4' solver='Newton' integrator='Euler' "
                "cone='elliptic'/><default><geom condim='%d' friction='%g %g 0'/></default>"
                "<worldbody><geom name='floor' type='plane' size='5 5 0.1'/>"
                "<body name='ball' pos='0 0 %g'><freejoint/>"
                "<geom name='ball' type='sphere' size='%g' mass='%g'/></body>"
                "</worldbody></mujoco>",
                condim, ball_mu, torsional, ball_radius, ball_radius, ball_mass);
  return xml;
}

// One ball run: MuJoCo's own friction (condim 4, elliptic cone, torsional
// coefficient μ(3π/16)a) when `torsional` > 0, else spinslide's Hertz law (a = √(Rδ)).
ball_log run_ball(double torsional) {
  const auto model = mujoco_scene::load(ball_xml(torsional > 0 ? 4 : 1, torsional));
  const mujoco_scene::data_ptr data(mj_makeData(model.get()));
  mjModel* m = model.get();
  mjData* d = data.get();
  std::unique_ptr<spinslide::mujoco::coupled_friction> coupled;
  if (torsional <= 0) {
    coupled = std::make_unique<spinslide::mujoco::coupled_friction>(m);
    coupled->couple(
        spinslide::mujoco::geom_name{"ball"}, spinslide::mujoco::geom_name{"floor"},
        spinslide::pair_friction(spinslide::hertz<>(), spinslide::hertz_radius{ball_radius},
                                 spinslide::friction_coefficient<double>{ball_mu}));
  }
  auto step = [&] {
    if (coupled)
      coupled->step(d);
    else
      mj_step(m, d);
  };
  for (int i = 0; i < 5000; ++i) step();  // settle
  ball_log log;
  if (coupled) log.patch = coupled->report(0).patch_radius;
  d->qvel[0] = 1.0;
  d->qvel[5] = 20.0;  // body frame; the ball has not turned yet
  d->time = 0;
  for (int i = 0; i <= 10000; ++i) {
    // The contact point's velocity: v + ω × (0, 0, -R), ω in the world frame.
    const mjtNum* q = d->qvel;
    const mjtNum* rot = d->xmat + 9;
    std::array<double, 3> w{};
    for (std::size_t k = 0; k < 3; ++k)
      w[k] = rot[3 * k] * q[3] + rot[3 * k + 1] * q[4] + rot[3 * k + 2] * q[5];
    const double slip = std::hypot(q[0] - w[1] * ball_radius, q[1] + w[0] * ball_radius);
    log.time.push_back(d->time);
    log.slip.push_back(slip);
    log.spin.push_back(w[2]);
    if (std::isnan(log.rolls_at) && slip < 1e-4) {
      log.rolls_at = d->time;
      log.spin_at_roll = w[2];
    }
    step();
  }
  return log;
}

// The ball in both models: a table row each, a CSV and a figure.
void compare_ball(const std::string& out) {
  const ball_log plugin = run_ball(0);
  // MuJoCo's torsional coefficient: the pure-spin torque over N, μ(3π/16)a.
  const double torsional = ball_mu * 3 * 3.14159265358979323846 / 16 * plugin.patch;
  const ball_log native = run_ball(torsional);
  FILE* table = spinslide_examples::open_output(out + "/mujoco_ball.md", "mujoco_disk");
  FILE* csv = spinslide_examples::open_output(out + "/mujoco_ball.csv", "mujoco_disk");
  if (!table || !csv) return;
  std::fprintf(table,
               "| model | rolls at [s] | side spin then [rad/s] | side spin at 1 s [rad/s] |\n"
               "|---|---|---|---|\n");
  std::printf(
      "billiard ball: R = %.1f mm, %.2f kg, mu = %.1f, v0 = 1 m/s sliding, side spin 20 "
      "rad/s; Hertz patch a = sqrt(R delta) = %.3f mm at rest\n",
      1e3 * ball_radius, ball_mass, ball_mu, 1e3 * plugin.patch);
  auto row = [&](const char* name, const ball_log& l) {
    std::fprintf(table, "| %s | %.4f | %.3f | %.3f |\n", name, l.rolls_at, l.spin_at_roll,
                 l.spin.back());
    std::printf("  %-52s rolls at %.4f s, side spin then %.3f rad/s, at 1 s %.3f rad/s\n", name,
                l.rolls_at, l.spin_at_roll, l.spin.back());
  };
  row("spinslide in MuJoCo (Hertz, coupled)", plugin);
  char name[96];
  std::snprintf(name, sizeof name, "MuJoCo condim 4, torsional mu(3pi/16)a = %.2e m", torsional);
  row(name, native);
  std::fclose(table);
  std::fprintf(csv, "# t slip_spinslide spin_spinslide slip_native spin_native\n");
  for (std::size_t i = 0; i < plugin.time.size(); i += 10)
    std::fprintf(csv, "%.4f %.6e %.6e %.6e %.6e\n", plugin.time[i], plugin.slip[i], plugin.spin[i],
                 native.slip[i], native.spin[i]);
  std::fclose(csv);
  spinslide_examples::plot(
      out, "mujoco_ball.gp",
      "set terminal pngcairo size 1100,420 font ',10'\n"
      "set output 'mujoco_ball.png'\n"
      "set multiplot layout 1,2\n"
      "set xlabel 't [s]'; set key right top\n"
      "set ylabel 'slip at the contact [m/s]'\n"
      "plot 'mujoco_ball.csv' u 1:2 w l lw 2 lc 'blue' t 'spinslide in MuJoCo', '' u 1:4 w l lw 2 "
      "lc '#d55e00' t 'MuJoCo condim 4'\n"
      "set ylabel 'side spin [rad/s]'\n"
      "plot 'mujoco_ball.csv' u 1:3 w l lw 2 lc 'blue' t 'spinslide in MuJoCo', '' u 1:5 w l lw 2 "
      "lc '#d55e00' t 'MuJoCo condim 4'\n"
      "unset multiplot\n");
}

}  // namespace

int main(int argc, char** argv) try {
  const std::string out = argc > 1 ? argv[1] : ".";
  double gamma = 0;
  {
    const auto model = mujoco_scene::load(mujoco_scene::disk_xml(spinslide_model));
    gamma = model->body_inertia[5] /
            (model->body_mass[1] * mujoco_scene::radius * mujoco_scene::radius);
  }
  const std::vector<throw_case> throws{{1, 1}, {1, 0.1}, {0.1, 1}, {2, 3}};
  FILE* table = spinslide_examples::open_output(out + "/mujoco_disk.md", "mujoco_disk");
  FILE* csv = spinslide_examples::open_output(out + "/mujoco_disk.csv", "mujoco_disk");
  if (!table || !csv) return 1;
  std::fprintf(table,
               "| throw (v0\\*, ω0\\*) | model | slide stops [ms] | spin stops [ms] | ε at 1e-2 "
               "| ε at 1e-3 | peak N/(mg) | steps with a contact lost | airborne steps | max(v, "
               "Rω) after the stop [m/s] |\n|---|---|---|---|---|---|---|---|---|---|\n");
  std::fprintf(csv, "# throw t v_exact Rw_exact v_spinslide Rw_spinslide");
  for (const auto& f : native_models)
    std::fprintf(csv, " v_%dd_%s Rw_%dd_%s", f.condim, f.cone, f.condim, f.cone);
  std::fprintf(csv, "\n");
  bool pass = true;
  cost_totals cost;
  for (std::size_t k = 0; k < throws.size(); ++k)
    pass = compare_throw(throws[k], k, gamma, {table, csv}, cost) && pass;
  std::fclose(table);
  std::fclose(csv);
  std::printf(
      "wall clock per step (the whole step; one disk, 3-4 contacts): MuJoCo condim 4 elliptic "
      "%.2f us, spinslide in MuJoCo %.2f us (%.2fx)\n",
      1e6 * cost.native / cost.throws, 1e6 * cost.spinslide / cost.throws,
      cost.spinslide / cost.native);

  std::string script =
      "set terminal pngcairo size 1500,1600 font ',10'\n"
      "set output 'mujoco_disk.png'\n"
      "set multiplot layout 4,3\n"
      "set xlabel 't [s]'; set key right top font ',8'\n"
      "names = 'c3e c4e c6e c3p c4p c6p'\n"
      "colors = '#e69f00 #d55e00 #f0c000 #009e73 #cc79a7 #56b4e9'\n";
  for (std::size_t k = 0; k < throws.size(); ++k) {
    const std::string idx = std::to_string(k);
    char title[96];
    std::snprintf(title, sizeof title, "(v0*, w0*) = (%g, %g)", throws[k].v0s, throws[k].w0s);
    script += "set title '" + std::string(title) +
              ": v' ; set ylabel 'v [m/s]'; unset logscale y; set yrange [0:*]\n"
              "plot 'mujoco_disk.csv' i " +
              idx + " u 2:3 w l lw 3 lc 'black' t 'exact', '' i " + idx +
              " u 2:5 w l lw 2 dt 2 lc 'blue' t 'spinslide in MuJoCo', for [j=1:6] '' i " + idx +
              " u 2:(column(5+2*j)) w l lw 1 lc rgb word(colors, j) t 'MuJoCo '.word(names, j)\n";
    script += "set title '" + std::string(title) +
              ": R omega'; set ylabel 'R omega [m/s]'\n"
              "plot 'mujoco_disk.csv' i " +
              idx + " u 2:4 w l lw 3 lc 'black' t 'exact', '' i " + idx +
              " u 2:6 w l lw 2 dt 2 lc 'blue' t 'spinslide in MuJoCo', for [j=1:6] '' i " + idx +
              " u 2:(column(6+2*j)) w l lw 1 lc rgb word(colors, j) t 'MuJoCo '.word(names, j)\n";
    script += "set title '" + std::string(title) +
              ": eps = v/(R omega)'; set ylabel 'eps'; set logscale y; set yrange [0.01:100]\n"
              "plot 'mujoco_disk.csv' i " +
              idx + " u 2:($4 > 1e-6 ? $3/$4 : 1/0) w l lw 3 lc 'black' t 'exact', '' i " + idx +
              " u 2:($6 > 1e-6 ? $5/$6 : 1/0) w l lw 2 dt 2 lc 'blue' t 'spinslide in MuJoCo', for "
              "[j=1:6] '' i " +
              idx +
              " u 2:(column(6+2*j) > 1e-6 ? column(5+2*j)/column(6+2*j) : 1/0) w l lw 1 lc rgb "
              "word(colors, j) t 'MuJoCo '.word(names, j)\n";
  }
  script += "unset multiplot\n";
  const bool figure = spinslide_examples::plot(out, "mujoco_disk.gp", script);
  std::printf("wrote %s/mujoco_disk.md, %s/mujoco_disk.csv%s\n", out.c_str(), out.c_str(),
              figure ? " and mujoco_disk.png" : " (no gnuplot: no figure)");
  compare_ball(out);
  std::printf("spinslide in MuJoCo meets every check: %s\n", pass ? "yes" : "NO");
  return pass ? 0 : 1;
} catch (const std::exception& e) {
  std::fprintf(stderr, "mujoco_disk: %s\n", e.what());
  return 1;
}
