//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Fuzz harness: the projection kernel and the DEM cap in float and in
// double (issue 26: what runs inside a step must answer in every precision).
// Profiles: the uniform disk, Hertz and an annulus, each in the fuzzed type.
// Calls: project_to_limit_set in a planar_metric (any symmetric matrix the
// metric accepts: it refuses beyond 1/√ε, 4.1e3 in float), and
// cap_trial_state with 2-component and 3-component vectors.
// Valid input must not throw (no evaluation_error, whatever the metric),
// and:
// - the projection keeps a sticking point, or lands on the curve (|f| = 𝓕(ε),
//   |t| = 𝓣(ε) to a few ulp) no farther than the curve's two ends along the
//   point's own force direction and torque sign;
// - the cap's friction stays in μN·(|F| ≤ 1, |T| ≤ a⟨r⟩), a sticking cap
//   keeps the springs, and a slipping one keeps springs that give it back
//   with the damping.

#include "fuzz.hpp"

#include <spinslide/contact/limit_set.hpp>
#include <spinslide/contact/trial_cap.hpp>
#include <spinslide/values/profile.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace {

using namespace spinslide_fuzz;

template <class Real>
using matrix = typename spinslide::planar_metric<Real>::matrix;

// D C D with C = L Lᵀ + 1e-3 I (L's entries in [−1, 1]) and D = diag(10^k),
// k in [−2, 2]: positive definite, of any condition up to about 1e11.
template <class Real>
matrix<Real> random_metric(fuzz_input& in) {
  matrix<Real> l{}, m{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j <= i; ++j) l[i][j] = 2 * in.uniform01<Real>() - 1;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t k = 0; k < 3; ++k) m[i][j] += l[i][k] * l[j][k];
  Real d[3];
  for (Real& x : d) x = static_cast<Real>(std::pow(10.0, static_cast<int>(in.byte() % 5) - 2));
  for (std::size_t i = 0; i < 3; ++i) m[i][i] += Real(1e-3);
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      m[i][j] *= d[i] * d[j];
      describe("m", m[i][j]);
    }
  return m;
}

template <class Real>
Real distance(const matrix<Real>& m, const std::array<Real, 3>& a, const std::array<Real, 3>& b) {
  const long double d[3] = {static_cast<long double>(a[0]) - b[0],
                            static_cast<long double>(a[1]) - b[1],
                            static_cast<long double>(a[2]) - b[2]};
  long double s = 0;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) s += d[i] * m[i][j] * d[j];
  return static_cast<Real>(s);
}

template <class P>
void fuzz_projection(fuzz_input& in, const P& p) {
  using Real = typename P::value_type;
  const matrix<Real> m = random_metric<Real>(in);
  const std::array<Real, 3> z{in.real<Real>(), in.real<Real>(), in.real<Real>()};
  for (Real x : z) describe("z", x);
  const bool finite = std::isfinite(z[0]) && std::isfinite(z[1]) && std::isfinite(z[2]);
  // A metric conditioned beyond 1/√ε is refused: either outcome.
  expect(validity::ambiguous, "planar_metric", [&] {
    const spinslide::planar_metric<Real> metric(m);
    expect(valid_if(finite), "project_to_limit_set(planar_metric)", [&] {
      const auto r = spinslide::project_to_limit_set(
          p, spinslide::tangent_wrench<Real>{z[0], z[1], z[2]}, metric);
      const char* call = "project_to_limit_set(planar_metric)";
      if (r.sticking) {
        check(r.force[0] == z[0] && r.force[1] == z[1] && r.torque == z[2], call,
              "sticking but moved");
        return;
      }
      check(r.ratio >= 0, call, "ratio < 0 or NaN");
      const Real eps = std::numeric_limits<Real>::epsilon();
      const auto c = p.force_torque(r.ratio);
      const Real f = std::hypot(r.force[0], r.force[1]);
      check(std::fabs(f - c.force) <= 8 * eps * (1 + c.force), call, "force off the curve");
      check(std::fabs(std::fabs(r.torque) - c.torque) <= 8 * eps * (1 + c.torque), call,
            "torque off the curve");
      const auto [dx, dy] = unit_direction(z[0], z[1]);
      const Real top = std::copysign(p.mean_radius(), z[2]);
      const std::array<Real, 3> here{r.force[0], r.force[1], r.torque};
      const Real d = distance(metric.entries(), here, z);
      if (!std::isfinite(d)) return;
      const Real slack = Real(1e-3) * d + 64 * eps * distance(metric.entries(), {0, 0, 0}, z) +
                         std::numeric_limits<Real>::min();
      check(d <= distance(metric.entries(), {dx, dy, 0}, z) + slack, call, "farther than (1, 0)");
      check(d <= distance(metric.entries(), {0, 0, top}, z) + slack, call, "farther than (0, <r>)");
    });
  });
}

