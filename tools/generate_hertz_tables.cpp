//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Generates include/spinslide/values/detail/hertz_tables.hpp: the piecewise
// polynomial table of Hertz's fast path for ε ≥ 13/10 (values/detail/hertz_fast.hpp,
// docs/theory.md §6, "Hertz's fast path").
//
// With k = 1/ε and z = k², Hertz's 𝓕, 𝓣, 𝓕′ and 𝓕″ are, exactly,
//   𝓕 = 1 − z·A₁(z),  𝓣 = k·A₂(z),  𝓕′ = k z·A₃(z),  𝓕″ = −z²·A₄(z),
// with four functions of z, analytic on |z| < 1 (the series (E3):
// A₁ = Σ_{j≥1} a_j z^(j−1), A₂ = Σ b_j z^j, A₃ = Σ 2j a_j z^(j−1),
// A₄ = Σ 2j(2j + 1) a_j z^(j−1), every coefficient positive), so that each is
// bounded and bounded away from 0 on z ∈ [0, Z], Z = (10/13)², and each of
// 𝓕, 𝓣, 𝓕′, 𝓕″ inherits their relative accuracy (𝓕 = 1 − zA₁ ≥ 0.88 there).
// The table covers [0, Z] with equal pieces (the nearest singularity, z = 1,
// lies 0.41 beyond its end), each a polynomial in x = z·(2P/Z) − (2i + 1) ∈
// [−1, 1] for piece i of P.
//
// The functions are evaluated here in cpp_bin_float_50 from the elementary
// closed forms (docs/theory.md (E2)), with w = √(ε² − 1) and A = atan2(1, w);
// they cancel as z → 0 (𝓣 and 𝓕″ by about ε⁴), which costs at most 12 of the
// 50 digits at the points sampled.  As a check, the generator also sums the
// series in multiprecision at every sample point and stops if the two
// disagree beyond 1e-30.  Every piece is interpolated at Chebyshev points,
// truncated to the table's degree, converted to monomials and rounded to
// double; then the table is measured in double, with the library's own
// evaluation (hertz_fast.hpp), against the multiprecision 𝓕, 𝓣, 𝓕′, 𝓕″ at
// random ratios of every piece.  The largest errors are printed to stderr
// and written into the header.
//
//   ./build/release/tests/generate_hertz_tables > include/spinslide/values/detail/hertz_tables.hpp
#include <spinslide/values/detail/hertz_fast.hpp>
#include <spinslide/values/detail/piecewise_chebyshev.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using mp = boost::multiprecision::cpp_bin_float_50;
using spinslide::detail::chebyshev_coefficients;
using spinslide::detail::chebyshev_point;
using spinslide::detail::chebyshev_to_monomial;

// 𝓕, 𝓣, 𝓕′, 𝓕″ at ε > 1 from the elementary closed forms (E2).
std::array<mp, 4> closed_forms(const mp& eps) {
  const mp w2 = (eps - 1) * (eps + 1), w = sqrt(w2), k = 1 / eps, a = atan2(mp(1), w);
  return {mp(3) / 16 * (eps * (4 - eps * eps) * a + w * (w2 + 3) * k),
          mp(3) / 64 * (((3 * w2 - 2) * w2 + 3) * a + 3 * w * (1 - w2)),
          mp(3) / 16 * ((1 - 3 * w2) * a + w * (1 + 3 * w2) * k * k),
          mp(3) / 8 * (w * k * (3 + 2 * k * k) - 3 * eps * a)};
}

// A₁..A₄ at z ∈ (0, 1), from the closed forms; at z = 0 their limits
// a₁ = 1/10, b₀ = 1/5, 2a₁ and 6a₁.
std::array<mp, 4> functions(const mp& z) {
  if (z == 0) return {mp(1) / 10, mp(1) / 5, mp(1) / 5, mp(3) / 5};
  const mp eps = 1 / sqrt(z);
  const auto c = closed_forms(eps);
  return {(1 - c[0]) / z, eps * c[1], eps * eps * eps * c[2], -eps * eps * eps * eps * c[3]};
}

