// The Jacobian of the complete static residual (solid, loads, essential conditions of every
// method) equals its central difference, on 1 to 3 ranks: what Newton needs for quadratic
// convergence (one iteration for a linear problem).
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

#include <cmath>

#include "drivers/StaticProblem.hpp"
#include "scene/SceneReader.hpp"
#include "support/BeamScene.hpp"

namespace efg {
namespace {

class StaticJacobian : public ::testing::TestWithParam<const char*> {};

TEST_P(StaticJacobian, MatchesCentralDifferences) {
  const auto comm = Tpetra::getDefaultComm();
  const std::string text = test::beam_scene(16, 4, 0.2, GetParam());
  const auto model = build_model(comm, parse_scene(text, "jacobian.yaml"));
  StaticProblem problem(model);
  problem.set_load_factor(LoadFactor([](const std::string&) { return 1.0; }, 1.0));
  Vector d(model.maps.owned_dofs), v(model.maps.owned_dofs), Kv(model.maps.owned_dofs);
  d.randomize(-1e-3, 1e-3);
  v.randomize(-1.0, 1.0);
  auto K = problem.create_matrix();
  problem.jacobian(d, *K);
  // Thyra wraps K with the owned-dof space: its domain and range must be exactly that map.
  EXPECT_TRUE(K->getDomainMap()->isSameAs(*model.maps.owned_dofs));
  EXPECT_TRUE(K->getRangeMap()->isSameAs(*model.maps.owned_dofs));
  EXPECT_TRUE(K->getRowMap()->isSameAs(*model.maps.owned_dofs));
  K->apply(v, Kv);
  const double h = 1e-4;
  Vector dp(d, Teuchos::Copy), dm(d, Teuchos::Copy), rp(model.maps.owned_dofs),
      rm(model.maps.owned_dofs);
  dp.update(h, v, 1.0);
  dm.update(-h, v, 1.0);
  problem.residual(dp, rp);
  problem.residual(dm, rm);
  rp.update(-1.0 / (2 * h), rm, 1.0 / (2 * h));
  rp.update(-1.0, Kv, 1.0);
  EXPECT_LT(rp.normInf(), 1e-8 * Kv.normInf())
      << GetParam() << " on " << comm->getSize() << " ranks";
}

INSTANTIATE_TEST_SUITE_P(Methods, StaticJacobian,
                         ::testing::Values("transformation", "nitsche", "penalty"));

}  // namespace
}  // namespace efg
