//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The expected stop time of a pure spin, shared by the tests of the
// dynamics (test_dynamics.cpp and test_dynamics_regressions.cpp).
#ifndef SPINSLIDE_TESTS_PURE_SPINNING_HPP
#define SPINSLIDE_TESTS_PURE_SPINNING_HPP

namespace spinslide_test {

// The pure-spinning stop time, derived: with v0 = 0 the ratio ε = v/ω stays 0,
// so dv/dt = −𝓕(0) = 0 and γ dω/dt = −𝓣(0), where 𝓣(0) = ∬ p r dA / ∬ p dA = ⟨r⟩
// (at ε = 0, ρ = r in the torque integral; docs/theory.md (L)): ω falls
// linearly and reaches 0 at t* = γω0/⟨r⟩.  ⟨r⟩ comes from quadrature of the load
// (quadrature_moments.hpp), γω0 is formed first and in long double, so that
// neither it nor ⟨r⟩/γ over- or underflows for the extreme γ of the fuzz
// regressions (test_dynamics_regressions.cpp).
// StopTime.PureSpinningIsWhereTheOdeintSpinCrossesZero (test_dynamics.cpp)
// checks the derivation on the odeint system.
inline long double pure_spin_stop_time(long double mean_radius, double gamma, double w0) {
  return static_cast<long double>(gamma) * w0 / mean_radius;
}

}  // namespace spinslide_test

#endif  // SPINSLIDE_TESTS_PURE_SPINNING_HPP
