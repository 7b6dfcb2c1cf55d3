//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file patch_pressure.hpp
/// The linear pressure of a convex polygon with a given centre of pressure,
/// and beyond the kern the no-tension pressure p = max(0, α + β·y) with the
/// same resultant and centre (docs/patches.md, "Pressure and lift-off").
///
/// Both are the minimum of one convex function of θ = (α, β),
///   Φ(θ) = ½ ∬_P (α + β·y)₊² dA − α − β·e,
/// whose gradient is (∬_Q p − 1, ∬_Q p y − e) and whose Hessian is the
/// moment matrix [[A, Sᵀ], [S, J]] of the loaded part Q (p = 0 on the lift-off
/// line, so the moving boundary adds nothing).  Inside the kern Q = P and
/// one Newton step from any full-contact point lands on the linear solution;
/// beyond it Newton with a backtracking line search on Φ converges (Φ is
/// convex and coercive for e inside P).  All in coordinates scaled by the
/// patch size, so that A, S, J are O(1).

#ifndef SPINSLIDE_VALUES_DETAIL_PATCH_PRESSURE_HPP
#define SPINSLIDE_VALUES_DETAIL_PATCH_PRESSURE_HPP

#include <spinslide/values/detail/patch_geometry.hpp>

#include <boost/math/tools/precision.hpp>

#include <array>
#include <cmath>
#include <cstddef>

namespace spinslide {
namespace detail {

/// A linear pressure α + β·y (y in the solve's scaled frame) and the region
/// where it is loaded.
template <class Real, std::size_t N>
struct linear_pressure {
  Real alpha = 0;
  point2<Real> beta{};
  vertex_list<Real, N> loaded;
  bool lifted = false;  ///< a part of the polygon lifts off (loaded ≠ the polygon)
};

/// Solves the symmetric 3×3 system M x = b (Gaussian elimination with
/// partial pivoting); false if M is singular.
template <class Real>
bool solve3(std::array<std::array<Real, 3>, 3> m, std::array<Real, 3> b, std::array<Real, 3>& x) {
  BOOST_MATH_STD_USING
  for (std::size_t c = 0; c < 3; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < 3; ++r)
      if (fabs(m[r][c]) > fabs(m[pivot][c])) pivot = r;
    if (!(fabs(m[pivot][c]) > 0)) return false;
    std::swap(m[c], m[pivot]);
    std::swap(b[c], b[pivot]);
    for (std::size_t r = c + 1; r < 3; ++r) {
      const Real f = m[r][c] / m[c][c];
      for (std::size_t k = c; k < 3; ++k) m[r][k] -= f * m[c][k];
      b[r] -= f * b[c];
    }
  }
  for (std::size_t c = 3; c-- > 0;) {
    Real s = b[c];
    for (std::size_t k = c + 1; k < 3; ++k) s -= m[c][k] * x[k];
    x[c] = s / m[c][c];
  }
  return true;
}

/// Φ, its gradient and Hessian at θ on the polygon `poly` (scaled frame, y
/// about the origin of that frame) for the centre e.
template <class Real, std::size_t N>
class no_tension_objective {
 public:
  no_tension_objective(const vertex_list<Real, N>& poly, const point2<Real>& e)
      : poly_(poly), e_(e) {}

  struct state {
    Real value;
    std::array<Real, 3> gradient;
    std::array<std::array<Real, 3>, 3> hessian;
  };

  state at(const std::array<Real, 3>& t) const {
    const area_moments<Real> m = clipped_moments(poly_, t[0], point2<Real>{t[1], t[2]});
    const Real A = m.area, Sx = m.first[0], Sy = m.first[1];
    const Real Jxx = m.second[0], Jxy = m.second[1], Jyy = m.second[2];
    const Real load = t[0] * A + t[1] * Sx + t[2] * Sy;
    const Real mx = t[0] * Sx + t[1] * Jxx + t[2] * Jxy;
    const Real my = t[0] * Sy + t[1] * Jxy + t[2] * Jyy;
    // ½∬p² = ½(α·load + β·∬p y): p² = p(α + β·y).
    const Real half_square = (t[0] * load + t[1] * mx + t[2] * my) / 2;
    return {half_square - t[0] - t[1] * e_[0] - t[2] * e_[1],
            {load - 1, mx - e_[0], my - e_[1]},
            {{{A, Sx, Sy}, {Sx, Jxx, Jxy}, {Sy, Jxy, Jyy}}}};
  }

