//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// generate_throw_reference: 𝓕 and 𝓣 of each load from the closed forms of
// docs/theory.md, evaluated here from scratch, and the attractor of a flow.
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <limits>
#include <stdexcept>

#include "throw_reference.hpp"

namespace throw_reference {

// Uniform disk, docs/theory.md §2: k = min(ε, 1/ε), m = k², y = 1 − m.
ft disk(const big& e) {
  if (e == 1) return {8 / (3 * pi()), 8 / (9 * pi())};
  const bool inside = e < 1;
  const big k = inside ? e : big(1 / e);
  const big m = k * k, y = (1 - k) * (1 + k);
  const big K = boost::math::ellint_1(k), E = boost::math::ellint_2(k);
  if (inside)
    return {4 * ((1 + m) * E - y * K) / (3 * pi() * k), 4 * ((4 - 2 * m) * E - y * K) / (9 * pi())};
  return {4 * ((1 + m) * E - y * K) / (3 * pi() * m),
          4 * ((4 * m - 2) * E + y * (2 - 3 * m) * K) / (9 * pi() * k * k * k)};
}

// Ring of radius 1 (R3).
ft ring(const big& e) {
  if (e == 1) return {2 / pi(), 2 / pi()};
  const bool inside = e < 1;
  const big k = inside ? e : big(1 / e);
  const big y = (1 - k) * (1 + k);
  const big K = boost::math::ellint_1(k), E = boost::math::ellint_2(k);
  if (inside) return {2 * (E - y * K) / (pi() * e), 2 * E / pi()};
  return {2 * E / pi(), 2 * e * (E - y * K) / pi()};
}

// Hertz (E1), (E2) and Boussinesq (B2), (B1).
ft hertz(const big& e) {
  const big e2 = e * e;
  if (e <= 1) return {3 * pi() * e * (4 - e2) / 32, 3 * pi() * (8 - 8 * e2 + 3 * e2 * e2) / 128};
  const big A = asin(1 / e), w = sqrt((e - 1) * (e + 1));
  return {3 * ((4 * e - e2 * e) * A + w * (e2 + 2) / e) / 16,
          3 * ((3 * e2 * e2 - 8 * e2 + 8) * A + 3 * w * (2 - e2)) / 64};
}

ft boussinesq(const big& e) {
  const big e2 = e * e;
  if (e <= 1) return {pi() * e / 4, pi() * (2 - e2) / 8};
  const big A = asin(1 / e), w = sqrt((e - 1) * (e + 1));
  return {(e * A + w / e) / 2, ((2 - e2) * A + w) / 4};
}

// 3/4 on the ring, 1/4 as a uniform disk of radius a = 1/8: the scaled disk
// has 𝓕(ε/a) and a𝓣(ε/a) (docs/theory.md §6, `scaled`).
ft ring_and_core(const big& e) {
  const big a = big(1) / 8;
  const ft r = ring(e), d = disk(e / a);
  return {(3 * r.force + d.force) / 4, (3 * r.torque + a * d.torque) / 4};
}

// The paper's CD: the annulus 1/8 ≤ r ≤ 1, the unit disk less the disk of
// radius b = 1/8, each uniform (docs/theory.md (A1)): 𝓕 = (𝓕_D(ε) − b²𝓕_D(ε/b))/(1 − b²),
// 𝓣 = (𝓣_D(ε) − b³𝓣_D(ε/b))/(1 − b²).  Singular at ε = b and ε = 1.
ft cd_annulus(const big& e) {
  const big b = big(1) / 8;
  const ft outer = disk(e), hole = disk(e / b);
  const big area = (1 - b) * (1 + b);
  return {(outer.force - b * b * hole.force) / area,
          (outer.torque - b * b * b * hole.torque) / area};
}

// The attractor the flow from ε_i reaches: march in the direction of the flow
// by factors 1.0625 until f changes sign, then TOMS 748 to full precision.
// 0 if ε falls below 1e-30 (pure spinning); sliding ends are not supported.
big attractor(const flow& fl, const big& ei) {
  const big fi = fl.rate(ei);
  if (abs(fi) < big("1e-90")) return ei;
  const bool down = fi < 0;
  const big factor("1.0625");
  big a = ei, fa = fi;
  for (int i = 0; i < 4000; ++i) {
    big b = down ? big(a / factor) : big(a * factor);
    if (down && b < big("1e-30")) return 0;
    if (!down && b > big("1e30")) throw std::runtime_error("the flow runs to pure sliding");
    const big fb = fl.rate(b);
    if (fb == 0) return b;
    if ((fb < 0) != (fa < 0)) {
      boost::uintmax_t iters = 500;
      auto f = [&](const big& e) { return fl.rate(e); };
      const auto r =
          down ? boost::math::tools::toms748_solve(
                     f, b, a, fb, fa,
                     boost::math::tools::eps_tolerance<big>(std::numeric_limits<big>::digits - 4),
                     iters)
               : boost::math::tools::toms748_solve(
                     f, a, b, fa, fb,
                     boost::math::tools::eps_tolerance<big>(std::numeric_limits<big>::digits - 4),
                     iters);
      return (r.first + r.second) / 2;
    }
    a = b;
    fa = fb;
  }
  throw std::runtime_error("no attractor found");
}

}  // namespace throw_reference
