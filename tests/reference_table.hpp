//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Reads tests/reference/disk_reference.csv (made by
// tests/reference/generate_disk_reference.cpp from the defining area
// integrals) and measures spinslide's error against it in units of epsilon,
// per range of ε.  Shared by the unit tests and the accuracy report.
#ifndef SPINSLIDE_TESTS_REFERENCE_TABLE_HPP
#define SPINSLIDE_TESTS_REFERENCE_TABLE_HPP

#include <spinslide/values/disk.hpp>

#include <boost/math/special_functions/relative_difference.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "reference/csv.hpp"

namespace spinslide_test {

struct reference_row {
  double eps;        // exact: parsed from the hex-float column
  bool float_exact;  // ε is also exactly a float
  std::string force, torque, force_derivative, torque_derivative;  // 64 digits
};

inline std::vector<reference_row> load_disk_reference(const std::string& path) {
  std::vector<reference_row> rows;
  for (const auto& f : spinslide_reference::read_csv_rows(path, "eps_hex")) {
    if (f.size() != 7)
      throw std::runtime_error("malformed reference row in " + path +
                               " at eps = " + (f.empty() ? std::string("?") : f[0]));
    rows.push_back({std::strtod(f[0].c_str(), nullptr), f[2] == "1", f[3], f[4], f[5], f[6]});
  }
  return rows;
}

enum class quantity { force, torque, force_derivative, torque_derivative, pair_force, pair_torque };
constexpr std::array<quantity, 6> all_quantities = {quantity::force,
                                                    quantity::torque,
                                                    quantity::force_derivative,
                                                    quantity::torque_derivative,
                                                    quantity::pair_force,
                                                    quantity::pair_torque};

inline const char* name(quantity q) {
  switch (q) {
    case quantity::force:
      return "force";
    case quantity::torque:
      return "torque";
    case quantity::force_derivative:
      return "force_derivative";
    case quantity::torque_derivative:
      return "torque_derivative";
    case quantity::pair_force:
      return "force_torque.force";
    case quantity::pair_torque:
      return "force_torque.torque";
  }
  return "?";
}

// The 64-digit reference rounded to Real (via long double for the built-in
// types, which adds at most half an ulp of double rounding for float/double).
template <class Real>
Real from_string(const std::string& s) {
  if constexpr (std::is_floating_point<Real>::value) {
    return static_cast<Real>(std::strtold(s.c_str(), nullptr));
  } else {
    return Real(s);
  }
}

template <class Real>
Real evaluate(quantity q, Real eps) {
  switch (q) {
    case quantity::force:
      return spinslide::force(eps);
    case quantity::torque:
      return spinslide::torque(eps);
    case quantity::force_derivative:
      return spinslide::force_derivative(eps);
    case quantity::torque_derivative:
      return spinslide::torque_derivative(eps);
    case quantity::pair_force:
      return spinslide::force_torque(eps).force;
    case quantity::pair_torque:
      return spinslide::force_torque(eps).torque;
  }
  return Real(0);
}

inline const std::string& reference_value(const reference_row& r, quantity q) {
  switch (q) {
    case quantity::force:
    case quantity::pair_force:
      return r.force;
    case quantity::torque:
    case quantity::pair_torque:
      return r.torque;
    case quantity::force_derivative:
      return r.force_derivative;
    case quantity::torque_derivative:
      return r.torque_derivative;
  }
  return r.force;
}

// The ranges the accuracy tables report.
enum class range { below_1e_3, middle, above_1e3, near_one };
constexpr std::array<range, 4> all_ranges = {range::below_1e_3, range::middle, range::above_1e3,
                                             range::near_one};
inline const char* name(range r) {
  switch (r) {
    case range::below_1e_3:
      return "ε < 1e-3";
    case range::middle:
      return "1e-3 ≤ ε ≤ 1e3";
    case range::above_1e3:
      return "ε > 1e3";
    case range::near_one:
      return "ε within 1e-6 of 1";
  }
  return "?";
}
inline bool in_range(range r, double eps) {
  switch (r) {
    case range::below_1e_3:
      return eps < 1e-3;
    case range::middle:
      return eps >= 1e-3 && eps <= 1e3;
    case range::above_1e3:
      return eps > 1e3;
    case range::near_one:
      return std::fabs(eps - 1) < 1e-6;
  }
  return false;
}

struct worst_case {
  double error = 0;  // in units of epsilon of Real
  double eps = 0;    // where
  int points = 0;
};

// Largest error of one function of type Real over the rows in one range.
template <class Real>
worst_case measure(const std::vector<reference_row>& rows, quantity q, range rg) {
  worst_case w;
  const bool is_float = std::numeric_limits<Real>::digits <= 24;
  for (const auto& row : rows) {
    if (!in_range(rg, row.eps) || (is_float && !row.float_exact)) continue;
    const Real eps = static_cast<Real>(row.eps);
    const Real got = evaluate(q, eps);
    const Real want = from_string<Real>(reference_value(row, q));
    const double e = static_cast<double>(boost::math::epsilon_difference(got, want));
    ++w.points;
    if (e > w.error || !(e == e)) {
      w.error = e;
      w.eps = row.eps;
    }
  }
  return w;
}

}  // namespace spinslide_test

#endif  // SPINSLIDE_TESTS_REFERENCE_TABLE_HPP
