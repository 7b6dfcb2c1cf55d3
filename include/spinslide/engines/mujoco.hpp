//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)

/// \file mujoco.hpp
/// spinslide's coupled friction inside MuJoCo (2.2 and later; docs/engines.md).
///
///     spinslide::mujoco::coupled_friction friction(model);
///     friction.couple(spinslide::mujoco::geom_name{"disk"}, spinslide::mujoco::geom_name{"floor"},
///                     spinslide::engines::pair_friction(spinslide::uniform_disk<>(),
///                                                       spinslide::patch_radius<double>{0.06},
///                                                       spinslide::friction_coefficient<double>{0.2}));
///     for (...) friction.step(data);  // instead of mj_step(model, data)
///
/// The coupled geoms' contacts must be frictionless (condim="1"): MuJoCo
/// solves their normal forces, and spinslide their friction.  Each step is
/// mj_step1; the forward dynamics up to the constraint forces, which gives
/// this step's normal forces (no lag) and the velocity each pair would have
/// at the end of the step without friction; then, per pair, the
/// velocity-level law of impulse_friction.hpp (exact stick; slip on the
/// coupled limit set) in the pair's effective inverse mass W = JM⁻¹Jᵀ; the
/// impulses, divided by the step, are added to qfrc_applied for mj_step2 and
/// removed after it.  W does not know MuJoCo's other constraints (the normal
/// contacts resist the tilt that a friction force below the centre of mass
/// starts), so a sticking pair would keep a residual slip (a disk on a slope:
/// 2.7 % of gΔt sin α per step, a steady creep of 4 μm/s): the constraints
/// are solved again with the friction applied, and each pair's law is applied
/// again to the velocity it would then have without friction, until every
/// sticking pair's residual slip is below 1e-9 of its own scale (at most
/// three such passes; one is typical).  The price is two to three constraint
/// solves per step instead of one (warm-started).
/// Needs the Euler or implicit integrator (mj_step1/mj_step2 do not split
/// RK4).
#ifndef SPINSLIDE_ENGINES_MUJOCO_HPP
#define SPINSLIDE_ENGINES_MUJOCO_HPP

#include <mujoco/mujoco.h>
#include <spinslide/engines/pair_friction.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace spinslide {
namespace mujoco {

/// A geom by its id in the model.
struct geom_id {
  /// The id (0 ≤ id < ngeom, checked by coupled_friction::couple).
  explicit constexpr geom_id(int id) : value(id) {}
  int value;  ///< the id
};

/// A geom by its name in the model.
struct geom_name {
  /// The name (looked up by coupled_friction::couple).
  explicit geom_name(std::string name) : value(std::move(name)) {}
  std::string value;  ///< the name
};

/// What happened at one coupled pair in the last step.
struct pair_report {
  int contacts = 0;                ///< MuJoCo's contacts between the two geoms
  double normal_force = 0;         ///< their summed normal force N [N]
  double penetration = 0;          ///< the deepest penetration δ [m]
  double patch_radius = 0;         ///< the patch radius used [m]
  std::array<double, 3> centre{};  ///< the patch centre: the N-weighted mean of the contacts
  std::array<double, 3> normal{};  ///< the contact normal, from the first geom to the second
  bool sticking = false;           ///< the friction impulse stopped the pair's relative motion
  double ratio = 0;                ///< ε after the step (NaN when sticking or without contact)
};

/// spinslide's coupled friction for chosen geom pairs of one MuJoCo model
/// (see the file's comment).
class coupled_friction {
 public:
  /// For `model` (not null; the Euler or implicit integrator), which must
  /// outlive this object.  Otherwise std::invalid_argument.
  explicit coupled_friction(const mjModel* model) : model_(require_model(model)) {
    const auto nv = static_cast<std::size_t>(model_->nv);
    jacobian_a_.assign(6 * nv, 0.0);
    jacobian_b_.assign(6 * nv, 0.0);
    solved_.assign(3 * nv, 0.0);
    generalized_.assign(nv, 0.0);
  }