// The same four functions from the series (E3), summed until the terms are
// below 1e-60 of the sum: a_j = 3c_j/((2j − 1)(2j + 1)(2j + 3)),
// b_j = 3c_j/((2j + 1)(2j + 3)(2j + 5)), c_j = C(2j, j)/4ʲ.
std::array<mp, 4> series(const mp& z) {
  std::array<mp, 4> s = {mp(0), mp(0), mp(0), mp(0)};
  mp c = 1, zj = 1;  // c_j and z^j
  const mp tiny("1e-60");
  for (int j = 0;; ++j) {
    if (j > 0) c *= mp(2 * j - 1) / (2 * j);
    const mp b = 3 * c / ((2 * j + 1) * (2 * j + 3) * (2 * j + 5));
    s[1] += b * zj;
    if (j > 0) {
      const mp a = 3 * c / ((2 * j - 1) * (2 * j + 1) * (2 * j + 3));
      const mp zm = zj / z;  // z^(j−1)
      s[0] += a * zm;
      s[2] += 2 * j * a * zm;
      s[3] += mp(2 * j) * (2 * j + 1) * a * zm;
      if (mp(2 * j) * (2 * j + 1) * a * zm < tiny * s[3]) break;
    }
    zj *= z;
  }
  return s;
}

using layout = spinslide::detail::hertz_table_layout;
constexpr int functions_per_piece = 4;

struct report {
  double tail[4] = {0, 0, 0, 0};  // largest truncated Chebyshev tail, relative, / epsilon
  double worst[4] = {0, 0, 0, 0};  // largest measured error of 𝓕, 𝓣, 𝓕′, 𝓕″, relative, / epsilon
  double sources = 0;  // largest relative disagreement of closed forms and series
};

// Piece i of `pieces` equal ones of [0, Z], as (middle, half width).
std::pair<mp, mp> interval(int i, int pieces) {
  const mp top = mp(100) / 169, width = top / pieces;
  return {width * (mp(i) + mp(0.5)), width / 2};
}

// Coefficient k of function f of piece i at 4(degree + 1)·i + 4k + f.
std::vector<double> build(int pieces, int degree, report& r) {
  const std::size_t n = static_cast<std::size_t>(degree) + 1, sample = n + 12;
  const std::size_t stride = functions_per_piece * n;
  std::vector<double> table(static_cast<std::size_t>(pieces) * stride);
  for (int i = 0; i < pieces; ++i) {
    const auto iv = interval(i, pieces);
    std::vector<std::array<mp, 4>> v(sample);
    for (std::size_t j = 0; j < sample; ++j) {
      const mp z = iv.first + iv.second * chebyshev_point<mp>(j, sample);
      v[j] = functions(z);
      const auto s = series(z);
      for (std::size_t f = 0; f < 4; ++f)
        r.sources = std::max(r.sources, static_cast<double>(abs(s[f] - v[j][f]) / v[j][f]));
    }
    for (std::size_t f = 0; f < 4; ++f) {
      std::vector<mp> values(sample), c(sample), m(n);
      for (std::size_t j = 0; j < sample; ++j) values[j] = v[j][f];
      chebyshev_coefficients(values.data(), sample, c.data());
      mp tail = 0;
      for (std::size_t k = n; k < sample; ++k) tail += abs(c[k]);
      r.tail[f] = std::max(r.tail[f], static_cast<double>(tail / abs(c[0] / 2) /
                                                          std::numeric_limits<double>::epsilon()));
      chebyshev_to_monomial(c.data(), n, m.data());
      for (std::size_t k = 0; k < n; ++k)
        table[static_cast<std::size_t>(i) * stride + functions_per_piece * k + f] =
            static_cast<double>(m[k]);
    }
  }
  return table;
}

// The table measured with the library's evaluation at random ratios of every
// piece, and at the pieces' ends, against the closed forms.
void measure(const std::vector<double>& table, int pieces, int degree, report& r) {
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> u(-1, 1);
  const double eps = std::numeric_limits<double>::epsilon();
  for (int i = 0; i < pieces; ++i) {
    const auto iv = interval(i, pieces);
    for (int t = 0; t < 400; ++t) {
      const mp zm = t == 0   ? iv.first - iv.second
                    : t == 1 ? iv.first + iv.second
                             : iv.first + iv.second * mp(u(rng));
      const double ratio = static_cast<double>(1 / sqrt(zm));
      if (zm <= 0 || ratio < 1.3) continue;
      const auto got = spinslide::detail::hertz_fast_evaluate<true, true, true>(
          {table.data(), pieces, degree}, ratio);
      const auto exact = closed_forms(mp(ratio));
      const double g[4] = {got.force, got.torque, got.slope, got.curvature};
      for (std::size_t f = 0; f < 4; ++f)
        r.worst[f] =
            std::max(r.worst[f], static_cast<double>(abs((mp(g[f]) - exact[f]) / exact[f]) / eps));
    }
  }
}

