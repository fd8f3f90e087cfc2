// Finite-strain patch test: a neo-Hookean block stretched to lambda = 2 in uniaxial tension
// (symmetry planes, free lateral faces) deforms homogeneously; the Cauchy stress at every particle
// matches the closed form sigma_xx = (mu (lambda^2 - 1) + lambda_L ln J) / J with the lateral
// stretch solving sigma_yy = 0, and Newton converges quadratically.
#include <gtest/gtest.h>

#include <cmath>

#include "materials/ElasticConstants.hpp"
#include "run/OutputFields.hpp"
#include "support/StaticSolve.hpp"

namespace efg {
namespace {

const char* kScene = R"(
mesh:
  generate: {element: hex8, lower: [0, 0, 0], upper: [1, 1, 1], cells: [3, 3, 3], perturbation: 0.2, seed: 9}
parts:
  - {name: block, blocks: [block_1], material: rubber, section: {formulation: total_lagrangian, dilation: 1.8}}
materials:
  - {name: rubber, model: neo_hookean, youngs_modulus: 10.0, poissons_ratio: 0.3}
boundary_conditions:
  - {name: symmetry_x, type: displacement, node_set: xmin, x: 0}
  - {name: symmetry_y, type: displacement, node_set: ymin, y: 0}
  - {name: symmetry_z, type: displacement, node_set: zmin, z: 0}
  - {name: pull, type: displacement, node_set: xmax, x: 1.0}
stages:
  - {name: stretch, driver: implicit, end_time: 1, load_steps: 4}
output:
  fields: [stress]
)";

TEST(NeoHookeanStretch, CauchyStressMatchesClosedFormAndNewtonIsQuadratic) {
  auto s = test::solve_static(kScene);
  // E = 10, nu = 0.3 by hand: mu = E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu)).
  struct {
    double mu = 10.0 / 2.6, lambda = 3.0 / 0.52;
  } c;
  // Lateral stretch t with sigma_yy = mu (t^2 - 1) + lambda ln(2 t^2) = 0 (Newton on t).
  double t = 0.8;
  for (int i = 0; i < 50; ++i) {
    const double f = c.mu * (t * t - 1) + c.lambda * std::log(2 * t * t);
    const double df = 2 * c.mu * t + 2 * c.lambda / t;
    t -= f / df;
  }
  const double J = 2 * t * t;
  const double sigma_xx = (c.mu * (4 - 1) + c.lambda * std::log(J)) / J;
  const auto columns = state_columns(*s.model, s.problem->solid(), *s.d_overlap);
  ASSERT_EQ(columns.size(), 6u);
  double worst = 0;
  for (std::size_t i = 0; i < columns[0].size(); ++i) {
    worst = std::max(worst, std::abs(columns[0][i] - sigma_xx) / sigma_xx);
    for (std::size_t k = 1; k < 6; ++k) worst = std::max(worst, std::abs(columns[k][i]) / sigma_xx);
  }
  EXPECT_LT(worst, 1e-8) << "sigma_xx closed form " << sigma_xx;
  // Quadratic convergence: in every load step some iteration shows order >= 1.8 before the
  // residual reaches round-off.
  ASSERT_EQ(s.summary.residual_histories.size(), 4u);
  for (const auto& h : s.summary.residual_histories) {
    double best = 0;
    for (std::size_t k = 2; k < h.size(); ++k)
      if (h[k] > 1e-12 * h[0])
        best = std::max(best, std::log(h[k] / h[k - 1]) / std::log(h[k - 1] / h[k - 2]));
    EXPECT_GE(best, 1.8) << "residual history of a load step";
    EXPECT_LE(h.size(), 8u);
  }
}

}  // namespace
}  // namespace efg
