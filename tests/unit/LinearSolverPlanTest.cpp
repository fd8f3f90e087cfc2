// The automatic linear solver choice (solvers/LinearSolverPlan): direct up to a dof limit,
// multigrid above; nearly incompressible models (nu >= 0.49) are factored up to 4x the limit in
// 3D and 2x in 2D, because multigrid stalls on them (a mixed u-p block at nu = 0.4999 and
// 33,516 dofs: 500 GMRES iterations, exit 3; direct: solved in 53 s).
#include <gtest/gtest.h>

#include <cmath>

#include "drivers/NewtonSolver.hpp"
#include "solvers/LinearSolverPlan.hpp"

namespace efg {
namespace {

LinearSolverPlan automatic(std::int64_t dofs, int dim, double nu, std::int64_t limit = 0) {
  return plan_linear_solver("auto", limit, Teuchos::ParameterList(), Teuchos::ParameterList(), dofs,
                            dim, 1, nu);
}

using P = LinearSolverPlan::Preconditioner;

TEST(LinearSolverPlan, CompressibleModelsSwitchToMultigridAboveTheLimit) {
  EXPECT_EQ(automatic(30000, 3, 0.3).preconditioner, P::direct);
  EXPECT_EQ(automatic(33516, 3, 0.3).preconditioner, P::multigrid);
  EXPECT_EQ(automatic(150000, 2, 0.3).preconditioner, P::direct);
  EXPECT_EQ(automatic(150001, 2, 0.3).preconditioner, P::multigrid);
}

// The multigrid's smoother on the Jacobian: symmetric Gauss-Seidel in 3D (as many iterations as
// ILU(0) or fewer from 40k particles on, a third less memory, 2 ranks 68 against 123
// iterations), ILU(0) in 2D (Gauss-Seidel doubled the beam's iterations): docs/implicit.md.
TEST(LinearSolverPlan, TheMultigridSmootherIsGaussSeidelIn3DAndIluIn2D) {
  const auto three = automatic(33516, 3, 0.3).settings;
  EXPECT_EQ(three.get<std::string>("smoother: type"), "RELAXATION");
  EXPECT_EQ(three.sublist("smoother: params").get<std::string>("relaxation: type"),
            "Symmetric Gauss-Seidel");
  const auto two = automatic(150001, 2, 0.3).settings;
  EXPECT_EQ(two.get<std::string>("smoother: type"), "RILUK");
  EXPECT_EQ(two.sublist("smoother: params").get<int>("fact: iluk level-of-fill"), 0);
}

TEST(LinearSolverPlan, NearlyIncompressibleModelsAreFactoredFurther) {
  const auto plan = automatic(33516, 3, 0.4999);
  EXPECT_EQ(plan.preconditioner, P::direct);
  EXPECT_NE(plan.reason.find("nearly incompressible"), std::string::npos) << plan.reason;
  EXPECT_EQ(automatic(120000, 3, 0.49).preconditioner, P::direct);
  EXPECT_EQ(automatic(120001, 3, 0.49).preconditioner, P::multigrid);
  EXPECT_EQ(automatic(300000, 2, 0.4999).preconditioner, P::direct);
  EXPECT_EQ(automatic(300001, 2, 0.4999).preconditioner, P::multigrid);
  EXPECT_EQ(automatic(33516, 3, 0.489).preconditioner, P::multigrid);  // below the threshold
}

TEST(LinearSolverPlan, AWrittenLimitWins) {
  EXPECT_EQ(automatic(33516, 3, 0.4999, 1000).preconditioner, P::multigrid);
  EXPECT_EQ(automatic(33516, 3, 0.3, 40000).preconditioner, P::direct);
}

// The auxiliary space (operators/AuxiliaryStiffness): taken by the 3D iterative path where it
// fits the model, never in 2D (the Jacobian's own multigrid was as fast there), refused with a
// fallback where it cannot stand in.
TEST(LinearSolverPlan, TheIterativePathUsesTheAuxiliarySpaceIn3DWhereItFits) {
  const auto fits = [](std::int64_t dofs, int dim, const std::string& misfit,
                       const std::string& solver = "auto") {
    return plan_linear_solver(solver, 0, Teuchos::ParameterList(), Teuchos::ParameterList(), dofs,
                              dim, 1, 0.3, misfit, misfit);
  };
  EXPECT_EQ(fits(33516, 3, "").preconditioner, P::auxiliary);
  EXPECT_EQ(fits(1000, 3, "", "iterative").preconditioner, P::auxiliary);
  EXPECT_EQ(fits(30000, 3, "").preconditioner, P::direct);
  const auto scni = fits(33516, 3, "part 'p' is integrated by scni");
  EXPECT_EQ(scni.preconditioner, P::multigrid);
  EXPECT_NE(scni.reason.find("integrated by scni"), std::string::npos) << scni.reason;
  EXPECT_EQ(fits(150001, 2, "").preconditioner, P::multigrid);
  // Asked for by name: taken where it can stand in, else multigrid on the Jacobian.
  Teuchos::ParameterList asked;
  asked.set("Type", std::string("auxiliary"));
  const auto named = plan_linear_solver("iterative", 0, Teuchos::ParameterList(), asked, 1000, 2, 1,
                                        0.3, "part 'p' is integrated by scni", "");
  EXPECT_EQ(named.preconditioner, P::auxiliary);
  EXPECT_EQ(named.settings.get<std::string>("smoother: type"), "CHEBYSHEV");
  const auto refused = plan_linear_solver("iterative", 0, Teuchos::ParameterList(), asked, 1000, 3,
                                          1, 0.3, "condition 'c' is imposed by nitsche",
                                          "condition 'c' is imposed by nitsche");
  EXPECT_EQ(refused.preconditioner, P::multigrid);
  EXPECT_EQ(refused.settings.get<std::string>("smoother: type"), "RELAXATION");
  EXPECT_NE(refused.reason.find("nitsche"), std::string::npos) << refused.reason;
}

}  // namespace
}  // namespace efg

