//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)

/// \file mujoco.hpp
/// spinslide's coupled friction inside MuJoCo (2.2 and later; docs/engines.md).
///
///     spinslide::mujoco::coupled_friction friction(model);
///     friction.couple(spinslide::mujoco::geom_name{"disk"}, spinslide::mujoco::geom_name{"floor"},
///                     spinslide::pair_friction(spinslide::uniform_disk<>(),
///                                              spinslide::patch_radius<double>{0.06},
///                                              spinslide::friction_coefficient<double>{0.2}));
///     for (...) friction.step(data);  // instead of mj_step(model, data)
///
/// A pair coupled with pair_friction(spinslide::own_patch{}, μ) takes the
/// contact's own patch instead of a round one: in every step the convex
/// hull of MuJoCo's contact points of the pair, under the linear
/// (no-tension) pressure of their normal forces (contact_patch.hpp; a box
/// on its face, its edge or its corner makes an area, a line or a point).
///
/// The coupled geoms' contacts must be frictionless (condim="1"): MuJoCo
/// solves their normal forces, and spinslide their friction.  Each step is
/// mj_step1; the forward dynamics up to the constraint forces, which gives
/// this step's normal forces (no lag) and the velocity each pair would have
/// at the end of the step without friction; then all coupled pairs'
/// friction impulses together (joint_pairs.hpp: block Gauss–Seidel, each
/// block the velocity-level law of impulse_friction.hpp, exact stick or
/// slip on the coupled limit set), in their joint inverse mass W = J H⁻¹ Jᵀ,
/// where H = M + J_cᵀ D J_c adds to the mass matrix the stiffness of
/// MuJoCo's active constraints (its soft contacts, joints and limits: the
/// Hessian of its constraint solve), so that W sees how the other
/// constraints respond to friction (a friction force below the centre of
/// mass tilts the body against its normal contacts; two feet on one body
/// push on each other through it).  The impulses, divided by the step, are
/// added to qfrc_applied for mj_step2 and removed after it.  As MuJoCo's
/// constraints are not linear (a contact may lift off), they are solved
/// again with the friction applied, and the pairs again from the motion
/// that solve leaves, until every sticking pair ends the step at rest to
/// 1e-9 of its own scale (at most three such passes; none is typical).
/// Needs the Euler or implicit integrator (mj_step1/mj_step2 do not split
/// RK4).
#ifndef SPINSLIDE_ENGINES_MUJOCO_HPP
#define SPINSLIDE_ENGINES_MUJOCO_HPP

#include <mujoco/mujoco.h>
#include <spinslide/base/detail/checks.hpp>
#include <spinslide/contact/contact_patch.hpp>
#include <spinslide/contact/detail/vector3.hpp>
#include <spinslide/contact/joint_pairs.hpp>
#include <spinslide/contact/pair_friction.hpp>
#include <spinslide/contact/pair_report.hpp>
#include <spinslide/engines/mujoco_hessian.hpp>

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

