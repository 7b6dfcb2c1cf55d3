//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// bench_disk: one (𝓕, 𝓣) pair of the uniform disk by each method (the
// literal closed form, the AGM, quadrature, a rational bound, spinslide in
// each real type, the tabulated disk) and the contact law; bench_disk.cpp
// says what is compared with what.
#include <benchmark/benchmark.h>

#include <spinslide/contact/contact_law.hpp>
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
#include <cstdint>
#include <cstdio>
#include <utility>
#include <vector>

#include "../tools/least_squares.hpp"
#include "bench_disk.hpp"

namespace spinslide_bench {

namespace {

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

}  // namespace

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

}  // namespace spinslide_bench
