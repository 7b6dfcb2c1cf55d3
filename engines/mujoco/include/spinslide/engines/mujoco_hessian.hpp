//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)

/// \file mujoco_hessian.hpp
/// The Hessian of MuJoCo's constraint solve and the joint inverse mass it
/// gives the coupled pairs (mujoco.hpp; docs/engines.md, "How it works"):
/// H = M + Σ D_r J_rᵀJ_r over the rows of MuJoCo's last solve that resist
/// motion, factorized, and W = J H⁻¹ Jᵀ over the pairs' rows, so that W
/// sees how MuJoCo's other constraints respond to friction.  Needs MuJoCo.
///
/// Where every such row moves the joints of one chain of the kinematic
/// tree only (a body against the world or a fixed body, a joint's limit:
/// its nonzero columns are one degree of freedom and some of its
/// ancestors), H has the sparsity of M itself, and it is kept in MuJoCo's
/// sparse layout of M (`dof_Madr`: row i holds H(i, i), then H(i, j) for j
/// = i's parent, grandparent, … up to the root) and factorized without fill
/// as H = LᵀDL, eliminating from the leaves (Featherstone's LTDL for
/// branch-induced sparsity, R. Featherstone, "Efficient factorization of
/// the joint-space inertia matrix for branched kinematic trees", IJRR 24,
/// 2005): each degree of freedom costs its depth squared, not nv².  A row
/// between two chains (two bodies of the tree in contact, an equality
/// between branches) would fill H in: then H is dense and factorized by
/// `mju_cholFactor`, as before.
#ifndef SPINSLIDE_ENGINES_MUJOCO_HESSIAN_HPP
#define SPINSLIDE_ENGINES_MUJOCO_HESSIAN_HPP

#include <mujoco/mujoco.h>
#include <spinslide/contact/joint_pairs.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace spinslide {
namespace mujoco {

/// H of one model's constraint solve, and W from it (see the file's
/// comment).  Keeps its workspace from one step to the next.
class constraint_hessian {
 public:
  /// For `model` (not null; checked by coupled_friction), which must outlive it.
  explicit constraint_hessian(const mjModel* model)
      : model_(model),
        row_(static_cast<std::size_t>(model->nv), 0.0),
        mark_(static_cast<std::size_t>(model->nv), 0) {}

  /// H = M + Σ D_r J_rᵀJ_r over the resisting rows of `data`'s last
  /// constraint solve, factorized: in M's sparse layout where every such
  /// row lies on one chain of the tree, else dense (see the file's comment).
  void factor(const mjData* data) {
    tree_ = factor_tree(data);
    if (!tree_) factor_dense(data);
  }

  /// True if the last factor() kept H in M's sparse layout (every resisting
  /// row on one chain of the tree), false if H was dense.
  bool tree() const { return tree_; }

  /// x = H⁻¹ b (nv entries each), after factor().
  void solve(double* x, const double* b) const {
    if (!tree_) return mju_cholSolve(x, hessian_.data(), b, model_->nv);
    const auto nv = static_cast<std::size_t>(model_->nv);
    std::copy(b, b + nv, x);
    transposed_solve(x);
    for (std::size_t i = 0; i < nv; ++i) x[i] *= root_inverse_[i] * root_inverse_[i];
    lower_solve(x);
  }

  /// W = J H⁻¹ Jᵀ into `w`, J the pairs' rows: `rows[k]` points to pair k's
  /// three rows (t1, t2, spin; nv entries each, row after row); after
  /// factor().  With H = LᵀDL, W = YᵀY for Y = D^(−1/2) L⁻ᵀJᵀ: half a solve
  /// per row.
  void inverse_mass(const std::vector<const double*>& rows, pair_coupling& w) {
    const auto nv = static_cast<std::size_t>(model_->nv);
    const std::size_t n = rows.size();
    w.reset(n);
    solved_.assign(3 * n * nv, 0.0);
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t row = 0; row < 3; ++row) {
        double* y = solved_.data() + (3 * k + row) * nv;
        const double* from = rows[k] + row * nv;
        if (!tree_) {
          solve(y, from);
          continue;
        }
        std::copy(from, from + nv, y);
        transposed_solve(y);
        for (std::size_t i = 0; i < nv; ++i) y[i] *= root_inverse_[i];
      }
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        w.at(i, j) = block(tree_ ? &solved_[3 * i * nv] : rows[i], j);
  }

