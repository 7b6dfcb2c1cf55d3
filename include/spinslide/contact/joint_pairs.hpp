//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)

/// \file joint_pairs.hpp
/// Several coupled pairs that share bodies (a body on two or four feet, a
/// gripper's fingers, a humanoid's feet through its joints), solved
/// together: the engine-independent half of the adapters' joint solve
/// (docs/engines.md, "Many pairs on one body"; docs/theory.md §11).
///
/// Over a step the slip of pair i after the friction impulses P_j of all
/// pairs is s_i + Σ_j W_ij P_j, W_ij the 3×3 blocks of the pairs' joint
/// inverse mass (the engine's Delassus operator over the pairs' rows,
/// including its other constraints' response).  Maximum dissipation asks for
/// the P that leaves the least kinetic energy, ½ Σ_ij (P_i − z_i)ᵀ W_ij
/// (P_j − z_j) with every P_i in its own limit set: a convex problem.  Block
/// Gauss–Seidel solves it, one pair at a time, each by the exact impulse law
/// (impulse_friction.hpp) in its own W_ii against the others' latest
/// impulses: each sweep lowers the energy (block coordinate descent on a
/// convex function with closed convex blocks), and a pair that sticks in the
/// answer stops exactly with the others.
///
/// Gauss–Seidel alone is slow where pairs are rigidly coupled near a
/// stick-slip transition (it zigzags between the pairs' sets), so after
/// each sweep x → G(x) the sweeps are mixed (Anderson acceleration over
/// the last four sweeps, detail/anderson_mixing.hpp: y = G(x_k) − Σ γ_a
/// ΔG_a, γ fitting the residual G(x_k) − x_k by its last three differences
/// in the blocks' own metrics); y, each block projected onto its own limit set, replaces
/// G(x_k) only if it leaves less energy, by more than the convergence test
/// resolves.  Every iterate is therefore feasible and at most the plain
/// sweep's energy from the same point: block coordinate descent's
/// convergence stays.  A refused mixture keeps the history; three in a row
/// restart it.  The sweeps end when one has moved the slips after the step
/// by less than the tolerance (solve_jointly) of their scale, the free
/// motions' and the impulses' own motions' (s + WP is known to the rounding
/// of WP: feet that hold a body's weight against each other at rest, whose
/// free motions are about 0, converged in 2 sweeps with it and ran to 200,
/// unconverged, in a third of the steps without it), or after `max_sweeps`; the
/// answer is always a sweep's (each impulse a point of its own limit set,
/// and the outcome says whether it converged).  Measured on two pairs at
/// one point of one body with random W and slips (tests/
/// test_joint_pairs.cpp, 400 cases): a median of 9 sweeps, 16 at the 99th
/// percentile, 21 at worst, all converged (with the projections, at most 40
/// law calls per pair); plain Gauss–Seidel (`accelerate = false`) a median
/// of 27, 3 623 at the 99th percentile and 3 of 400 unconverged after 5 000.
#ifndef SPINSLIDE_CONTACT_JOINT_PAIRS_HPP
#define SPINSLIDE_CONTACT_JOINT_PAIRS_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/contact/detail/anderson_mixing.hpp>
#include <spinslide/contact/detail/matrix3.hpp>
#include <spinslide/contact/pair_friction.hpp>
#include <spinslide/contact/planar_metric.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace spinslide {

/// The joint inverse mass of n pairs: n × n blocks W_ij of 3×3, over each
/// pair's (v_x, v_y, ω) in its own tangent axes (W_ij: the change of pair i's
/// slip per unit impulse at pair j).
class pair_coupling {
 public:
  /// One 3×3 block.
  using block = detail::matrix3<double>;
  /// n pairs, every block 0.
  explicit pair_coupling(std::size_t pairs) : n_(pairs), w_(pairs * pairs) {}
  /// The number of pairs.
  std::size_t size() const { return n_; }
  /// n pairs, every block 0 (keeping the storage).
  void reset(std::size_t pairs) {
    n_ = pairs;
    w_.assign(pairs * pairs, block{});
  }
  /// W_ij (i, j < size(); otherwise std::out_of_range naming the index).
  const block& at(std::size_t i, std::size_t j) const { return w_[index(i, j)]; }
  /// W_ij, to set.
  block& at(std::size_t i, std::size_t j) { return w_[index(i, j)]; }

