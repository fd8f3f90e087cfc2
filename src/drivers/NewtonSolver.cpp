#include "drivers/NewtonSolver.hpp"

#include <NOX.H>
#include <NOX_StatusTest_Factory.H>
#include <NOX_Thyra.H>
#include <NOX_Observer.hpp>
#include <NOX_SolverStats.hpp>
#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include <cmath>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "parallel/ExitReport.hpp"
#include "scene/ParameterListFromYaml.hpp"
#include "solvers/RigidBodyModes.hpp"

namespace efg {
namespace {

std::string sci(double v) {
  std::ostringstream o;
  o.precision(3);
  o << std::scientific << v;
  return o.str();
}

// Prints one line per Newton iteration from the record NewtonConvergence keeps.
class ResidualLog : public NOX::Observer {
 public:
  explicit ResidualLog(const NewtonRecord& record) : record_(record) {}
  void runPostIterate(const NOX::Solver::Generic& solver) override {
    const auto& h = record_.residuals;
    if (h.size() == 2) Log::info("    Newton 0: ||r|| = " + sci(h[0]));
    if (h.size() < 2 || record_.linear_iterations.empty()) return;
    const double r = h.back();
    std::string rate;
    if (h.size() >= 3 && h[h.size() - 2] > 0 && h[h.size() - 3] > 0 && r > 0)
      rate = ", order " +
             sci(std::log(r / h[h.size() - 2]) / std::log(h[h.size() - 2] / h[h.size() - 3]));
    Log::info("    Newton " + std::to_string(solver.getNumIterations()) + ": ||r|| = " + sci(r) +
              " (" + std::to_string(record_.linear_iterations.back()) +
              " linear iterations, reduction " + sci(record_.linear_reductions.back()) +
              (record_.linear_converged.back() ? "" : ", not converged") + rate + ")");
  }

