//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Every failure the fuzz harnesses (fuzz/) found, as a regression test with
// the input the fuzzer reported and an independent expectation: an exact
// limit, a scale invariance or a bound.  docs/reliability.md lists them.

#include <spinslide/spinslide.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace {

using namespace spinslide;
constexpr double max_d = std::numeric_limits<double>::max();
constexpr double min_d = std::numeric_limits<double>::min();

}  // namespace
