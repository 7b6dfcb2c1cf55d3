//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Fuzz harness: the uniform disk's force, torque, force_torque, their
// derivatives and force_torque_batch, in float, double and long double.
// Valid: ε ≥ 0 (+∞ included).  Then 0 ≤ 𝓕 ≤ 1, 0 ≤ 𝓣 ≤ 2/3, 𝓕′ ≥ 0 ≥ 𝓣′,
// all finite; force_torque within 4 ulp of force and torque (the batch too).

#include "fuzz.hpp"

#include <spinslide/values/disk.hpp>

#include <vector>

namespace {

using namespace spinslide_fuzz;

template <class Real>
bool close(Real a, Real b, Real ulps) {
  const Real scale = std::fmax(std::fabs(a), std::fabs(b));
  return std::fabs(a - b) <= ulps * std::numeric_limits<Real>::epsilon() * scale ||
         std::fabs(a - b) <= std::numeric_limits<Real>::min();
}

template <class Real>
void check_values(Real F, Real T, const char* call) {
  check_finite(F, call, "F");
  check_finite(T, call, "T");
  const Real rounding = 1 + 4 * std::numeric_limits<Real>::epsilon();
  check(F >= 0 && F <= 1, call, "F outside [0, 1]");
  check(T >= 0 && T <= Real(2) / 3 * rounding, call, "T outside [0, 2/3]");
}

template <class Real>
void disk(Real eps) {
  context().clear();
  describe("eps", eps);
  const validity v = valid_if(eps >= 0);
  Real F = 0, T = 0;
  expect(v, "force", [&] { F = spinslide::force(eps); });
  expect(v, "torque", [&] { T = spinslide::torque(eps); });
  if (v == validity::valid) check_values(F, T, "force/torque");
  expect(v, "force_torque", [&] {
    const auto ft = spinslide::force_torque(eps);
    check_values(ft.force, ft.torque, "force_torque");
    check(close(ft.force, F, Real(4)) && close(ft.torque, T, Real(4)), "force_torque",
          "differs from force(eps), torque(eps) by more than 4 ulp");
  });
  expect(v, "force_derivative", [&] {
    const Real d = spinslide::force_derivative(eps);
    check_finite(d, "force_derivative", "dF/deps");
    check(d >= 0, "force_derivative", "dF/deps < 0");
  });
  expect(v, "torque_derivative", [&] {
    const Real d = spinslide::torque_derivative(eps);
    check_finite(d, "torque_derivative", "dT/deps");
    check(d <= 0, "torque_derivative", "dT/deps > 0");
  });
}

template <class Real>
void batch(fuzz_input& in) {
  const std::size_t n = in.choice(20);
  std::vector<Real> eps(n), F(n), T(n);
  bool ok = true;
  context().clear();
  for (std::size_t i = 0; i < n; ++i) {
    eps[i] = in.real<Real>();
    describe("eps", eps[i]);
    ok = ok && eps[i] >= 0;
  }
  expect(valid_if(ok), "force_torque_batch", [&] {
    spinslide::force_torque_batch(eps.data(), n, F.data(), T.data());
    for (std::size_t i = 0; i < n; ++i) {
      check_values(F[i], T[i], "force_torque_batch");
      const auto ft = spinslide::force_torque(eps[i]);
      check(close(F[i], ft.force, Real(4)) && close(T[i], ft.torque, Real(4)), "force_torque_batch",
            "differs from force_torque by more than 4 ulp");
    }
  });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz_input in(data, size);
  disk(in.real<double>());
  disk(in.real<float>());
  disk(in.real<long double>());
  batch<double>(in);
  batch<float>(in);
  return 0;
}
