//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Cost of one (𝓕, 𝓣) pair of the uniform disk over 4096 log-uniform ε in
// [1e-3, 1e3], against, in the same binary:
//   - the literal closed form with Boost's ellint_1/ellint_2, default policy
//     (double promoted to long double): the baseline;
//   - the same with promote_double<false>;
//   - K and E together by the arithmetic-geometric mean, then the closed form;
//   - Boost's tanh_sinh quadrature of the defining integral (inner integral
//     in closed form, as in tests/reference/generate_disk_reference.cpp);
//   - a degree-8/8 rational for each of 𝓕 and 𝓣: a speed bound, not a
//     method (its accuracy is printed; it cannot follow the ε = 1 singularity).
// And the projection onto the limit set (limit_set.hpp) of the uniform disk,
// Hertz and a tabulated profile (the CD annulus, b = 1/8), against that
// profile's force_torque at the same ratios:
//   - sliding: P = C(ε) + 0.2 (ε, 1) (w = 1), which projects to C(ε); "warm"
//     starts from ε(1 + 1e-3) (a contact whose ratio moved 0.1 % since the
//     last step), "cold" from no guess;
//   - sticking: P = θ C(ε), θ uniform in [0.5, 0.99] (inside L, most of them
//     outside the triangle that decides without an evaluation), warm.
// "scalar" benchmarks hand each result to benchmark::DoNotOptimize, which
// keeps the loop scalar; "array" benchmarks write output arrays in a plain
// loop, which the compiler may vectorize.
//   ./build/release/benchmarks/bench_disk
#include <benchmark/benchmark.h>

#include <spinslide/contact/contact_law.hpp>
#include <spinslide/contact/impulse_friction.hpp>
#include <spinslide/contact/limit_set.hpp>
#include <spinslide/contact/spring_friction.hpp>
#include <spinslide/values/disk.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/tabulated.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/asinh.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "../tools/least_squares.hpp"
#include "ratio_reporter.hpp"

namespace {

template <class Real>
const std::vector<Real>& inputs() {
  static const std::vector<Real> xs = [] {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-3, 3);
    std::vector<Real> v(4096);
    for (auto& x : v) x = static_cast<Real>(std::pow(10.0, u(rng)));
    return v;
  }();
  return xs;
}

using pair = spinslide::force_torque_result<double>;

// The paper's closed forms (torque corrected, docs/theory.md §3), literally.
pair closed_form(double e, double K, double E) {
  const double pi = boost::math::constants::pi<double>();
  const double k = e <= 1 ? e : 1 / e, m = k * k;
  if (e <= 1)
    return {4 * ((1 + m) * E - (1 - m) * K) / (3 * pi * k),
            4 * ((4 - 2 * m) * E - (1 - m) * K) / (9 * pi)};
  return {4 * ((1 + m) * E - (1 - m) * K) / (3 * pi * m),
          4 * ((4 * m - 2) * E + (1 - m) * (2 - 3 * m) * K) / (9 * pi * k * m)};
}

template <class Policy>
pair literal(double e, const Policy& pol) {
  const double k = e <= 1 ? e : 1 / e;
  return closed_form(e, boost::math::ellint_1(k, pol), boost::math::ellint_2(k, pol));
}

// K(k) and E(k) by the AGM (DLMF 19.8.1, 19.8.6): a₀ = 1, b₀ = k′, c₀ = k;
// K = π/(2 a_N), E = K (1 − Σ 2^(n−1) c_n²).
pair agm(double e) {
  const double k = e <= 1 ? e : 1 / e;
  double a = 1, b = std::sqrt((1 - k) * (1 + k)), c = k, sum = c * c / 2, w = 0.5;
  // c_{n+1} = c_n²/(4a_{n+1}): once c is below 1e-15 a it is at the rounding
  // level; the bound guards against a stall there.
  for (int n = 0; n < 64 && std::fabs(c) > 1e-15 * a; ++n) {
    const double an = (a + b) / 2;
    c = (a - b) / 2;
    b = std::sqrt(a * b);
    a = an;
    w *= 2;
    sum += w * c * c;
  }
  const double K = boost::math::constants::pi<double>() / (2 * a);
  return closed_form(e, K, K * (1 - sum));
}

