//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// force_torque_batch's vectorized form (F2) for targets with AVX2 and FMA but
// without AVX-512, four ratios at a time in AVX2 intrinsics: the formulas and
// order of disk_fast_vector (disk_fast.hpp) and branch_free_log, with FMA in
// the Horner steps, so not bit for bit its results; the same budgets
// (tests/test_disk_fast.cpp, also built as test_disk_fast_avx2).
//
// Why intrinsics, not the compiler's vectorization of disk_fast_vector as on
// AVX-512.  g++ 12 keeps branches in that loop on AVX2: jump threading merges
// the many selects on y ≥ ½ and ε > 1 into branches, and PRE moves arithmetic
// with a constant operand into them (1/ε or 1/1, ε + 1 or 2^64 + 1); under
// -ftrapping-math if-conversion may not execute such floating-point operations
// unconditionally unless it can mask them, which AVX-512 can.  With every
// select written as a bitwise blend the loop does vectorize on AVX2, but it
// measured 7.3 ns per pair, no faster than the scalar table loop: per
// coefficient 𝓕 picks one of two values (piece y < ½ or y ≥ ½) and 𝓣 one of
// four (t₁ or t₂ too), three two-way blends with both constants in registers,
// and those blends in scalar code slowed the scalar path by half.  Here one
// vpermd picks each coefficient among its four candidates, read from memory.
#ifndef SPINSLIDE_VALUES_DETAIL_DISK_FAST_AVX2_HPP
#define SPINSLIDE_VALUES_DETAIL_DISK_FAST_AVX2_HPP

#if defined(__AVX2__) && defined(__FMA__)

#include <spinslide/values/detail/disk_tables.hpp>

#include <immintrin.h>

#include <cstddef>
#include <type_traits>

