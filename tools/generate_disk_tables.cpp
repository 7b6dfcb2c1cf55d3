//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Generates include/spinslide/values/detail/disk_tables.hpp: the piecewise
// polynomial tables of the fast double and float paths of disk.hpp
// (docs/theory.md §4, "The fast path").
//
// With k = min(ε, 1/ε) and y = 1 − k², the uniform disk's force and torque
// are, exactly,
//   ε ≤ 1:  𝓕 = ε·g(y),   𝓣 = t₁(y)
//   ε > 1:  𝓕 = g(y),     𝓣 = k·t₂(y)
// with three functions of y ∈ [0, 1], each bounded and bounded away from 0
// (docs/theory.md (C1a), (C1b), (C2a), (C2b), with m = 1 − y):
//   g  = 4[(1 + m)E − yK] / (3π m)               g(1) = 1,    g(0) = 8/(3π)
//   t₁ = 4[(4 − 2m)E − yK] / (9π)                t₁(1) = 2/3, t₁(0) = 8/(9π)
//   t₂ = 4[(4m − 2)E + y(2 − 3m)K] / (9π m²)      t₂(1) = 1/4, t₂(0) = 8/(9π)
// K = K(k), E = E(k) evaluated here by Boost's ellint_1/ellint_2 in
// cpp_bin_float_50 (the cancellations of these forms as m → 0 cost at most
// 10 of the 50 digits at the sample points used).
//
// Both tables are of double and evaluated in double: float's is a smaller
// one (lower degree, fewer pieces), whose result is then rounded to float.
//
// The pieces are addressed by the bits of y: piece i ≥ 1 of the table is
// [2^(j−J)(1 + s/2^b), 2^(j−J)(1 + (s+1)/2^b)] with j = i >> b,
// s = i & (2^b − 1), J binades and b index bits, so that the index is the
// top bits of y's representation minus a constant.  Piece 0 is [0, 2^−J(1 + 2^−b)]:
// the functions behave as P(y) + y² ln(y) Q(y) near y = 0 (ε = 1), and below
// 2^−J the y² ln y part is under 2^−57 relative, so a polynomial suffices.
// Every piece is interpolated at Chebyshev points, truncated to the table's
// degree, converted to monomials in x ∈ [−1, 1] (x = y·scale + offset), and
// rounded to the table's type; the values at y = 0 and y = 1 are pinned to
// the correctly rounded limits.  Each table is then checked, in the table's
// own arithmetic (the same Horner loop as the library), against the
// multiprecision functions at random points of every piece; the largest
// error is printed to stderr and written into the header.
//
//   ./build/release/tools/generate_disk_tables > include/spinslide/values/detail/disk_tables.hpp
#include <spinslide/values/detail/branch_free_log.hpp>
#include <spinslide/values/detail/piecewise_chebyshev.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/math/special_functions/next.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "least_squares.hpp"

