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

TEST(ElasticConstants, PlaneStressGivesZeroOutOfPlaneStress) {
  // Uniaxial in-plane strain state of a plane stress sheet: sigma_xx = E eps / (1 - nu^2) for
  // eps_yy = 0, eps_xx = eps.
  const double e = 200.0, nu = 0.25, eps = 1e-3;
  const auto c = plane_stress_constants(e, nu);
  EXPECT_NEAR((c.lambda + 2 * c.mu) * eps, e * eps / (1 - nu * nu), 1e-12);
}

}  // namespace
}  // namespace efg::physics
