//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file friction_wrench.hpp
/// The exact friction wrench of a flat patch (polygon_patch.hpp) moving with
/// a planar twist, per unit μN (docs/patches.md): the slip velocity at x is
/// u(x) = v + ω ẑ × x, the friction density −p û, so that
///   F = −∬ p û dA,   τ = −∬ p (x × û) dA (about the patch origin),
/// and the dissipation D = ∬ p |u| dA, of which (F, τ) is minus the gradient.
/// Near the instantaneous centre c = ẑ × v/ω the closed-form edge sums
/// (detail/patch_edge_sums.hpp), far from it the far field's contour
/// integrals (detail/patch_far_field.hpp), for ω = 0 the sliding wrench; nothing allocates, nothing
/// throws but the policy's error for a bad twist.

#ifndef SPINSLIDE_VALUES_FRICTION_WRENCH_HPP
#define SPINSLIDE_VALUES_FRICTION_WRENCH_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/values/detail/patch_edge_sums.hpp>
#include <spinslide/values/detail/patch_far_field.hpp>
#include <spinslide/values/detail/patch_slabs.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/hypot.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

namespace spinslide {

/// A planar twist: the velocity of the patch origin and the spin (rad per
/// unit time, counter-clockwise positive): planar_twist<double>{{vx, vy}, omega}.
template <class Real>
struct planar_twist {
  using value_type = Real;       ///< the floating type
  std::array<Real, 2> velocity;  ///< v of the patch origin
  Real omega;                    ///< ω
};

/// A friction wrench per unit μN: the force and the torque about the patch
/// origin (in the vertices' length unit).
template <class Real>
struct planar_wrench {
  using value_type = Real;    ///< the floating type
  std::array<Real, 2> force;  ///< F per μN
  Real torque;                ///< τ per μN, about the origin
};

namespace detail {

/// The twist after its checks; `valid` false once the policy returned NaN.
template <class Real, class Policy>
bool check_twist(const char* function, const planar_twist<Real>& w, Real& bad, const Policy& pol) {
  if (!check(function, "twist.velocity[0]", w.velocity[0], argument_rule::finite, &bad, pol) ||
      !check(function, "twist.velocity[1]", w.velocity[1], argument_rule::finite, &bad, pol) ||
      !check(function, "twist.omega", w.omega, argument_rule::finite, &bad, pol))
    return false;
  if (w.velocity[0] == 0 && w.velocity[1] == 0 && w.omega == 0) {
    bad = raise_argument_error(function, "twist.omega",
                               "non-zero when the velocity is zero (a zero twist has no friction "
                               "direction)",
                               w.omega, pol);
    return false;
  }
  return true;
}

/// `w` with its component k (v_x, v_y, ω) moved by `step` (the differences
/// of the far Hessian, and the tests').
template <class Real>
planar_twist<Real> shifted_twist(planar_twist<Real> w, std::size_t k, Real step) {
  if (k < 2) {
    w.velocity[k] += step;
  } else {
    w.omega += step;
  }
  return w;
}

template <class Real>
Real fabs_real(Real x) {
  return x < 0 ? Real(-x) : x;
}

/// Point friction at x: −û(x), and 0 where x does not slip (the pivot).
template <class Real>
planar_wrench<Real> point_wrench(const point2<Real>& x, const planar_twist<Real>& w) {
  const point2<Real> u{w.velocity[0] - w.omega * x[1], w.velocity[1] + w.omega * x[0]};
  const Real speed = boost::math::hypot(u[0], u[1]);
  if (!(speed > 0)) return {{Real(0), Real(0)}, Real(0)};
  const point2<Real> f{-u[0] / speed, -u[1] / speed};
  return {f, cross(x, f)};
}

/// What the wrench needs of a loaded region: its vertices (an area, or a
/// segment's two ends), its pressure p₀ + β·(x − z₀) and ρ₀ about z₀.
template <class Real, std::size_t N>
struct loaded_region {
  const vertex_list<Real, N>& vertices;
  bool area;
  point2<Real> z0;
  Real rho0, p0;
  point2<Real> beta;
};

/// The edge sums about the instantaneous centre c: F = −sign(ω) ẑ × G,
/// τ = −sign(ω)(H + c·G) (docs/patches.md, "The wrench"), in coordinates
/// divided by the power of 2 nearest ρ₀ (exactly: ρ⁴ in ∫ρ³ neither
/// overflows nor underflows for any length unit, and no rounding is added;
/// dividing by ρ₀ itself, or moving to z₀, cost up to 2× more).
template <class Real, std::size_t N>
planar_wrench<Real> near_wrench(const loaded_region<Real, N>& r, const planar_twist<Real>& w,
                                Real* dissipation) {
  BOOST_MATH_STD_USING
  int e = 0;
  frexp(r.rho0, &e);
  const Real unit = ldexp(Real(1), e), inverse = ldexp(Real(1), -e);
  const point2<Real> c{-w.velocity[1] / w.omega * inverse, w.velocity[0] / w.omega * inverse};
  vertex_list<Real, N> scaled;
  for (const auto& v : r.vertices) scaled.push_back({v[0] * inverse, v[1] * inverse});
  // An area's pressure scales with the unit², a segment's line density with the unit.
  const Real r2 = r.area ? Real(unit * unit) : unit;
  const Real alpha = (r.p0 - dot(r.beta, r.z0)) * r2;
  const point2<Real> beta{r.beta[0] * r2 * unit, r.beta[1] * r2 * unit};
  const centre_integrals<Real> I =
      r.area ? polygon_centre_integrals(scaled, alpha, beta, c)
             : segment_centre_integrals(scaled[0], scaled[1], alpha, beta, c);
  const Real s = w.omega > 0 ? Real(1) : Real(-1);
  if (dissipation) *dissipation = fabs_real(w.omega) * unit * I.H;
  return {{s * I.G[1], -s * I.G[0]}, -s * unit * (I.H + dot(c, I.G))};
}

/// The far field about z₀ in the frame scaled by ρ₀: F = −i q̂ S,
/// τ = −ρ₀ Re(q̂ T) + z₀ × F (docs/patches.md, "Far centres").
template <class Real, std::size_t N>
planar_wrench<Real> far_wrench(const loaded_region<Real, N>& r, const planar_twist<Real>& w,
                               const cplx<Real>& q, Real q_norm, Real* dissipation) {
  const Real rho0 = r.rho0;
  // W = ωρ₀/q = ωρ₀ q̄/|q|², computed from q̂ (no overflow of |q|²).
  const cplx<Real> qhat{q.re / q_norm, q.im / q_norm};
  const Real wr = w.omega * rho0 / q_norm;
  // An area's pressure scales with ρ₀², a segment's line density with ρ₀.
  const Real r2 = r.area ? Real(rho0 * rho0) : rho0;
  const far_frame<Real> f{
      r.p0 * r2, {r.beta[0] * r2 * rho0, r.beta[1] * r2 * rho0}, {wr * qhat.re, -wr * qhat.im}};
  const far_sums<Real> m =
      r.area ? polygon_far_integrals(r.vertices, r.z0, rho0, f, dissipation != nullptr)
             : segment_far_integrals(r.vertices[0], r.vertices[1], r.z0, rho0, f,
                                     dissipation != nullptr);
  if (dissipation) *dissipation = q_norm * m.SD.re;
  const cplx<Real> qs = qhat * m.S, qt = qhat * m.T;
  const point2<Real> F{qs.im, -qs.re};
  return {F, -rho0 * qt.re + cross(r.z0, F)};
}

/// One region's wrench, ω ≠ 0: the far field beyond 4ρ₀, the edge sums within.
template <class Real, std::size_t N>
planar_wrench<Real> region_wrench(const loaded_region<Real, N>& r, const planar_twist<Real>& w,
                                  Real* dissipation) {
  // q = ω z₀ − i v: the centre is c = z₀ − q/ω, at R = |q|/(|ω|ρ₀) loaded radii.
  const cplx<Real> q{w.omega * r.z0[0] + w.velocity[1], w.omega * r.z0[1] - w.velocity[0]};
  const Real q_norm = boost::math::hypot(q.re, q.im);
  if (q_norm >= far_crossover<Real>() * fabs_real(w.omega) * r.rho0)
    return far_wrench(r, w, q, q_norm, dissipation);
  return near_wrench(r, w, dissipation);
}

/// A thin area's wrench as the sum over its fat slabs (detail/patch_slabs.hpp).
template <class Real, std::size_t N>
planar_wrench<Real> slab_wrench(const loaded_region<Real, N>& whole, const slab_plan<Real>& plan,
                                const planar_twist<Real>& w, Real* dissipation) {
  BOOST_MATH_STD_USING
  planar_wrench<Real> sum{{Real(0), Real(0)}, Real(0)};
  Real total = 0;
  vertex_list<Real, 12> scratch, piece;
  for (std::size_t k = 0; k < plan.count; ++k) {
    slab(whole.vertices, plan, k, scratch, piece);
    if (piece.size() < 3) continue;
    point2<Real> z{0, 0};
    for (const auto& v : piece) {
      z[0] += v[0] / Real(piece.size());
      z[1] += v[1] / Real(piece.size());
    }
    Real rho = 0;
    for (const auto& v : piece) rho = fmax(rho, sqrt(dot(minus(v, z), minus(v, z))));
    const loaded_region<Real, 12> r{
        piece, true, z, rho, whole.p0 + dot(whole.beta, minus(z, whole.z0)), whole.beta};
    Real d = 0;
    const planar_wrench<Real> f = region_wrench(r, w, dissipation ? &d : nullptr);
    sum.force[0] += f.force[0];
    sum.force[1] += f.force[1];
    sum.torque += f.torque;
    total += d;
  }
  if (dissipation) *dissipation = total;
  return sum;
}

/// The wrench of an area or a line patch whose loaded vertices, in the
/// working type W (double for float), are `vertices`; ω ≠ 0; a thin area by slabs.
template <class W, class Real>
planar_wrench<W> working_wrench(const polygon_patch<Real>& p, const vertex_list<W>& vertices,
                                const planar_twist<W>& w, W* dissipation) {
  const loaded_region<W, 9> r{vertices,
                              p.shape() == patch_shape::area,
                              {W(p.pressure_origin()[0]), W(p.pressure_origin()[1])},
                              W(p.loaded_radius()),
                              W(p.pressure_at_origin()),
                              {W(p.pressure_gradient()[0]), W(p.pressure_gradient()[1])}};
  if (p.thin()) return slab_wrench(r, plan_slabs(vertices), w, dissipation);
  return region_wrench(r, w, dissipation);
}

/// The patch's own vertices when W is Real; a copy in W otherwise.
template <class W, class Real>
planar_wrench<W> working_wrench(const polygon_patch<Real>& p, const planar_twist<W>& w,
                                W* dissipation) {
  if constexpr (std::is_same<W, Real>::value) {
    return working_wrench(p, p.loaded_vertices(), w, dissipation);
  } else {
    vertex_list<W> vertices;
    for (const auto& v : p.loaded_vertices()) vertices.push_back({W(v[0]), W(v[1])});
    return working_wrench(p, vertices, w, dissipation);
  }
}

/// The wrench of a checked twist.
template <class Real>
planar_wrench<Real> wrench_of(const polygon_patch<Real>& patch, const planar_twist<Real>& w,
                              Real* dissipation = nullptr) {
  if (patch.shape() == patch_shape::point) {
    const auto& x = patch.pressure_origin();
    if (dissipation)
      *dissipation =
          boost::math::hypot(w.velocity[0] - w.omega * x[1], w.velocity[1] + w.omega * x[0]);
    return point_wrench(x, w);
  }
  // ω = 0: û = v̂ everywhere, F = −v̂ and τ = −e × v̂, e the centre of pressure
  // (docs/patches.md, "The wrench").
  if (w.omega == 0) {
    const Real speed = boost::math::hypot(w.velocity[0], w.velocity[1]);
    const point2<Real> f{-w.velocity[0] / speed, -w.velocity[1] / speed};
    if (dissipation) *dissipation = speed;
    return {f, cross(patch.centre(), f)};
  }
  using W = working_type<Real>;
  W d = 0;
  const planar_wrench<W> f =
      working_wrench(patch, planar_twist<W>{{W(w.velocity[0]), W(w.velocity[1])}, W(w.omega)},
                     dissipation ? &d : nullptr);
  if (dissipation) *dissipation = Real(d);
  return {{Real(f.force[0]), Real(f.force[1])}, Real(f.torque)};
}

}  // namespace detail

/// The friction wrench of `patch` moving with the twist `w`, per unit μN:
/// w.force (F_x, F_y) and w.torque about the patch origin.  A non-finite
/// component or a zero twist (v = 0 and ω = 0) is a domain error through
/// `pol` (NaN components unless it throws).
template <class Real, class Policy = boost::math::policies::policy<>>
planar_wrench<Real> friction_wrench(const polygon_patch<Real>& patch, const planar_twist<Real>& w,
                                    const Policy& pol = Policy()) {
  static const char* function = "spinslide::friction_wrench<%1%>(polygon_patch, planar_twist)";
  Real bad = 0;
  if (!detail::check_twist(function, w, bad, pol)) return {{bad, bad}, bad};
  return detail::wrench_of(patch, w);
}

}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_FRICTION_WRENCH_HPP