namespace {

using mp = boost::multiprecision::cpp_bin_float_50;
using spinslide::detail::chebyshev_coefficients;
using spinslide::detail::chebyshev_point;
using spinslide::detail::chebyshev_to_monomial;

// (g, t₁, t₂) at y ∈ [0, 1], the exact limits at the two ends.
std::array<mp, 3> functions(const mp& y) {
  using boost::math::constants::pi;
  const mp p = pi<mp>();
  if (y == 0) return {8 / (3 * p), 8 / (9 * p), 8 / (9 * p)};  // ε = 1: K = ∞, yK → 0, E = 1
  if (y == 1) return {mp(1), mp(2) / 3, mp(1) / 4};            // ε = 0 or ∞
  const mp m = 1 - y;
  const mp K = boost::math::ellint_1(sqrt(m)), E = boost::math::ellint_2(sqrt(m));
  return {4 * ((1 + m) * E - y * K) / (3 * p * m), 4 * ((4 - 2 * m) * E - y * K) / (9 * p),
          4 * ((4 * m - 2) * E + y * (2 - 3 * m) * K) / (9 * p * m * m)};
}

struct layout {
  const char* name;  // the result type the table serves; it is evaluated in double
  double epsilon;    // of that type: the unit of the reported errors
  int bits;          // b: 2^b pieces per binade
  int binades;       // J: piece 0 is [0, 2^−J (1 + 2^−b)]
  int degree;
  int pieces() const { return binades << bits; }
  std::pair<mp, mp> interval(int i) const {
    const int per = 1 << bits;
    if (i == 0) return {mp(0), ldexp(mp(1) + ldexp(mp(1), -bits), -binades)};
    const int j = i >> bits, s = i & (per - 1);
    const mp lo = ldexp(mp(1) + mp(s) / per, j - binades);
    return {lo, lo + ldexp(mp(1), j - binades - bits)};
  }
};

// One piece: x = y·scale + offset maps it onto [−1, 1]; coefficient k of
// function f is c[3k + f].
template <class Real>
struct piece {
  Real scale, offset;
  std::vector<Real> c;
};

// The library's evaluation (disk_fast.hpp) of function f of a piece.
template <class Real>
Real evaluate(const piece<Real>& p, std::size_t degree, std::size_t f, Real y) {
  const Real x = y * p.scale + p.offset;
  Real s = p.c[3 * degree + f];
  for (std::size_t k = degree; k-- > 0;) s = s * x + p.c[3 * k + f];
  return s;
}

struct report {
  double tail[3] = {0, 0, 0};   // largest truncated Chebyshev tail Σ|c_k|, relative, / epsilon
  double worst[3] = {0, 0, 0};  // largest measured relative error / epsilon
};

template <class Real>
std::vector<piece<Real>> build(const layout& L, report& r) {
  const std::size_t degree = static_cast<std::size_t>(L.degree), n = degree + 1,
                    sample = degree + 12;
  const mp eps = L.epsilon;
  std::vector<piece<Real>> table;
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < L.pieces(); ++i) {
    const auto iv = L.interval(i);
    const mp mid = (iv.first + iv.second) / 2, half = (iv.second - iv.first) / 2;
    std::vector<std::array<mp, 3>> v(sample);
    for (std::size_t j = 0; j < sample; ++j)
      v[j] = functions(mid + half * chebyshev_point<mp>(j, sample));
    piece<Real> p;
    // Exact for pieces i ≥ 1: a power of two and an integer.
    p.scale = static_cast<Real>(1 / half);
    p.offset = static_cast<Real>(-mid / half);
    p.c.resize(3 * n);
    for (std::size_t f = 0; f < 3; ++f) {
      std::vector<mp> values(sample), c(sample), m(n);
      for (std::size_t j = 0; j < sample; ++j) values[j] = v[j][f];
      chebyshev_coefficients(values.data(), sample, c.data());
      mp tail = 0;
      for (std::size_t k = n; k < sample; ++k) tail += abs(c[k]);
      r.tail[f] = std::max(r.tail[f], static_cast<double>(tail / abs(c[0] / 2) / eps));
      chebyshev_to_monomial(c.data(), n, m.data());
      for (std::size_t k = 0; k < n; ++k) p.c[3 * k + f] = static_cast<Real>(m[k]);
    }
    // Pin the ends, y = 0 (ε = 1) and y = 1 (ε = 0 and ε = ∞), to the
    // correctly rounded values, so that 𝓕(1) = 8/(3π), 𝓣(1) = 8/(9π),
    // 𝓣(0) = 2/3 and 𝓕(∞) = 1 come out exactly: move the two lowest
    // coefficients by the fewest ulps that achieve it (c₀'s ulp may exceed
    // the result's, so c₁ takes most of it).  x = ±1 there, so the Horner
    // steps s·x + c are exact products plus one rounding, with or without
    // fused multiply-adds.
    for (const mp& end : {iv.first, iv.second}) {
      if (end != 0 && end != 1) continue;
      const auto exact = functions(end);
      const Real y = static_cast<Real>(end);
      for (std::size_t f = 0; f < 3; ++f) {
        const Real target = static_cast<Real>(exact[f]);
        // First move c₀ by the whole difference (the lower-degree float table
        // is off by far more than an ulp of double), then search.
        for (int step = 0; step < 3; ++step) p.c[f] += target - evaluate(p, degree, f, y);
        const Real c0 = p.c[f], c1 = p.c[3 + f];
        bool pinned = false;
        for (int a0 = 0; a0 <= 4 && !pinned; ++a0) {
          for (int d0 : {a0, -a0}) {
            for (int a1 = 0; a1 <= 1 << 14 && !pinned; ++a1) {
              for (int d1 : {a1, -a1}) {
                p.c[f] = boost::math::float_advance(c0, d0);
                p.c[3 + f] = boost::math::float_advance(c1, d1);
                if (evaluate(p, degree, f, y) == target) {
                  pinned = true;
                  break;
                }
              }
            }
            if (pinned) break;
          }
        }
        if (!pinned) {
          std::fprintf(stderr, "could not pin function %zu at y = %g\n", f,
                       static_cast<double>(end));
          std::exit(1);
        }
      }
    }
    // Measure, in Real arithmetic, at both ends and at random points.
    for (int t = 0; t < 300; ++t) {
      const mp ym = t == 0 ? iv.first : t == 1 ? iv.second : mid + half * mp(u(rng));
      const Real y = static_cast<Real>(ym);
      if (mp(y) < iv.first || mp(y) > iv.second) continue;
      const auto exact = functions(mp(y));
      for (std::size_t f = 0; f < 3; ++f) {
        const mp err = abs(mp(evaluate(p, degree, f, y)) - exact[f]) / exact[f] / eps;
        r.worst[f] = std::max(r.worst[f], static_cast<double>(err));
      }
    }
    table.push_back(std::move(p));
  }
  return table;
}

