//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)

/// \file anderson_mixing.hpp
/// Anderson mixing of a fixed-point map's last iterates, for the joint
/// solve's Gauss–Seidel sweeps (joint_pairs.hpp): given the last few x_k
/// and g_k = G(x_k), the mixed point is g_k − Σ_a γ_a (g_{a+1} − g_a), γ the
/// least-squares fit of the residual f_k = g_k − x_k by the residuals'
/// differences f_{a+1} − f_a (Walker & Ni, SIAM J. Numer. Anal. 49 (2011)
/// 1715, §2, the form with differences and no damping).  The residuals are
/// measured in each block's own metric, the norm the sweeps' energy uses.
/// The mixed point need not be feasible nor better: the caller projects and
/// safeguards it.
#ifndef SPINSLIDE_CONTACT_DETAIL_ANDERSON_MIXING_HPP
#define SPINSLIDE_CONTACT_DETAIL_ANDERSON_MIXING_HPP

#include <spinslide/contact/detail/matrix3.hpp>
#include <spinslide/contact/detail/vector3.hpp>
#include <spinslide/contact/planar_metric.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace spinslide {
namespace detail {

/// The last `depth + 1` iterates of a map over n blocks of 3, and their
/// mixture.  Keeps its storage: no allocation once it has seen the largest n.
class anderson_mixing {
 public:
  /// At most this many differences mix: measured on the rigidly coupled
  /// pairs (tests/test_joint_pairs.cpp), 3 gives 16 sweeps at the 99th
  /// percentile and 21 at worst, 5 gives 19 and 24, 2 gives 17 and 25 (a
  /// map this nonsmooth is described by few recent iterates).
  static constexpr std::size_t depth = 3;
  static_assert(depth == 3, "the fit's normal equations are solved as matrix3.hpp's 3x3 system");

  /// Forgets the history and sizes it for `blocks` blocks.
  void restart(std::size_t blocks) {
    blocks_ = blocks;
    count_ = 0;
    if (g_.size() < slots * blocks) {
      g_.resize(slots * blocks);
      f_.resize(slots * blocks);
    }
  }

  /// Forgets the history (the safeguard refused the last mixture).
  void forget() { count_ = 0; }

  /// Adds g = G(x) and its residual g − x.
  void push(const std::vector<vector3<double>>& x, const std::vector<vector3<double>>& g) {
    newest_ = (newest_ + 1) % slots;
    for (std::size_t i = 0; i < blocks_; ++i)
      for (std::size_t k = 0; k < 3; ++k) {
        at(g_, newest_, i)[k] = g[i][k];
        at(f_, newest_, i)[k] = g[i][k] - x[i][k];
      }
    if (count_ < slots) ++count_;
  }

  /// The mixture into `y`; false (y untouched) with fewer than two iterates
  /// or least squares too ill-conditioned to trust.
  bool mix(const std::vector<planar_metric<double>>& metric, std::vector<vector3<double>>& y) {
    if (count_ < 2) return false;
    const std::size_t m = count_ - 1;
    matrix3<double> h{};  // the fit's normal equations (depth = 3 differences at most)
    vector3<double> b{};
    for (std::size_t a = 0; a < m; ++a) {
      b[a] = against_newest(metric, slot(a));
      for (std::size_t c = 0; c <= a; ++c) h[a][c] = h[c][a] = inner(metric, slot(a), slot(c));
    }
    if (!solve(h, b, m)) return false;
    for (std::size_t i = 0; i < blocks_; ++i)
      for (std::size_t k = 0; k < 3; ++k) {
        double v = at(g_, newest_, i)[k];
        for (std::size_t a = 0; a < m; ++a)
          v -= b[a] * (at(g_, next(slot(a)), i)[k] - at(g_, slot(a), i)[k]);
        if (!std::isfinite(v)) return false;
        y[i][k] = v;
      }
    return true;
  }

 private:
  static constexpr std::size_t slots = depth + 1;

  vector3<double>& at(std::vector<vector3<double>>& v, std::size_t s, std::size_t i) {
    return v[s * blocks_ + i];
  }
  const vector3<double>& at(const std::vector<vector3<double>>& v, std::size_t s,
                            std::size_t i) const {
    return v[s * blocks_ + i];
  }
  // The a-th oldest slot (a < count_), and the one after a slot.
  std::size_t slot(std::size_t a) const { return (newest_ + slots + 1 - count_ + a) % slots; }
  static std::size_t next(std::size_t s) { return (s + 1) % slots; }

  // ⟨Δf_a, Δf_c⟩ (slots a, c; Δf at a slot: its successor's f minus its
  // own), and ⟨Δf_a, f_k⟩: Σ_i uᵢᵀ Mᵢ vᵢ.
  double inner(const std::vector<planar_metric<double>>& metric, std::size_t a,
               std::size_t c) const {
    double sum = 0;
    for (std::size_t i = 0; i < blocks_; ++i)
      sum += dot(difference(a, i), multiply(metric[i].entries(), difference(c, i)));
    return sum;
  }
  double against_newest(const std::vector<planar_metric<double>>& metric, std::size_t a) const {
    double sum = 0;
    for (std::size_t i = 0; i < blocks_; ++i)
      sum += dot(difference(a, i), multiply(metric[i].entries(), at(f_, newest_, i)));
    return sum;
  }
  vector3<double> difference(std::size_t s, std::size_t i) const {
    const auto& later = at(f_, next(s), i);
    const auto& earlier = at(f_, s, i);
    return {later[0] - earlier[0], later[1] - earlier[1], later[2] - earlier[2]};
  }

  // h γ = b by Cholesky (matrix3.hpp's, the m fitted rows padded with the
  // identity, b 0 there), h shifted by 1e-12 of its trace: the residuals'
  // differences become nearly dependent as the sweeps converge, and a
  // mixture fitted to rounding would only be refused by the safeguard; a
  // pivot below 1e-14 of the trace is not trusted.
  static bool solve(matrix3<double>& h, vector3<double>& b, std::size_t m) {
    double trace = 0;
    for (std::size_t a = 0; a < m; ++a) trace += h[a][a];
    if (!(trace > 0) || !std::isfinite(trace)) return false;
    for (std::size_t a = 0; a < m; ++a) h[a][a] += 1e-12 * trace;
    for (std::size_t a = m; a < depth; ++a) h[a][a] = 1;
    matrix3<double> l{};
    if (!cholesky(h, l)) return false;
    for (std::size_t a = 0; a < m; ++a)
      if (!(l[a][a] * l[a][a] > 1e-14 * trace)) return false;
    b = cholesky_solve(l, b);
    return true;
  }

  std::size_t blocks_ = 0, count_ = 0, newest_ = 0;
  std::vector<vector3<double>> g_, f_;  // slot s, block i at s·n + i
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_DETAIL_ANDERSON_MIXING_HPP
