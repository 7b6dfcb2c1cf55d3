//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// bench_mujoco's disk scene (engines/mujoco/examples/mujoco_disk/scene.hpp)
// with one of three frictions, for bench_mujoco.cpp (timed) and
// engines/mujoco/tests/step_instructions.cpp (counted): MuJoCo's own (condim 4, elliptic),
// none (condim 1), or spinslide's coupled pair (condim 1 and
// spinslide::mujoco::coupled_friction).
#ifndef SPINSLIDE_BENCHMARKS_MUJOCO_DISK_BENCH_HPP
#define SPINSLIDE_BENCHMARKS_MUJOCO_DISK_BENCH_HPP

#include <spinslide/engines/mujoco.hpp>
#include <spinslide/spinslide.hpp>

#include "../engines/mujoco/examples/mujoco_disk/scene.hpp"

#include <memory>

namespace mujoco_disk_bench {

enum class friction { native, none, spinslide };

// The disk on its floor, settled and then thrown with (v0, omega0).
class scene {
 public:
  scene(friction kind, double v0, double omega0)
      : model_(mujoco_scene::load(
            mujoco_scene::disk_xml({"", kind == friction::native ? 4 : 1, "elliptic"}))),
        data_(mj_makeData(model_.get())) {
    if (kind == friction::spinslide) {
      coupled_ = std::make_unique<spinslide::mujoco::coupled_friction>(model_.get());
      coupled_->couple(spinslide::mujoco::geom_name{"disk"}, spinslide::mujoco::geom_name{"floor"},
                       spinslide::pair_friction(spinslide::uniform_disk<>(),
                                                spinslide::patch_radius<double>{0.06},
                                                spinslide::friction_coefficient<double>{0.2}));
    }
    mujoco_scene::settle_and_throw(model_.get(), data_.get(), v0, omega0, [this] { step(); });
  }
  // One time step with the scene's friction.
  void step() {
    if (coupled_)
      coupled_->step(data_.get());
    else
      mj_step(model_.get(), data_.get());
  }
  mjModel* model() const { return model_.get(); }
  mjData* data() const { return data_.get(); }

 private:
  mujoco_scene::model_ptr model_;
  mujoco_scene::data_ptr data_;
  std::unique_ptr<spinslide::mujoco::coupled_friction> coupled_;
};

}  // namespace mujoco_disk_bench

#endif  // SPINSLIDE_BENCHMARKS_MUJOCO_DISK_BENCH_HPP
