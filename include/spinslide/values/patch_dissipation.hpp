//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file patch_dissipation.hpp
/// The dissipation function of a flat patch (docs/patches.md, "Dissipation"):
/// D(w) = ∬ p |u| dA per unit μN for the twist w = (v_x, v_y, ω), its
/// gradient, which is minus the friction wrench, and its Hessian (symmetric,
/// positive semi-definite, homogeneous of degree −1): what the contact
/// kernel's projections need of a patch (docs/architecture.md, "Three shared
/// decisions", 1).

#ifndef SPINSLIDE_VALUES_PATCH_DISSIPATION_HPP
#define SPINSLIDE_VALUES_PATCH_DISSIPATION_HPP

#include <spinslide/base/detail/checks.hpp>
#include <spinslide/values/detail/patch_far_hessian.hpp>
#include <spinslide/values/detail/patch_hessian.hpp>
#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/hypot.hpp>
#include <boost/math/tools/precision.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace spinslide {

/// D, ∇D = −(F_x, F_y, τ) and ∇²D of a patch at a twist.
template <class Real>
struct patch_dissipation {
  using value_type = Real;                     ///< the floating type
  Real value;                                  ///< D per unit μN
  std::array<Real, 3> gradient;                ///< ∂D/∂(v_x, v_y, ω) = −(F_x, F_y, τ)
  std::array<std::array<Real, 3>, 3> hessian;  ///< ∂²D/∂(v_x, v_y, ω)², +∞ where it diverges
};

namespace detail {

template <class Real>
using patch_matrix = std::array<std::array<Real, 3>, 3>;

template <class Real>
patch_matrix<Real> infinite_hessian() {
  const Real inf = std::numeric_limits<Real>::infinity();
  return {{{inf, inf, inf}, {inf, inf, inf}, {inf, inf, inf}}};
}

/// a aᵀ·scale.
template <class Real>
patch_matrix<Real> outer(const std::array<Real, 3>& a, Real scale) {
  patch_matrix<Real> m{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) m[i][j] = scale * a[i] * a[j];
  return m;
}

/// ∫ q x xᵀ of a line patch (2-point Gauss along it: q x xᵀ is cubic), or of
/// the area (patch_hessian.hpp), or x xᵀ of a point.
template <class Real>
sym2<Real> second_moment(const polygon_patch<Real>& p) {
  BOOST_MATH_STD_USING
  const auto& v = p.loaded_vertices();
  const Real alpha = p.pressure_at_origin() - dot(p.pressure_gradient(), p.pressure_origin());
  if (p.shape() == patch_shape::area)
    return pressure_second_moment(v, alpha, p.pressure_gradient());
  if (p.shape() == patch_shape::point)
    return {v[0][0] * v[0][0], v[0][0] * v[0][1], v[0][1] * v[0][1]};
  const point2<Real> d = minus(v[1], v[0]);
  const Real length = sqrt(dot(d, d)), g = 1 / sqrt(Real(3));
  sym2<Real> m{};
  for (const Real& t : {(1 - g) / 2, (1 + g) / 2}) {
    const point2<Real> x{v[0][0] + t * d[0], v[0][1] + t * d[1]};
    const Real w = length / 2 * p.pressure(x);
    m[0] += w * x[0] * x[0];
    m[1] += w * x[0] * x[1];
    m[2] += w * x[1] * x[1];
  }
  return m;
}

/// ω = 0: (1/|v|) ∬ p a aᵀ with a = (n̂, x·v̂), n̂ = ẑ × v̂.
template <class Real>
patch_matrix<Real> sliding_hessian(const polygon_patch<Real>& p, const planar_twist<Real>& w) {
  const Real speed = boost::math::hypot(w.velocity[0], w.velocity[1]);
  const point2<Real> vh{w.velocity[0] / speed, w.velocity[1] / speed}, nh{-vh[1], vh[0]};
  const sym2<Real> J = second_moment(p);
  const Real ev = dot(p.centre(), vh);
  const Real vjv = vh[0] * vh[0] * J[0] + 2 * vh[0] * vh[1] * J[1] + vh[1] * vh[1] * J[2];
  return {{{nh[0] * nh[0] / speed, nh[0] * nh[1] / speed, nh[0] * ev / speed},
           {nh[0] * nh[1] / speed, nh[1] * nh[1] / speed, nh[1] * ev / speed},
           {nh[0] * ev / speed, nh[1] * ev / speed, vjv / speed}}};
}

/// Far centres of a line patch: central differences of the exact wrench
/// (−∂(F, τ)/∂w), steps ∛ε of the twist's scale: about ε^{2/3} relative (docs/patches.md).
template <class Real>
patch_matrix<Real> far_hessian(const polygon_patch<Real>& p, const planar_twist<Real>& w) {
  BOOST_MATH_STD_USING
  const Real size =
      fmax(p.loaded_radius(), boost::math::hypot(p.pressure_origin()[0], p.pressure_origin()[1]));
  const Real scale = boost::math::hypot(w.velocity[0], w.velocity[1]) + fabs(w.omega) * size;
  const Real h = boost::math::tools::cbrt_epsilon<Real>() * scale;
  patch_matrix<Real> m{};
  for (std::size_t k = 0; k < 3; ++k) {
    const Real step = k < 2 ? h : Real(h / size);
    const auto a = wrench_of(p, shifted_twist(w, k, step)),
               b = wrench_of(p, shifted_twist(w, k, Real(-step)));
    m[0][k] = -(a.force[0] - b.force[0]) / (2 * step);
    m[1][k] = -(a.force[1] - b.force[1]) / (2 * step);
    m[2][k] = -(a.torque - b.torque) / (2 * step);
  }
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = i + 1; j < 3; ++j) m[i][j] = m[j][i] = (m[i][j] + m[j][i]) / 2;
  return m;
}

