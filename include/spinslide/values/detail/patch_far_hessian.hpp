//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file patch_far_hessian.hpp
/// The Hessian of the dissipation D = ∬ p |u| dA of a patch whose
/// instantaneous centre is far from it, in closed form by the far field's
/// contour integrals (patch_far_field.hpp; docs/patches.md, "Dissipation").
/// In the twist θ' = (v₀, ω), v₀ the velocity of z₀, with x' = x − z₀:
///   ∇²D = ∬ p a aᵀ/|u|,   a = (n̂, x'·û),   n̂ = ẑ × û
/// (∇²|u| = g'ᵀ n̂n̂ᵀ g'/|u|, g' = [I | ẑ × x'], (ẑ × x')·n̂ = x'·û); nothing
/// is divided by ω.  In the scaled frame (z = x'/ρ₀, ζ = Wz, v = (1 + ζ)^{1/2},
/// u = v̄): u(x) = iq(1 + ζ), |u| = |q| u v, n̂ = −q̂ v/u, so with
///   I₀ = ∬ p/(uv),  Z₁ = ∬ p z/(uv),  Z₂ = ∬ p |z|²/(uv),
///   N_k = ∬ p z̄^(k−2) v/u³ (k = 2, 3, 4):
///   ∂²D/∂v₀² = (1/2|q|)(I₀ I + [[Re n, Im n], [Im n, −Re n]]),  n = q̂² N₂,
///   ∂²D/∂v₀∂ω = (−iρ₀/2|q|)(q̂² N₃ − Z₁)  (as x + iy),
///   ∂²D/∂ω² = (ρ₀²/2|q|)(Z₂ − Re(q̂² N₄)).
/// The antiderivatives in z̄ (s = 1 + W̄t, g = z̄/(u + 1)):
///   C₀ = ∫ u⁻³ = 2g/u,  C₁ = ∫ t u⁻³ = 2g²/u,  C₂ = ⅔ g³(u + 3)/u,
///   C₃ = ⅖ g⁴(u² + 4u + 5)/u,
/// beside A₀, A₁, A₂ of patch_far_field.hpp; F = v⁻¹[(a + b̄z/2)A_k + (b/2)A_{k+1}]
/// (times z for Z₁, Z₂) and v[(a + b̄z/2)C_k + (b/2)C_{k+1}].  The terms of F
/// reach degree 4 in z, z̄: the rule's target is the far field's times R.
/// Then θ' = Tθ, v₀ = v + ω ẑ × z₀, and ∇²_θ D = Tᵀ ∇²_θ' D T.

#ifndef SPINSLIDE_VALUES_DETAIL_PATCH_FAR_HESSIAN_HPP
#define SPINSLIDE_VALUES_DETAIL_PATCH_FAR_HESSIAN_HPP

#include <spinslide/values/detail/patch_far_field.hpp>

#include <array>
#include <cmath>
#include <cstddef>

namespace spinslide {
namespace detail {

/// The six contour sums of the far Hessian (I₀, Z₁, Z₂, N₂, N₃, N₄ before
/// the factor 1/2i), an edge's nodes at a time (far_batch: the loop after the
/// square roots vectorizes).
template <class Real>
struct far_hessian_node {
  cplx<Real> a, half_b;
  std::array<cplx<Real>, 6> sum{};