namespace spinslide {
namespace detail {

// Coefficient j of the vector form as vpermd's four candidates, in the order
// of the lane index 2·above + high: 𝓕's g (low piece, high piece, twice) and
// 𝓣's t₁ (low, high) then t₂ (low, high).
struct disk_avx2_row {
  alignas(32) double value[4];
};
struct disk_avx2_tables {
  disk_avx2_row g[disk_global_layout::row], t[disk_global_layout::row];
};
constexpr disk_avx2_tables make_disk_avx2_tables() {
  disk_avx2_tables r{};
  for (int j = 0; j < disk_global_layout::row; ++j) {
    r.g[j] = {{disk_global_g[0][j], disk_global_g[1][j], disk_global_g[0][j], disk_global_g[1][j]}};
    r.t[j] = {
        {disk_global_t1[0][j], disk_global_t1[1][j], disk_global_t2[0][j], disk_global_t2[1][j]}};
  }
  return r;
}
inline constexpr disk_avx2_tables disk_avx2_coefficients = make_disk_avx2_tables();

inline __m256d disk_avx2_pick(const disk_avx2_row& row, __m256i lanes) {
  const __m256i candidates = _mm256_load_si256(reinterpret_cast<const __m256i*>(row.value));
  return _mm256_castsi256_pd(_mm256_permutevar8x32_epi32(candidates, lanes));
}
inline __m256d disk_avx2_select(__m256d if_false, __m256d if_true, __m256d mask) {
  return _mm256_blendv_pd(if_false, if_true, mask);
}
inline __m256d disk_avx2_constant(double x) { return _mm256_set1_pd(x); }

// branch_free_log (branch_free_log.hpp), four at a time.
inline __m256d disk_avx2_log(__m256d y) {
  const __m256i bits = _mm256_castpd_si256(y);
  const __m256d biased = _mm256_castsi256_pd(
      _mm256_or_si256(_mm256_srli_epi64(bits, 52), _mm256_set1_epi64x(0x4330000000000000)));
  __m256d m = _mm256_castsi256_pd(
      _mm256_or_si256(_mm256_and_si256(bits, _mm256_set1_epi64x(0x000FFFFFFFFFFFFF)),
                      _mm256_set1_epi64x(0x3FF0000000000000)));
  const __m256d one = disk_avx2_constant(1.0);
  const __m256d high = _mm256_cmp_pd(m, disk_avx2_constant(1.4142135623730951), _CMP_GT_OQ);
  m = _mm256_mul_pd(m, disk_avx2_select(one, disk_avx2_constant(0.5), high));
  const __m256d exponent =
      _mm256_add_pd(_mm256_sub_pd(biased, disk_avx2_constant(4503599627370496.0 + 1023)),
                    _mm256_and_pd(high, one));
  const __m256d z = _mm256_div_pd(_mm256_sub_pd(m, one), _mm256_add_pd(m, one));
  const __m256d z2 = _mm256_mul_pd(z, z);
  __m256d s = disk_avx2_constant(1.0 / 23);
  for (int j = 10; j >= 0; --j) s = _mm256_fmadd_pd(s, z2, disk_avx2_constant(1.0 / (2 * j + 1)));
  const __m256d ln2_hi = disk_avx2_constant(0.693147180369123816490);
  const __m256d ln2_lo = disk_avx2_constant(1.90821492927058770002e-10);
  const __m256d series = _mm256_fmadd_pd(exponent, ln2_lo, _mm256_mul_pd(_mm256_add_pd(z, z), s));
  return _mm256_fmadd_pd(exponent, ln2_hi, series);
}

// disk_reduce (disk_fast.hpp), four at a time: y = 1 − min(ε, 1/ε)² as the
// product that stays accurate near ε = 1, and k = 1/ε above 1, else 1; the
// divisor is selected first and ε capped at 2^64, so nothing divides by 0
// or multiplies ∞, as there.
inline __m256d disk_avx2_reduce(__m256d eps, __m256d above, __m256d& k) {
  const __m256d one = disk_avx2_constant(1.0), cap = disk_avx2_constant(18446744073709551616.0);
  k = _mm256_div_pd(one, disk_avx2_select(one, eps, above));
  const __m256d below_cap = _mm256_cmp_pd(eps, cap, _CMP_LT_OQ);
  const __m256d e_c = disk_avx2_select(cap, eps, below_cap);
  const __m256d k_c =
      disk_avx2_select(disk_avx2_constant(1 / 18446744073709551616.0), k, below_cap);
  const __m256d distance = _mm256_andnot_pd(disk_avx2_constant(-0.0), _mm256_sub_pd(e_c, one));
  return _mm256_mul_pd(_mm256_mul_pd(distance, k_c), _mm256_mul_pd(_mm256_add_pd(e_c, one), k_c));
}

// 𝓕 and 𝓣 of four ratios ε ≥ 0 (or +∞): disk_fast_vector's form (F2).
inline void disk_avx2_force_torque(__m256d eps, __m256d& force, __m256d& torque) {
  using layout = disk_global_layout;
  const disk_avx2_tables& c = disk_avx2_coefficients;
  eps = _mm256_add_pd(eps, _mm256_setzero_pd());  // −0 → +0
  const __m256d one = disk_avx2_constant(1.0);
  const __m256d above = _mm256_cmp_pd(eps, one, _CMP_GT_OQ);
  __m256d k;
  const __m256d y = disk_avx2_reduce(eps, above, k);
  const __m256d high = _mm256_cmp_pd(y, disk_avx2_constant(0.5), _CMP_GE_OQ);
  // vpermd's 32-bit lane indices (2i, 2i + 1) for candidate i = 2·above + high.
  const __m256i lanes = _mm256_or_si256(
      _mm256_set1_epi64x(0x0000000100000000),
      _mm256_or_si256(
          _mm256_and_si256(_mm256_castpd_si256(high), _mm256_set1_epi64x(0x0000000200000002)),
          _mm256_and_si256(_mm256_castpd_si256(above), _mm256_set1_epi64x(0x0000000400000004))));
  const __m256d v = _mm256_fmsub_pd(disk_avx2_constant(4.0), y,
                                    disk_avx2_select(one, disk_avx2_constant(3.0), high));
  const __m256d s = _mm256_sub_pd(y, _mm256_and_pd(high, one));
  const __m256d L = _mm256_mul_pd(y, _mm256_mul_pd(y, disk_avx2_log(y)));
  constexpr int np = layout::p_degree, nq = layout::q_degree;
  __m256d gp = disk_avx2_pick(c.g[1 + np], lanes), gq = disk_avx2_pick(c.g[2 + np + nq], lanes);
  __m256d tp = disk_avx2_pick(c.t[1 + np], lanes), tq = disk_avx2_pick(c.t[2 + np + nq], lanes);
  for (int j = np; j-- > 0;) {
    gp = _mm256_fmadd_pd(gp, v, disk_avx2_pick(c.g[1 + j], lanes));
    tp = _mm256_fmadd_pd(tp, v, disk_avx2_pick(c.t[1 + j], lanes));
  }
  for (int j = nq; j-- > 0;) {
    gq = _mm256_fmadd_pd(gq, v, disk_avx2_pick(c.g[2 + np + j], lanes));
    tq = _mm256_fmadd_pd(tq, v, disk_avx2_pick(c.t[2 + np + j], lanes));
  }
  const __m256d g =
      _mm256_add_pd(disk_avx2_pick(c.g[0], lanes), _mm256_fmadd_pd(s, gp, _mm256_mul_pd(L, gq)));
  const __m256d t =
      _mm256_add_pd(disk_avx2_pick(c.t[0], lanes), _mm256_fmadd_pd(s, tp, _mm256_mul_pd(L, tq)));
  force = _mm256_mul_pd(disk_avx2_select(eps, one, above), g);
  torque = _mm256_mul_pd(t, k);
}

// Four ratios in, four results out, for double and float.
inline __m256d disk_avx2_load(const double* p) { return _mm256_loadu_pd(p); }
inline __m256d disk_avx2_load(const float* p) { return _mm256_cvtps_pd(_mm_loadu_ps(p)); }
inline void disk_avx2_store(double* p, __m256d x) { _mm256_storeu_pd(p, x); }
inline void disk_avx2_store(float* p, __m256d x) { _mm_storeu_ps(p, _mm256_cvtpd_ps(x)); }

// disk_fast_batch for AVX2 (ε[i] ≥ 0 checked by the caller).  Each group of
// four is read before it is written, so the outputs may alias the input;
// the last count mod 4 ratios go through a padded local group.
template <class Real>
inline void disk_fast_batch_avx2(const Real* eps, std::size_t count, Real* force, Real* torque) {
  static_assert(std::is_same<Real, double>::value || std::is_same<Real, float>::value,
                "the AVX2 batch is for float and double");
  std::size_t i = 0;
  __m256d f, t;
  for (; i + 4 <= count; i += 4) {
    disk_avx2_force_torque(disk_avx2_load(eps + i), f, t);
    if (force) disk_avx2_store(force + i, f);
    if (torque) disk_avx2_store(torque + i, t);
  }
  if (i == count) return;
  Real e[4] = {1, 1, 1, 1}, fr[4], tr[4];
  for (std::size_t j = 0; i + j < count; ++j) e[j] = eps[i + j];
  disk_avx2_force_torque(disk_avx2_load(e), f, t);
  disk_avx2_store(fr, f);
  disk_avx2_store(tr, t);
  for (std::size_t j = 0; i + j < count; ++j) {
    if (force) force[i + j] = fr[j];
    if (torque) torque[i + j] = tr[j];
  }
}

}  // namespace detail
}  // namespace spinslide

#endif  // __AVX2__ && __FMA__

#endif  // SPINSLIDE_VALUES_DETAIL_DISK_FAST_AVX2_HPP