/// Far centres on an area: in closed form by the far field's contour
/// integrals (detail/patch_far_hessian.hpp), about the pressure origin z₀.
template <class Real>
patch_matrix<Real> far_area_hessian(const polygon_patch<Real>& p, const planar_twist<Real>& w) {
  const auto& z0 = p.pressure_origin();
  const Real rho0 = p.loaded_radius();
  const cplx<Real> q{w.omega * z0[0] + w.velocity[1], w.omega * z0[1] - w.velocity[0]};
  const Real q_norm = boost::math::hypot(q.re, q.im);
  const cplx<Real> qhat{q.re / q_norm, q.im / q_norm};
  const Real wr = w.omega * rho0 / q_norm, r2 = rho0 * rho0;
  const auto& beta = p.pressure_gradient();
  const far_frame<Real> f{p.pressure_at_origin() * r2,
                          {beta[0] * r2 * rho0, beta[1] * r2 * rho0},
                          {wr * qhat.re, -wr * qhat.im}};
  return from_origin_twist(polygon_far_hessian(p.loaded_vertices(), z0, rho0, f, qhat, q_norm), z0);
}

/// ∇²D at a checked twist.
template <class Real>
patch_matrix<Real> patch_dissipation_hessian(const polygon_patch<Real>& p,
                                             const planar_twist<Real>& w) {
  BOOST_MATH_STD_USING
  if (p.shape() == patch_shape::point) {
    const auto& x = p.pressure_origin();
    const point2<Real> u{w.velocity[0] - w.omega * x[1], w.velocity[1] + w.omega * x[0]};
    const Real speed = boost::math::hypot(u[0], u[1]);
    if (!(speed > 0)) return infinite_hessian<Real>();
    const point2<Real> n{-u[1] / speed, u[0] / speed};
    return outer<Real>({n[0], n[1], x[0] * n[1] - x[1] * n[0]}, 1 / speed);
  }
  if (w.omega == 0) return sliding_hessian(p, w);
  const auto& z0 = p.pressure_origin();
  const Real qx = w.omega * z0[0] + w.velocity[1], qy = w.omega * z0[1] - w.velocity[0];
  if (boost::math::hypot(qx, qy) >= far_crossover<Real>() * fabs(w.omega) * p.loaded_radius())
    return p.shape() == patch_shape::area ? far_area_hessian(p, w) : far_hessian(p, w);
  const point2<Real> c{-w.velocity[1] / w.omega, w.velocity[0] / w.omega};
  const Real alpha = p.pressure_at_origin() - dot(p.pressure_gradient(), z0);
  const auto& v = p.loaded_vertices();
  const sym2<Real> M = p.shape() == patch_shape::area
                           ? polygon_inverse_moment(v, alpha, p.pressure_gradient(), c)
                           : segment_inverse_moment(v[0], v[1], alpha, p.pressure_gradient(), c);
  if (!((boost::math::isfinite)(M[0]) && (boost::math::isfinite)(M[1]) &&
        (boost::math::isfinite)(M[2])))
    return infinite_hessian<Real>();
  return hessian_from(M, point2<Real>{-c[1], c[0]}, Real(1 / fabs(w.omega)));
}

}  // namespace detail

/// D, ∇D and ∇²D of `patch` at the twist `w` (the checks of friction_wrench).
/// One call gives the wrench (−gradient) and the Hessian at one twist, for
/// the projections that need all three: the Hessian is in closed form for
/// an instantaneous centre near the patch (the edge sums, within 4 loaded
/// radii of its centre), far from an area (the far field's contour
/// integrals, at about the cost of two more wrenches) and for ω = 0; a line
/// patch's far Hessian is by central differences of the exact wrench (six
/// wrenches, about ε^{2/3} relative); +∞ in every entry where it diverges:
/// a point patch or a line patch pivoting about one of its points.
template <class Real, class Policy = boost::math::policies::policy<>>
patch_dissipation<Real> friction_dissipation(const polygon_patch<Real>& patch,
                                             const planar_twist<Real>& w,
                                             const Policy& pol = Policy()) {
  static const char* function = "spinslide::friction_dissipation<%1%>(polygon_patch, planar_twist)";
  Real bad = 0;
  if (!detail::check_twist(function, w, bad, pol))
    return {bad, {bad, bad, bad}, {{{bad, bad, bad}, {bad, bad, bad}, {bad, bad, bad}}}};
  Real value = 0;
  const planar_wrench<Real> f = detail::wrench_of(patch, w, &value);
  return {
      value, {-f.force[0], -f.force[1], -f.torque}, detail::patch_dissipation_hessian(patch, w)};
}

}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_PATCH_DISSIPATION_HPP