 private:
  std::size_t index(std::size_t i, std::size_t j) const {
    if (i >= n_ || j >= n_)
      throw std::out_of_range("spinslide::pair_coupling::at: block (" + std::to_string(i) + ", " +
                              std::to_string(j) + ") of " + std::to_string(n_) + " pairs");
    return i * n_ + j;
  }
  std::size_t n_;
  std::vector<block> w_;
};

/// One pair's part in a joint solve: what the engine knows before friction,
/// and, after solve_jointly, the pair's impulse.
struct joint_pair {
  /// The pair's settings and its kept curve point (updated by the solve).
  std::reference_wrapper<spinslide::pair_friction<double>> friction;
  /// The pair's slip (v_x, v_y, ω) at the end of the step without any of the
  /// pairs' friction (a detail::vector3<double>, the library's 3-vector).
  std::array<double, 3> free_motion{};
  /// Λ, the normal impulse of the step.
  normal_impulse<double> normal{0};
  /// δ, the penetration (for a hertz_radius).
  double penetration = 0;
  /// In: where the sweeps start (the pair's impulse of the last step, which
  /// in a steady contact is nearly the answer; or 0).  Out: (P_x, P_y, L),
  /// the friction impulse on the pair's first body.
  std::array<double, 3> impulse{};
  /// Out: the pair stops exactly.
  bool sticking = false;
  /// Out: ε after the step (NaN when sticking).
  double ratio = std::numeric_limits<double>::quiet_NaN();
  /// The pair's own patch this step (an own_patch pair; contact_patch.hpp),
  /// or null.  Not owned: it must outlive the solve.
  const polygon_patch<double>* patch = nullptr;
};

/// How far the sweeps went.
struct joint_outcome {
  int sweeps = 0;          ///< sweeps made
  bool converged = false;  ///< the last sweep changed no impulse beyond the tolerance
};

/// The sweeps' limits.
struct joint_settings {
  double tolerance = 1e-10;  ///< ends the sweeps: a sweep moves the slips by below this, relative
  int max_sweeps = 200;      ///< at most this many sweeps
  /// Mixes the last sweeps (Anderson, safeguarded; see the file's comment)
  /// where false leaves plain Gauss–Seidel.
  bool accelerate = true;
};

/// `w` made acceptable to planar_metric: symmetrized, and, where its
/// condition number (‖W‖_F‖W⁻¹‖_F) is beyond 1/√ε_mach or it is not
/// positive definite (a pair that cannot move in some direction: a body
/// locked against spin, or held by its other constraints), shifted by the
/// least multiple of ‖W‖_F·I that brings it to 1e7: the law then sees a
/// very stiff direction as such, where an exact W would not be accepted.
inline planar_metric<double> conditioned_metric(detail::matrix3<double> w) {
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < i; ++j) w[i][j] = w[j][i] = (w[i][j] + w[j][i]) / 2;
  const double size = detail::frobenius(w);
  double shift = 0;
  for (int attempt = 0; attempt < 64; ++attempt) {
    detail::matrix3<double> shifted = w, factor{};
    for (std::size_t i = 0; i < 3; ++i) shifted[i][i] += shift;
    if (detail::cholesky(shifted, factor)) {
      const auto inverse = detail::cholesky_inverse(factor);
      if (detail::frobenius(shifted) * detail::frobenius(inverse) <= 1e7)
        return planar_metric<double>(shifted);
    }
    shift = shift == 0 ? size * 1e-9 : shift * 4;
  }
  return planar_metric<double>(
      detail::matrix3<double>{{{size, 0, 0}, {0, size, 0}, {0, 0, size}}});  // w was not finite
}

