#include "drivers/SolverSettingsCheck.hpp"

#include <NOX.H>
#include <NOX_LAPACK_Group.H>
#include <NOX_LAPACK_Interface.H>
#include <NOX_StatusTest_Factory.H>
#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>

#include <iostream>
#include <sstream>
#include <string>
#include <typeinfo>
#include <vector>

#include "core/Errors.hpp"
#include "drivers/NewtonSolver.hpp"
#include "scene/ParameterListFromYaml.hpp"
#include "scene/SchemaValidator.hpp"
#include "scene/Suggest.hpp"
#include "solvers/MatrixPreconditioner.hpp"

namespace efg {
namespace {

using List = Teuchos::ParameterList;

// The located message of a key path below a stage map ("Line Search", "Method").
class Locator {
 public:
  Locator(const YAML::Node& written, std::string file, std::string path)
      : written_(written), file_(std::move(file)), path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& map, const std::vector<std::string>& keys,
                         const std::string& message) const {
    YAML::Node at = written_[map];
    std::string path = path_ + "." + map;
    for (const auto& k : keys) {
      if (at && at.IsMap() && at[k]) at = at[k];
      path += "." + k;
    }
    throw InputError(schema::located_message(file_, at ? at : written_, path, message));
  }

 private:
  YAML::Node written_;
  std::string file_, path_;
};

// The reason in a Trilinos exception text, on one line: without the file:line banner, the
// "Throw number" and "Throw test" lines and the braces of value lists.
std::string trilinos_reason(const std::string& text) {
  std::istringstream in(text);
  std::string line, reason, verdict;
  while (std::getline(in, line)) {
    // MueLu ends with its own verdict after a table of every valid name: that line says it all.
    if (line.find("is not valid") != std::string::npos) verdict = line;
    const auto begin = line.find_first_not_of(" \t");
    if (begin == std::string::npos) continue;
    line = line.substr(begin);
    const bool banner = line.back() == ':' && line.find(".hpp:") != std::string::npos;
    if (banner || line.rfind("Throw number", 0) == 0 || line.rfind("Throw test", 0) == 0 ||
        line == "{" || line == "}")
      continue;
    reason += (reason.empty() ? "" : " ") + line;
  }
  if (!verdict.empty()) return verdict.substr(verdict.find_first_not_of(" \t"));
  return reason.size() > 600 ? reason.substr(0, 600) + " ..." : reason;
}

std::vector<std::string> names_of(const List& list) {
  std::vector<std::string> names;
  for (auto it = list.begin(); it != list.end(); ++it) names.push_back(list.name(it));
  return names;
}

std::string unknown_key(const std::string& key, const std::vector<std::string>& known,
                        const std::string& owner) {
  std::string message = "'" + key + "' is not a parameter of " + owner;
  std::vector<std::string> others;
  for (const auto& k : known)
    if (k != key) others.push_back(k);
  if (auto guess = closest_match(key, others)) message += " (did you mean '" + *guess + "'?)";
  return message;
}

// A text value where a number is read (Maximum Iterations: abc): Teuchos' get<int> throws a
// bare type message ('An attempt was made to access parameter "NAME" of type "string" ...')
// naming no scene key. The key is taken from it and reported at its line.
void refuse_text_for_number(const List& user, const std::string& what, const Locator& at) {
  const std::string mark = "parameter \"";
  const auto begin = what.find(mark);
  if (begin == std::string::npos) return;
  const auto end = what.find('"', begin + mark.size());
  const auto key = what.substr(begin + mark.size(), end - begin - mark.size());
  if (user.isParameter(key) && user.getEntry(key).getAny().type() == typeid(std::string))
    at.fail("linear_solver", {key},
            "expected a number, found '" + user.get<std::string>(key) + "'");
}

void check_linear(const List& user, const LinearSolverPlan& plan, const Locator& at) {
  Stratimikos::DefaultLinearSolverBuilder builder;
  try {
    builder.setParameterList(linear_parameters(plan));
    builder.createLinearSolveStrategy("");
  } catch (const std::exception& e) {
    at.fail("linear_solver", {"Solver Type"},
            "Stratimikos rejected it: " + trilinos_reason(e.what()));
  }
  const auto method = plan.krylov.get<std::string>("Solver Type");
  const auto& valid = builder.getValidParameters()
                          ->sublist("Linear Solver Types")
                          .sublist("Belos")
                          .sublist("Solver Types")
                          .sublist(method);
  const auto known = names_of(valid);
  for (auto it = user.begin(); it != user.end(); ++it) {
    const auto& key = user.name(it);
    if (key != "Solver Type" && !valid.isParameter(key))
      at.fail("linear_solver", {key}, unknown_key(key, known, "Belos '" + method + "'"));
    if (key == "Solver Type" || valid.isSublist(key) || user.isSublist(key)) continue;
    // Text where Belos reads a number or a flag: its get<int> would throw a bare Teuchos type
    // message at solve time (Maximum Iterations: abc).
    const auto& expected = valid.getEntry(key).getAny().type();
    const char* kind = expected == typeid(int)      ? "an integer"
                       : expected == typeid(double) ? "a number"
                       : expected == typeid(bool)   ? "true or false"
                                                    : nullptr;
    if (kind && user.getEntry(key).getAny().type() == typeid(std::string))
      at.fail("linear_solver", {key},
              "expected " + std::string(kind) + " for Belos '" + method + "', found '" +
                  user.get<std::string>(key) + "'");
  }
}

// F(x) = x - 1 on one unknown: NOX reads its whole list while it builds and runs on it.
class OneUnknown : public NOX::LAPACK::Interface {
 public:
  OneUnknown() : x0_(1) {}
  const NOX::LAPACK::Vector& getInitialGuess() override { return x0_; }
  bool computeF(NOX::LAPACK::Vector& f, const NOX::LAPACK::Vector& x) override {
    f(0) = x(0) - 1.0;
    return true;
  }
  bool computeJacobian(NOX::LAPACK::Matrix<double>& J, const NOX::LAPACK::Vector&) override {
    J(0, 0) = 1.0;
    return true;
  }

