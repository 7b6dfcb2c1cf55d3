//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The parts of generate_throw_reference (its main file,
// generate_throw_reference.cpp, says what it computes and how):
//   throw_reference_loads.cpp     the closed forms of 𝓕 and 𝓣 of each load,
//                                 and the attractor of a flow;
//   throw_reference_integral.cpp  the nested quadrature in the ratio (the
//                                 Gauss–Legendre panels and the tail);
//   throw_reference_validate.cpp  --validate: synthetic flows with exact
//                                 answers, the closed forms against the tables.
// Standard library and Boost only: nothing of spinslide.
#ifndef SPINSLIDE_TESTS_REFERENCE_THROW_REFERENCE_HPP
#define SPINSLIDE_TESTS_REFERENCE_THROW_REFERENCE_HPP

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cstddef>
#include <vector>

namespace throw_reference {

using big = boost::multiprecision::cpp_bin_float_100;

struct ft {
  big force, torque;
};

inline big pi() { return boost::math::constants::pi<big>(); }

// 𝓕 and 𝓣 of each load at ratio e (throw_reference_loads.cpp): the uniform
// disk, the ring of radius 1, Hertz, Boussinesq, 3/4 on the ring and 1/4 as
// a uniform disk of radius 1/8 at the centre, and the paper's CD (the annulus
// 1/8 ≤ r ≤ 1).
ft disk(const big& e);
ft ring(const big& e);
ft hertz(const big& e);
ft boussinesq(const big& e);
ft ring_and_core(const big& e);
ft cd_annulus(const big& e);

// The synthetic flows of --validate: f = ε − γ𝓕/𝓣 prescribed, so 𝓕 = (𝓣/γ)(ε − f),
// and 𝓣 = T constant: t* = γω0/T and θ* = γω0²/(2T) exactly, s* exactly for the
// linear flows; or 𝓣 = T + T₁(ε − ε₀) with f linear (linear_torque): t*, s*, θ*
// as series (validate()), a check of the tail's 𝓣 = 𝓣(ε₀).
inline const big synthetic_torque = big(7) / 10, torque_slope = big(1) / 10;
inline const big linear_zero = big(4) / 5, linear_rate = big(13) / 10, quadratic_b = big(1) / 2;

inline long evaluations = 0;  // of f, for the progress report

enum class load {
  disk,
  hertz,
  boussinesq,
  ring_and_core,
  cd_annulus,
  linear,
  linear_torque,
  quadratic,
  spin_linear
};

struct flow {
  load kind;
  big gamma;

  [[nodiscard]] ft at(const big& e) const {
    switch (kind) {
      case load::disk:
        return disk(e);
      case load::hertz:
        return hertz(e);
      case load::boussinesq:
        return boussinesq(e);
      case load::ring_and_core:
        return ring_and_core(e);
      case load::cd_annulus:
        return cd_annulus(e);
      default:
        break;
    }
    const big torque = kind == load::linear_torque
                           ? big(synthetic_torque + torque_slope * (e - linear_zero))
                           : synthetic_torque;
    return {torque * (e - synthetic_rate(e)) / gamma, torque};
  }
  // The prescribed f of the synthetic flows.
  [[nodiscard]] big synthetic_rate(const big& e) const {
    const big d = e - linear_zero;
    if (kind == load::linear || kind == load::linear_torque) return -linear_rate * d;
    if (kind == load::quadratic) return -linear_rate * d + quadratic_b * d * d;
    return -e / 2;  // spin_linear: ε → 0 with κ = 1/2
  }
  [[nodiscard]] big rate(const big& e) const {  // f(ε)
    ++evaluations;
    const ft v = at(e);
    return e - gamma * v.force / v.torque;
  }
  // Points where 𝓕 or 𝓣 is not analytic.
  [[nodiscard]] std::vector<big> breaks() const {
    if (kind == load::ring_and_core || kind == load::cd_annulus) return {big(1) / 8, big(1)};
    if (kind == load::disk || kind == load::hertz || kind == load::boussinesq) return {big(1)};
    return {};
  }
};

// The attractor the flow from ε_i reaches (0: pure spinning).
big attractor(const flow& fl, const big& ei);

struct route {
  std::size_t points;  // Gauss–Legendre points per panel
  big width;           // the largest panel in u
  big tolerance;       // of the panels' last Legendre coefficients, relative
  big narrowest;       // panels are not bisected below this width
  big cut, cut_zero;   // δ_c for ε₀ > 0 and for ε₀ = 0
};
inline const route route_a{40, big(1), big("1e-40"), big("1e-40"), big("1e-45"), big("1e-22")};
inline const route route_b{30, big(1) / 2, big("1e-38"), big("1e-36"), big("1e-40"), big("1e-20")};

struct result {
  big end, time, distance, angle;
};

// A throw with ω0 = 1 (throw_reference_integral.cpp).
result unit_throw(const flow& fl, const route& r, const big& ei);

inline big rel(const big& a, const big& b) { return b == 0 ? abs(a) : big(abs(a / b - 1)); }

// --validate (throw_reference_validate.cpp): the exit status.
int validate();

}  // namespace throw_reference

#endif  // SPINSLIDE_TESTS_REFERENCE_THROW_REFERENCE_HPP
