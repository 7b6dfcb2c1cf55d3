//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// A puck (a disk, 5 cm radius, γ = 1/2) thrown sliding and spinning on a
// table, in the Box2D physics engine (top-down, no gravity in the engine;
// the table's normal force is m g).  Two pucks side by side:
//   A: spinslide's coupled friction (spinslide::box2d::table_friction: the
//      velocity-level law, an impulse before each step; exact stick);
//   B: Box2D's own b2FrictionJoint to a static ground body, with
//      maxForce = μmg and maxTorque = μmg⟨r⟩R (the uncoupled caps).
// Puck A stops sliding and spinning together with v/(Rω) → ε₀ = 0.653;
// puck B stops spinning long before it stops sliding.
//   ./build/release/engines/box2d/examples/box2d_puck [output-directory]
// writes box2d_puck.csv and, with gnuplot, box2d_puck.png there.
#include <box2d/box2d.h>
#include <spinslide/engines/box2d.hpp>
#include <spinslide/spinslide.hpp>

#include "gnuplot.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

struct puck_log {
  double slide_stop = -1, spin_stop = -1;  // first time below the thresholds
  double ratio_late = 0;                   // v/(Rω) when v first falls below `stopped`
};

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : ".";
  const double R = 0.05, mu = 0.3, g = 9.81, mass = 0.016;
  const double v0 = 2.5, w0 = 10.0;  // initial v/(Rω) = 5
  const double dt = 1.0 / 1000;
  const double pi = 3.14159265358979323846;

  b2World world(b2Vec2(0.0f, 0.0f));
  b2BodyDef ground_def;
  b2Body* ground = world.CreateBody(&ground_def);

  auto make_puck = [&](float y) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(0.0f, y);
    def.linearVelocity.Set(static_cast<float>(v0), 0.0f);
    def.angularVelocity = static_cast<float>(w0);
    def.bullet = false;
    b2Body* body = world.CreateBody(&def);
    b2CircleShape circle;
    circle.m_radius = static_cast<float>(R);
    b2FixtureDef fd;
    fd.shape = &circle;
    fd.density = static_cast<float>(mass / (pi * R * R));
    fd.filter.groupIndex = -1;  // the pucks do not collide with each other
    body->CreateFixture(&fd);
    return body;
  };
  b2Body* a = make_puck(0.0f);
  b2Body* b = make_puck(1.0f);
  const double m = a->GetMass(), I = a->GetInertia();
  const double gamma = I / (m * R * R);

  b2FrictionJointDef jd;
  jd.Initialize(ground, b, b->GetWorldCenter());
  jd.maxForce = static_cast<float>(mu * m * g);
  jd.maxTorque = static_cast<float>(mu * m * g * R * 2.0 / 3.0);
  world.CreateJoint(&jd);

  // snippet begin
  spinslide::box2d::table_friction table(spinslide::gravity{g});
  table.couple(
      a, spinslide::pair_friction(spinslide::uniform_disk<>(), spinslide::patch_radius<double>{R},
                                  spinslide::friction_coefficient<double>{mu}));
  // snippet end

  const std::string csv = out + "/box2d_puck.csv";
  FILE* f = spinslide_examples::open_output(csv, "box2d_puck");
  if (!f) return 1;
  std::fprintf(f, "# t  A: x y angle v R*omega ratio   B: x y angle v R*omega ratio\n");
  puck_log la, lb;
  const double stopped = 1e-3;  // m/s: below this a motion counts as stopped
  for (int step = 0; step <= 1500; ++step) {
    const double t = step * dt;
    auto state = [&](b2Body* p, puck_log& l) {
      const b2Vec2 v = p->GetLinearVelocity();
      const double speed = std::hypot(v.x, v.y), rim = R * std::fabs(p->GetAngularVelocity());
      if (l.slide_stop < 0 && speed < stopped) {
        l.slide_stop = t;
        l.ratio_late = rim > 0 ? speed / rim : INFINITY;
      }
      if (l.spin_stop < 0 && rim < stopped) l.spin_stop = t;
      std::fprintf(f, " %.6f %.6f %.6f %.6f %.6f %.9g", p->GetPosition().x, p->GetPosition().y,
                   p->GetAngle(), speed, rim, rim > 0 ? speed / rim : INFINITY);
    };
    std::fprintf(f, "%.4f", t);
    state(a, la);
    state(b, lb);
    std::fprintf(f, "\n");
    table.apply(dt);  // puck A: spinslide's coupled friction over this step
    world.Step(static_cast<float>(dt), 8, 3);
  }
  std::fclose(f);

  // The exact stop of puck A from spinslide's own integration, for comparison.
  const auto exact = spinslide::simulate_throw_si(
      spinslide::uniform_disk<>(), spinslide::disk_radius{R}, spinslide::friction_coefficient{mu},
      spinslide::gravity{g}, gamma, spinslide::initial_speed{v0}, spinslide::initial_spin{w0});
  const double e0 = spinslide::terminal_ratio();
  std::printf(
      "puck: R = %.2f m, m = %.3f kg, gamma = %.3f, mu = %.2f, v0 = %.2f m/s, omega0 = %.1f rad/s "
      "(initial v/(R omega) = %.2f), dt = %.4f s\n",
      R, m, gamma, mu, v0, w0, v0 / (R * w0), dt);
  std::printf(
      "A (spinslide::box2d, coupled): sliding stops at %.3f s, spinning at %.3f s, "
      "v/(R omega) at the stop = %.4f (eps0 = %.4f)\n",
      la.slide_stop, la.spin_stop, la.ratio_late, e0);
  std::printf("  spinslide's exact integration of the same throw stops at %.4f s, eps -> %.4f\n",
              exact.time, exact.terminal.ratio);
  std::printf("B (b2FrictionJoint, uncoupled caps): sliding stops at %.3f s, spinning at %.3f s\n",
              lb.slide_stop, lb.spin_stop);
  const bool together = std::fabs(la.slide_stop - la.spin_stop) <= 0.02 * la.slide_stop;
  const bool ratio_ok = std::fabs(la.ratio_late / e0 - 1) < 0.05;
  const bool time_ok = std::fabs(la.slide_stop / exact.time - 1) < 0.02;
  const bool apart = std::fabs(lb.slide_stop - lb.spin_stop) > 0.5 * lb.slide_stop;
  std::printf(
      "checks: A stops together %s, A ratio -> eps0 %s, A stop time matches %s, B stops apart %s\n",
      together ? "yes" : "NO", ratio_ok ? "yes" : "NO", time_ok ? "yes" : "NO",
      apart ? "yes" : "NO");

  const bool figure = spinslide_examples::plot(
      out, "box2d_puck.gp",

      "set terminal pngcairo size 1200,450 font ',11'\n"
      "set output 'box2d_puck.png'\n"
      "set multiplot layout 1,2\n"
      "set xrange [0:1.1]; set xlabel 't [s]'; set ylabel 'speed [m/s]'; set key right top\n"
      "plot 'box2d_puck.csv' u 1:5 w l lw 2 lc 'black' t 'A spinslide: v', '' u 1:6 w l lw 2 dt "
      "2 lc 'black' "
      "t 'A spinslide: R omega', '' u 1:11 w l lc 'red' t 'B b2FrictionJoint: v', '' u 1:12 w l "
      "dt 2 lc 'red' t "
      "'B b2FrictionJoint: R omega'\n"
      "set ylabel 'v/(R omega)'; set logscale y; set yrange [0.1:100]\n"
      "plot 'box2d_puck.csv' u 1:($5 > 0.002 ? $7 : 1/0) w l lw 2 lc 'black' t 'A spinslide', "
      "'' u 1:($11 > 0.002 && $12 > 0.002 ? $13 : 1/0) w l lc 'red' t 'B b2FrictionJoint', 0.653 "
      "w l dt 3 lc "
      "'blue' t 'eps0 = 0.653'\n"
      "unset multiplot\n");
  if (figure)
    std::printf("wrote %s/box2d_puck.csv and %s/box2d_puck.png\n", out.c_str(), out.c_str());
  else
    std::printf("wrote %s/box2d_puck.csv (no gnuplot: no figure)\n", out.c_str());
  return together && ratio_ok && time_ok && apart ? 0 : 1;
}