  /// Couples geoms `a` and `b` with `friction`; returns the pair's index for
  /// report().  Both geoms must be frictionless (condim 1) and distinct;
  /// otherwise std::invalid_argument.
  std::size_t couple(geom_id a, geom_id b, const engines::pair_friction& friction) {
    const int ngeom = model_->ngeom;
    if (a.value < 0 || a.value >= ngeom || b.value < 0 || b.value >= ngeom || a.value == b.value)
      throw std::invalid_argument(
          "spinslide::mujoco::coupled_friction::couple: two distinct geom ids in [0, ngeom) are "
          "needed");
    for (const int g : {a.value, b.value}) {
      if (model_->geom_condim[g] != 1)
        throw std::invalid_argument(
            "spinslide::mujoco::coupled_friction::couple: geom " + std::to_string(g) +
            " has condim " + std::to_string(model_->geom_condim[g]) +
            "; coupled geoms must be frictionless (condim=\"1\"), so that MuJoCo adds no "
            "friction of its own");
    }
    coupled_pair pair{a.value, b.value, friction};
    pair.rows.assign(3 * static_cast<std::size_t>(model_->nv), 0.0);
    pairs_.push_back(std::move(pair));
    return pairs_.size() - 1;
  }

  /// couple() by the geoms' names; an unknown name is std::invalid_argument.
  std::size_t couple(const geom_name& a, const geom_name& b,
                     const engines::pair_friction& friction) {
    return couple(lookup(a), lookup(b), friction);
  }

  /// One time step of `data` (made for the model) with the coupled pairs'
  /// friction: use it instead of mj_step.  qfrc_applied is left as it was.
  void step(mjData* data) {
    if (data == nullptr)
      throw std::invalid_argument("spinslide::mujoco::coupled_friction::step: data is null");
    mj_step1(model_, data);
    mj_fwdActuation(model_, data);
    mj_fwdAcceleration(model_, data);
    mj_fwdConstraint(model_, data);
    for (auto& pair : pairs_) prepare(pair, data);
    impulses();
    for (int pass = 0; pass < max_corrections && !settled(data); ++pass) impulses();
    add_to(data->qfrc_applied, 1.0);
    mj_step2(model_, data);
    add_to(data->qfrc_applied, -1.0);
  }

  /// The last step at pair `index` (as couple() returned it).
  const pair_report& report(std::size_t index) const { return pairs_.at(index).report; }

  /// The generalized friction force of the last step (nv entries): the
  /// impulses divided by the time step.
  const std::vector<double>& generalized_force() const { return generalized_; }

 private:
  using vec3 = std::array<double, 3>;
  struct coupled_pair {
    coupled_pair(int first, int second, const engines::pair_friction& f)
        : a(first), b(second), friction(f) {}
    int a, b;
    engines::pair_friction friction;
    pair_report report{};
    bool active = false;       // in contact this step
    std::vector<double> rows;  // 3×nv: t1, t2 and spin rows of the relative motion
    vec3 free_motion{};        // the relative motion at the step's end without friction
    planar_metric<double> inverse_mass{detail::matrix3<double>{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}};
    vec3 impulse{};  // (P_x, P_y, L) on geom a's body
  };
  static constexpr int max_corrections = 3;

  static const mjModel* require_model(const mjModel* model) {
    if (model == nullptr)
      throw std::invalid_argument("spinslide::mujoco::coupled_friction: the model is null");
    if (model->opt.integrator == mjINT_RK4)
      throw std::invalid_argument(
          "spinslide::mujoco::coupled_friction: the RK4 integrator does not split into "
          "mj_step1/mj_step2; use Euler or implicit");
    return model;
  }

  geom_id lookup(const geom_name& name) const {
    const int id = mj_name2id(model_, mjOBJ_GEOM, name.value.c_str());
    if (id < 0)
      throw std::invalid_argument("spinslide::mujoco::coupled_friction::couple: no geom named '" +
                                  name.value + "'");
    return geom_id{id};
  }

