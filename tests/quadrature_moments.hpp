//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The load-weighted moments ⟨r⟩, ⟨1/r⟩, ⟨r²⟩ of the built-in pressure
// profiles, straight from their defining integrals
//   ⟨r^k⟩ = ∫ r^k w(r) dr / ∫ w(r) dr,   w(r) = r p(r) (the load per unit radius),
// by Boost's tanh_sinh in long double (about 1e-19): the tests' reference for
// the moments, independent of the closed forms that profile.hpp returns.
// Hertz (p ∝ √(1 − r²)) and Boussinesq (p ∝ 1/√(1 − r²)) are integrated in
// r = sin s, where w(r) dr is smooth: 3 sin s cos² s ds and sin s ds.
#ifndef SPINSLIDE_TESTS_QUADRATURE_MOMENTS_HPP
#define SPINSLIDE_TESTS_QUADRATURE_MOMENTS_HPP

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace spinslide_test {

struct load_moments {
  long double mean_radius, mean_inverse_radius, mean_square_radius;
};

// One piece of a load: r(s) and w(r(s)) r′(s) for s in [s0, s1].
struct load_piece {
  std::function<long double(long double)> radius, load;
  long double s0, s1;
};

inline load_moments moments_of(const std::vector<load_piece>& pieces) {
  boost::math::quadrature::tanh_sinh<long double> integrator;  // not const: Boost 1.74
  const long double tol = std::pow(std::numeric_limits<long double>::epsilon(), 0.75L);
  auto integral = [&](int k) {
    long double sum = 0;
    for (const load_piece& p : pieces)
      sum += integrator.integrate(
          [&](long double s) { return std::pow(p.radius(s), k) * p.load(s); }, p.s0, p.s1, tol);
    return sum;
  };
  const long double total = integral(0);
  return {integral(1) / total, integral(-1) / total, integral(2) / total};
}

inline long double identity(long double s) { return s; }
inline long double sine(long double s) { return std::sin(s); }

// p = 1 on the unit disk: w = 2r.
inline load_moments uniform_disk_moments() {
  return moments_of({{identity, [](long double r) { return 2 * r; }, 0, 1}});
}
// p = 1 on b ≤ r ≤ 1: w = 2r/(1 − b²).
inline load_moments annulus_moments(long double b) {
  return moments_of({{identity, [b](long double r) { return 2 * r / (1 - b * b); }, b, 1}});
}
// p ∝ √(1 − r²): w dr ∝ r √(1 − r²) dr = sin s cos² s ds.
inline load_moments hertz_moments() {
  return moments_of({{sine, [](long double s) { return std::sin(s) * std::pow(std::cos(s), 2); }, 0,
                      boost::math::constants::half_pi<long double>()}});
}
// p ∝ 1/√(1 − r²): w dr ∝ r/√(1 − r²) dr = sin s ds.
inline load_moments boussinesq_moments() {
  return moments_of({{sine, [](long double s) { return std::sin(s); }, 0,
                      boost::math::constants::half_pi<long double>()}});
}

}  // namespace spinslide_test

#endif  // SPINSLIDE_TESTS_QUADRATURE_MOMENTS_HPP