 private:
  const NewtonRecord& record_;
};

Teuchos::ParameterList from_stage(const YAML::Node& stage, const char* key, const std::string& file,
                                  const std::string& where) {
  return parameter_list_from_yaml(stage[key], key, file, where + "." + key);
}

std::string linear_failure_advice(const LinearSolverPlan& plan) {
  return "linear solver " + plan.describe() +
         ". Candidates: a body or part not held against rigid motion (missing essential "
         "conditions), a nearly incompressible material (nu >= 0.49: the displacement-only "
         "formulation locks and its system is ill-conditioned), an inverted or degenerate "
         "state; with multigrid, supports several rows of particles wide where the cells are "
         "sheared or curved against the axes (try section.spacing: edges) or SCNI's soft modes "
         "(try integration: scni_subcells). Try solver: direct, or a preconditioner suited to "
         "the problem (docs/implicit.md, 'When a solve fails')";
}

}  // namespace

Teuchos::RCP<Teuchos::ParameterList> nonlinear_parameters(const Teuchos::ParameterList& user,
                                                          bool line_search,
                                                          double linear_tolerance) {
  auto p = Teuchos::parameterList("Nonlinear Solver");
  p->set("Nonlinear Solver", "Line Search Based");
  auto& newton = p->sublist("Direction");
  newton.set("Method", "Newton");
  newton.sublist("Newton").set("Forcing Term Method", "Constant");
  // NOX passes this to Stratimikos as the solve criterion of every linear solve, where it
  // overrides Belos' own "Convergence Tolerance": the plan's (and a stage's linear_solver
  // map's) tolerance reaches Belos only through it.
  newton.sublist("Newton").sublist("Linear Solver").set("Tolerance", linear_tolerance);
  auto& ls = p->sublist("Line Search");
  ls.set("Method", line_search ? "Backtrack" : "Full Step");
  ls.sublist("Backtrack").set("Minimum Step", 1e-6);
  ls.sublist("Backtrack").set("Max Iters", 20);
  auto& out = p->sublist("Printing").sublist("Output Information");
  out.set("Error", true);
  out.set("Warning", false);
  out.set("Outer Iteration", false);
  out.set("Outer Iteration StatusTest", false);
  out.set("Inner Iteration", false);
  out.set("Linear Solver Details", false);
  out.set("Parameters", false);
  out.set("Details", false);
  p->sublist("Solver Options").set("Status Test Check Type", "Complete");
  // Convergence itself is efg's test (NewtonConvergence); NOX's list adds the iteration cap and
  // the finite-value check.
  auto& st = p->sublist("Status Tests");
  st.set("Test Type", "Combo");
  st.set("Combo Type", "OR");
  st.set("Number of Tests", 2);
  st.sublist("Test 0").set("Test Type", "MaxIters");
  st.sublist("Test 0").set("Maximum Iterations", 20);
  st.sublist("Test 1").set("Test Type", "FiniteValue");
  if (user.isSublist("Status Tests")) p->remove("Status Tests");  // the user's replace these
  p->setParameters(user);
  return p;
}

Teuchos::RCP<Teuchos::ParameterList> linear_parameters(const LinearSolverPlan& plan) {
  auto p = Teuchos::parameterList("Linear Solver");
  p->set("Linear Solver Type", "Belos");
  auto& belos = p->sublist("Linear Solver Types").sublist("Belos");
  belos.setParameters(plan.krylov);
  belos.sublist("VerboseObject").set("Verbosity Level", "none");
  p->set("Preconditioner Type", "None");  // efg's own, handed over as W_prec
  return p;
}

NewtonSolver::NewtonSolver(NonlinearProblem& problem, const YAML::Node& stage,
                           const std::string& file, const std::string& where)
    : problem_(problem) {
  const auto& model = problem.model();
  const int ranks = problem.owned_dofs()->getComm()->getSize();
  const auto dofs = static_cast<std::int64_t>(problem.owned_dofs()->getGlobalNumElements());
  // Shells' dofs are not displacements: no rigid-body modes for multigrid, the direct solver.
  const std::string solver = !problem.displacement_dofs() ? "direct"
                             : stage["solver"]            ? stage["solver"].as<std::string>()
                                                          : "auto";
  plan_ = plan_linear_solver(
      solver, stage["direct_limit"] ? stage["direct_limit"].as<std::int64_t>() : 0,
      from_stage(stage, "linear_solver", file, where),
      from_stage(stage, "preconditioner", file, where), dofs, model.mesh.dimension, ranks,
      model.scene.largest_poissons_ratio(), problem.auxiliary_misfit(),
      problem.auxiliary_impossible(), problem.bulk_split_misfit().empty());
  {
    // A stalled multigrid need not end a stage the automatic choice could also have factored
    // (sheared supports, SCNI's soft modes: docs/implicit.md, "When a solve fails"), up to the
    // raised limit of nearly incompressible models (300,000 dofs in 2D, 120,000 in 3D: about
    // 7-8 GB of factors, measured growth).
    const std::int64_t factorable = default_direct_limit(model.mesh.dimension, true);
    direct_fallback_ = plan_.automatic &&
                       plan_.preconditioner != LinearSolverPlan::Preconditioner::direct &&
                       dofs <= factorable;
  }
  if (stage["residual_tolerance"]) tolerance_ = stage["residual_tolerance"].as<double>();
  try {
    nox_params_ = nonlinear_parameters(from_stage(stage, "nonlinear_solver", file, where),
                                       problem.residual_norm_is_a_merit(), plan_.tolerance);
    Stratimikos::DefaultLinearSolverBuilder builder;
    builder.setParameterList(linear_parameters(plan_));
    lows_factory_ = builder.createLinearSolveStrategy("");
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(file + ": " + where +
                     ": the solver parameters were rejected by Trilinos: " + e.what());
  }
  Teuchos::RCP<Tpetra::MultiVector<>> modes, coordinates;
  AuxiliaryMatrix auxiliary;
  if (plan_.preconditioner == LinearSolverPlan::Preconditioner::auxiliary)
    auxiliary = [&problem](const Tpetra::CrsMatrix<>& K) { return problem.auxiliary_matrix(K); };
  BulkSplit bulk;
  if (plan_.preconditioner == LinearSolverPlan::Preconditioner::bulk_split) {
    bulk = problem.bulk_split();
    bulk.tolerance = plan_.saddle_tolerance;
  }
  if (plan_.preconditioner == LinearSolverPlan::Preconditioner::multigrid ||
      plan_.preconditioner == LinearSolverPlan::Preconditioner::auxiliary ||
      plan_.preconditioner == LinearSolverPlan::Preconditioner::bulk_split) {
    modes = rigid_body_modes(model.maps, model.mesh);
    coordinates = particle_coordinates(model.maps, model.mesh);
  }
  preconditioner_ =
      make_matrix_preconditioner(plan_, problem.owned_dofs(), modes, coordinates, auxiliary, bulk);
  Vector zero(problem.owned_dofs());
  model_ = Teuchos::rcp(new SolidModelEvaluator(problem_, zero));
  model_->set_W_factory(lows_factory_);
  model_->set_preconditioner(preconditioner_);
  jacobian_ = model_->create_W_op();
  preconditioner_op_ = model_->create_W_prec();
  Log::info("  linear solver: " + plan_.describe() + " (" + plan_.reason + ")");
}

double NewtonSolver::preconditioner_seconds() const {
  return preconditioner_.is_null() ? 0.0 : preconditioner_->setup_seconds();
}

NewtonResult NewtonSolver::solve_predicted(Vector& d, const Vector& increment, double ratio) {
  if (!(ratio > 0)) return solve(d);
  Vector start_residual(d.getMap());
  problem_.residual(d, start_residual);
  const double scale = start_residual.norm2();
  const double energy = std::abs(ratio * increment.dot(start_residual));
  d.update(ratio, increment, 1.0);
  return solve(d, scale, energy);
}

NewtonResult NewtonSolver::solve(Vector& d, double step_scale, double step_energy) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: Newton iterations"));
  NewtonResult result;
  model_->set_initial_guess(d);
  model_->clear_failure();
  NOX::Thyra::Vector x0(model_->getNominalValues().get_x()->clone_v());
  const Teuchos::RCP<const Thyra::ModelEvaluator<double>> model = model_;
  const Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>> no_factory;
  auto group = Teuchos::rcp(
      new NOX::Thyra::Group(x0, model, jacobian_, lows_factory_, preconditioner_op_, no_factory));
  auto params = Teuchos::rcp(new Teuchos::ParameterList(*nox_params_));
  params->sublist("Solver Options")
      .set<Teuchos::RCP<NOX::Observer>>("Observer", Teuchos::rcp(new ResidualLog(result.record)));
  NOX::Utils utils(params->sublist("Printing"));
  auto tests = Teuchos::rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
  auto ratio = [this](const NOX::Abstract::Vector& dd, const NOX::Abstract::Vector& r) {
    return model_->linear_residual_ratio(
        dynamic_cast<const NOX::Thyra::Vector&>(dd).getThyraVector(),
        dynamic_cast<const NOX::Thyra::Vector&>(r).getThyraVector());
  };
  tests->addStatusTest(Teuchos::rcp(new NewtonConvergence(
      problem_, tolerance_, energy_tolerance_, ratio, result.record, step_scale, step_energy)));
  tests->addStatusTest(NOX::StatusTest::buildStatusTests(params->sublist("Status Tests"), utils));
  auto solver = NOX::Solver::buildSolver(group, tests, params);
  group->computeF();
  NOX::StatusTest::StatusType status = NOX::StatusTest::Failed;
  try {
    status = solver->solve();
  } catch (const NumericalError& e) {  // a singular factorization, a failed multigrid setup
    // The stage goes on collectively (a cutback, the last state written): only once every rank
    // knows (a factorization fails on all); a failure of this rank alone ends the run here.
    meet_with_current_failure();
    result.failure = e.what();
    result.linear_failure = true;
  } catch (const std::exception& e) {
    meet_with_current_failure();
    result.failure = std::string("linear or nonlinear solver failed: ") + e.what();
  }
  // A failed evaluation at a line-search trial point (an inverted point, say) is no failure of
  // the step when NOX still converges: the trial point was rejected.
  result.converged = status == NOX::StatusTest::Converged;
  result.iterations = solver->getNumIterations();
  result.residual_history = result.record.residuals;
  for (int its : result.record.linear_iterations) result.linear_iterations += its;
  result.linear_failure = result.linear_failure || result.record.linear_failure;
  if (result.record.linear_failure) {
    result.failure = result.record.reason + "; " + linear_failure_advice(plan_);
  } else if (!result.converged && !model_->failure().empty()) {
    result.failure = model_->failure();
  }
  if (result.converged) Log::info("    converged: " + result.record.reason);
  using Extract = Thyra::TpetraOperatorVectorExtraction<double, Map::local_ordinal_type,
                                                        GlobalOrdinal, Map::node_type>;
  const auto& x = dynamic_cast<const NOX::Thyra::Vector&>(solver->getSolutionGroup().getX());
  Tpetra::deep_copy(d, *Extract::getConstTpetraVector(x.getThyraRCPVector()));
  return result;
}