 private:
  NOX::LAPACK::Vector x0_;
};

bool any_used(const List& list) {
  for (auto it = list.begin(); it != list.end(); ++it) {
    const auto& key = list.name(it);
    if (list.isSublist(key) ? any_used(list.sublist(key)) : list.getEntry(key).isUsed())
      return true;
  }
  return false;
}

// Keys of `user` that NOX never read in `used` (same shape); the linear solver's own sublist is
// read by Stratimikos/Belos, not by this dry run, and is left out.
void find_unused(const List& user, const List& used, std::vector<std::string>& keys,
                 std::vector<std::string>& where) {
  for (auto it = user.begin(); it != user.end(); ++it) {
    const auto& key = user.name(it);
    keys.push_back(key);
    if (keys.size() == 3 && keys[0] == "Direction" && keys[2] == "Linear Solver") {
      keys.pop_back();
      continue;
    }
    if (user.isSublist(key) && used.isSublist(key)) {
      if (!any_used(used.sublist(key))) {  // a misspelled sublist name: report the name
        where = keys;
        return;
      }
      find_unused(user.sublist(key), used.sublist(key), keys, where);
      if (!where.empty()) return;
    } else if (!used.getEntryPtr(key) || !used.getEntryPtr(key)->isUsed()) {
      where = keys;
      return;
    }
    keys.pop_back();
  }
}

void check_nonlinear(const List& user, const Locator& at) {
  auto params = nonlinear_parameters(user);
  try {
    OneUnknown problem;
    auto group = Teuchos::rcp(new NOX::LAPACK::Group(problem));
    NOX::Utils utils(params->sublist("Printing"));
    auto tests = NOX::StatusTest::buildStatusTests(params->sublist("Status Tests"), utils);
    auto solver = NOX::Solver::buildSolver(group, tests, params);
    solver->solve();
  } catch (const std::exception& e) {
    at.fail("nonlinear_solver", {}, "NOX rejected it: " + trilinos_reason(e.what()));
  }
  std::vector<std::string> keys, where;
  find_unused(user, *params, keys, where);
  if (where.empty()) return;
  const List* parent = params.get();
  for (std::size_t k = 0; k + 1 < where.size(); ++k) parent = &parent->sublist(where[k]);
  at.fail("nonlinear_solver", where,
          unknown_key(where.back(), names_of(*parent), "NOX (it was never read)"));
}

// Redirects std::cout while alive.
class SilencedOutput {
 public:
  explicit SilencedOutput(std::ostream& to) : saved_(std::cout.rdbuf(to.rdbuf())) {}
  ~SilencedOutput() { std::cout.rdbuf(saved_); }
  SilencedOutput(const SilencedOutput&) = delete;
  SilencedOutput& operator=(const SilencedOutput&) = delete;

