// One linear solve with the assembled tangent removes the whole residual of a linear problem on
// any number of ranks. (Before the ghost layer held two support reaches, couplings assembled by
// another rank into a ghost row were dropped at export for want of a column, and Newton needed
// three iterations on two ranks; a random-direction finite-difference check did not see it.)
#include <gtest/gtest.h>

#include <BelosSolverFactory.hpp>
#include <BelosTpetraAdapter.hpp>
#include <Tpetra_Core.hpp>

#include "drivers/StaticProblem.hpp"
#include "scene/SceneReader.hpp"
#include "support/BeamScene.hpp"

namespace efg {
namespace {

TEST(LinearSolve, OneNewtonStepSolvesTheLinearBeam) {
  const auto comm = Tpetra::getDefaultComm();
  const auto model =
      build_model(comm, parse_scene(test::beam_scene(32, 8, 0.0), "linear_solve.yaml"));
  StaticProblem problem(model);
  problem.set_load_factor(LoadFactor([](const std::string&) { return 1.0; }, 1.0));
  Vector d(model.maps.owned_dofs), r0(model.maps.owned_dofs), r1(model.maps.owned_dofs),
      dx(model.maps.owned_dofs);
  auto K = problem.create_matrix();
  problem.residual(d, r0);
  problem.jacobian(d, *K);
  Vector rhs(r0, Teuchos::Copy);
  rhs.scale(-1.0);
  using MV = Tpetra::MultiVector<>;
  using OP = Tpetra::Operator<>;
  auto lp = Teuchos::rcp(new Belos::LinearProblem<double, MV, OP>(K, Teuchos::rcpFromRef(dx),
                                                                  Teuchos::rcpFromRef(rhs)));
  lp->setProblem();
  auto params = Teuchos::parameterList();
  params->set("Convergence Tolerance", 1e-12);
  params->set("Maximum Iterations", 5000);
  params->set("Num Blocks", 500);
  Belos::SolverFactory<double, MV, OP> factory;
  auto solver = factory.create("GMRES", params);
  solver->setProblem(lp);
  solver->solve();
  d.update(1.0, dx, 1.0);
  problem.residual(d, r1);
  EXPECT_LT(r1.norm2(), 1e-9 * r0.norm2()) << comm->getSize() << " ranks";
}

}  // namespace
}  // namespace efg