// tanh_sinh over y of the inner x-integrals of the area integral (theory (D)).
pair quadrature(double eps) {
  static boost::math::quadrature::tanh_sinh<double> q;
  auto parts = [eps](double y, double& X, double& S, double& c, double& L) {
    X = std::sqrt((1 - y) * (1 + y));
    c = y - eps;
    S = std::sqrt(X * X + c * c);
    L = c == 0 ? 0.0 : boost::math::asinh(X / std::fabs(c));
  };
  auto f = [&](double y) {
    double X, S, c, L;
    parts(y, X, S, c, L);
    return -2 * c * L;
  };
  auto t = [&](double y) {
    double X, S, c, L;
    parts(y, X, S, c, L);
    return X * S + c * (y + eps) * L;
  };
  auto over_y = [&](auto g) {
    const double tol = 1e-10;
    if (eps < 1) return q.integrate(g, -1.0, eps, tol) + q.integrate(g, eps, 1.0, tol);
    return q.integrate(g, -1.0, 1.0, tol);
  };
  const double pi = boost::math::constants::pi<double>();
  return {over_y(f) / pi, over_y(t) / pi};
}

// P₈/Q₈ for g_F(t) = 𝓕/t and g_T(t) = 𝓣/(1 − t), t = ε/(1 + ε), fitted by
// linearized least squares (P − g·Q = 0, Q's constant term 1) at 400
// Chebyshev points, solved by Householder QR in long double.
struct rational {
  std::array<double, 9> p, q;  // q[0] = 1
  double operator()(double u) const {
    double n = p[8], d = q[8];
    for (std::size_t k = 8; k-- > 0;) {
      n = n * u + p[k];
      d = d * u + q[k];
    }
    return n / d;
  }
};

std::pair<rational, rational> fit_rationals() {
  const int n = 400;
  std::vector<std::vector<long double>> AF, AT;
  std::vector<long double> bF, bT;
  for (int j = 0; j < n; ++j) {
    const long double u = std::cos(boost::math::constants::pi<long double>() * (j + 0.5L) / n);
    const long double t = (1 + u) / 2, eps = t / (1 - t);
    const auto ft = spinslide::force_torque(eps);
    const long double gF = ft.force / t, gT = ft.torque / (1 - t);
    std::vector<long double> rowF, rowT;
    long double w = 1;
    for (int k = 0; k <= 8; ++k, w *= u) {
      rowF.push_back(w);
      rowT.push_back(w);
    }
    w = u;
    for (int k = 1; k <= 8; ++k, w *= u) {
      rowF.push_back(-gF * w);
      rowT.push_back(-gT * w);
    }
    AF.push_back(rowF);
    AT.push_back(rowT);
    bF.push_back(0 + gF);
    bT.push_back(0 + gT);
  }
  auto make = [](const std::vector<long double>& x) {
    rational r;
    for (std::size_t k = 0; k <= 8; ++k) r.p[k] = static_cast<double>(x[k]);
    r.q[0] = 1;
    for (std::size_t k = 1; k <= 8; ++k) r.q[k] = static_cast<double>(x[8 + k]);
    return r;
  };
  return {make(spinslide_tools::least_squares(AF, bF)),
          make(spinslide_tools::least_squares(AT, bT))};
}

const std::pair<rational, rational>& rationals() {
  static const auto r = fit_rationals();
  return r;
}

inline pair rational_pair(double eps, const rational& rf, const rational& rt) {
  const double s = 1 / (1 + eps), t = eps * s, u = 2 * t - 1;
  return {t * rf(u), s * rt(u)};
}

