//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The Hessian of MuJoCo's constraint solve (mujoco_hessian.hpp), checked
// against MuJoCo's own products, not against a factorization: x = H⁻¹b must
// leave the residual Mx + Jᵀ D J x − b (mj_mulM, mj_mulJacVec and
// mj_mulJacTVec, D over the rows that resist motion) at rounding's size,
// and W = J H⁻¹ Jᵀ must be J times those solves.  In M's sparse layout
// (the humanoid: every row a body against the floor or a joint's limit)
// and dense (two boxes stacked: the row between them spans two chains).

#include <gtest/gtest.h>

#include "../examples/mujoco_humanoid/humanoid.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <utility>
#include <vector>

namespace {

using spinslide::mujoco::constraint_hessian;

// H x: M x + Σ D_r J_rᵀ (J_r x) over the rows resisting motion (quadratic
// or in their cone, after MuJoCo's primal solvers).
std::vector<double> hessian_times(const mjModel* m, mjData* d, const std::vector<double>& x) {
  const auto nv = static_cast<std::size_t>(m->nv), nefc = static_cast<std::size_t>(d->nefc);
  std::vector<double> out(nv), jx(nefc), back(nv);
  mj_mulM(m, d, out.data(), x.data());
  mj_mulJacVec(m, d, jx.data(), x.data());
  for (std::size_t r = 0; r < nefc; ++r) {
    const int state = d->efc_state[r];
    const bool resisting = state == mjCNSTRSTATE_QUADRATIC || state == mjCNSTRSTATE_CONE;
    jx[r] = resisting ? d->efc_D[r] * jx[r] : 0.0;
  }
  mj_mulJacTVec(m, d, back.data(), jx.data());
  for (std::size_t i = 0; i < nv; ++i) out[i] += back[i];
  return out;
}

double largest(const std::vector<double>& v) {
  double a = 0;
  for (const double x : v) a = std::max(a, std::fabs(x));
  return a;
}

int resisting_rows(const mjData* d) {
  int n = 0;
  for (int r = 0; r < d->nefc; ++r)
    n += d->efc_state[r] == mjCNSTRSTATE_QUADRATIC || d->efc_state[r] == mjCNSTRSTATE_CONE;
  return n;
}

// Random rows in [−1, 1], seeded.
std::vector<double> random_vector(std::size_t n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> v(n);
  for (double& x : v) x = u(rng);
  return v;
}

// x = H⁻¹b leaves a residual H x − b within 1e-11 of |H| |x| (which bounds
// the products' rounding).
void check_solve(const mjModel* m, mjData* d, const constraint_hessian& h,
                 const std::vector<double>& b) {
  const auto nv = static_cast<std::size_t>(m->nv);
  std::vector<double> x(nv);
  h.solve(x.data(), b.data());
  std::vector<double> residual = hessian_times(m, d, x);
  for (std::size_t i = 0; i < nv; ++i) residual[i] -= b[i];
  const double scale = largest(hessian_times(m, d, std::vector<double>(nv, largest(x))));
  EXPECT_LE(largest(residual), 1e-11 * scale);
}

// Pair i's row a times H⁻¹ (pair j's row b)ᵀ, by solve(), and the sum of
// its terms' sizes.
std::pair<double, double> row_times_solve(const constraint_hessian& h,
                                          const std::vector<double>& from,
                                          const std::vector<double>& to, std::size_t nv) {
  std::vector<double> x(nv);
  h.solve(x.data(), to.data());
  double sum = 0, size = 0;
  for (std::size_t q = 0; q < nv; ++q) {
    sum += from[q] * x[q];
    size += std::fabs(from[q] * x[q]);
  }
  return {sum, size};
}

// Solves and W of `d`'s state against MuJoCo's products: random right-hand
// sides, and two pairs of random rows, whose W blocks must be J times
// solve()'s columns to 1e-12 of their terms.
void check_against_products(const mjModel* m, mjData* d, bool tree) {
  ASSERT_GT(resisting_rows(d), 0);
  constraint_hessian h(m);
  h.factor(d);
  EXPECT_EQ(h.tree(), tree);
  const auto nv = static_cast<std::size_t>(m->nv);
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 4; ++trial) check_solve(m, d, h, random_vector(nv, rng));
  const std::vector<std::vector<double>> rows{random_vector(3 * nv, rng),
                                              random_vector(3 * nv, rng)};
  spinslide::pair_coupling w(2);
  h.inverse_mass({rows[0].data(), rows[1].data()}, w);
  auto row = [&](std::size_t pair, std::size_t r) {
    return std::vector<double>(rows[pair].begin() + static_cast<std::ptrdiff_t>(r * nv),
                               rows[pair].begin() + static_cast<std::ptrdiff_t>((r + 1) * nv));
  };
  for (std::size_t k = 0; k < 36; ++k) {
    const std::size_t i = k / 18, j = k / 9 % 2, a = k / 3 % 3, b = k % 3;
    const auto [expected, size] = row_times_solve(h, row(i, a), row(j, b), nv);
    EXPECT_NEAR(w.at(i, j)[a][b], expected, 1e-12 * size) << i << j << a << b;
  }
}

}  // namespace

// The humanoid in its fall (its feet, hands and knees on the floor), every
// pair coupled: its rows each move one chain, so H is kept in M's layout.
TEST(MujocoHessian, TreeFactorSolvesTheHumanoidsConstraintHessian) {
  humanoid::scene s(humanoid::coupled);
  s.data->qpos[3] = std::cos(0.25);
  s.data->qpos[4] = std::sin(0.25);
  mj_forward(s.model.get(), s.data.get());
  for (const int steps : {100, 300, 500}) {
    s.run(steps * humanoid::time_step);
    mj_forward(s.model.get(), s.data.get());
    check_against_products(s.model.get(), s.data.get(), true);
  }
}

// A box on a box on the floor: the contact between the boxes moves both
// free joints (two chains from the world), which would fill H in: H is
// dense, and the same checks hold.
TEST(MujocoHessian, RowsBetweenTwoChainsTakeTheDenseFactor) {
  const char* xml =
      "<mujoco><option timestep='0.002' solver='Newton'/><worldbody>"
      "<geom type='plane' size='1 1 0.1'/>"
      "<body pos='0 0 0.1'><freejoint/><geom type='box' size='0.1 0.1 0.1' mass='1'/></body>"
      "<body pos='0.02 0 0.3'><freejoint/><geom type='box' size='0.1 0.1 0.1' mass='2'/></body>"
      "</worldbody></mujoco>";
  const mujoco_scene::model_ptr m = mujoco_scene::load(xml);
  const mujoco_scene::data_ptr d(mj_makeData(m.get()));
  for (int i = 0; i < 200; ++i) mj_step(m.get(), d.get());
  mj_forward(m.get(), d.get());
  check_against_products(m.get(), d.get(), false);
}