 private:
  std::streambuf* saved_;
};

// A 1D Laplacian per displacement component: small, SPD, with `dimension` unknowns per node as
// the real systems have.
Teuchos::RCP<Tpetra::CrsMatrix<>> small_spd_matrix(int dimension) {
  using GO = Tpetra::Map<>::global_ordinal_type;
  const int nodes = 40;
  const GO rows = nodes * dimension;
  // MPI_COMM_SELF, not a Teuchos::SerialComm: MueLu's hierarchy report dereferences the MPI
  // communicator and crashed on a serial one.
  auto comm = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  auto map = Teuchos::rcp(new Tpetra::Map<>(rows, 0, comm));
  auto K = Teuchos::rcp(new Tpetra::CrsMatrix<>(map, 3));
  for (GO r = 0; r < rows; ++r) {
    std::vector<GO> cols = {r};
    std::vector<double> vals = {2.0};
    if (r >= dimension) cols.push_back(r - dimension), vals.push_back(-1.0);
    if (r + dimension < rows) cols.push_back(r + dimension), vals.push_back(-1.0);
    K->insertGlobalValues(r, Teuchos::ArrayView<const GO>(cols),
                          Teuchos::ArrayView<const double>(vals));
  }
  K->fillComplete();
  return K;
}

// Node coordinates of small_spd_matrix (node i at x = i), one column per dimension, as the runs
// hand them to multigrid: options that read them (MueLu's distance-Laplacian dropping) are then
// checked like any other instead of failing for want of coordinates.
Teuchos::RCP<Tpetra::MultiVector<>> small_matrix_coordinates(const Tpetra::CrsMatrix<>& K,
                                                             int dimension) {
  const auto nodes = K.getGlobalNumRows() / static_cast<std::size_t>(dimension);
  auto map = Teuchos::rcp(new Tpetra::Map<>(nodes, 0, K.getRowMap()->getComm()));
  auto x = Teuchos::rcp(new Tpetra::MultiVector<>(map, static_cast<std::size_t>(dimension)));
  auto view = x->getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (std::size_t i = 0; i < view.extent(0); ++i)
    for (std::size_t d = 0; d < view.extent(1); ++d)
      view(i, d) = d == 0 ? static_cast<double>(map->getGlobalElement(static_cast<int>(i))) : 0.0;
  return x;
}

void check_preconditioner(const LinearSolverPlan& plan, int dimension, const Locator& at) {
  if (plan.preconditioner == LinearSolverPlan::Preconditioner::none) return;
  const auto K = small_spd_matrix(dimension);
  // MueLu prints its table of valid names to std::cout before it throws: keep it out of the log.
  std::ostringstream swallowed;
  const SilencedOutput silence(swallowed);
  try {
    auto prec = make_matrix_preconditioner(plan, K->getRowMap(), Teuchos::null,
                                           small_matrix_coordinates(*K, dimension));
    prec->compute(K);
  } catch (const std::exception& e) {
    at.fail("preconditioner", {},
            "the preconditioner (" + plan.describe() +
                ") could not be built with these settings: " + trilinos_reason(e.what()));
  }
}

}  // namespace

void check_solver_settings(const YAML::Node& stage, const YAML::Node& written,
                           const std::string& file, const std::string& path, std::int64_t dofs,
                           int dimension, double poissons_ratio) {
  const Locator at(written, file, path);
  auto list = [&](const char* key) {
    return parameter_list_from_yaml(stage[key], key, file, path + "." + key);
  };
  const auto linear = list("linear_solver"), nonlinear = list("nonlinear_solver");
  LinearSolverPlan plan;
  try {
    plan = plan_linear_solver(stage["solver"] ? stage["solver"].as<std::string>() : "auto",
                              stage["direct_limit"] ? stage["direct_limit"].as<std::int64_t>() : 0,
                              linear, list("preconditioner"), dofs, dimension, 1, poissons_ratio);
  } catch (const Teuchos::Exceptions::InvalidParameterType& e) {
    refuse_text_for_number(linear, e.what(), at);  // the plan reads the Krylov limits as numbers
    throw;
  }
  check_linear(linear, plan, at);
  check_nonlinear(nonlinear, at);
  check_preconditioner(plan, dimension, at);
}

}  // namespace efg