template <class Real, class F>
void scalar(benchmark::State& state, F f) {
  const auto& xs = inputs<Real>();
  for (auto _ : state) {
    for (const Real& x : xs) {
      auto r = f(x);
      benchmark::DoNotOptimize(r);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(xs.size()));
}

void literal_boost_default_policy(benchmark::State& s) {
  scalar<double>(s, [](double e) { return literal(e, boost::math::policies::policy<>()); });
}
void literal_boost_no_promotion(benchmark::State& s) {
  using namespace boost::math::policies;
  scalar<double>(s, [](double e) { return literal(e, policy<promote_double<false>>()); });
}
void agm_closed_form(benchmark::State& s) { scalar<double>(s, agm); }
void boost_tanh_sinh_quadrature(benchmark::State& s) { scalar<double>(s, quadrature); }
void rational_8_8_scalar(benchmark::State& s) {
  const rational rf = rationals().first, rt = rationals().second;
  scalar<double>(s, [&](double e) { return rational_pair(e, rf, rt); });
}
void rational_8_8_array(benchmark::State& s) {
  const rational rf = rationals().first, rt = rationals().second;
  const auto& xs = inputs<double>();
  std::vector<double> f(xs.size()), t(xs.size());
  for (auto _ : s) {
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const pair r = rational_pair(xs[i], rf, rt);
      f[i] = r.force;
      t[i] = r.torque;
    }
    benchmark::DoNotOptimize(f.data());
    benchmark::DoNotOptimize(t.data());
    benchmark::ClobberMemory();
  }
  s.SetItemsProcessed(s.iterations() * static_cast<int64_t>(xs.size()));
}
void spinslide_force_torque_double(benchmark::State& s) {
  scalar<double>(s, [](double e) { return spinslide::force_torque(e); });
}
void spinslide_force_plus_torque_double(benchmark::State& s) {
  scalar<double>(s, [](double e) { return spinslide::force(e) + spinslide::torque(e); });
}
template <class Real>
void spinslide_batch(benchmark::State& s) {
  const auto& xs = inputs<Real>();
  std::vector<Real> f(xs.size()), t(xs.size());
  for (auto _ : s) {
    spinslide::force_torque_batch(xs.data(), xs.size(), f.data(), t.data());
    benchmark::DoNotOptimize(f.data());
    benchmark::DoNotOptimize(t.data());
    benchmark::ClobberMemory();
  }
  s.SetItemsProcessed(s.iterations() * static_cast<int64_t>(xs.size()));
}
void spinslide_batch_double(benchmark::State& s) { spinslide_batch<double>(s); }
void spinslide_force_torque_float(benchmark::State& s) {
  scalar<float>(s, [](float e) { return spinslide::force_torque(e); });
}
void spinslide_batch_float(benchmark::State& s) { spinslide_batch<float>(s); }
void spinslide_force_torque_long_double(benchmark::State& s) {
  scalar<long double>(s, [](long double e) { return spinslide::force_torque(e); });
}
void spinslide_force_torque_cpp_bin_float_50(benchmark::State& s) {
  using mp = boost::multiprecision::cpp_bin_float_50;
  scalar<mp>(s, [](const mp& e) { return spinslide::force_torque(e); });
}

// The contact law per call, at the same ratios: v = (ε cos φ, ε sin φ), ω = 1, a = 1.
// a = 1, N = 2, μ = 0.5; the regularization of 1e-6 is below every input.
const spinslide::force_contact<double>& law_contact() {
  static const spinslide::force_contact<double> c{spinslide::patch_radius<double>{1.0},
                                                  spinslide::normal_force<double>{2.0},
                                                  spinslide::friction_coefficient<double>{0.5}};
  return c;
}
void contact_law_uniform_disk(benchmark::State& s) {
  static const spinslide::contact_law<> law(spinslide::uniform_disk<>(),
                                            spinslide::velocity_scale<double>{1e-6});
  scalar<double>(s, [](double e) {
    const std::array<double, 2> v = {0.6 * e, 0.8 * e};
    return law(v, 1.0, law_contact());
  });
}
void contact_law_tabulated_disk(benchmark::State& s) {
  static const spinslide::contact_law<spinslide::tabulated_profile<>> law{
      spinslide::tabulated_profile<>(spinslide::uniform_disk<>()),
      spinslide::velocity_scale<double>{1e-6}};
  scalar<double>(s, [](double e) {
    const std::array<double, 2> v = {0.6 * e, 0.8 * e};
    return law(v, 1.0, law_contact());
  });
}
void tabulated_disk_force_torque(benchmark::State& s) {
  static const spinslide::tabulated_profile<> tab{spinslide::uniform_disk<>()};
  scalar<double>(s, [](double e) { return tab.force_torque(e); });
}

