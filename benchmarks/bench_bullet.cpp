//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The cost of spinslide's friction inside Bullet (docs/engines.md,
// docs/performance.md): one time step (Δt = 1e-5 s) of 64 coins of
// engines/bullet/examples/bullet_coin (R = 12 mm, 2 mm thick, 7.1 g, μ = 0.3) on a static
// box table, each one contact with the table, sliding and spinning
// (re-thrown at 0.1 m/s and 10 rad/s every 1000 steps, 0.01 s, before they
// stop: friction takes 0.03 m/s and 3.3 rad/s in that time) or at rest:
//   bullet_native: Bullet's own friction, μ per contact point, spinning
//     friction μ·(2/3)R and rolling friction 1e-9 (without which Bullet adds
//     no spinning friction) (the baseline);
//   bullet_frictionless: friction 0, for the engine's cost without friction;
//   spinslide_in_bullet: spinslide::bullet::coupled_friction_solver
//     (uniform_disk, a = R).
// Items are contacts × steps: the time per item is per contact per step.
// The ratio lines at the end compare spinslide with native friction.
//   ./build/release/benchmarks/bench_bullet
#include <benchmark/benchmark.h>
#include <btBulletDynamicsCommon.h>
#include <spinslide/engines/bullet.hpp>
#include <spinslide/spinslide.hpp>

#include "../engines/bullet/examples/bullet_coin/scene.hpp"
#include "ratio_reporter.hpp"

#include <cmath>
#include <memory>
#include <vector>

namespace {

enum class friction { native, none, spinslide };

constexpr int coins = 64, rethrow_every = 1000;
constexpr double dt = 1e-5, coin_mass = 0.0071;
using bullet_scene::coin_half_thickness;
using bullet_scene::coin_radius;

// The example's scene (engines/bullet/examples/bullet_coin/scene.hpp; its table's top face
// centred at (0.7, 0.7, 0)) and 64 coins on an 8 × 8 grid 0.2 m apart,
// released at rest and settled for 100 steps.
class scene {
 public:
  explicit scene(friction kind)
      : coin_shape_(btVector3(coin_radius, coin_radius, coin_half_thickness)),
        world_(kind == friction::spinslide ? bullet_scene::friction::plugin
                                           : bullet_scene::friction::native,
               btVector3(0.7, 0.7, 0)) {
    for (int i = 0; i < coins; ++i) {
      btRigidBody* c = world_.add(&coin_shape_, coin_mass,
                                  btVector3(0.2 * (i % 8), 0.2 * (i / 8), coin_half_thickness));
      if (kind == friction::none)
        c->setFriction(0);
      else
        bullet_scene::set_coin_friction(world_, c);
      coins_.push_back(c);
    }
    for (int i = 0; i < 100; ++i) step();
  }

  void step() { world_.step(dt); }

  // Sets every coin sliding and spinning, each a little differently.
  void throw_coins() {
    for (std::size_t i = 0; i < coins_.size(); ++i) {
      const double k = static_cast<double>(i);
      coins_[i]->setLinearVelocity(btVector3(0.1 + 0.001 * k, 0.05, 0));
      coins_[i]->setAngularVelocity(btVector3(0, 0, 10.0 - 0.05 * k));
    }
  }

  // The coins' poses and velocities, to go back to.
  struct state {
    std::vector<btTransform> pose;
    std::vector<btVector3> v, w;
  };
  state save() const {
    state s;
    for (const btRigidBody* c : coins_) {
      s.pose.push_back(c->getCenterOfMassTransform());
      s.v.push_back(c->getLinearVelocity());
      s.w.push_back(c->getAngularVelocity());
    }
    return s;
  }
  void restore(const state& s) {
    for (std::size_t i = 0; i < coins_.size(); ++i) {
      coins_[i]->setCenterOfMassTransform(s.pose[i]);
      coins_[i]->setLinearVelocity(s.v[i]);
      coins_[i]->setAngularVelocity(s.w[i]);
    }
  }

  // The manifolds with at least one point: the contacts.
  int contacts() {
    int n = 0;
    btCollisionDispatcher& d = world_.dispatcher();
    for (int i = 0; i < d.getNumManifolds(); ++i)
      if (d.getManifoldByIndexInternal(i)->getNumContacts() > 0) ++n;
    return n;
  }

 private:
  btCylinderShapeZ coin_shape_;  // before world_: outlives the coins
  bullet_scene::scene world_;
  std::vector<btRigidBody*> coins_;  // world_'s
};

void step_the_coins(benchmark::State& state, friction kind, bool moving) {
  scene s(kind);
  if (moving) s.throw_coins();
  const scene::state thrown = s.save();
  int since_throw = 0;
  for (auto _ : state) {
    s.step();
    if (++since_throw == rethrow_every) {
      s.restore(thrown);
      since_throw = 0;
    }
  }
  const int contacts = s.contacts();
  state.SetItemsProcessed(state.iterations() * contacts);
  state.counters["contacts"] = contacts;
}

void bullet_native(benchmark::State& s) { step_the_coins(s, friction::native, true); }
void bullet_frictionless(benchmark::State& s) { step_the_coins(s, friction::none, true); }
void spinslide_in_bullet(benchmark::State& s) { step_the_coins(s, friction::spinslide, true); }
void bullet_native_at_rest(benchmark::State& s) { step_the_coins(s, friction::native, false); }
void bullet_frictionless_at_rest(benchmark::State& s) { step_the_coins(s, friction::none, false); }
void spinslide_in_bullet_at_rest(benchmark::State& s) {
  step_the_coins(s, friction::spinslide, false);
}

BENCHMARK(bullet_native)->Unit(benchmark::kMicrosecond);
BENCHMARK(bullet_frictionless)->Unit(benchmark::kMicrosecond);
BENCHMARK(spinslide_in_bullet)->Unit(benchmark::kMicrosecond);
BENCHMARK(bullet_native_at_rest)->Unit(benchmark::kMicrosecond);
BENCHMARK(bullet_frictionless_at_rest)->Unit(benchmark::kMicrosecond);
BENCHMARK(spinslide_in_bullet_at_rest)->Unit(benchmark::kMicrosecond);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  spinslide_bench::ratio_reporter reporter(
      "bullet_native", {{"spinslide_in_bullet", "bullet_native"},
                        {"spinslide_in_bullet_at_rest", "bullet_native_at_rest"}});
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