template <int N, class P>
void fuzz_cap(fuzz_input& in, const P& p) {
  using Real = typename P::value_type;
  using vec = std::array<Real, N>;
  vec xi{}, damping{};
  for (Real& x : xi) x = in.real<Real>();
  for (Real& x : damping) x = in.real<Real>();
  const Real phi = in.real<Real>(), damping_torque = in.real<Real>();
  const Real kt = in.real<Real>(), kw = in.real<Real>();
  const Real a = in.real<Real>(), n = in.real<Real>(), mu = in.unit<Real>();
  for (Real x : {phi, damping_torque, kt, kw, a, n, mu}) describe("arg", x);
  bool finite = std::isfinite(phi) && std::isfinite(damping_torque);
  for (std::size_t i = 0; i < std::size_t(N); ++i)
    finite = finite && std::isfinite(xi[i]) && std::isfinite(damping[i]);
  const bool ok = finite && kt > 0 && std::isfinite(kt) && kw > 0 && std::isfinite(kw) && a > 0 &&
                  std::isfinite(a) && n >= 0 && std::isfinite(n) && mu >= 0 && std::isfinite(mu);
  // Valid where nothing on the way can overflow: the type's square root of
  // its range bounds every factor (the trial k ξ, the rewritten F/k).
  const Real big = std::sqrt(std::sqrt(std::numeric_limits<Real>::max()));
  auto moderate = [big](Real v) {
    return std::fabs(v) < big && (v == 0 || std::fabs(v) > 1 / big);
  };
  bool tame = ok && moderate(phi) && moderate(damping_torque) && moderate(kt) && moderate(kw) &&
              moderate(a) && moderate(n) && moderate(mu);
  for (std::size_t i = 0; i < std::size_t(N); ++i)
    tame = tame && moderate(xi[i]) && moderate(damping[i]);
  const validity v = !ok ? validity::invalid : tame ? validity::valid : validity::ambiguous;
  expect(v, "cap_trial_state", [&] {
    const auto r = spinslide::cap_trial_state(
        p, spinslide::spring_trial<vec, Real>{xi, phi, damping, damping_torque},
        spinslide::spring_stiffness<Real>{spinslide::tangential_stiffness<Real>{kt},
                                          spinslide::twisting_stiffness<Real>{kw}},
        spinslide::force_contact<Real>{spinslide::patch_radius<Real>{a},
                                       spinslide::normal_force<Real>{n},
                                       spinslide::friction_coefficient<Real>{mu}});
    const char* call = "cap_trial_state";
    const long double load = static_cast<long double>(mu) * n;
    long double f2 = 0;
    for (std::size_t i = 0; i < std::size_t(N); ++i) {
      check_finite(r.force[i], call, "force");
      f2 += static_cast<long double>(r.force[i]) * r.force[i];
    }
    check_finite(r.torque, call, "torque");
    if (r.sticking) {
      check(r.displacement == xi && r.twist == phi, call, "sticking but the springs moved");
      return;
    }
    // The bounds where no factor is near the type's limits (μN among the
    // subnormals carries a bit or two: 1e-43 in float).
    if (!tame) return;
    const long double eps = std::numeric_limits<Real>::epsilon();
    check(std::sqrt(f2) <= load * (1 + 16 * eps) + std::numeric_limits<Real>::denorm_min() * 4,
          call, "|F| > mu N while slipping");
    check(std::fabs(static_cast<long double>(r.torque)) <=
              load * a * p.mean_radius() * (1 + 16 * eps) +
                  std::numeric_limits<Real>::denorm_min() * 4,
          call, "|T| > mu N a <r> while slipping");
  });
}

template <class Real>
void fuzz_type(fuzz_input& in) {
  const std::size_t which = in.choice(3), call = in.choice(3);
  auto run = [&](const auto& p) {
    if (call == 0) fuzz_projection(in, p);
    if (call == 1) fuzz_cap<2>(in, p);
    if (call == 2) fuzz_cap<3>(in, p);
  };
  if (which == 0) run(spinslide::uniform_disk<Real>());
  if (which == 1) run(spinslide::hertz<Real>());
  if (which == 2) {
    const Real b = in.uniform01<Real>() * Real(0.95);
    describe("inner_ratio", b);
    run(spinslide::annulus<Real>(b));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz_input in(data, size);
  context().clear();
  if (in.choice(2) == 0) {
    fuzz_type<float>(in);
  } else {
    fuzz_type<double>(in);
  }
  return 0;
}