template <class Real>
void emit(const layout& L, const char* table, const std::vector<piece<Real>>& t, const report& r) {
  std::printf(
      "\n// %s: %d index bits, %d binades, degree %d.  Largest truncated Chebyshev\n"
      "// tail (relative, in units of epsilon): g %.2g, t1 %.2g, t2 %.2g.  Largest\n"
      "// error measured by the generator: g %.3f, t1 %.3f, t2 %.3f epsilon.\n",
      L.name, L.bits, L.binades, L.degree, r.tail[0], r.tail[1], r.tail[2], r.worst[0], r.worst[1],
      r.worst[2]);
  std::printf("struct %s_layout {\n", table);
  std::printf("  static constexpr int index_bits = %d;\n", L.bits);
  std::printf("  static constexpr int binades = %d;\n", L.binades);
  std::printf("  static constexpr int degree = %d;\n", L.degree);
  std::printf("  static constexpr int pieces = %d;\n", L.pieces());
  std::printf("  static constexpr int mantissa_bits = %d;  // of double, in which y is indexed\n",
              std::numeric_limits<double>::digits - 1);
  std::printf(
      "  // (representation of y) >> (mantissa_bits − index_bits), minus this, is the piece.\n");
  std::printf("  static constexpr long long first_index = %lld;\n",
              static_cast<long long>(std::numeric_limits<double>::max_exponent - 1 - L.binades)
                  << L.bits);
  std::printf("  static constexpr int stride = %d;  // scale, offset, (g, t1, t2) × (degree + 1)\n",
              2 + 3 * (L.degree + 1));
  std::printf("};\n");
  std::printf("alignas(64) inline constexpr double %s[] = {\n", table);
  const char* fmt = "%a";
  for (std::size_t i = 0; i < t.size(); ++i) {
    std::printf("    // piece %zu\n   ", i);
    std::vector<Real> row = {t[i].scale, t[i].offset};
    row.insert(row.end(), t[i].c.begin(), t[i].c.end());
    for (std::size_t k = 0; k < row.size(); ++k) {
      char buf[64];
      std::snprintf(buf, sizeof buf, fmt, static_cast<double>(row[k]));
      std::printf(" %s,", buf);
      if (k % 4 == 1 && k + 1 < row.size()) std::printf("\n   ");
    }
    std::printf("\n");
  }
  std::printf("};\n");
}

// The vectorizable form of the batch: for each function two pieces, y < ½
// (piece 0) and y ≥ ½ (piece 1), each
//   f(y) ≈ A + s P(v) + y² ln(y) Q(v),
// piece 0: A = f(0), s = y,     v = 4y − 1;
// piece 1: A = f(1), s = y − 1, v = 4y − 3 (y − 1 and v exact there),
// which carries the y² ln y singularity at y = 0 (ε = 1) explicitly, so that
// two pieces (selected per ratio, not looked up) are enough, and is exact at
// y = 0 and y = 1, where s and y² ln y vanish.  P and Q are fitted by least
// squares of the relative error at 300 Chebyshev points of each piece
// (Householder QR in cpp_bin_float_50).  One piece over all of [0, 1] was
// tried first: P and y² ln(y) Q then cancel inside (0, 1) and the torque
// reached 4.9 ulp in double.
struct global_piece {
  double anchor = 0;
  std::vector<double> p, q;
};
struct global_fit {
  global_piece piece[2];
  double approximation = 0;  // largest relative error of the fit itself, / epsilon
  double evaluated = 0;      // largest relative error evaluated in double, / epsilon
};

// As disk_fast_vector evaluates it.
double evaluate_global(const global_fit& g, double y) {
  const bool high = y >= 0.5;
  const global_piece& c = g.piece[high];
  const double v = high ? 4 * y - 3 : 4 * y - 1, s = high ? y - 1 : y;
  double P = c.p.back(), Q = c.q.back();
  for (std::size_t k = c.p.size() - 1; k-- > 0;) P = P * v + c.p[k];
  for (std::size_t k = c.q.size() - 1; k-- > 0;) Q = Q * v + c.q[k];
  const double L = y * (y * spinslide::detail::branch_free_log(y));
  return c.anchor + (s * P + L * Q);
}

