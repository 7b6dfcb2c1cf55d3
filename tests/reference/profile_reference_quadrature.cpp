//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// generate_profile_reference: the nested 2-D tanh_sinh quadrature of the
// area integrals (the inner θ-integral and the outer r- or φ-integral), and
// the profiles it integrates.  generate_profile_reference.cpp says how and
// why.
#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <cstddef>
#include <vector>

#include "profile_reference.hpp"

namespace profile_reference {

namespace {

const big pi = boost::math::constants::pi<big>();
const big half_pi = boost::math::constants::half_pi<big>();

// ∫_a^b f, with the interval mapped onto [0, 1] by hand.
template <class F>
big integrate01(tanh_sinh<big>& q, F f, const big& a, const big& b, const big& tol, double& worst) {
  const big w = b - a;
  auto g = [&](const big& s) -> big { return f(a + w * s); };
  big err = 0, l1 = 0;
  std::size_t levels = 0;
  const big v = q.integrate(g, big(0), big(1), tol, &err, &l1, &levels);
  if (l1 != 0) worst = std::max(worst, static_cast<double>(err / l1));
  return w * v;
}

}  // namespace

// I_F(r) or I_T(r): ∫₀^π of the raw polar integrand.  The quadrature variable
// is u = tan(θ/4) ∈ [0, 1] (θ = 4 atan u, dθ = 4 du/(1 + u²),
// sin(θ/2) = 2u/(1 + u²)): a plain change of variables that makes the
// integrand rational in u apart from ρ's square root, i.e. no sin/cos in the
// innermost loop (they dominate the cost in 50-digit arithmetic).  θ = 0, where
// the integrand peaks for r ≈ ε, stays an endpoint (u = 0).
big theta_integral(quad& q, quantity what, const big& r, const big& eps, const big& tol) {
  const big d = r - eps;
  const big four_r_eps = 4 * r * eps;
  auto f = [&](const big& u) -> big {
    const big t = u * u;
    const big inv = 1 / (1 + t);
    const big h = 4 * t * inv * inv;  // sin²(θ/2) = (1 − cosθ)/2
    const big rho2 = d * d + four_r_eps * h;
    if (rho2 == 0) return big(0);                   // ρ = 0: a single point, measure zero
    const big jac_over_rho = 4 * inv / sqrt(rho2);  // (dθ/du)/ρ
    if (what == quantity::force) return big((2 * r * h - d) * jac_over_rho);  // (ε − r cosθ)/ρ
    return big(r * (d + 2 * eps * h) * jac_over_rho);  // r (r − ε cosθ)/ρ
  };
  return integrate01(q.inner, f, big(0), big(1), tol, q.worst_inner);
}

std::vector<profile> make_profiles() {
  std::vector<profile> ps;
  {
    profile p;
    p.name = "uniform";
    p.u0 = 0;
    p.u1 = 1;
    p.weight = [](const big& r, const big&) { return r; };
    p.norm = big(1) / 2;
    p.mean_r = big(2) / 3;
    p.mean_inv_r = 2;
    p.mean_r2 = big(1) / 2;
    ps.push_back(p);
  }
  {
    const big b = big(1) / 8;
    profile p;
    p.name = "annulus_0.125";
    p.u0 = b;
    p.u1 = 1;
    p.weight = [](const big& r, const big&) { return r; };
    p.norm = (1 - b * b) / 2;
    p.mean_r = big(2) / 3 * (1 - b * b * b) / (1 - b * b);
    p.mean_inv_r = 2 / (1 + b);
    p.mean_r2 = (1 + b * b) / 2;
    ps.push_back(p);
  }
  {
    profile p;  // p = √(1 − r²): p r dr = sin φ cos² φ dφ
    p.name = "hertz";
    p.phi = true;
    p.u0 = 0;
    p.u1 = half_pi;
    p.weight = [](const big& phi, const big&) {
      const big c = cos(phi);
      return big(sin(phi) * c * c);
    };
    p.norm = big(1) / 3;
    p.mean_r = 3 * pi / 16;
    p.mean_inv_r = 3 * pi / 4;
    p.mean_r2 = big(2) / 5;
    ps.push_back(p);
  }
  {
    profile p;  // p = 1/√(1 − r²): p r dr = sin φ dφ
    p.name = "boussinesq";
    p.phi = true;
    p.u0 = 0;
    p.u1 = half_pi;
    p.weight = [](const big& phi, const big&) { return big(sin(phi)); };
    p.norm = 1;
    p.mean_r = pi / 4;
    p.mean_inv_r = pi / 2;
    p.mean_r2 = big(2) / 3;
    ps.push_back(p);
  }
  {
    profile p;
    p.name = "ring";
    p.ring = true;
    p.u0 = 1;
    p.u1 = 1;
    p.norm = 1;
    p.mean_r = 1;
    p.mean_inv_r = 1;
    p.mean_r2 = 1;
    ps.push_back(p);
  }
  {
    // p1 on r < 1/2, p2 on 1/2 < r ≤ 1 with p1·π/4 : p2·3π/4 = 0.6 : 0.4;
    // p1 = 12/5, p2 = 8/15 gives ∫ p r dr = 3/10 + 1/5 = 1/2.
    profile p;
    p.name = "two_tier";
    p.u0 = 0;
    p.u1 = 1;
    p.breaks = {big(1) / 2};
    p.weight = [](const big& r, const big& mid) {
      return big(mid < big(1) / 2 ? r * 12 / 5 : r * 8 / 15);
    };
    p.norm = big(1) / 2;
    p.mean_r = big(23) / 45;
    p.mean_inv_r = big(44) / 15;
    p.mean_r2 = big(13) / 40;
    ps.push_back(p);
  }
  {
    profile p;
    p.name = "parabolic";
    p.u0 = 0;
    p.u1 = 1;
    p.weight = [](const big& r, const big&) { return big(r * (1 - r * r)); };
    p.norm = big(1) / 4;
    p.mean_r = big(8) / 15;
    p.mean_inv_r = big(8) / 3;
    p.mean_r2 = big(1) / 3;
    ps.push_back(p);
  }
  return ps;
}

values compute(quad& q, const profile& p, const big& eps, const big& tol) {
  const big one(1);
  const big tol_f = tol * std::min(one, eps) / 100;
  const big tol_t = tol * std::min(one, one / eps) / 100;
  values v;
  if (p.ring) {
    // Both are positive 1-D integrals (no outer level); tanh_sinh's tolerance
    // is relative to the L1 norm, so use the cancellation-aware one.
    v.force = theta_integral(q, quantity::force, one, eps, tol_f) / pi;
    v.torque = theta_integral(q, quantity::torque, one, eps, tol_t) / pi;
    return v;
  }
  // Pieces of the u-range: profile breakpoints plus u(r = ε).
  std::vector<big> cuts{p.u0, p.u1};
  for (const big& b : p.breaks) cuts.push_back(b);
  if (eps < 1) cuts.push_back(p.phi ? big(asin(eps)) : eps);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  big sum_f = 0, sum_t = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const big a = cuts[i], b = cuts[i + 1];
    if (a < p.u0 || b > p.u1) continue;
    const big mid = (a + b) / 2;
    auto outer_f = [&](const big& u) -> big {
      const big w = p.weight(u, mid);
      if (w == 0) return big(0);
      const big r = p.phi ? big(sin(u)) : u;
      return big(w * theta_integral(q, quantity::force, r, eps, tol_f));
    };
    auto outer_t = [&](const big& u) -> big {
      const big w = p.weight(u, mid);
      if (w == 0) return big(0);
      const big r = p.phi ? big(sin(u)) : u;
      return big(w * theta_integral(q, quantity::torque, r, eps, tol_t));
    };
    sum_f += integrate01(q.outer, outer_f, a, b, tol, q.worst_outer);
    sum_t += integrate01(q.outer, outer_t, a, b, tol, q.worst_outer);
  }
  v.force = sum_f / (pi * p.norm);
  v.torque = sum_t / (pi * p.norm);
  return v;
}

}  // namespace profile_reference