void emit(const std::vector<double>& t, int pieces, int degree, const report& r) {
  std::printf(
      "\n// %d pieces of degree %d.  Largest truncated Chebyshev tail (relative,\n"
      "// in units of epsilon): A1 %.2g, A2 %.2g, A3 %.2g, A4 %.2g.  Largest\n"
      "// error measured by the generator: F %.3f, T %.3f, F' %.3f, F'' %.3f epsilon.\n",
      pieces, degree, r.tail[0], r.tail[1], r.tail[2], r.tail[3], r.worst[0], r.worst[1],
      r.worst[2], r.worst[3]);
  std::printf("alignas(64) inline constexpr double hertz_table[] = {\n");
  const std::size_t stride = t.size() / static_cast<std::size_t>(pieces);
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (i % stride == 0) std::printf("    // piece %zu\n   ", i / stride);
    std::printf(" %a,", t[i]);
    if (i % 4 == 3 && (i + 1) % stride != 0) std::printf("\n   ");
    if ((i + 1) % stride == 0) std::printf("\n");
  }
  std::printf("};\n");
}

}  // namespace

int main(int argc, char** argv) {
  int pieces = layout::pieces, degree = layout::degree;
  bool header = true;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&] { return i + 1 < argc ? std::atoi(argv[++i]) : -1; };
    if (a == "--pieces") {
      pieces = next();
      header = false;  // a trial layout: measured and reported, not emitted
    } else if (a == "--degree") {
      degree = next();
      header = false;
    } else {
      std::fprintf(stderr, "usage: %s [--pieces N] [--degree D]\n", argv[0]);
      return 2;
    }
  }
  if (pieces < 1 || degree < 1 || degree > 30) {
    std::fprintf(stderr, "bad layout\n");
    return 2;
  }
  report r;
  const auto table = build(pieces, degree, r);
  measure(table, pieces, degree, r);
  std::fprintf(stderr,
               "%d pieces, degree %d: closed forms against series %.2g; tail A1 %.2g A2 %.2g "
               "A3 %.2g A4 %.2g; measured F %.3f T %.3f F' %.3f F'' %.3f eps\n",
               pieces, degree, r.sources, r.tail[0], r.tail[1], r.tail[2], r.tail[3], r.worst[0],
               r.worst[1], r.worst[2], r.worst[3]);
  if (r.sources > 1e-30) {
    std::fprintf(stderr, "the closed forms and the series disagree\n");
    return 1;
  }
  if (!header) return 0;
  std::printf(
      "//  Copyright (c) 2026 the spinslide developers.\n"
      "//  Distributed under the Boost Software License, Version 1.0.\n"
      "//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)\n"
      "//\n"
      "// GENERATED by tools/generate_hertz_tables.cpp; do not edit.  Regenerate with\n"
      "//   ./build/release/tests/generate_hertz_tables > "
      "include/spinslide/values/detail/hertz_tables.hpp\n"
      "// The piecewise polynomials A1..A4(z) of Hertz's fast path, hertz_fast.hpp\n"
      "// (docs/theory.md §6, \"Hertz's fast path\"): coefficient k of A(f + 1) of\n"
      "// piece i at i * stride + 4k + f.\n"
      "// clang-format off\n"
      "#ifndef SPINSLIDE_VALUES_DETAIL_HERTZ_TABLES_HPP\n"
      "#define SPINSLIDE_VALUES_DETAIL_HERTZ_TABLES_HPP\n\n"
      "namespace spinslide {\nnamespace detail {\n");
  emit(table, pieces, degree, r);
  std::printf(
      "\n}  // namespace detail\n}  // namespace spinslide\n\n"
      "#endif  // SPINSLIDE_VALUES_DETAIL_HERTZ_TABLES_HPP\n// clang-format on\n");
  return 0;
}
