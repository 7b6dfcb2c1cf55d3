//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)

/// \file mujoco_hessian.hpp
/// The Hessian of MuJoCo's constraint solve and the joint inverse mass it
/// gives the coupled pairs (mujoco.hpp; docs/engines.md, "How it works"):
/// H = M + Σ D_r J_rᵀJ_r over the rows of MuJoCo's last solve that resist
/// motion, factorized, and W = J H⁻¹ Jᵀ over the pairs' rows, so that W
/// sees how MuJoCo's other constraints respond to friction.  Needs MuJoCo.
#ifndef SPINSLIDE_ENGINES_MUJOCO_HESSIAN_HPP
#define SPINSLIDE_ENGINES_MUJOCO_HESSIAN_HPP

#include <mujoco/mujoco.h>
#include <spinslide/contact/joint_pairs.hpp>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace spinslide {
namespace mujoco {

/// H of one model's constraint solve, and W from it (see the file's
/// comment).  Keeps its workspace from one step to the next.
class constraint_hessian {
 public:
  /// For `model` (not null; checked by coupled_friction), which must outlive it.
  explicit constraint_hessian(const mjModel* model)
      : model_(model), row_(static_cast<std::size_t>(model->nv), 0.0) {}

  /// H = M + Σ D_r J_rᵀJ_r over the resisting rows of `data`'s last
  /// constraint solve, factorized.
  void factor(const mjData* data) {
    const auto nv = static_cast<std::size_t>(model_->nv);
    hessian_.assign(nv * nv, 0.0);
    mj_fullM(model_, hessian_.data(), data->qM);
    for (int r = 0; r < data->nefc; ++r) {
      if (!resisting(data, r)) continue;
      constraint_row(data, r);
      const double d = data->efc_D[r];
      for (const std::size_t i : nonzero_)
        for (const std::size_t j : nonzero_) hessian_[i * nv + j] += d * row_[i] * row_[j];
    }
    mju_cholFactor(hessian_.data(), model_->nv, mjMINVAL);
  }

  /// x = H⁻¹ b (nv entries each), after factor().
  void solve(double* x, const double* b) const { mju_cholSolve(x, hessian_.data(), b, model_->nv); }

  /// W = J H⁻¹ Jᵀ into `w`, J the pairs' rows: `rows[k]` points to pair k's
  /// three rows (t1, t2, spin; nv entries each, row after row); after
  /// factor().
  void inverse_mass(const std::vector<const double*>& rows, pair_coupling& w) {
    const auto nv = static_cast<std::size_t>(model_->nv);
    const std::size_t n = rows.size();
    w.reset(n);
    solved_.assign(3 * n * nv, 0.0);
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t row = 0; row < 3; ++row)
        solve(solved_.data() + (3 * k + row) * nv, rows[k] + row * nv);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) w.at(i, j) = block(rows[i], j);
  }

 private:
  // True for a constraint row of MuJoCo's last solve that resists motion:
  // in its quadratic zone (or in an elliptic cone, taken as quadratic), or,
  // after a dual solver (whose states are not kept), carrying a force.
  bool resisting(const mjData* data, int row) const {
    if (mj_isDual(model_)) return data->efc_force[row] != 0;
    const int state = data->efc_state[row];
    return state == mjCNSTRSTATE_QUADRATIC || state == mjCNSTRSTATE_CONE;
  }

  // Row r of MuJoCo's constraint Jacobian, dense, into row_, and the
  // indices of its nonzero entries into nonzero_ (a contact's row touches
  // only the joints between its body and the root: H's update is
  // nonzero² terms, not nv²).
  void constraint_row(const mjData* data, int r) {
    const auto nv = static_cast<std::size_t>(model_->nv);
    std::fill(row_.begin(), row_.end(), 0.0);
    nonzero_.clear();
    if (mj_isSparse(model_)) {
      const int start = data->efc_J_rowadr[r];
      for (int k = 0; k < data->efc_J_rownnz[r]; ++k) {
        const auto column = static_cast<std::size_t>(data->efc_J_colind[start + k]);
        row_[column] = data->efc_J[start + k];
        if (row_[column] != 0) nonzero_.push_back(column);
      }
    } else {
      const mjtNum* from = data->efc_J + static_cast<std::size_t>(r) * nv;
      for (std::size_t i = 0; i < nv; ++i) {
        row_[i] = from[i];
        if (from[i] != 0) nonzero_.push_back(i);
      }
    }
  }

  // W_ij = J_i (H⁻¹ J_jᵀ), from the solved columns.
  pair_coupling::block block(const double* rows, std::size_t j) const {
    const auto nv = static_cast<std::size_t>(model_->nv);
    pair_coupling::block out{};
    for (std::size_t a = 0; a < 3; ++a)
      for (std::size_t b = 0; b < 3; ++b) {
        double sum = 0;
        for (std::size_t q = 0; q < nv; ++q)
          sum += rows[a * nv + q] * solved_[(3 * j + b) * nv + q];
        out[a][b] = sum;
      }
    return out;
  }

  const mjModel* model_;
  std::vector<double> hessian_, solved_, row_;
  std::vector<std::size_t> nonzero_;  // the nonzero columns of row_
};

}  // namespace mujoco
}  // namespace spinslide

#endif  // SPINSLIDE_ENGINES_MUJOCO_HESSIAN_HPP