 private:
  // H in M's sparse layout, factorized as LᵀDL (LTDL: from the leaves to the
  // root, each row i's entries below i's, about its ancestors, updated by
  // the rows of its descendants); false, with nothing kept, where a
  // resisting row spans two chains.
  bool factor_tree(const mjData* data) {
    const int nv = model_->nv;
    const int* parent = model_->dof_parentid;
    const int* address = model_->dof_Madr;
    tree_hessian_.assign(data->qM, data->qM + model_->nM);
    for (int r = 0; r < data->nefc; ++r) {
      if (!resisting(data, r)) continue;
      constraint_row(data, r);
      if (!on_one_chain()) return false;
      const double d = data->efc_D[r];
      for (const std::size_t i : nonzero_) {
        const double di = d * row_[i];
        int at = address[i];
        for (int j = static_cast<int>(i); j >= 0; j = parent[j])
          tree_hessian_[static_cast<std::size_t>(at++)] += di * row_[static_cast<std::size_t>(j)];
      }
    }
    double* h = tree_hessian_.data();
    for (int k = nv - 1; k >= 0; --k) {
      double& dk = h[address[k]];
      if (!(dk >= mjMINVAL)) dk = mjMINVAL;  // as mju_cholFactor's smallest diagonal
      int ki = address[k] + 1;
      for (int i = parent[k]; i >= 0; i = parent[i], ++ki) {
        const double lki = h[ki] / dk;  // L(k, i)
        // H(i, j) −= L(k, i) H(k, j) for j = i and its ancestors: k's
        // entries from ki on are i's row, entry for entry.
        int kj = ki, ij = address[i];
        for (int j = i; j >= 0; j = parent[j]) h[ij++] -= lki * h[kj++];
        h[ki] = lki;
      }
    }
    root_inverse_.resize(static_cast<std::size_t>(nv));
    for (int k = 0; k < nv; ++k)
      root_inverse_[static_cast<std::size_t>(k)] = 1 / std::sqrt(h[address[k]]);
    return true;
  }

  void factor_dense(const mjData* data) {
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

  // True if row_'s nonzero columns are one degree of freedom and some of
  // its ancestors: all on the chain from the last of them to the root.
  bool on_one_chain() {
    if (nonzero_.empty()) return true;
    ++stamp_;
    const int* parent = model_->dof_parentid;
    const std::size_t last = *std::max_element(nonzero_.begin(), nonzero_.end());
    for (int j = static_cast<int>(last); j >= 0; j = parent[j])
      mark_[static_cast<std::size_t>(j)] = stamp_;
    return std::all_of(nonzero_.begin(), nonzero_.end(),
                       [&](std::size_t c) { return mark_[c] == stamp_; });
  }

  // x ← L⁻ᵀx: x_i −= L(k, i) x_k for each ancestor i of k, from the leaves.
  void transposed_solve(double* x) const {
    const int* parent = model_->dof_parentid;
    const int* address = model_->dof_Madr;
    const double* h = tree_hessian_.data();
    for (int k = model_->nv - 1; k >= 0; --k) {
      const double xk = x[k];
      if (xk == 0) continue;
      int ki = address[k] + 1;
      for (int i = parent[k]; i >= 0; i = parent[i]) x[i] -= h[ki++] * xk;
    }
  }

  // x ← L⁻¹x: x_k −= Σ L(k, i) x_i over the ancestors i of k, from the root.
  void lower_solve(double* x) const {
    const int* parent = model_->dof_parentid;
    const int* address = model_->dof_Madr;
    const double* h = tree_hessian_.data();
    for (int k = 0; k < model_->nv; ++k) {
      int ki = address[k] + 1;
      double sum = 0;
      for (int i = parent[k]; i >= 0; i = parent[i]) sum += h[ki++] * x[i];
      x[k] -= sum;
    }
  }

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

  // W_ij = J_i (H⁻¹ J_jᵀ) from the solved columns (dense H: `rows` are
  // pair i's rows), or Y_iᵀY_j (tree: `rows` are pair i's solved rows).
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
  // The tree's form: H in M's layout, then L (below the diagonals) and D;
  // D^(−1/2); the chain test's marks.
  std::vector<double> tree_hessian_, root_inverse_;
  std::vector<std::uint64_t> mark_;
  std::uint64_t stamp_ = 0;  // one per chain test: never wraps in a run
  bool tree_ = false;
};

}  // namespace mujoco
}  // namespace spinslide

#endif  // SPINSLIDE_ENGINES_MUJOCO_HESSIAN_HPP
