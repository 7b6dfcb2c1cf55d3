//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// What every fuzz harness shares (docs/reliability.md, "Fuzzing"):
//
// - fuzz_input turns libFuzzer's bytes into arguments.  A number is read as a
//   mode byte and a payload: raw bits (every NaN, infinity, subnormal and sign
//   the type has), a special value (0, −0, ±∞, NaN, the extremes, values one
//   ulp from 1, ...), or a log-uniform or uniform draw, so that valid and
//   invalid arguments both come often.  Missing bytes read as zero.
// - expect() runs one call and holds it to its contract: on valid input it
//   must not throw and every result must pass the harness's checks; on invalid
//   input it must throw std::domain_error and nothing else.  `ambiguous`
//   input (where the contract allows both, e.g. a custom pressure that is
//   negative somewhere between quadrature nodes) may do either.
// - A broken contract prints the call, the arguments and the reason, and
//   aborts: libFuzzer saves the input as crash-<hash> (replay: ./fuzz_x crash-<hash>).

#ifndef SPINSLIDE_FUZZ_HPP
#define SPINSLIDE_FUZZ_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <typeinfo>

namespace spinslide_fuzz {

/// Reads arguments from the fuzzer's bytes.
class fuzz_input {
 public:
  fuzz_input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  /// The next byte, 0 once the input is used up.
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : std::uint8_t(0); }

  /// The next n ≤ 8 bytes as an unsigned integer (little end first).
  std::uint64_t bits(int n) {
    std::uint64_t b = 0;
    for (int i = 0; i < n; ++i) b |= std::uint64_t(byte()) << (8 * i);
    return b;
  }

  /// One of n choices.
  std::size_t choice(std::size_t n) { return byte() % n; }

  /// A number of type Real, valid or not (see the file comment).
  template <class Real>
  Real real() {
    switch (byte() % 8) {
      case 0:
        return raw<Real>();
      case 1:
        return special<Real>();
      case 2:
      case 3:
      case 4:
        return log_uniform<Real>();
      case 5:
        return uniform01<Real>() * 4;
      case 6:
        return -log_uniform<Real>();
      default:
        return uniform01<Real>();
    }
  }

  /// A number that is mostly in [0, 1] (for ratios such as an annulus's
  /// inner radius or a force), and otherwise anything real<Real>() gives.
  template <class Real>
  Real unit() {
    const std::uint8_t m = byte();
    if (m % 4 != 0) return uniform01<Real>();
    return real<Real>();
  }

  /// A uniform draw on [0, 1], 0 and 1 included, with 53 bits.
  template <class Real>
  Real uniform01() {
    const std::uint64_t b = bits(7) & ((std::uint64_t(1) << 53) - 1);
    return static_cast<Real>(static_cast<long double>(b) / 9007199254740991.0L);
  }

 private:
  template <class Real>
  Real raw() {
    Real x;
    unsigned char bytes[sizeof(Real)] = {};
    // long double: 10 significant bytes of 16 on x86.
    const std::size_t n = std::numeric_limits<Real>::digits == 64 ? 10 : sizeof(Real);
    for (std::size_t i = 0; i < n; ++i) bytes[i] = byte();
    std::memcpy(&x, bytes, sizeof(Real));
    return x;
  }
  template <class Real>
  Real special() {
    using L = std::numeric_limits<Real>;
    const Real values[] = {Real(0),
                           -Real(0),
                           Real(1),
                           -Real(1),
                           L::infinity(),
                           -L::infinity(),
                           L::quiet_NaN(),
                           L::denorm_min(),
                           L::min(),
                           L::max(),
                           L::epsilon(),
                           Real(1) - L::epsilon() / 2,
                           Real(1) + L::epsilon(),
                           Real(1) / 2,
                           Real(2),
                           Real(2) / 3,
                           Real(0.653),
                           -L::denorm_min(),
                           L::max() / 2,
                           Real(1) / L::max()};
    return values[byte() % (sizeof(values) / sizeof(values[0]))];
  }
  // 10^u, u uniform over the type's decimal exponent range (subnormals included).
  template <class Real>
  Real log_uniform() {
    using L = std::numeric_limits<Real>;
    const long double lo = L::min_exponent10 - L::digits10, hi = L::max_exponent10;
    const long double u = lo + (hi - lo) * (static_cast<long double>(bits(4)) / 4294967295.0L);
    return static_cast<Real>(std::pow(10.0L, u));
  }

  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

/// The arguments of the call under test, printed if it breaks its contract.
inline std::string& context() {
  static thread_local std::string c;
  return c;
}

/// Appends "name=value" to the context, with all the digits of value.
template <class Real>
void describe(const char* name, Real value) {
  char buf[96];
  std::snprintf(buf, sizeof buf, " %s=%.21Lg", name, static_cast<long double>(value));
  context() += buf;
}

[[noreturn]] inline void fail(const char* call, const char* reason) {
  std::fprintf(stderr, "\nspinslide fuzz: %s broke its contract: %s\n  arguments:%s\n", call,
               reason, context().c_str());
  std::fflush(stderr);
  std::abort();
}

/// Fails unless `ok`.
inline void check(bool ok, const char* call, const char* reason) {
  if (!ok) fail(call, reason);
}

/// Fails unless x is finite.
template <class Real>
void check_finite(Real x, const char* call, const char* what) {
  if (!std::isfinite(static_cast<long double>(x))) {
    std::string reason = std::string(what) + " is not finite: ";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.21Lg", static_cast<long double>(x));
    fail(call, (reason + buf).c_str());
  }
}

/// The unit vector along (x, y), (1, 0) for (0, 0): scaled first, since the
/// hypot of two subnormals rounds to a subnormal and the quotients would not
/// be a unit vector ((-5e-324, -5e-324) gave (-0.5, -0.5): fuzz_impulse).
template <class Real>
std::array<Real, 2> unit_direction(Real x, Real y) {
  const Real big = std::fmax(std::fabs(x), std::fabs(y));
  if (!(big > 0)) return {Real(1), Real(0)};
  const Real ux = x / big, uy = y / big, length = std::hypot(ux, uy);
  return {ux / length, uy / length};
}

/// Whether the arguments are valid, invalid, or may be either.
enum class validity { valid, invalid, ambiguous };

inline validity valid_if(bool ok) { return ok ? validity::valid : validity::invalid; }

/// Runs `body` (which calls the library and checks its results) and holds it
/// to the contract for `v`.  Returns whether body completed (no exception).
template <class Body>
bool expect(validity v, const char* call, Body body) {
  try {
    body();
  } catch (const std::domain_error& e) {
    if (v == validity::valid)
      fail(call, (std::string("std::domain_error on valid input: ") + e.what()).c_str());
    return false;
  } catch (const std::exception& e) {
    fail(call, (std::string("threw ") + typeid(e).name() + ", not std::domain_error: " + e.what())
                   .c_str());
  } catch (...) {
    fail(call, "threw something that is not a std::exception");
  }
  if (v == validity::invalid) fail(call, "invalid input, but no std::domain_error");
  return true;
}

}  // namespace spinslide_fuzz

#endif  // SPINSLIDE_FUZZ_HPP
