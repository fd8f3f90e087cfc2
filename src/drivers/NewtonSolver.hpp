// NOX Newton with line search on the solid model evaluator; linear solves by Belos (through
// Stratimikos) with a preconditioner efg builds from each Jacobian (solvers/): a direct LU
// factorization on one rank for small and medium models, smoothed-aggregation multigrid with
// rigid-body modes otherwise (solvers/LinearSolverPlan.hpp). Newton stops on the tests of
// drivers/NewtonConvergence.hpp. The stage's keys and maps override the defaults (docs/scene.md).
#pragma once

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

#include "drivers/NewtonConvergence.hpp"
#include "drivers/SolidModelEvaluator.hpp"
#include "solvers/LinearSolverPlan.hpp"

namespace efg {

struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  int linear_iterations = 0;
  std::vector<double> residual_history;  ///< ||r||_2 before the first and after every iteration
  NewtonRecord record;                   ///< linear iterations and reductions per iteration
  std::string failure;                   ///< a numerical failure inside an evaluation, if any
  bool linear_failure = false;  ///< the linear system could not be solved: no cutback helps
};

class NewtonSolver {
 public:
  /// `stage` is the stage's resolved YAML (its solver maps); `where` names it in messages.
  NewtonSolver(NonlinearProblem& problem, const YAML::Node& stage, const std::string& scene_file,
               const std::string& where);

  /// Solves r(d) = 0 starting from d; d holds the last iterate on return. `step_scale`: the
  /// residual norm where the load step began before a predictor moved d (0: none), a further
  /// floor of the Newton test's force scale; `step_energy`: the work of that residual over the
  /// predicted increment, a floor of its energy scale (NewtonConvergence).
  NewtonResult solve(Vector& d, double step_scale = 0.0, double step_energy = 0.0);
  /// solve() from the extrapolated predictor of a load step (docs/implicit.md): d moves by
  /// `ratio` times the last accepted increment (the step's length over the last one; 0: no
  /// predictor, the first step of a stage), and the residual of the unpredicted start and its
  /// work over the predicted move become the scales of the Newton test. The predictor is the
  /// start of Newton, not a change of any history, which each iterate recomputes.
  NewtonResult solve_predicted(Vector& d, const Vector& increment, double ratio);

  /// x = K(d)^-1 b with the Jacobian at d and the stage's linear solver (its preconditioner
  /// rebuilt there): a tangent direction (drivers/BodyForceBalance). Returns the linear
  /// iterations, or -1 when the solve did not converge.
  int solve_tangent(const Vector& d, const Vector& b, Vector& x);

  const LinearSolverPlan& plan() const { return plan_; }
  /// True when `solver: auto` took the iterative path for a model it could still factor (up to
  /// the nearly incompressible models' direct limit): a stalled linear solve then retries with
  /// the direct solver.
  bool direct_fallback() const { return direct_fallback_; }
  /// Seconds spent building preconditioners / factorizations so far.
  double preconditioner_seconds() const;

 private:
  NonlinearProblem& problem_;
  LinearSolverPlan plan_;
  bool direct_fallback_ = false;
  double tolerance_ = 1e-9, energy_tolerance_ = 1e-12;
  Teuchos::RCP<Teuchos::ParameterList> nox_params_;
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> lows_factory_;
  Teuchos::RCP<MatrixPreconditioner> preconditioner_;
  Teuchos::RCP<SolidModelEvaluator> model_;
  Teuchos::RCP<Thyra::LinearOpBase<double>> jacobian_;
  Teuchos::RCP<Thyra::PreconditionerBase<double>> preconditioner_op_;
};

/// The default NOX list merged with a stage's map, and the Stratimikos list of a plan (exposed
/// for tests and docs).
/// `line_search`: false gives full Newton steps by default (NonlinearProblem::
/// residual_norm_is_a_merit); `linear_tolerance`: the relative residual every linear solve
/// reaches (LinearSolverPlan::tolerance); the user's list overrides either.
Teuchos::RCP<Teuchos::ParameterList> nonlinear_parameters(const Teuchos::ParameterList& user,
                                                          bool line_search = true,
                                                          double linear_tolerance = 1e-10);
Teuchos::RCP<Teuchos::ParameterList> linear_parameters(const LinearSolverPlan& plan);

}  // namespace efg
