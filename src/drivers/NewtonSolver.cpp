#include "drivers/NewtonSolver.hpp"

#include <NOX.H>
#include <NOX_StatusTest_Factory.H>
#include <NOX_Thyra.H>
#include <NOX_Observer.hpp>
#include <NOX_SolverStats.hpp>
#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Stratimikos_MueLuHelpers.hpp>
#include <Teuchos_AbstractFactoryStd.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Thyra_Ifpack2PreconditionerFactory.hpp>

#include <cmath>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "scene/ParameterListFromYaml.hpp"

namespace efg {
namespace {

class ResidualLog : public NOX::Observer {
 public:
  explicit ResidualLog(NewtonResult& result) : result_(result) {}
  void runPreSolve(const NOX::Solver::Generic& solver) override {
    if (!solver.getSolutionGroup().isF()) return;
    result_.residual_history.push_back(solver.getSolutionGroup().getNormF());
    Log::info("    Newton 0: ||r|| = " + format(result_.residual_history.back()));
  }
  void runPostIterate(const NOX::Solver::Generic& solver) override {
    const double r = solver.getSolutionGroup().getNormF();
    const int its = solver.getSolverStatistics()->linearSolve.lastLinearSolve_NumIterations;
    result_.linear_iterations += its;
    std::string rate;
    const auto& h = result_.residual_history;
    if (h.size() >= 2 && h[h.size() - 1] > 0 && h[h.size() - 2] > 0 && r > 0)
      rate =
          ", order " + format(std::log(r / h.back()) / std::log(h[h.size() - 1] / h[h.size() - 2]));
    result_.residual_history.push_back(r);
    Log::info("    Newton " + std::to_string(solver.getNumIterations()) + ": ||r|| = " + format(r) +
              " (" + std::to_string(its) + " linear iterations" + rate + ")");
  }

 private:
  static std::string format(double v) {
    std::ostringstream o;
    o.precision(3);
    o << std::scientific << v;
    return o.str();
  }
  NewtonResult& result_;
};

// Stops a Newton iteration whose residual grew a thousandfold: it will not come back, and every
// further iteration costs a full linear solve. The driver then cuts the load step.
class RelativeDivergence : public NOX::StatusTest::Generic {
 public:
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver,
                                          NOX::StatusTest::CheckType) override {
    const double r = solver.getSolutionGroup().getNormF();
    if (solver.getNumIterations() == 0) initial_ = r;
    status_ = initial_ > 0 && !(r <= 1e3 * initial_) ? NOX::StatusTest::Failed
                                                     : NOX::StatusTest::Unconverged;
    return status_;
  }
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& stream, int indent) const override {
    for (int i = 0; i < indent; ++i) stream << ' ';
    return stream << status_ << " ||r|| below 1e3 x its initial value\n";
  }

 private:
  double initial_ = -1;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

Teuchos::ParameterList from_stage(const YAML::Node& stage, const char* key, const std::string& file,
                                  const std::string& where) {
  return parameter_list_from_yaml(stage[key], key, file, where + "." + key);
}

}  // namespace

Teuchos::RCP<Teuchos::ParameterList> nonlinear_parameters(const Teuchos::ParameterList& user) {
  auto p = Teuchos::parameterList("Nonlinear Solver");
  p->set("Nonlinear Solver", "Line Search Based");
  auto& newton = p->sublist("Direction");
  newton.set("Method", "Newton");
  newton.sublist("Newton").set("Forcing Term Method", "Constant");
  newton.sublist("Newton").sublist("Linear Solver").set("Tolerance", 1e-10);
  auto& ls = p->sublist("Line Search");
  ls.set("Method", "Backtrack");
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
  // Converged when ||r|| drops 1e-9 below its value at the start of the step (or below an
  // absolute floor), within 25 iterations; NaN or Inf stops the step.
  auto& st = p->sublist("Status Tests");
  st.set("Test Type", "Combo");
  st.set("Combo Type", "OR");
  st.set("Number of Tests", 4);
  auto& relative = st.sublist("Test 0");
  relative.set("Test Type", "RelativeNormF");
  relative.set("Tolerance", 1e-9);
  auto& absolute = st.sublist("Test 1");
  absolute.set("Test Type", "NormF");
  absolute.set("Tolerance", 1e-300);
  absolute.set("Norm Type", "Two Norm");
  absolute.set("Scale Type", "Unscaled");
  st.sublist("Test 2").set("Test Type", "MaxIters");
  st.sublist("Test 2").set("Maximum Iterations", 20);
  st.sublist("Test 3").set("Test Type", "FiniteValue");
  p->setParameters(user);
  return p;
}

