//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// W over (v_x, v_y, ω) at a point of a humanoid's foot (issue 27's grazing
// contact), for the tests of the impulse law on thin sets: mass 2 kg,
// inertia diag(0.03, 0.03, 0.02) kg m² about its centre, the contact point
// at r = (0.05, 0.02, −0.04) m from it, normal z: rows of v_point = v + ω × r
// and of ω_z.
#ifndef SPINSLIDE_TESTS_FOOT_METRIC_HPP
#define SPINSLIDE_TESTS_FOOT_METRIC_HPP

#include <spinslide/contact/planar_metric.hpp>

#include <cstddef>

namespace spinslide_test {

inline spinslide::planar_metric<double>::matrix foot_inverse_mass() {
  const double m = 2, inertia[3] = {0.03, 0.03, 0.02}, r[3] = {0.05, 0.02, -0.04};
  // J (3×6) over (v, ω): row x: (1, 0, 0, 0, r_z, −r_y); row y: (0, 1, 0, −r_z, 0, r_x);
  // spin: (0, 0, 0, 0, 0, 1).
  const double j[3][6] = {{1, 0, 0, 0, r[2], -r[1]}, {0, 1, 0, -r[2], 0, r[0]}, {0, 0, 0, 0, 0, 1}};
  const double inverse[6] = {1 / m, 1 / m, 1 / m, 1 / inertia[0], 1 / inertia[1], 1 / inertia[2]};
  spinslide::planar_metric<double>::matrix w{};
  for (std::size_t a = 0; a < 3; ++a)
    for (std::size_t b = 0; b < 3; ++b)
      for (std::size_t k = 0; k < 6; ++k) w[a][b] += j[a][k] * inverse[k] * j[b][k];
  return w;
}

}  // namespace spinslide_test

#endif  // SPINSLIDE_TESTS_FOOT_METRIC_HPP