  void operator()(const far_batch<Real>& b) {
    std::array<std::array<Real, far_batch<Real>::capacity>, 12> out;
    for (std::size_t i = 0; i < b.size; ++i) {
      const cplx<Real> z{b.zr[i], b.zi[i]}, v{b.vr[i], b.vi[i]}, u = conj(v);
      const cplx<Real> wd{b.wr[i], b.wi[i]};
      const cplx<Real> u1{u.re + 1, u.im};
      const Real n1 = 1 / (u1.re * u1.re + u1.im * u1.im), nu = 1 / (u.re * u.re + u.im * u.im);
      const cplx<Real> g = conj(z) * cplx<Real>{u1.re * n1, -u1.im * n1};  // z̄/(u + 1)
      const cplx<Real> ui{u.re * nu, -u.im * nu}, vi = conj(ui);           // 1/u, 1/v
      const cplx<Real> g2 = g * g, g3 = g2 * g, u2 = u * u;
      const cplx<Real> A0 = Real(2) * g, A1 = Real(Real(2) / 3) * (g2 * cplx<Real>{u.re + 2, u.im});
      const cplx<Real> A2 =
          Real(Real(2) / 15) * (g3 * cplx<Real>{3 * u2.re + 9 * u.re + 8, 3 * u2.im + 9 * u.im});
      const cplx<Real> gu = g * ui;
      const cplx<Real> C0 = Real(2) * gu, C1 = Real(2) * (g * gu);
      const cplx<Real> C2 = Real(Real(2) / 3) * (g2 * gu * cplx<Real>{u.re + 3, u.im});
      const cplx<Real> C3 =
          Real(Real(2) / 5) * (g3 * gu * cplx<Real>{u2.re + 4 * u.re + 5, u2.im + 4 * u.im});
      const cplx<Real> lin = a + conj(half_b) * z;
      const cplx<Real> viw = vi * wd, vw = v * wd;
      const cplx<Real> i0 = (lin * A0 + half_b * A1) * viw;
      const std::array<cplx<Real>, 6> t{i0,
                                        z * i0,
                                        z * ((lin * A1 + half_b * A2) * viw),
                                        (lin * C0 + half_b * C1) * vw,
                                        (lin * C1 + half_b * C2) * vw,
                                        (lin * C2 + half_b * C3) * vw};
      for (std::size_t k = 0; k < 6; ++k) {
        out[2 * k][i] = t[k].re;
        out[2 * k + 1][i] = t[k].im;
      }
    }
    for (std::size_t i = 0; i < b.size; ++i)
      for (std::size_t k = 0; k < 6; ++k)
        sum[k] = sum[k] + cplx<Real>{out[2 * k][i], out[2 * k + 1][i]};
  }
};

/// ∇²D in (v₀, ω) of the polygon `poly` (vertices (x − z0)/rho0 scaled on
/// the fly) in the frame `f` (patch_far_field.hpp), q̂ and |q| of the twist.
template <class Real, std::size_t N>
std::array<std::array<Real, 3>, 3> polygon_far_hessian(const vertex_list<Real, N>& poly,
                                                       const point2<Real>& z0, Real rho0,
                                                       const far_frame<Real>& f,
                                                       const cplx<Real>& qhat, Real q_norm) {
  far_hessian_node<Real> node{{f.a, Real(0)}, {f.b.re / 2, f.b.im / 2}};
  const double target =
      far_rule_target(f.W) -
      std::log(static_cast<double>(f.W.re * f.W.re + f.W.im * f.W.im)) / 2;  // × R
  for_each_far_batch(poly, z0, rho0, f.W, target, node);
  std::array<cplx<Real>, 6> I{};  // ∬ = (1/2i)∮: X/(2i) = (Im X, −Re X)/2
  for (std::size_t k = 0; k < 6; ++k) I[k] = {node.sum[k].im / 2, -node.sum[k].re / 2};
  const cplx<Real> q2 = qhat * qhat;
  const cplx<Real> n = q2 * I[3], c = q2 * I[4] + cplx<Real>{-I[1].re, -I[1].im}, t = q2 * I[5];
  const Real k0 = 1 / (2 * q_norm);
  // −iρ₀/(2|q|) c = (ρ₀/(2|q|))(Im c, −Re c).
  std::array<std::array<Real, 3>, 3> h{};
  h[0][0] = k0 * (I[0].re + n.re);
  h[1][1] = k0 * (I[0].re - n.re);
  h[0][1] = h[1][0] = k0 * n.im;
  h[0][2] = h[2][0] = k0 * rho0 * c.im;
  h[1][2] = h[2][1] = -k0 * rho0 * c.re;
  h[2][2] = k0 * rho0 * rho0 * (I[2].re - t.re);
  return h;
}

/// Tᵀ H T for v₀ = v + ω ẑ × z₀: T = [[1, 0, −z₀y], [0, 1, z₀x], [0, 0, 1]].
template <class Real>
std::array<std::array<Real, 3>, 3> from_origin_twist(const std::array<std::array<Real, 3>, 3>& h,
                                                     const point2<Real>& z0) {
  const std::array<Real, 3> t{-z0[1], z0[0], Real(1)};  // the third column of T
  std::array<std::array<Real, 3>, 3> m = h;
  for (std::size_t i = 0; i < 2; ++i) m[i][2] = m[2][i] = h[i][0] * t[0] + h[i][1] * t[1] + h[i][2];
  Real tt = 0;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) tt += t[i] * h[i][j] * t[j];
  m[2][2] = tt;
  return m;
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DETAIL_PATCH_FAR_HESSIAN_HPP
