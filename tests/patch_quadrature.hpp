//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// ∬ f over a flat patch's loaded polygon by Gauss quadrature, independent of
// the library's closed forms: the triangles fanned from its first vertex,
// the square mapped onto each (Duffy: (u, t) → v₀ + u(1 − t)e₁ + ut e₂,
// Jacobian u), K × K Gauss–Legendre points (exact to degree 2K − 1 in each
// variable; for a smooth f, spectrally convergent).
#ifndef SPINSLIDE_TESTS_PATCH_QUADRATURE_HPP
#define SPINSLIDE_TESTS_PATCH_QUADRATURE_HPP

#include <spinslide/values/polygon_patch.hpp>

#include <boost/math/quadrature/gauss.hpp>

#include <array>
#include <cstddef>

namespace patch_quadrature {

template <unsigned K, class F>
double loaded_integral(const spinslide::polygon_patch<double>& p, F f) {
  using rule = boost::math::quadrature::gauss<double, K>;
  using point = std::array<double, 2>;
  const auto& v = p.loaded_vertices();
  double sum = 0;
  for (std::size_t i = 1; i + 1 < v.size(); ++i) {
    const point e1{v[i][0] - v[0][0], v[i][1] - v[0][1]};
    const point e2{v[i + 1][0] - v[0][0], v[i + 1][1] - v[0][1]};
    const double jac = e1[0] * e2[1] - e1[1] * e2[0];
    sum += jac * rule::integrate([&](double a) {
             const double u = (a + 1) / 2;
             return rule::integrate([&](double b) {
               const double t = (b + 1) / 2;
               const point x{v[0][0] + u * (1 - t) * e1[0] + u * t * e2[0],
                             v[0][1] + u * (1 - t) * e1[1] + u * t * e2[1]};
               return f(x) * u / 4;
             });
           });
  }
  return sum;
}

}  // namespace patch_quadrature

#endif  // SPINSLIDE_TESTS_PATCH_QUADRATURE_HPP