Teuchos::RCP<Teuchos::ParameterList> linear_parameters(
    const Teuchos::ParameterList& solver, const Teuchos::ParameterList& preconditioner) {
  auto p = Teuchos::parameterList("Linear Solver");
  p->set("Linear Solver Type", "Belos");
  auto& belos = p->sublist("Linear Solver Types").sublist("Belos");
  const std::string type =
      solver.isParameter("Solver Type") ? solver.get<std::string>("Solver Type") : "Block GMRES";
  belos.set("Solver Type", type);
  auto& chosen = belos.sublist("Solver Types").sublist(type);
  chosen.set("Convergence Tolerance", 1e-10);  // NOX passes its own forcing term per solve
  chosen.set("Maximum Iterations", 2000);
  if (type == "Block GMRES" || type == "Pseudo Block GMRES") chosen.set("Num Blocks", 300);
  chosen.set("Verbosity", 1);  // errors only
  for (auto it = solver.begin(); it != solver.end(); ++it)
    if (solver.name(it) != "Solver Type") chosen.setEntry(solver.name(it), solver.entry(it));
  belos.sublist("VerboseObject").set("Verbosity Level", "none");

  const std::string prec =
      preconditioner.isParameter("Type") ? preconditioner.get<std::string>("Type") : "Ifpack2";
  p->set("Preconditioner Type", prec);
  if (prec == "Ifpack2") {
    auto& ifpack = p->sublist("Preconditioner Types").sublist("Ifpack2");
    const std::string kind = preconditioner.isParameter("Prec Type")
                                 ? preconditioner.get<std::string>("Prec Type")
                                 : "RILUK";
    ifpack.set("Prec Type", kind);
    // ILU(2): ILU(1) stalls on the constraint rows of the transformation method at dilation 2.
    if (kind == "RILUK") ifpack.sublist("Ifpack2 Settings").set("fact: iluk level-of-fill", 2);
    for (auto it = preconditioner.begin(); it != preconditioner.end(); ++it)
      if (preconditioner.name(it) != "Type" && preconditioner.name(it) != "Prec Type")
        ifpack.sublist("Ifpack2 Settings")
            .setEntry(preconditioner.name(it), preconditioner.entry(it));
  } else if (prec == "MueLu") {
    auto& muelu = p->sublist("Preconditioner Types").sublist("MueLu");
    muelu.set("verbosity", "none");
    muelu.set("coarse: type", "RELAXATION");  // not KLU2: wrong answers on more than one rank
    for (auto it = preconditioner.begin(); it != preconditioner.end(); ++it)
      if (preconditioner.name(it) != "Type")
        muelu.setEntry(preconditioner.name(it), preconditioner.entry(it));
  }
  return p;
}

NewtonSolver::NewtonSolver(StaticProblem& problem, const YAML::Node& stage, const std::string& file,
                           const std::string& where)
    : problem_(problem) {
  try {
    nox_params_ = nonlinear_parameters(from_stage(stage, "nonlinear_solver", file, where));
    auto linear = linear_parameters(from_stage(stage, "linear_solver", file, where),
                                    from_stage(stage, "preconditioner", file, where));
    Stratimikos::DefaultLinearSolverBuilder builder;
    using Factory = Thyra::PreconditionerFactoryBase<double>;
    builder.setPreconditioningStrategyFactory(
        Teuchos::abstractFactoryStd<Factory,
                                    Thyra::Ifpack2PreconditionerFactory<Tpetra::CrsMatrix<>>>(),
        "Ifpack2");
    Stratimikos::enableMueLu<Map::local_ordinal_type, GlobalOrdinal, Map::node_type>(builder);
    builder.setParameterList(linear);
    lows_factory_ = builder.createLinearSolveStrategy("");
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(file + ": " + where +
                     ": the solver parameters were rejected by Trilinos: " + e.what());
  }
}

NewtonResult NewtonSolver::solve(Vector& d) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: Newton iterations"));
  NewtonResult result;
  auto model = Teuchos::rcp(new SolidModelEvaluator(problem_, d));
  model->set_W_factory(lows_factory_);
  NOX::Thyra::Vector x0(model->getNominalValues().get_x()->clone_v());
  auto group = Teuchos::rcp(new NOX::Thyra::Group(x0, model));
  auto params = Teuchos::rcp(new Teuchos::ParameterList(*nox_params_));
  params->sublist("Solver Options")
      .set<Teuchos::RCP<NOX::Observer>>("Observer", Teuchos::rcp(new ResidualLog(result)));
  NOX::Utils utils(params->sublist("Printing"));
  auto tests = Teuchos::rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
  tests->addStatusTest(NOX::StatusTest::buildStatusTests(params->sublist("Status Tests"), utils));
  tests->addStatusTest(Teuchos::rcp(new RelativeDivergence));
  auto solver = NOX::Solver::buildSolver(group, tests, params);
  group->computeF();
  NOX::StatusTest::StatusType status = NOX::StatusTest::Failed;
  try {
    status = solver->solve();
  } catch (const std::exception& e) {
    result.failure = std::string("linear or nonlinear solver failed: ") + e.what();
  }
  // A failed evaluation at a line-search trial point (an inverted point, say) is no failure of
  // the step when NOX still converges: the trial point was rejected.
  result.converged = status == NOX::StatusTest::Converged;
  result.iterations = solver->getNumIterations();
  if (!result.converged && !model->failure().empty()) result.failure = model->failure();
  using Extract = Thyra::TpetraOperatorVectorExtraction<double, Map::local_ordinal_type,
                                                        GlobalOrdinal, Map::node_type>;
  const auto& x = dynamic_cast<const NOX::Thyra::Vector&>(solver->getSolutionGroup().getX());
  Tpetra::deep_copy(d, *Extract::getConstTpetraVector(x.getThyraRCPVector()));
  return result;
}

}  // namespace efg
