//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// tests/reference/flow_zeros.csv for the tests: the loads by name, the zeros
// of each (load, γ), and the attractor the flow reaches from a given ratio
// according to those zeros alone.
#ifndef SPINSLIDE_TESTS_FLOW_ZEROS_REFERENCE_HPP
#define SPINSLIDE_TESTS_FLOW_ZEROS_REFERENCE_HPP

#include <gtest/gtest.h>

#include <spinslide/spinslide.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference/csv.hpp"

namespace spinslide_reference {

using namespace spinslide;

// The loads of tests/reference/flow_zeros.csv (generate_flow_zeros.cpp: the
// zeros of the flow from the ring's defining integral in cpp_bin_float_50).
template <class F>
void with_load(const std::string& name, F f) {
  if (name == "two_rings")
    f(weighted_sum({0.1, 0.9}, scaled<ring<>>(ring<>(), 0.1), ring<>()));
  else if (name == "three_rings")
    f(weighted_sum({0.01, 0.09, 0.9}, scaled<ring<>>(ring<>(), 0.01), scaled<ring<>>(ring<>(), 0.1),
                   ring<>()));
  else if (name == "disk_and_ring")
    f(weighted_sum({0.1, 0.9}, scaled<uniform_disk<>>(uniform_disk<>(), 0.15), ring<>()));
  else
    FAIL() << "unknown load " << name;
}

struct flow_case {
  std::string load;
  double gamma;
  std::vector<ratio_flow_zero<double>> zeros;  // ascending
};

inline std::vector<flow_case> reference_flow_cases() {
  std::vector<flow_case> cases;
  for (const auto& row : read_csv_rows(SPINSLIDE_FLOW_ZEROS_REFERENCE)) {
    if (row.size() != 4) throw std::runtime_error("bad row in " SPINSLIDE_FLOW_ZEROS_REFERENCE);
    const double gamma = std::strtod(row[1].c_str(), nullptr);
    if (cases.empty() || cases.back().load != row[0] || cases.back().gamma != gamma)
      cases.push_back({row[0], gamma, {}});
    cases.back().zeros.push_back({std::strtod(row[2].c_str(), nullptr), row[3] == "1"});
  }
  return cases;
}

// The attractor the flow reaches from ε, from the reference zeros alone: the
// next zero above ε if that one attracts (then f > 0 below it), else the
// zero below ε (or 0 if there is none); above the last zero, the last one if
// it attracts, else ∞.
inline double expected_attractor(const flow_case& c, double eps) {
  const auto& z = c.zeros;
  std::size_t k = 0;
  while (k < z.size() && z[k].ratio < eps) ++k;
  if (k == z.size())
    return z.back().attracting ? z.back().ratio : std::numeric_limits<double>::infinity();
  if (z[k].attracting) return z[k].ratio;
  return k == 0 ? 0.0 : z[k - 1].ratio;
}

}  // namespace spinslide_reference

#endif  // SPINSLIDE_TESTS_FLOW_ZEROS_REFERENCE_HPP