  // Sums the pair's contacts: N, the N-weighted centre, the deepest
  // penetration and the normal from geom a to geom b.
  void gather(coupled_pair& pair, const mjData* data) const {
    pair_report& r = pair.report;
    r = pair_report{};
    for (int i = 0; i < data->ncon; ++i) {
      const mjContact& c = data->contact[i];
      const bool forward = c.geom1 == pair.a && c.geom2 == pair.b;
      if (!forward && !(c.geom1 == pair.b && c.geom2 == pair.a)) continue;
      if (c.efc_address < 0) continue;
      if (c.dim != 1)
        throw std::logic_error(
            "spinslide::mujoco::coupled_friction: a coupled pair has a contact with friction "
            "(an explicit <pair> with condim > 1?)");
      std::array<mjtNum, 6> f{};
      mj_contactForce(model_, data, i, f.data());
      const double sign = forward ? 1.0 : -1.0;
      ++r.contacts;
      r.normal_force += f[0];
      for (std::size_t k = 0; k < 3; ++k) {
        r.centre[k] += f[0] * c.pos[k];
        r.normal[k] += sign * c.frame[k];
      }
      r.penetration = std::fmax(r.penetration, -c.dist);
    }
  }

  // The rows of the pair's relative motion (a against b) at the centre:
  // along t1, along t2, spin about n.
  void relative_rows(coupled_pair& pair, const std::array<vec3, 3>& axes, mjData* data) {
    const auto nv = static_cast<std::size_t>(model_->nv);
    const int body_a = model_->geom_bodyid[pair.a], body_b = model_->geom_bodyid[pair.b];
    const mjtNum* point = pair.report.centre.data();
    mj_jac(model_, data, jacobian_a_.data(), jacobian_a_.data() + 3 * nv, point, body_a);
    mj_jac(model_, data, jacobian_b_.data(), jacobian_b_.data() + 3 * nv, point, body_b);
    for (std::size_t j = 0; j < nv; ++j) {
      for (std::size_t row = 0; row < 3; ++row) {
        const std::size_t block = row == 2 ? 3 * nv : 0;  // spin: the rotational Jacobian
        double sum = 0;
        for (std::size_t k = 0; k < 3; ++k)
          sum += axes[row][k] * (jacobian_a_[block + k * nv + j] - jacobian_b_[block + k * nv + j]);
        pair.rows[row * nv + j] = sum;
      }
    }
  }

  // This step's contacts, Jacobian rows, W and the relative motion at the
  // end of the step without friction.
  void prepare(coupled_pair& pair, mjData* data) {
    gather(pair, data);
    pair_report& r = pair.report;
    const double n_length = std::sqrt(r.normal[0] * r.normal[0] + r.normal[1] * r.normal[1] +
                                      r.normal[2] * r.normal[2]);
    pair.active = r.normal_force > 0 && n_length > 0;
    if (!pair.active) {
      pair.friction.forget();
      r.ratio = std::nan("");
      return;
    }
    for (std::size_t k = 0; k < 3; ++k) {
      r.centre[k] /= r.normal_force;
      r.normal[k] /= n_length;
    }
    relative_rows(pair, tangent_axes(r.normal), data);
    const auto nv = static_cast<std::size_t>(model_->nv);
    pair.free_motion = end_of_step_motion(pair, data);
    mj_solveM(model_, data, solved_.data(), pair.rows.data(), 3);
    detail::matrix3<double> w{};
    for (std::size_t row = 0; row < 3; ++row)
      for (std::size_t col = 0; col < 3; ++col)
        for (std::size_t j = 0; j < nv; ++j)
          w[row][col] += pair.rows[row * nv + j] * solved_[col * nv + j];
    pair.inverse_mass = planar_metric<double>(w);
    r.patch_radius = pair.friction.radius(r.penetration);
  }