// The projection's profiles: the uniform disk, Hertz, and a tabulated CD annulus.
template <class P>
const P& projected() {
  static const P p;
  return p;
}
using tabulated_cd = spinslide::tabulated_profile<>;
template <>
const tabulated_cd& projected<tabulated_cd>() {
  static const tabulated_cd p{spinslide::annulus<>(0.125)};
  return p;
}

struct projection_case {
  double force, torque, start;
};
template <class P>
const std::vector<projection_case>& projection_cases(bool sliding) {
  static const auto make = [](bool slide) {
    std::mt19937_64 rng(43);
    std::uniform_real_distribution<double> theta(0.5, 0.99);
    std::vector<projection_case> v;
    for (double e : inputs<double>()) {
      const auto c = projected<P>().force_torque(e);
      const double q = theta(rng);
      v.push_back(slide ? projection_case{c.force + 0.2 * e, c.torque + 0.2, e * (1 + 1e-3)}
                        : projection_case{q * c.force, q * c.torque, e});
    }
    return v;
  };
  static const std::vector<projection_case> slide = make(true), stick = make(false);
  return sliding ? slide : stick;
}

template <class P>
void profile_force_torque(benchmark::State& s) {
  scalar<double>(s, [](double e) { return projected<P>().force_torque(e); });
}
// The same evaluations as a dependent chain (each ε waits for the previous
// result, as a projection's iterations do): the latency of one evaluation,
// where the loop above measures the throughput of independent ones.
template <class P>
void profile_force_torque_chained(benchmark::State& s) {
  const auto& xs = inputs<double>();
  for (auto _ : s) {
    double carry = 0;
    for (const double e : xs) {
      const auto r = projected<P>().force_torque(e + carry);
      carry = r.force * 1e-300;  // ≈ 0, but the compiler cannot know
    }
    benchmark::DoNotOptimize(carry);
  }
  s.SetItemsProcessed(s.iterations() * static_cast<int64_t>(xs.size()));
}
template <class P>
void projection(benchmark::State& s, bool sliding, bool warm) {
  const auto& cases = projection_cases<P>(sliding);
  for (auto _ : s) {
    for (const auto& c : cases) {
      const auto r =
          spinslide::project_to_limit_set(projected<P>(), c.force, c.torque, 1.0,
                                          spinslide::curve_point<double>{warm ? c.start : 0.0});
      benchmark::DoNotOptimize(r);
    }
  }
  s.SetItemsProcessed(s.iterations() * static_cast<int64_t>(cases.size()));
}
template <class P>
void projection_sliding_warm(benchmark::State& s) {
  projection<P>(s, true, true);
}
template <class P>
void projection_sliding_cold(benchmark::State& s) {
  projection<P>(s, true, false);
}
template <class P>
void projection_sticking_warm(benchmark::State& s) {
  projection<P>(s, false, true);
}
// The sliding cases from the curve point of the last step's answer (the
// projection of C(ε') + 0.2(ε', 1), ε' = ε(1 + 1e-3): the warm start's ratio,
// with 𝓕, 𝓣, 𝓕′ and 𝓕″ there), as a contact's history keeps it.
template <class P>
void projection_sliding_from_point(benchmark::State& s) {
  const auto& cases = projection_cases<P>(true);
  static const std::vector<spinslide::curve_point<double>> points = [&cases] {
    std::vector<spinslide::curve_point<double>> v;
    for (const auto& c : cases) {
      const double e = c.start;
      const auto ft = projected<P>().force_torque(e);
      v.push_back(spinslide::project_to_limit_set(projected<P>(), ft.force + 0.2 * e,
                                                  ft.torque + 0.2, 1.0,
                                                  spinslide::curve_point<double>{e})
                      .curve());
    }
    return v;
  }();
  for (auto _ : s) {
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const auto r = spinslide::project_to_limit_set(projected<P>(), cases[i].force,
                                                     cases[i].torque, 1.0, points[i]);
      benchmark::DoNotOptimize(r);
    }
  }
  s.SetItemsProcessed(s.iterations() * static_cast<int64_t>(cases.size()));
}
// The impulse law (impulse_friction.hpp) with a coupled inverse mass (a body
// whose contact point has a lever arm): each input ratio ε gives a slip
// (ε cos φ, ε sin φ, 1) with φ = ε; a normal impulse of 1e-3 lets every one
// slip, one of 1e3 stops every one.  Warm: started from the answer's ratio
// times 1 + 1e-3 (the last step's, in an engine).
struct impulse_case {
  std::array<double, 2> v;
  double spin, start;
};
const spinslide::planar_metric<double>& coupled_inverse_mass() {
  static const spinslide::planar_metric<double> w(
      {{{2.0, 0.3, 0.2}, {0.3, 1.5, -0.1}, {0.2, -0.1, 3.0}}});
  return w;
}
spinslide::impulse_contact<double> impulse_load(double normal) {
  return {spinslide::patch_radius<double>{1.0}, spinslide::normal_impulse<double>{normal},
          spinslide::friction_coefficient<double>{1.0}};
}
template <class P>
const std::vector<impulse_case>& impulse_cases() {
  static const std::vector<impulse_case> v = [] {
    std::vector<impulse_case> out;
    for (double e : inputs<double>()) {
      impulse_case c{{e * std::cos(e), e * std::sin(e)}, 1.0, 0.0};
      c.start = spinslide::impulse_friction(projected<P>(), c.v, c.spin, coupled_inverse_mass(),
                                            impulse_load(1e-3))
                    .ratio *
                (1 + 1e-3);
      out.push_back(c);
    }
    return out;
  }();
  return v;
}
template <class P>
void impulse(benchmark::State& s, double normal, bool warm) {
  const auto& cases = impulse_cases<P>();
  const auto load = impulse_load(normal);
  for (auto _ : s) {
    for (const auto& c : cases) {
      const auto r =
          spinslide::impulse_friction(projected<P>(), c.v, c.spin, coupled_inverse_mass(), load,
                                      spinslide::curve_point<double>{warm ? c.start : 0.0});
      benchmark::DoNotOptimize(r);
    }
  }
  s.SetItemsProcessed(s.iterations() * static_cast<int64_t>(cases.size()));
}
template <class P>
void impulse_sliding_warm(benchmark::State& s) {
  impulse<P>(s, 1e-3, true);
}
// The sliding cases from the curve point of the last step's answer (the
// slip with its spin 1e-3 higher: ratio, 𝓕 and 𝓣 there), as
// spinslide::pair_friction keeps it.
template <class P>
void impulse_sliding_from_point(benchmark::State& s) {
  const auto& cases = impulse_cases<P>();
  const auto load = impulse_load(1e-3);
  static const std::vector<spinslide::curve_point<double>> points = [&cases, &load] {
    std::vector<spinslide::curve_point<double>> v;
    for (const auto& c : cases)
      v.push_back(spinslide::impulse_friction(projected<P>(), c.v, c.spin * (1 + 1e-3),
                                              coupled_inverse_mass(), load)
                      .curve());
    return v;
  }();
  for (auto _ : s) {
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const auto r = spinslide::impulse_friction(projected<P>(), cases[i].v, cases[i].spin,
                                                 coupled_inverse_mass(), load, points[i]);
      benchmark::DoNotOptimize(r);
    }
  }
  s.SetItemsProcessed(s.iterations() * static_cast<int64_t>(cases.size()));
}
template <class P>
void impulse_sliding_cold(benchmark::State& s) {
  impulse<P>(s, 1e-3, false);
}
template <class P>
void impulse_sticking(benchmark::State& s) {
  impulse<P>(s, 1e3, false);
}
// The spring-history law (spring_friction.hpp), Mindlin springs: sliding
// from the steady state of each ratio ε (the springs holding μN(𝓕, a𝓣)(ε),
// the history's ratio ε and its curve point, the next increment
// (εaΔφ, 0, Δφ)), which caps back
// onto the same point; sticking from relaxed springs and a small increment.
struct spring_case {
  spinslide::spring_history<std::array<double, 2>, double> history;
  std::array<double, 2> increment;
  double twist;
};
const spinslide::spring_stiffness<double>& bench_springs() {
  static const auto k = spinslide::mindlin_springs(spinslide::tangential_stiffness<double>{1e5},
                                                   spinslide::patch_radius<double>{0.01});
  return k;
}
spinslide::force_contact<double> spring_load() {
  return {spinslide::patch_radius<double>{0.01}, spinslide::normal_force<double>{10.0},
          spinslide::friction_coefficient<double>{0.3}};
}
template <class P>
const std::vector<spring_case>& spring_cases(bool sliding) {
  static const auto make = [](bool slide) {
    std::vector<spring_case> out;
    const double a = 0.01, load = 3, dphi = 1e-4;
    const auto& k = bench_springs();
    for (double e : inputs<double>()) {
      const auto c = projected<P>().force_torque(e);
      spring_case sc{
          {{load * c.force / k.tangential.value, 0}, load * a * c.torque / k.twisting.value, {e}},
          {-e * a * dphi, 0},
          -dphi};
      // the curve point the steady slip keeps (ε, 𝓕, 𝓣, 𝓕′, 𝓕″ at ε): the
      // projection of a point on the normal at ε, from next to ε
      sc.history.curve =
          spinslide::project_to_limit_set(projected<P>(), c.force + 0.01 * 2 * e, c.torque + 0.01,
                                          2.0, spinslide::curve_point<double>{e * (1 + 1e-4)})
              .curve();
      if (!slide) sc = {{{0, 0}, 0, {}}, {1e-7, 0}, 1e-5};
      out.push_back(sc);
    }
    return out;
  };
  static const std::vector<spring_case> slide = make(true), stick = make(false);
  return sliding ? slide : stick;
}
template <class P>
void springs(benchmark::State& s, bool sliding) {
  const auto& cases = spring_cases<P>(sliding);
  const auto load = spring_load();
  for (auto _ : s) {
    for (const auto& c : cases) {
      auto h = c.history;
      const auto r = spinslide::spring_history_friction(projected<P>(), h, c.increment, c.twist,
                                                        bench_springs(), load);
      benchmark::DoNotOptimize(r);
      benchmark::DoNotOptimize(h);
    }
  }
  s.SetItemsProcessed(s.iterations() * static_cast<int64_t>(cases.size()));
}
template <class P>
void spring_sliding_warm(benchmark::State& s) {
  springs<P>(s, true);
}
template <class P>
void spring_sticking(benchmark::State& s) {
  springs<P>(s, false);
}
#define SPINSLIDE_BENCH_PROJECTION(P)                   \
  BENCHMARK_TEMPLATE(profile_force_torque, P);          \
  BENCHMARK_TEMPLATE(profile_force_torque_chained, P);  \
  BENCHMARK_TEMPLATE(projection_sliding_warm, P);       \
  BENCHMARK_TEMPLATE(projection_sliding_from_point, P); \
  BENCHMARK_TEMPLATE(projection_sliding_cold, P);       \
  BENCHMARK_TEMPLATE(projection_sticking_warm, P);      \
  BENCHMARK_TEMPLATE(impulse_sliding_warm, P);          \
  BENCHMARK_TEMPLATE(impulse_sliding_from_point, P);    \
  BENCHMARK_TEMPLATE(impulse_sliding_cold, P);          \
  BENCHMARK_TEMPLATE(impulse_sticking, P);              \
  BENCHMARK_TEMPLATE(spring_sliding_warm, P);           \
  BENCHMARK_TEMPLATE(spring_sticking, P);
