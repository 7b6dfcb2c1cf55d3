//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The cylinder on one face with a tilted pressure (cylinder.hpp).
#include <gtest/gtest.h>

#include <spinslide/spinslide.hpp>

#include <boost/math/special_functions/relative_difference.hpp>

namespace {

using namespace spinslide;

// B − A = 𝓣 (the torque integrand x² + y² − εy = x² − y(ε − y)), and the
// exact values at ε = 0: B = 1/3, A = −1/3, C = 0.
TEST(TiltIntegrals, IdentityWithTheTorqueAndValuesAtZero) {
  for (double e : {1e-6, 0.1, 0.653, 0.999, 1.0, 1.001, 3.0, 100.0}) {
    const auto I = tilted_pressure_integrals(e);
    EXPECT_NEAR(I.B - I.A, torque(e), 1e-12) << e;
  }
  const auto z = tilted_pressure_integrals(0.0);
  EXPECT_NEAR(z.B, 1.0 / 3, 1e-15);
  EXPECT_NEAR(z.A, -1.0 / 3, 1e-15);
  EXPECT_NEAR(z.C, 0.0, 1e-15);
}

TEST(TiltedCylinder, ZeroHeightIsTheFlatDisk) {
  for (double e : {0.0, 0.2, 1.0, 5.0}) {
    const auto c = tilted_cylinder_friction(e, 0.0, 0.05, 0.3);
    EXPECT_EQ(c.along, -force(e));
    EXPECT_EQ(c.sideways, 0.0);
    EXPECT_EQ(c.torque, -torque(e));
    EXPECT_EQ(c.tilt_forward, 0.0);
  }
}

// The moment balance: pressure higher at the front (α > 0), sideways force
// along v × ω growing with h, and the self-consistency relations.
TEST(TiltedCylinder, MomentBalanceAndSidewaysForce) {
  const double R = 0.05, mu = 0.3;
  double prev = 0;
  for (double h : {0.005, 0.01, 0.02, 0.03}) {
    const double e = 1.0, kappa = 4 * mu * h / R;
    const auto c = tilted_cylinder_friction(e, h, R, mu);
    const auto I = tilted_pressure_integrals(e);
    EXPECT_GT(c.tilt_forward, 0);
    EXPECT_GT(c.sideways, prev);
    prev = c.sideways;
    // α = κ(−F_along), β = κ F_sideways: ∫x p = −h F_x, ∫y' p = −h F_y'.
    EXPECT_NEAR(c.tilt_forward, -kappa * c.along, 1e-14);
    EXPECT_NEAR(c.tilt_sideways, kappa * c.sideways, 1e-14);
    EXPECT_NEAR(c.sideways, c.tilt_forward * I.B, 1e-15);
  }
}

TEST(TiltedCylinder, TippingAndBadInputAreDomainErrors) {
  EXPECT_THROW(tilted_cylinder_friction(1.0, 0.2, 0.05, 0.3), std::domain_error);  // κ = 4.8
  EXPECT_THROW(tilted_cylinder_friction(-1.0, 0.01, 0.05, 0.3), std::domain_error);
  EXPECT_THROW(tilted_cylinder_friction(1.0, -0.01, 0.05, 0.3), std::domain_error);
  EXPECT_THROW(tilted_cylinder_friction(1.0, 0.01, 0.0, 0.3), std::domain_error);
  EXPECT_THROW(tilted_cylinder_friction(1.0, 0.01, 0.05, std::nan("")), std::domain_error);
}

}  // namespace
