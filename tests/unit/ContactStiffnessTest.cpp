// The explicit contact's material-rule stiffness (contact/ContactStiffness.hpp,
// contact/FacingArea.hpp): the bulk moduli by hand, the stable step with contact springs against
// central differences run on a spring (the step it gives is the edge of stability: 1 % below
// stays bounded, 1 % above grows, with and without the lagged damper), its reduction to
// 2 / omega sqrt(1 - S / 4) without dampers, and the facing area of a block's corner particle.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/ContactStiffness.hpp"
#include "contact/FacingArea.hpp"

namespace {

using efg::contact::damped_stable_step;

TEST(ContactStiffness, BulkModulusByHand) {
  EXPECT_NEAR(efg::contact::bulk_modulus(1.0, 0.3, false), 1.0 / 1.2, 1e-15);
  EXPECT_NEAR(efg::contact::bulk_modulus(1.0, 0.3, true), 1.0 / 1.4, 1e-15);
  // k = scale K A / h: the penetration under a pressure p is p h / (scale K)
  const double k = efg::contact::material_stiffness(2.0, 0.5, 3.0, 0.1);
  EXPECT_NEAR(k, 30.0, 1e-12);
}

// Largest |x| over n steps of central differences (velocity Verlet) for m x'' = -(K_s + k) x
// - c x'_lagged, as the driver and the contact do it: the damper sees the velocity over the last
// step.
double largest_amplitude(double omega2, double w2, double damping, double dt, int steps) {
  const double m = 1.0, k = w2 * m, c = 2.0 * damping * std::sqrt(k * m);
  double x = 1.0, x_old = 1.0, v = 0.0, largest = 0.0;
  auto force = [&](double at, double before) {
    return -omega2 * m * at - k * at - c * (at - before) / dt;
  };
  double a = force(x, x_old) / m;
  for (int n = 0; n < steps; ++n) {
    v += 0.5 * dt * a;
    x_old = x;
    x += dt * v;
    a = force(x, x_old) / m;
    v += 0.5 * dt * a;
    largest = std::max(largest, std::abs(x));
  }
  return largest;
}

TEST(ContactStiffness, StableStepIsTheEdgeOfStability) {
  // A solid mode omega^2 = 9 and a contact spring k / m = 16 on the same mass: undamped, the
  // sum's frequency is 5 and central differences hold up to dt = 2 / 5 exactly.
  const double dt = damped_stable_step(9.0 + 16.0, 0.0, 0.0);
  EXPECT_NEAR(dt, 0.4, 1e-14);
  EXPECT_LT(largest_amplitude(9.0, 16.0, 0.0, 0.99 * dt, 2000), 1.5);
  EXPECT_GT(largest_amplitude(9.0, 16.0, 0.0, 1.01 * dt, 2000), 1e3);
  // With a damper the root of (omega^2 + w^2) dt^2 + 4 D w dt = 4 is smaller and still stable.
  const double damped = damped_stable_step(25.0, 4.0 * 0.2 * 4.0, 0.0);
  EXPECT_LT(damped, dt);
  EXPECT_NEAR(25.0 * damped * damped + 4.0 * 0.2 * 4.0 * damped, 4.0, 1e-12);
  EXPECT_LT(largest_amplitude(9.0, 16.0, 0.2, 0.99 * damped, 2000), 1.5);
}

TEST(ContactStiffness, WithoutMaterialSpringsTheMassRuleAlone) {
  // No damper: 2 / omega sqrt(1 - S / 4), the walls' and the mass rule's reduction.
  const double S = 0.1 + 4.0 * 0.3 * std::sqrt(0.1);
  EXPECT_NEAR(damped_stable_step(49.0, 0.0, S), 2.0 / 7.0 * std::sqrt(1.0 - S / 4.0), 1e-15);
}

TEST(ContactStiffness, FacingAreaOfACornerParticle) {
  // A cube corner of spacing h: three faces, each giving it a quarter of a cell face, h^2 / 4.
  const double h = 0.5, q = h * h / 4;
  const efg::SideShares corner = {{q, 0, 0}, {0, -q, 0}, {0, 0, q}};
  const double down[3] = {0, 0, -1};  // a plate pressing the top face
  EXPECT_NEAR(efg::contact::facing_area(corner, down), q, 1e-15);
  const double r = 1.0 / std::sqrt(3.0), diagonal[3] = {r, r, r};  // a ball on the corner
  EXPECT_NEAR(efg::contact::facing_area(corner, diagonal), 3 * q * r, 1e-15);
  EXPECT_NEAR(efg::contact::largest_facing_area(corner), std::sqrt(3.0) * q, 1e-15);
}

}  // namespace