/// The pairs' friction impulses, solved together by block Gauss–Seidel (see
/// the file's comment), keeping its workspace from one step to the next (no
/// allocation once it has seen the largest number of pairs).
class joint_solver {
 public:
  /// Solves `pairs` in their joint inverse mass `w`, of `pairs.size()`
  /// pairs (otherwise std::invalid_argument).  The sweeps end when one moves
  /// the pairs' slips after the step by no more than `tolerance` of their
  /// scale, Σ sᵢᵀWᵢᵢ⁻¹sᵢ + PᵢᵀWᵢᵢPᵢ (the free motions' and the impulses' own,
  /// in each pair's energy norm): the motion has converged,
  /// though impulses may still drift in directions that do not move
  /// anything (how a statically indeterminate load is shared between pairs
  /// that stick, which Gauss–Seidel settles slowly and the motion does not
  /// see).  Never throws for numerical reasons: each pair's law answers for
  /// every input its checks accept.
  joint_outcome solve(std::vector<joint_pair>& pairs, const pair_coupling& w,
                      const joint_settings& settings = {}) {
    const std::size_t n = pairs.size();
    if (w.size() != n)
      detail::refuse("spinslide::joint_solver::solve", "a coupling of " + std::to_string(w.size()) +
                                                           " pairs for " + std::to_string(n) +
                                                           " pairs");
    own_.clear();
    slip_.clear();
    double scale = 0;  // Σ sᵢᵀWᵢᵢ⁻¹sᵢ: twice the free motions' energy, pair by pair
    for (std::size_t i = 0; i < n; ++i) {
      own_.push_back(conditioned_metric(w.at(i, i)));
      const auto z = detail::multiply(own_.back().inverse(), pairs[i].free_motion);
      scale += detail::dot(z, pairs[i].free_motion);
      slip_.push_back(pairs[i].free_motion);  // s_i + Σ_j W_ij P_j: the slip after the step
    }
    joint_outcome out;
    if (n == 1) {  // one block: its projection is the exact answer, no sweep to check it
      pairs[0].impulse = {0, 0, 0};
      update(pairs, w, 0);
      return {1, true};
    }
    for (std::size_t i = 0; i < n; ++i)  // the slips after the starting impulses
      for (std::size_t j = 0; j < n; ++j) {
        const auto moved = detail::multiply(w.at(i, j), pairs[j].impulse);
        for (std::size_t k = 0; k < 3; ++k) slip_[i][k] += moved[k];
      }
    mixing_.restart(n);
    refused_ = 0;
    for (out.sweeps = 1; out.sweeps <= settings.max_sweeps; ++out.sweeps) {
      before_ = slip_;
      keep(pairs, start_);
      for (std::size_t i = 0; i < n; ++i) update(pairs, w, i);
      const double resolved = settings.tolerance * settings.tolerance * (scale + held(pairs));
      if (!(moved() > resolved)) {
        out.converged = true;
        break;
      }
      if (settings.accelerate && out.sweeps < settings.max_sweeps) accelerate(pairs, w, resolved);
    }
    if (out.sweeps > settings.max_sweeps) out.sweeps = settings.max_sweeps;
    return out;
  }

 private:
  // Pair i by its law against the others' impulses, and every slip after it.
  void update(std::vector<joint_pair>& pairs, const pair_coupling& w, std::size_t i) {
    joint_pair& p = pairs[i];
    const auto mine = detail::multiply(w.at(i, i), p.impulse);
    const detail::vector3<double> s{slip_[i][0] - mine[0], slip_[i][1] - mine[1],
                                    slip_[i][2] - mine[2]};
    const auto r =
        p.friction.get().impulse({s[0], s[1]}, s[2], own_[i], p.normal, p.penetration, p.patch);
    const detail::vector3<double> step{r.force[0] - p.impulse[0], r.force[1] - p.impulse[1],
                                       r.torque - p.impulse[2]};
    for (std::size_t j = 0; j < pairs.size(); ++j) {
      const auto moved = detail::multiply(w.at(j, i), step);
      for (std::size_t k = 0; k < 3; ++k) slip_[j][k] += moved[k];
    }
    p.impulse = {r.force[0], r.force[1], r.torque};
    p.sticking = r.sticking;
    p.ratio = r.ratio;
  }

  // The impulses into `to`.
  static void keep(const std::vector<joint_pair>& pairs, std::vector<detail::vector3<double>>& to) {
    to.resize(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i) to[i] = pairs[i].impulse;
  }