namespace efg {
namespace {

// Mixed u-p parts above nu = 1/4 (operators/BulkSplit.hpp): the iterative path goes through the
// saddle point of their bulk stiffness, in 2D and 3D, unless a preconditioner is named; its outer
// tolerance stays 10x above the round-off floor of the condensed system (100 eps kappa / mu, by
// hand: kappa / mu = 2 (1 + nu) / (3 (1 - 2 nu)) = 499,999.33 at nu = 0.499999) and the inner one
// goes below that floor by 100 sqrt(kappa / mu). The plan's tolerance is what NOX hands every linear
// solve (Stratimikos lets that solve criterion override Belos' own "Convergence Tolerance"; before,
// a fixed 1e-10 did and the outer GMRES took two iterations at nu = 0.499999). The outer
// iteration is a fixed point (the preconditioner's result added unscaled).
TEST(LinearSolverPlan, MixedPartsTakeTheSaddlePointOnTheIterativePath) {
  const auto plan = [](const std::string& solver, int dim, double nu,
                       const Teuchos::ParameterList& preconditioner = Teuchos::ParameterList()) {
    return plan_linear_solver(solver, 0, Teuchos::ParameterList(), preconditioner, 1000, dim, 1, nu,
                              "", "", true);
  };
  for (int dim : {2, 3}) {
    const auto split = plan("iterative", dim, 0.499999);
    EXPECT_EQ(split.preconditioner, P::bulk_split) << split.reason;
    const double kappa_over_mu = 2 * 1.499999 / (3 * 2e-6);
    const double tolerance = split.krylov.sublist("Solver Types")
                                 .sublist("Fixed Point")
                                 .get<double>("Convergence Tolerance");
    EXPECT_NEAR(tolerance, 1000 * 2.220446049250313e-16 * kappa_over_mu, 1e-8 * tolerance);
    EXPECT_NEAR(split.saddle_tolerance, tolerance / (1000 * std::sqrt(kappa_over_mu)),
                1e-8 * split.saddle_tolerance);
    EXPECT_EQ(split.max_iterations, 2);
    EXPECT_EQ(split.tolerance, tolerance);
    EXPECT_EQ(nonlinear_parameters(Teuchos::ParameterList(), true, split.tolerance)
                  ->sublist("Direction")
                  .sublist("Newton")
                  .sublist("Linear Solver")
                  .get<double>("Tolerance"),
              tolerance);
    EXPECT_EQ(split.krylov.get<std::string>("Solver Type"), "Fixed Point");
  }
  // Below the floor the Newton's 1e-10 stands.
  const auto compressible = plan("iterative", 2, 0.3);
  EXPECT_EQ(compressible.krylov.sublist("Solver Types")
                .sublist("Fixed Point")
                .get<double>("Convergence Tolerance"),
            1e-10);
  // A named Krylov method wins; GMRES around the inner solve is flexible.
  Teuchos::ParameterList gmres;
  gmres.set("Solver Type", std::string("Block GMRES"));
  EXPECT_TRUE(plan_linear_solver("iterative", 0, gmres, Teuchos::ParameterList(), 1000, 2, 1,
                                 0.499999, "", "", true)
                  .krylov.sublist("Solver Types")
                  .sublist("Block GMRES")
                  .get<bool>("Flexible Gmres"));
  // A stage's linear_solver map sets the tolerance every solve reaches.
  Teuchos::ParameterList loose;
  loose.set("Convergence Tolerance", 1e-6);
  EXPECT_EQ(plan_linear_solver("iterative", 0, loose, Teuchos::ParameterList(), 1000, 2, 1, 0.3, "",
                               "", false)
                .tolerance,
            1e-6);
  EXPECT_EQ(plan("direct", 2, 0.499999).preconditioner, P::direct);
  EXPECT_EQ(plan("auto", 2, 0.499999).preconditioner, P::direct);  // 1,000 dofs: factored
  Teuchos::ParameterList named;
  named.set("Type", std::string("MueLu"));
  EXPECT_EQ(plan("iterative", 2, 0.499999, named).preconditioner, P::multigrid);
}

}  // namespace
}  // namespace efg