std::array<global_fit, 3> fit_global(std::size_t p_degree, std::size_t q_degree) {
  using boost::math::constants::pi;
  const int n = 300;
  // Check points: uniform in y, log-uniform down to 1e-40 and up to 1 − 1e-16.
  std::vector<double> check;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(0, 1), exponent(-40, 0);
  for (int j = 0; j < 6000; ++j)
    check.push_back(j % 3 == 0   ? uniform(rng)
                    : j % 3 == 1 ? std::pow(10.0, exponent(rng))
                                 : 1 - std::pow(10.0, exponent(rng) / 2.5));
  check.push_back(0.5);
  check.push_back(1.0);
  const mp eps = std::numeric_limits<double>::epsilon();
  std::array<global_fit, 3> out;
  std::array<std::array<std::vector<mp>, 2>, 3> exact_coefficients;
  for (std::size_t f = 0; f < 3; ++f) {
    for (std::size_t h = 0; h < 2; ++h) {
      const mp lo = h ? mp(0.5) : mp(0), hi = h ? mp(1) : mp(0.5);
      const mp anchor = functions(h ? mp(1) : mp(0))[f];
      std::vector<std::vector<mp>> A;
      std::vector<mp> b;
      for (int j = 0; j < n; ++j) {
        const mp y = lo + (hi - lo) * (1 - cos(pi<mp>() * (j + mp(0.5)) / n)) / 2;
        const mp v = (2 * y - (lo + hi)) / (hi - lo), s = h ? y - 1 : y, L = y * y * log(y);
        const mp fy = functions(y)[f];
        std::vector<mp> row;
        mp w = 1;
        for (std::size_t k = 0; k <= p_degree; ++k, w *= v) row.push_back(s * w / fy);
        w = 1;
        for (std::size_t k = 0; k <= q_degree; ++k, w *= v) row.push_back(L * w / fy);
        A.push_back(row);
        b.push_back((fy - anchor) / fy);
      }
      exact_coefficients[f][h] = spinslide_tools::least_squares(A, b);
      global_piece& c = out[f].piece[h];
      c.anchor = static_cast<double>(anchor);
      for (std::size_t k = 0; k <= p_degree; ++k)
        c.p.push_back(static_cast<double>(exact_coefficients[f][h][k]));
      for (std::size_t k = 0; k <= q_degree; ++k)
        c.q.push_back(static_cast<double>(exact_coefficients[f][h][p_degree + 1 + k]));
    }
    global_fit& g = out[f];
    for (const double y : check) {
      const mp exact = functions(mp(y))[f];
      const std::size_t h = y >= 0.5;
      const auto& x = exact_coefficients[f][h];
      const mp ym = y, v = h ? 4 * ym - 3 : 4 * ym - 1;
      mp P = 0, Q = 0;
      for (std::size_t k = p_degree + 1; k-- > 0;) P = P * v + x[k];
      for (std::size_t k = q_degree + 1; k-- > 0;) Q = Q * v + x[p_degree + 1 + k];
      const mp fit = functions(h ? mp(1) : mp(0))[f] + (h ? ym - 1 : ym) * P +
                     (y == 0 ? mp(0) : ym * ym * log(ym) * Q);
      g.approximation =
          std::max(g.approximation, static_cast<double>(abs(fit - exact) / exact / eps));
      g.evaluated = std::max(
          g.evaluated, static_cast<double>(abs(mp(evaluate_global(g, y)) - exact) / exact / eps));
    }
  }
  return out;
}