int NewtonSolver::solve_tangent(const Vector& d, const Vector& b, Vector& x) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: tangent solves"));
  using Extract = Thyra::TpetraOperatorVectorExtraction<double, Map::local_ordinal_type,
                                                        GlobalOrdinal, Map::node_type>;
  const auto K = Teuchos::rcp_dynamic_cast<FEMatrix>(Extract::getTpetraOperator(jacobian_), true);
  problem_.jacobian(d, *K);
  if (!preconditioner_.is_null()) preconditioner_->compute(K);
  auto lows = lows_factory_->createOp();
  Thyra::initializePreconditionedOp<double>(*lows_factory_, jacobian_, preconditioner_op_,
                                            lows.ptr());
  const auto space = jacobian_->range();
  Vector rhs(b, Teuchos::Copy);
  const auto b_thyra = Thyra::createVector(Teuchos::rcpFromRef(rhs), space);
  x.putScalar(0.0);
  const auto x_thyra = Thyra::createVector(Teuchos::rcpFromRef(x), space);
  const auto status = Thyra::solve<double>(*lows, Thyra::NOTRANS, *b_thyra, x_thyra.ptr());
  if (status.solveStatus != Thyra::SOLVE_STATUS_CONVERGED) return -1;
  const auto& extra = status.extraParameters;
  return extra.is_null() || !extra->isParameter("Belos/Iteration Count")
             ? 1
             : extra->get<int>("Belos/Iteration Count");
}

}  // namespace efg