  // The pair's relative motion at the end of the step, from qacc as it is.
  vec3 end_of_step_motion(const coupled_pair& pair, const mjData* data) const {
    const auto nv = static_cast<std::size_t>(model_->nv);
    const double h = model_->opt.timestep;
    vec3 s{};
    for (std::size_t row = 0; row < 3; ++row)
      for (std::size_t j = 0; j < nv; ++j)
        s[row] += pair.rows[row * nv + j] * (data->qvel[j] + h * data->qacc[j]);
    return s;
  }

  // Each active pair's impulse from its free motion, into generalized_.
  void impulses() {
    std::fill(generalized_.begin(), generalized_.end(), 0.0);
    const auto nv = static_cast<std::size_t>(model_->nv);
    const double h = model_->opt.timestep;
    for (auto& pair : pairs_) {
      if (!pair.active) continue;
      pair_report& r = pair.report;
      const vec3& s = pair.free_motion;
      const auto p =
          pair.friction.impulse({s[0], s[1]}, s[2], pair.inverse_mass,
                                normal_impulse<double>{r.normal_force * h}, r.penetration);
      r.sticking = p.sticking;
      r.ratio = p.ratio;
      pair.impulse = {p.force[0], p.force[1], p.torque};
      for (std::size_t row = 0; row < 3; ++row)
        for (std::size_t j = 0; j < nv; ++j)
          generalized_[j] += pair.rows[row * nv + j] * pair.impulse[row] / h;
    }
  }

  // Solves MuJoCo's constraints with the friction applied; true if every
  // sticking pair then ends the step at rest (to 1e-9 of its free motion).
  // Otherwise each pair's free motion becomes the motion it would have
  // without its friction impulse under that solve, for the next pass.
  bool settled(mjData* data) {
    add_to(data->qfrc_applied, 1.0);
    mj_fwdAcceleration(model_, data);
    mj_fwdConstraint(model_, data);
    add_to(data->qfrc_applied, -1.0);
    bool done = true;
    for (auto& pair : pairs_) {
      if (!pair.active) continue;
      const vec3 s = end_of_step_motion(pair, data);
      const double a = pair.report.patch_radius;
      const vec3& f = pair.free_motion;
      const double slip = std::hypot(s[0], s[1], a * s[2]);
      const double scale = std::hypot(f[0], f[1], a * f[2]);
      if (pair.report.sticking && slip > 1e-9 * scale) done = false;
      const auto w = pair.inverse_mass.entries();
      for (std::size_t row = 0; row < 3; ++row)
        pair.free_motion[row] =
            s[row] - (w[row][0] * pair.impulse[0] + w[row][1] * pair.impulse[1] +
                      w[row][2] * pair.impulse[2]);
    }
    return done;
  }

  void add_to(mjtNum* qfrc, double sign) const {
    const auto nv = static_cast<std::size_t>(model_->nv);
    for (std::size_t i = 0; i < nv; ++i) qfrc[i] += sign * generalized_[i];
  }

  // A right-handed orthonormal (t1, t2, n).
  static std::array<vec3, 3> tangent_axes(const vec3& n) {
    const vec3 helper = std::fabs(n[0]) < 0.6 ? vec3{1, 0, 0} : vec3{0, 1, 0};
    vec3 t1{helper[1] * n[2] - helper[2] * n[1], helper[2] * n[0] - helper[0] * n[2],
            helper[0] * n[1] - helper[1] * n[0]};
    const double length = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
    for (double& x : t1) x /= length;
    const vec3 t2{n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2],
                  n[0] * t1[1] - n[1] * t1[0]};
    return {t1, t2, n};
  }

  const mjModel* model_;
  std::vector<coupled_pair> pairs_;
  std::vector<double> jacobian_a_, jacobian_b_, solved_, generalized_;
};

}  // namespace mujoco
}  // namespace spinslide

#endif  // SPINSLIDE_ENGINES_MUJOCO_HPP
