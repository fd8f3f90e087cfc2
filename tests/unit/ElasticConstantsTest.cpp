#include <gtest/gtest.h>

#include "materials/ElasticConstants.hpp"

namespace efg::physics {
namespace {

TEST(ElasticConstants, RoundTripToYoungsModulusAndPoisson) {
  const auto c = elastic_constants(3.0e7, 0.3);
  // E = mu (3 lambda + 2 mu) / (lambda + mu), nu = lambda / (2 (lambda + mu))
  EXPECT_NEAR(c.mu * (3 * c.lambda + 2 * c.mu) / (c.lambda + c.mu), 3.0e7, 1e-7);
  EXPECT_NEAR(c.lambda / (2 * (c.lambda + c.mu)), 0.3, 1e-15);
  EXPECT_NEAR(c.kappa, c.lambda + 2 * c.mu / 3, 1e-7);
}

TEST(ElasticConstants, HandComputedValues) {
  // E = 10, nu = 0.3: mu = 10 / 2.6 = 3.846153846..., lambda = 3 / 0.52 = 5.769230769...,
  // kappa = E / (3 (1 - 2 nu)) = 10 / 1.2 = 8.333...
  const auto c = elastic_constants(10.0, 0.3);
  EXPECT_NEAR(c.mu, 3.8461538461538463, 1e-14);
  EXPECT_NEAR(c.lambda, 5.7692307692307692, 1e-14);
  EXPECT_NEAR(c.kappa, 8.3333333333333333, 1e-14);
  // Plane stress: lambda* = E nu / (1 - nu^2) = 3 / 0.91.
  EXPECT_NEAR(plane_stress_constants(10.0, 0.3).lambda, 3.2967032967032967, 1e-14);
}

TEST(ElasticConstants, PlaneStressGivesZeroOutOfPlaneStress) {
  // Uniaxial in-plane strain state of a plane stress sheet: sigma_xx = E eps / (1 - nu^2) for
  // eps_yy = 0, eps_xx = eps.
  const double e = 200.0, nu = 0.25, eps = 1e-3;
  const auto c = plane_stress_constants(e, nu);
  EXPECT_NEAR((c.lambda + 2 * c.mu) * eps, e * eps / (1 - nu * nu), 1e-12);
}

}  // namespace
}  // namespace efg::physics