/// What happened at one coupled pair in the last step, geom a as its first
/// body: the report every adapter gives (pair_report.hpp).
using pair_report = spinslide::pair_report;

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
    generalized_.assign(nv, 0.0);
  }

  /// Couples geoms `a` and `b` with `friction`; returns the pair's index for
  /// report().  Both geoms must be frictionless (condim 1) and distinct;
  /// otherwise std::invalid_argument.  A pair already coupled (in either
  /// order) keeps its index and takes the new friction.
  std::size_t couple(geom_id a, geom_id b, const spinslide::pair_friction<double>& friction) {
    static const char* function = "spinslide::mujoco::coupled_friction::couple";
    const int ngeom = model_->ngeom;
    if (a.value < 0 || a.value >= ngeom || b.value < 0 || b.value >= ngeom || a.value == b.value)
      detail::refuse(function, "geom ids " + std::to_string(a.value) + " and " +
                                   std::to_string(b.value) + "; two distinct ids in [0, " +
                                   std::to_string(ngeom) + ") are needed");
    for (const int g : {a.value, b.value}) {
      if (model_->geom_condim[g] != 1)
        detail::refuse(function, "geom " + std::to_string(g) + " has condim " +
                                     std::to_string(model_->geom_condim[g]) +
                                     "; coupled geoms must be frictionless (condim=\"1\"), so "
                                     "that MuJoCo adds no friction of its own");
    }
    // A pair coupled again (in either order) gets the new friction: one rule
    // with the Bullet adapter (a first version added it twice, doubling it).
    for (std::size_t i = 0; i < pairs_.size(); ++i) {
      const coupled_pair& p = pairs_[i];
      if ((p.a == a.value && p.b == b.value) || (p.a == b.value && p.b == a.value)) {
        pairs_[i].friction = friction;
        return i;
      }
    }
    coupled_pair pair{a.value, b.value, friction};
    pair.rows.assign(3 * static_cast<std::size_t>(model_->nv), 0.0);
    pairs_.push_back(std::move(pair));
    return pairs_.size() - 1;
  }

  /// couple() by the geoms' names; an unknown name is std::invalid_argument.
  std::size_t couple(const geom_name& a, const geom_name& b,
                     const spinslide::pair_friction<double>& friction) {
    return couple(lookup(a), lookup(b), friction);
  }

  /// One time step of `data` (made for the model) with the coupled pairs'
  /// friction: use it instead of mj_step.  qfrc_applied is left as it was.
  void step(mjData* data) {
    detail::required("spinslide::mujoco::coupled_friction::step", "data", data);
    mj_step1(model_, data);
    mj_fwdActuation(model_, data);
    mj_fwdAcceleration(model_, data);
    mj_fwdConstraint(model_, data);
    active_.clear();
    for (std::size_t i = 0; i < pairs_.size(); ++i)
      if (prepare(pairs_[i], data)) active_.push_back(i);
    couple_active(data);
    impulses();
    if (linear_update(data)) {  // mj_step2 without its constraint solve
      finish_euler(data);
      return;
    }
    for (int pass = 0; pass < max_corrections; ++pass) {
      if (settled(data)) {
        // settled() has just solved MuJoCo's constraints with this friction:
        // what mj_step2 would solve again.
        if (model_->opt.integrator == mjINT_EULER) {
          finish_euler(data);
          return;
        }
        break;
      }
      impulses();
    }
    add_to(data->qfrc_applied, 1.0);
    mj_step2(model_, data);
    add_to(data->qfrc_applied, -1.0);
  }

  /// The last step at pair `index` (as couple() returned it), its geom a
  /// as the first body; an index beyond the pairs coupled is
  /// std::out_of_range, naming both.
  const pair_report& report(std::size_t index) const {
    return pairs_[detail::checked_index("spinslide::mujoco::coupled_friction::report", "pair",
                                        index, pairs_.size())]
        .report;
  }

  /// How the last step's joint solve of the pairs went (its last pass):
  /// sweeps made, and whether they converged.
  const joint_outcome& last_solve() const { return last_solve_; }

  /// The generalized friction force of the last step (nv entries): the
  /// impulses divided by the time step.
  const std::vector<double>& generalized_force() const { return generalized_; }

 private:
  using vec3 = detail::vector3<double>;  // the library's 3-vector
  struct coupled_pair {
    coupled_pair(int first, int second, const spinslide::pair_friction<double>& f)
        : a(first), b(second), friction(f) {}
    int a, b;
    spinslide::pair_friction<double> friction;
    pair_report report{};
    bool active = false;         // in contact this step
    std::array<vec3, 3> axes{};  // t1, t2, n
    std::vector<double> rows;    // 3×nv: t1, t2 and spin rows of the relative motion
    vec3 free_motion{};          // the relative motion at the step's end without friction
    vec3 impulse{};              // (P_x, P_y, L) on geom a's body
    // An own_patch pair's points this step (world position, normal force)
    // and the patch they make, about the centre in the axes.
    std::vector<std::array<double, 4>> points;
    std::vector<contact_point<double>> plane_points;
    polygon_patch<double> patch = polygon_patch<double>::point({0, 0});
  };
  static constexpr int max_corrections = 3;

  static const mjModel* require_model(const mjModel* model) {
    static const char* function = "spinslide::mujoco::coupled_friction::coupled_friction";
    detail::required(function, "the model", model);
    if (model->opt.integrator == mjINT_RK4)
      detail::refuse(function,
                     "the RK4 integrator does not split into mj_step1/mj_step2; use Euler or "
                     "implicit");
    return model;
  }

  geom_id lookup(const geom_name& name) const {
    const int id = mj_name2id(model_, mjOBJ_GEOM, name.value.c_str());
    if (id < 0)
      detail::refuse("spinslide::mujoco::coupled_friction::couple",
                     "no geom named '" + name.value + "'");
    return geom_id{id};
  }

  // Sums the pair's contacts: Λ = N h, the N-weighted centre, the deepest
  // penetration and the normal from geom a to geom b (not yet of unit
  // length).
  void gather(coupled_pair& pair, const mjData* data) const {
    pair_report& r = pair.report;
    r = pair_report{};
    r.step = model_->opt.timestep;
    pair.points.clear();
    double force = 0;
    for (int i = 0; i < data->ncon; ++i) {
      const mjContact& c = data->contact[i];
      const bool forward = c.geom1 == pair.a && c.geom2 == pair.b;
      if (!forward && !(c.geom1 == pair.b && c.geom2 == pair.a)) continue;
      if (c.efc_address < 0) continue;
      if (c.dim != 1)
        detail::refuse("spinslide::mujoco::coupled_friction::step",
                       "a coupled pair has a contact with friction (an explicit <pair> with "
                       "condim " +
                           std::to_string(c.dim) + "?)");
      std::array<mjtNum, 6> f{};
      mj_contactForce(model_, data, i, f.data());
      const double sign = forward ? 1.0 : -1.0;
      ++r.contacts;
      if (pair.friction.uses_own_patch())
        pair.points.push_back({c.pos[0], c.pos[1], c.pos[2], f[0]});
      force += f[0];
      for (std::size_t k = 0; k < 3; ++k) {
        r.centre[k] += f[0] * c.pos[k];
        r.normal[k] += sign * c.frame[k];
      }
      r.penetration = std::fmax(r.penetration, -c.dist);
    }
    if (force > 0)
      for (double& x : r.centre) x /= force;
    r.normal_impulse = force * r.step;
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

  // This step's contacts, Jacobian rows and the relative motion at the end
  // of the step without friction; false if the pair is not in contact.
  bool prepare(coupled_pair& pair, mjData* data) {
    gather(pair, data);
    pair_report& r = pair.report;
    const double n_length = std::sqrt(r.normal[0] * r.normal[0] + r.normal[1] * r.normal[1] +
                                      r.normal[2] * r.normal[2]);
    pair.active = r.normal_impulse > 0 && n_length > 0;
    if (!pair.active) {
      pair.friction.forget();
      pair.impulse = {0, 0, 0};
      return false;
    }
    for (double& x : r.normal) x /= n_length;
    pair.axes = tangent_axes(r.normal);
    relative_rows(pair, pair.axes, data);
    pair.free_motion = end_of_step_motion(pair, data);
    r.patch_radius = pair.friction.radius(r.penetration);
    if (pair.friction.uses_own_patch()) {
      build_patch(pair);
      r.patch_radius = pair.patch.radius();
    }
    return true;
  }

  // An own_patch pair's patch from its points, in its tangent axes about
  // the centre (the force-weighted mean: the centre of pressure is the
  // origin).  contact_patch never throws.
  static void build_patch(coupled_pair& pair) {
    pair.plane_points.clear();
    const auto& centre = pair.report.centre;
    for (const auto& q : pair.points) {
      const vec3 d{q[0] - centre[0], q[1] - centre[1], q[2] - centre[2]};
      pair.plane_points.push_back(
          {{detail::dot(d, pair.axes[0]), detail::dot(d, pair.axes[1])}, q[3]});
    }
    pair.patch = contact_patch(pair.plane_points);
  }

  // The active pairs' joint inverse mass W = J H⁻¹ Jᵀ (3×3 blocks), H the
  // Hessian of MuJoCo's constraint solve (mujoco_hessian.hpp).
  void couple_active(const mjData* data) {
    coupling_.reset(active_.size());
    if (active_.empty()) return;
    hessian_.factor(data);
    active_rows_.clear();
    for (const std::size_t i : active_) active_rows_.push_back(pairs_[i].rows.data());
    hessian_.inverse_mass(active_rows_, coupling_);
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

  // The active pairs' impulses from their free motions, solved together,
  // into generalized_.
  void impulses() {
    std::fill(generalized_.begin(), generalized_.end(), 0.0);
    const auto nv = static_cast<std::size_t>(model_->nv);
    const double h = model_->opt.timestep;
    joint_.clear();
    for (const std::size_t i : active_) {
      coupled_pair& pair = pairs_[i];
      // Started from the pair's last impulse (0 after a step without
      // contact): in a steady contact the sweeps then have little to do.
      joint_.push_back(joint_pair{std::ref(pair.friction), pair.free_motion,
                                  normal_impulse<double>{pair.report.normal_impulse},
                                  pair.report.penetration, pair.impulse});
      if (pair.friction.uses_own_patch()) joint_.back().patch = &pair.patch;
    }
    // Gauss–Seidel sweeps with Anderson mixing (joint_pairs.hpp; issue 41).
    // A plate that stops on several feet may rest with one foot's impulse
    // on its limit (the stop's load shared in directions that move nothing,
    // kept by the warm start), which then reports slipping at a slip of
    // rounding's size: MujocoAdapter.PlateOnSeveralFeetStopsSpinningAndStaysStopped.
    last_solve_ = solver_.solve(joint_, coupling_, {1e-10, 200, true});
    for (std::size_t k = 0; k < active_.size(); ++k) {
      coupled_pair& pair = pairs_[active_[k]];
      pair.report.sticking = joint_[k].sticking;
      pair.report.ratio = joint_[k].ratio;
      pair.impulse = joint_[k].impulse;
      for (std::size_t c = 0; c < 3; ++c)
        pair.report.friction_impulse[c] =
            pair.axes[0][c] * pair.impulse[0] + pair.axes[1][c] * pair.impulse[1];
      pair.report.spin_impulse = pair.impulse[2];
      for (std::size_t row = 0; row < 3; ++row)
        for (std::size_t j = 0; j < nv; ++j)
          generalized_[j] += pair.rows[row * nv + j] * pair.impulse[row] / h;
    }
  }

  // MuJoCo's constraint solve with the friction added, without solving: its
  // primal problem with the friction's generalized force τ has the answer
  // q̈ + H⁻¹τ wherever no constraint row changes its state (H is that
  // problem's Hessian for the rows' states).  True, with q̈, the forces and
  // the smooth force updated as MuJoCo's solve would leave them, if the
  // states stayed (checked by mj_constraintUpdate at the new q̈); false
  // (nothing to keep) for the implicit integrator, a dual solver, an
  // elliptic cone's row in its cone, or a row that changed its state.
  bool linear_update(mjData* data) {
    if (model_->opt.integrator != mjINT_EULER || mj_isDual(model_) || active_.empty()) return false;
    const int nv = model_->nv, nefc = data->nefc;
    const auto n = static_cast<std::size_t>(nv);
    states_.assign(data->efc_state, data->efc_state + nefc);
    for (const int state : states_)
      if (state == mjCNSTRSTATE_CONE) return false;
    delta_.assign(n, 0.0);
    hessian_.solve(delta_.data(), generalized_.data());
    acceleration_.assign(data->qacc, data->qacc + nv);
    for (std::size_t i = 0; i < n; ++i) acceleration_[i] += delta_[i];
    jar_.assign(static_cast<std::size_t>(nefc), 0.0);
    mj_mulJacVec(model_, data, jar_.data(), acceleration_.data());
    for (int r = 0; r < nefc; ++r) jar_[static_cast<std::size_t>(r)] -= data->efc_aref[r];
    mj_constraintUpdate(model_, data, jar_.data(), nullptr, 0);
    for (int r = 0; r < nefc; ++r)
      if (data->efc_state[r] != states_[static_cast<std::size_t>(r)]) return false;
    std::copy(acceleration_.begin(), acceleration_.end(), data->qacc);
    std::copy(acceleration_.begin(), acceleration_.end(), data->qacc_warmstart);
    mj_solveM(model_, data, delta_.data(), generalized_.data(), 1);
    for (std::size_t i = 0; i < n; ++i) {
      data->qfrc_smooth[i] += generalized_[i];
      data->qacc_smooth[i] += delta_[i];
    }
    return true;
  }

  // Solves MuJoCo's constraints with the friction applied; true if every
  // sticking pair then ends the step at rest (to 1e-9 of its free motion).
  // Otherwise each pair's free motion becomes the motion it would have
  // without any pair's friction impulse under that solve (by W), for the
  // next pass.
  bool settled(mjData* data) {
    add_to(data->qfrc_applied, 1.0);
    mj_fwdAcceleration(model_, data);
    mj_fwdConstraint(model_, data);
    add_to(data->qfrc_applied, -1.0);
    bool done = true;
    ends_.clear();
    for (const std::size_t i : active_) {
      coupled_pair& pair = pairs_[i];
      const vec3 s = end_of_step_motion(pair, data);
      const double a = pair.report.patch_radius;
      const vec3& f = pair.free_motion;
      const double slip = std::hypot(s[0], s[1], a * s[2]);
      const double scale = std::hypot(f[0], f[1], a * f[2]);
      if (pair.report.sticking && slip > 1e-9 * scale) done = false;
      ends_.push_back(s);
    }
    for (std::size_t i = 0; i < active_.size(); ++i) {
      vec3 motion = ends_[i];
      for (std::size_t j = 0; j < active_.size(); ++j) {
        const auto moved = detail::multiply(coupling_.at(i, j), pairs_[active_[j]].impulse);
        for (std::size_t k = 0; k < 3; ++k) motion[k] -= moved[k];
      }
      pairs_[active_[i]].free_motion = motion;
    }
    return done;
  }

  // The rest of mj_step2 once the accelerations are those with the
  // friction (Euler's integrator only: the implicit one needs mj_step2).
  void finish_euler(mjData* data) const {
    mj_sensorAcc(model_, data);
    mj_checkAcc(model_, data);
    mj_Euler(model_, data);
  }

  void add_to(mjtNum* qfrc, double sign) const {
    const auto nv = static_cast<std::size_t>(model_->nv);
    for (std::size_t i = 0; i < nv; ++i) qfrc[i] += sign * generalized_[i];
  }

  // A right-handed orthonormal (t1, t2, n).
  static std::array<vec3, 3> tangent_axes(const vec3& n) {
    const vec3 helper = std::fabs(n[0]) < 0.6 ? vec3{1, 0, 0} : vec3{0, 1, 0};
    vec3 t1 = detail::cross(helper, n);
    const double length = std::sqrt(detail::dot(t1, t1));
    for (double& x : t1) x /= length;
    return {t1, detail::cross(n, t1), n};
  }

  const mjModel* model_;
  std::vector<coupled_pair> pairs_;
  std::vector<double> jacobian_a_, jacobian_b_, generalized_;
  constraint_hessian hessian_{model_};
  std::vector<const double*> active_rows_;  // the active pairs' rows, for hessian_
  std::vector<double> delta_, acceleration_, jar_;
  std::vector<int> states_;
  std::vector<std::size_t> active_;  // the pairs in contact this step
  std::vector<vec3> ends_;           // their motion at the step's end (settled())
  pair_coupling coupling_{0};
  std::vector<joint_pair> joint_;
  joint_solver solver_;
  joint_outcome last_solve_;
};

}  // namespace mujoco
}  // namespace spinslide

#endif  // SPINSLIDE_ENGINES_MUJOCO_HPP