SPINSLIDE_BENCH_PROJECTION(spinslide::uniform_disk<>)
SPINSLIDE_BENCH_PROJECTION(spinslide::hertz<>)
SPINSLIDE_BENCH_PROJECTION(tabulated_cd)

BENCHMARK(literal_boost_default_policy);
BENCHMARK(literal_boost_no_promotion);
BENCHMARK(agm_closed_form);
BENCHMARK(boost_tanh_sinh_quadrature);
BENCHMARK(rational_8_8_scalar);
BENCHMARK(rational_8_8_array);
BENCHMARK(spinslide_force_torque_double);
BENCHMARK(spinslide_batch_double);
BENCHMARK(spinslide_force_plus_torque_double);
BENCHMARK(spinslide_force_torque_float);
BENCHMARK(spinslide_batch_float);
BENCHMARK(spinslide_force_torque_long_double);
BENCHMARK(spinslide_force_torque_cpp_bin_float_50);
BENCHMARK(contact_law_uniform_disk);
BENCHMARK(tabulated_disk_force_torque);
BENCHMARK(contact_law_tabulated_disk);

// The largest relative error of each double method over the benchmark's
// inputs, against spinslide's long double evaluation.
void print_accuracy() {
  const rational rf = rationals().first, rt = rationals().second;
  const std::pair<const char*, pair (*)(double)> methods[] = {
      {"literal_boost_default_policy",
       [](double e) { return literal(e, boost::math::policies::policy<>()); }},
      {"agm_closed_form", agm},
      {"boost_tanh_sinh_quadrature", quadrature},
      {"spinslide_force_torque_double", [](double e) { return spinslide::force_torque(e); }},
  };
  std::printf("largest relative error over the inputs (vs long double):\n");
  auto report = [](const char* name, auto f) {
    double worst = 0;
    for (double e : inputs<double>()) {
      const auto exact = spinslide::force_torque(static_cast<long double>(e));
      const pair r = f(e);
      worst = std::max({worst, static_cast<double>(std::fabs(r.force - exact.force) / exact.force),
                        static_cast<double>(std::fabs(r.torque - exact.torque) / exact.torque)});
    }
    std::printf("  %-40s %.2e\n", name, worst);
  };
  for (const auto& m : methods) report(m.first, m.second);
  report("rational_8_8", [&](double e) { return rational_pair(e, rf, rt); });
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  print_accuracy();
  spinslide_bench::ratio_reporter reporter(
      "literal_boost_default_policy",
      {{"spinslide_force_torque_double", "rational_8_8_scalar"},
       {"spinslide_batch_double", "rational_8_8_array"},
       {"spinslide_force_torque_float", "rational_8_8_scalar"},
       {"spinslide_batch_float", "rational_8_8_array"},
       {"contact_law_uniform_disk", "spinslide_force_torque_double"},
       {"contact_law_tabulated_disk", "tabulated_disk_force_torque"}});
  for (const char* p : {"spinslide::uniform_disk<>", "spinslide::hertz<>", "tabulated_cd"}) {
    const std::string base = std::string("profile_force_torque<") + p + ">";
    const std::string chained = std::string("profile_force_torque_chained<") + p + ">";
    for (const char* kind :
         {"projection_sliding_warm", "projection_sliding_from_point", "projection_sliding_cold",
          "projection_sticking_warm", "impulse_sliding_warm", "impulse_sliding_from_point",
          "impulse_sliding_cold", "impulse_sticking", "spring_sliding_warm", "spring_sticking"}) {
      reporter.add_comparison(std::string(kind) + "<" + p + ">", base);
      reporter.add_comparison(std::string(kind) + "<" + p + ">", chained);
    }
    reporter.add_comparison(std::string("projection_sliding_from_point<") + p + ">",
                            std::string("projection_sliding_warm<") + p + ">");
  }
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