  // After a sweep from start_ to the pairs' impulses: the Anderson mixture
  // of the last sweeps (detail/anderson_mixing.hpp), each block projected
  // onto its own limit set in its own metric (the law asked for the slip
  // −Wᵢᵢy, whose answer is that projection), replaces the sweep's impulses
  // only where it leaves less energy.  So every iterate is feasible and at
  // most the plain sweep's energy from the same point: the descent, and the
  // convergence, of block coordinate descent stay.  The gain must exceed
  // `least_gain` (what the convergence test resolves): a gain of rounding
  // size says nothing, and where pairs stick together, the load shared in
  // directions that move nothing (the energy's flat directions), taking it
  // would only move that share.
  void accelerate(std::vector<joint_pair>& pairs, const pair_coupling& w, double least_gain) {
    keep(pairs, swept_);
    mixing_.push(start_, swept_);
    mixed_.resize(pairs.size());
    if (!mixing_.mix(own_, mixed_)) return;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      joint_pair& p = pairs[i];
      const auto s = detail::multiply(own_[i].entries(), mixed_[i]);
      if (!std::isfinite(s[0] + s[1] + s[2])) return refuse();  // the law would refuse it
      const auto r = p.friction.get().impulse({-s[0], -s[1]}, -s[2], own_[i], p.normal,
                                              p.penetration, p.patch);
      mixed_[i] = {r.force[0], r.force[1], r.torque};
    }
    trial_slip_.resize(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      trial_slip_[i] = pairs[i].free_motion;
      for (std::size_t j = 0; j < pairs.size(); ++j) {
        const auto moved = detail::multiply(w.at(i, j), mixed_[j]);
        for (std::size_t k = 0; k < 3; ++k) trial_slip_[i][k] += moved[k];
      }
    }
    if (!(energy(pairs, mixed_, trial_slip_) < energy(pairs, swept_, slip_) - least_gain))
      return refuse();
    refused_ = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i) pairs[i].impulse = mixed_[i];
    slip_ = trial_slip_;
  }

  // The mixture is not taken: a refusal alone keeps the history, several in
  // a row restart it.
  void refuse() {
    if (++refused_ < refusals_to_restart) return;
    refused_ = 0;
    mixing_.forget();
    mixing_.push(start_, swept_);
  }

  // ½PᵀWP + sᵀP = Σᵢ Pᵢᵀ(sᵢ + sᵢ')/2, sᵢ' = sᵢ + (WP)ᵢ the slip after: the
  // kinetic energy after the step less its value at P = 0.
  static double energy(const std::vector<joint_pair>& pairs,
                       const std::vector<detail::vector3<double>>& impulse,
                       const std::vector<detail::vector3<double>>& after) {
    double sum = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i)
      for (std::size_t k = 0; k < 3; ++k)
        sum += impulse[i][k] * (pairs[i].free_motion[k] + after[i][k]) / 2;
    return sum;
  }

  // Σ PᵢᵀWᵢᵢPᵢ: twice the energy of the motions the impulses alone would
  // make, pair by pair.  The slips after the step, s + WP, are known to the
  // rounding of WP: where the pairs hold a load against each other (feet
  // that share a body's weight in directions that move nothing, the free
  // motions about 0), that, not the free motions, is their scale.
  double held(const std::vector<joint_pair>& pairs) const {
    double sum = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i)
      sum += detail::dot(pairs[i].impulse, detail::multiply(own_[i].entries(), pairs[i].impulse));
    return sum;
  }

  // Σ Δsᵢᵀ Wᵢᵢ⁻¹ Δsᵢ: how far the last sweep moved the slips after the step.
  double moved() const {
    double sum = 0;
    for (std::size_t i = 0; i < slip_.size(); ++i) {
      const detail::vector3<double> d{slip_[i][0] - before_[i][0], slip_[i][1] - before_[i][1],
                                      slip_[i][2] - before_[i][2]};
      sum += detail::dot(d, detail::multiply(own_[i].inverse(), d));
    }
    return sum;
  }

  std::vector<planar_metric<double>> own_;  // each pair's own block, conditioned
  std::vector<detail::vector3<double>> slip_, before_;
  // The impulses before and after the last sweep, the projected mixture and
  // the slips after it.
  std::vector<detail::vector3<double>> start_, swept_, mixed_, trial_slip_;
  detail::anderson_mixing mixing_;
  // Mixtures refused in a row.  A refusal alone keeps the history (its
  // iterates still describe the map: measured on the rigidly coupled pairs,
  // restarting at every refusal stalls the mixing at one difference, 75
  // sweeps at the 99th percentile and 100 at worst); three in a row restart
  // it, in case the active set has changed (never restarting: 17 and 21
  // here, but with five differences one of the 400 cases took 502).
  static constexpr int refusals_to_restart = 3;
  int refused_ = 0;
};

/// joint_solver::solve with a workspace of its own, for one call.
inline joint_outcome solve_jointly(std::vector<joint_pair>& pairs, const pair_coupling& w,
                                   const joint_settings& settings = {}) {
  return joint_solver().solve(pairs, w, settings);
}

}  // namespace spinslide

#endif  // SPINSLIDE_CONTACT_JOINT_PAIRS_HPP