void emit_global(const std::array<global_fit, 3>& fits) {
  const std::size_t np = fits[0].piece[0].p.size() - 1, nq = fits[0].piece[0].q.size() - 1;
  std::printf(
      "\n// The batch's vectorizable form, for f = g, t1, t2, in two pieces h = 0\n"
      "// (y < 1/2) and h = 1 (y >= 1/2):\n"
      "//   f(y) = A + s P(v) + y^2 ln(y) Q(v),  h = 0: A = f(0), s = y, v = 4y - 1;\n"
      "//                                       h = 1: A = f(1), s = y - 1, v = 4y - 3.\n"
      "// Row h: A, the coefficients of P (degree %zu), then those of Q (degree %zu).\n",
      np, nq);
  std::printf(
      "// Largest error of the fit (relative, in units of epsilon): g %.2g, t1 %.2g,\n"
      "// t2 %.2g; evaluated in double by the generator: g %.3f, t1 %.3f, t2 %.3f.\n",
      fits[0].approximation, fits[1].approximation, fits[2].approximation, fits[0].evaluated,
      fits[1].evaluated, fits[2].evaluated);
  std::printf(
      "struct disk_global_layout {\n  static constexpr int p_degree = %zu;\n"
      "  static constexpr int q_degree = %zu;\n  static constexpr int row = %zu;\n};\n",
      np, nq, np + nq + 3);
  const char* names[3] = {"g", "t1", "t2"};
  for (std::size_t f = 0; f < 3; ++f) {
    std::printf("alignas(64) inline constexpr double disk_global_%s[2][%zu] = {\n", names[f],
                np + nq + 3);
    for (int h = 0; h < 2; ++h) {
      const global_piece& c = fits[f].piece[h];
      std::vector<double> row = {c.anchor};
      row.insert(row.end(), c.p.begin(), c.p.end());
      row.insert(row.end(), c.q.begin(), c.q.end());
      std::printf("    {");
      for (std::size_t k = 0; k < row.size(); ++k) {
        std::printf("%s%a,", k ? " " : "", row[k]);
        if (k % 4 == 3 && k + 1 < row.size()) std::printf("\n     ");
      }
      std::printf("},\n");
    }
    std::printf("};\n");
  }
}
}  // namespace

int main(int argc, char** argv) {
  layout D{"double", std::numeric_limits<double>::epsilon(), 3, 32, 8};
  layout F{"float", std::numeric_limits<float>::epsilon(), 2, 16, 4};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&] { return i + 1 < argc ? std::atoi(argv[++i]) : -1; };
    if (a == "--double-bits")
      D.bits = next();
    else if (a == "--double-binades")
      D.binades = next();
    else if (a == "--double-degree")
      D.degree = next();
    else if (a == "--float-bits")
      F.bits = next();
    else if (a == "--float-binades")
      F.binades = next();
    else if (a == "--float-degree")
      F.degree = next();
    else {
      std::fprintf(stderr, "usage: %s [--{double,float}-{bits,binades,degree} N]\n", argv[0]);
      return 2;
    }
  }
  report rd, rf;
  const auto td = build<double>(D, rd);
  std::fprintf(stderr, "double: tail g %.2g t1 %.2g t2 %.2g; measured g %.3f t1 %.3f t2 %.3f eps\n",
               rd.tail[0], rd.tail[1], rd.tail[2], rd.worst[0], rd.worst[1], rd.worst[2]);
  const auto tf = build<double>(F, rf);
  std::fprintf(stderr, "float: tail g %.2g t1 %.2g t2 %.2g; measured g %.3f t1 %.3f t2 %.3f eps\n",
               rf.tail[0], rf.tail[1], rf.tail[2], rf.worst[0], rf.worst[1], rf.worst[2]);
  const auto global = fit_global(10, 8);
  std::fprintf(stderr, "global: fit g %.2g t1 %.2g t2 %.2g; evaluated g %.3f t1 %.3f t2 %.3f eps\n",
               global[0].approximation, global[1].approximation, global[2].approximation,
               global[0].evaluated, global[1].evaluated, global[2].evaluated);
  std::printf(
      "//  Copyright (c) 2026 the spinslide developers.\n"
      "//  Distributed under the Boost Software License, Version 1.0.\n"
      "//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)\n"
      "//\n"
      "// GENERATED by tools/generate_disk_tables.cpp; do not edit.  Regenerate with\n"
      "//   ./build/release/tools/generate_disk_tables > "
      "include/spinslide/values/detail/disk_tables.hpp\n"
      "// The piecewise polynomials of g(y), t1(y), t2(y) used by disk_fast.hpp\n"
      "// (docs/theory.md §4, \"The fast path\").\n"
      "// clang-format off\n"
      "#ifndef SPINSLIDE_VALUES_DETAIL_DISK_TABLES_HPP\n"
      "#define SPINSLIDE_VALUES_DETAIL_DISK_TABLES_HPP\n\n"
      "namespace spinslide {\nnamespace detail {\n");
  emit(D, "disk_table_double", td, rd);
  emit(F, "disk_table_float", tf, rf);
  emit_global(global);
  std::printf(
      "\n}  // namespace detail\n}  // namespace spinslide\n\n"
      "#endif  // SPINSLIDE_VALUES_DETAIL_DISK_TABLES_HPP\n// clang-format on\n");
  return 0;
}
