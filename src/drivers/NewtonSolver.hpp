// NOX Newton with line search on the solid model evaluator, linear solves by Belos with an
// Ifpack2 or MueLu preconditioner through Stratimikos. Defaults suit the nonsymmetric systems of
// the transformation method (GMRES + ILU(2)); the stage's nonlinear_solver, linear_solver and
// preconditioner maps override them (see docs/scene.md).
#pragma once

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

#include "drivers/SolidModelEvaluator.hpp"

namespace efg {

struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  int linear_iterations = 0;
  std::vector<double> residual_history;  ///< ||r||_2 before the first and after every iteration
  std::string failure;                   ///< a numerical failure inside an evaluation, if any
};

class NewtonSolver {
 public:
  /// `stage` is the stage's resolved YAML (its solver maps); `where` names it in messages.
  NewtonSolver(StaticProblem& problem, const YAML::Node& stage, const std::string& scene_file,
               const std::string& where);

  /// Solves r(d) = 0 starting from d; d holds the last iterate on return.
  NewtonResult solve(Vector& d);

 private:
  StaticProblem& problem_;
  Teuchos::RCP<Teuchos::ParameterList> nox_params_;
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> lows_factory_;
};

/// The default NOX, Stratimikos lists, merged with a stage's maps (exposed for tests and docs).
Teuchos::RCP<Teuchos::ParameterList> nonlinear_parameters(const Teuchos::ParameterList& user);
Teuchos::RCP<Teuchos::ParameterList> linear_parameters(
    const Teuchos::ParameterList& solver, const Teuchos::ParameterList& preconditioner);

}  // namespace efg