 private:
  const vertex_list<Real, N>& poly_;
  point2<Real> e_;
};

template <class Real>
Real gradient_norm(const std::array<Real, 3>& g) {
  BOOST_MATH_STD_USING
  return fmax(fabs(g[0]), fmax(fabs(g[1]), fabs(g[2])));
}

/// The pressure of the polygon `poly` (scaled frame) with centre e, starting
/// from θ (any point with Q = P, e.g. the linear solution): damped Newton on Φ,
/// at most `max_iterations` steps; it ends at the best θ found.
template <class Real, std::size_t N>
linear_pressure<Real, N> no_tension_pressure(const vertex_list<Real, N>& poly,
                                             const point2<Real>& e, std::array<Real, 3> theta,
                                             int max_iterations = 100) {
  const no_tension_objective<Real, N> phi(poly, e);
  linear_pressure<Real, N> out;
  auto s = phi.at(theta);
  const Real tolerance = 16 * boost::math::tools::epsilon<Real>();
  for (int it = 0; it < max_iterations && gradient_norm(s.gradient) > tolerance; ++it) {
    std::array<Real, 3> step{};
    if (!solve3(s.hessian, {-s.gradient[0], -s.gradient[1], -s.gradient[2]}, step)) break;
    const Real slope = s.gradient[0] * step[0] + s.gradient[1] * step[1] + s.gradient[2] * step[2];
    Real t = 1;
    bool moved = false;
    for (int halvings = 0; halvings < 60; ++halvings, t /= 2) {
      const std::array<Real, 3> trial{theta[0] + t * step[0], theta[1] + t * step[1],
                                      theta[2] + t * step[2]};
      const auto ts = phi.at(trial);
      // Armijo on Φ, or (at rounding level, where Φ no longer resolves the
      // decrease) a smaller gradient.
      if (ts.value <= s.value + t * slope / 4 ||
          gradient_norm(ts.gradient) < gradient_norm(s.gradient) / 2) {
        theta = trial;
        s = ts;
        moved = true;
        break;
      }
    }
    if (!moved) break;
  }
  out.alpha = theta[0];
  out.beta = {theta[1], theta[2]};
  clip_polygon(poly, point2<Real>{}, theta[0], out.beta, out.loaded);
  out.lifted = true;
  return out;
}

/// The linear pressure with centre e on the whole polygon (scaled frame):
/// p = 1/A + β·(y − ȳ), β = J_c⁻¹(e − ȳ) (docs/patches.md, "Pressure and
/// lift-off"); then, if it is negative at a vertex, the no-tension pressure.
template <class Real, std::size_t N>
linear_pressure<Real, N> patch_pressure(const vertex_list<Real, N>& poly, const point2<Real>& e) {
  const area_moments<Real> m = polygon_moments(poly, point2<Real>{});
  const Real A = m.area;
  const point2<Real> c{m.first[0] / A, m.first[1] / A};
  const Real jxx = m.second[0] - A * c[0] * c[0], jxy = m.second[1] - A * c[0] * c[1],
             jyy = m.second[2] - A * c[1] * c[1];
  const Real det = jxx * jyy - jxy * jxy;
  const point2<Real> d = minus(e, c);
  const point2<Real> beta{(jyy * d[0] - jxy * d[1]) / det, (jxx * d[1] - jxy * d[0]) / det};
  const Real alpha = 1 / A - dot(beta, c);
  bool full = true;
  for (const auto& y : poly) full = full && alpha + dot(beta, y) >= 0;
  if (full) {
    linear_pressure<Real, N> out;
    out.alpha = alpha;
    out.beta = beta;
    out.loaded = poly;
    return out;
  }
  return no_tension_pressure(poly, e, {alpha, beta[0], beta[1]});
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DETAIL_PATCH_PRESSURE_HPP
