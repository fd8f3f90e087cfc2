#include "run/Simulation.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <memory>
#include <optional>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "drivers/ExplicitDriver.hpp"
#include "drivers/ImplicitDriver.hpp"
#include "io/ResultsOutput.hpp"
#include "parallel/Collective.hpp"
#include "run/InitialConditions.hpp"
#include "run/OutputFields.hpp"
#include "run/RunHistory.hpp"
#include "run/RunReport.hpp"
#include "verification/ErrorNorms.hpp"

namespace efg {
namespace {
/// Strain magnitude |sym grad u| beyond which a small-strain part is warned about.
constexpr double kSmallStrainLimit = 0.2;
}  // namespace

RunOutcome run_stages(const CommPtr& comm, const Model& model, const std::string& path,
                      double setup_seconds) {
  const auto started = std::chrono::steady_clock::now();
  const auto columns = output_columns(model.scene.output.fields, model.mesh.dimension);
  // A scene builds only what it needs: the stiffness graph and solvers only for implicit stages.
  std::shared_ptr<ModelOperators> ops;
  std::unique_ptr<StaticProblem> problem;
  run_collectively(comm, [&] {
    ops = std::make_shared<ModelOperators>(model);
    for (const auto& s : model.scene.stages)
      if (s.driver == "implicit" && !problem) problem = std::make_unique<StaticProblem>(ops);
  });
  RunHistory history(model);
  ResultsOutput output(comm, path, model.mesh, model.maps.owned_nodes,
                       OutputLayout{columns, {}, history.names()},
                       model.scene.title.empty() ? model.scene.name : model.scene.title);
  std::unique_ptr<std::ofstream> csv;
  std::string csv_final;
  if (!model.scene.output.history.empty() && comm->getRank() == 0) {
    const auto csv_path =
        (std::filesystem::path(path).parent_path() / model.scene.output.history).string();
    csv_final = csv_path;
    csv = std::make_unique<std::ofstream>(csv_path + ".part");  // renamed when the run succeeds
    *csv << history.csv_header() << "\n";
  }
  RunState state(model.maps.owned_dofs);
  apply_initial_conditions(model, state);
  Vector d_overlap(model.maps.overlap_dofs), v_overlap(model.maps.overlap_dofs),
      a_overlap(model.maps.overlap_dofs);
  int records = 0;
  std::vector<double> last_globals;

  // Small-strain parts: particles passing through each other stop the run before the record is
  // written; strains beyond what the formulation represents are announced once.
  bool strain_warned = false;
  auto check_kinematics = [&](double time) {
    double mine = 0, largest = 0;
    run_collectively(comm, [&] { mine = ops->solid().check_small_strain(d_overlap, time); });
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, mine, Teuchos::outArg(largest));
    if (largest > kSmallStrainLimit && !strain_warned) {
      strain_warned = true;
      Log::warning("strains of " + std::to_string(100 * largest) + " % at t = " +
                   std::to_string(time) + " in a small-strain (linear_elastic) part: beyond " +
                   std::to_string(static_cast<int>(100 * kSmallStrainLimit)) +
                   " % its results are no longer a good approximation; use model neo_hookean "
                   "with formulation total_lagrangian");
    }
  };
  auto write = [&](const RunState& s) {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: output"));
    ops->to_overlap(s.d, d_overlap);
    check_kinematics(s.time);
    ops->to_overlap(s.v, v_overlap);
    ops->to_overlap(s.a, a_overlap);
    const auto reactions = s.reactions_from_driver ? s.reactions
                           : problem               ? problem->reactions(s.d)
                                                   : std::vector<std::array<double, 3>>();
    const auto globals = history.values(*ops, s, d_overlap, v_overlap, reactions);
    const auto values = state_columns(model, ops->solid(), d_overlap, &v_overlap, &a_overlap);
    ResultsOutput::MultiVector nodal(model.maps.owned_nodes, columns.size());
    {
      auto view = nodal.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (std::size_t c = 0; c < values.size(); ++c)
        for (std::size_t i = 0; i < values[c].size(); ++i) view(i, c) = values[c][i];
    }
    output.write(s.time, nodal, globals);
    last_globals = globals;
    if (csv) {
      *csv << std::setprecision(12) << s.time;
      for (double g : globals) *csv << "," << g;
      *csv << "\n" << std::flush;
    }
    ++records;
  };

  const double first_end = model.scene.stages.empty() ? 1.0 : model.scene.stages.front().end_time;
  std::vector<ImplicitStageReport> implicit_reports;
  auto keep_partial = [&] {
    // The records up to the failure, the last good state included, stay in the .part files:
    // a failed run never replaces an earlier result or history of the same name.
    output.close_partial();
    if (csv) csv->close();
    Log::info("results up to the failure: " + path + ".part" +
              (csv_final.empty() ? std::string() : " and " + csv_final + ".part"));
  };
  auto guarded = [&](const std::function<void()>& work) {
    try {
      work();
    } catch (const NumericalError&) {
      keep_partial();
      throw;
    } catch (const PeerFailure&) {  // the failing rank holds the message; all keep the .part
      keep_partial();
      throw;
    }
  };
  // The first record: an explicit first stage writes it itself, once the start energies are
  // known (written here it would show a kinetic energy of 0 with a nonzero initial velocity).
  const bool explicit_first =
      !model.scene.stages.empty() && model.scene.stages.front().driver == "explicit";
  if (!explicit_first) guarded([&] { write(state); });
  for (const auto& stage : model.scene.stages) {
    Log::info("stage '" + stage.name + "' (" + stage.driver +
              "), t = " + std::to_string(state.time) + " to " + std::to_string(stage.end_time));
    guarded([&] {
      if (stage.driver == "implicit") {
        state.v.putScalar(0.0);
        state.a.putScalar(0.0);
        state.reactions_from_driver = false;
        ImplicitDriver driver(*problem, stage, state.time, first_end);
        const auto s = driver.run(state.d, [&](double t, const Vector&) {
          state.time = t;
          write(state);
        });
        implicit_reports.push_back({stage.name, s});
        Log::info("stage '" + stage.name + "' done: " + std::to_string(s.steps) + " steps, " +
                  std::to_string(s.cutbacks) + " cutbacks, " + std::to_string(s.newton_iterations) +
                  " Newton iterations, " + std::to_string(s.linear_iterations) +
                  " linear iterations");
      } else {
        std::unique_ptr<ExplicitDriver> driver;
        run_collectively(comm, [&] { driver = std::make_unique<ExplicitDriver>(*ops, stage); });
        const auto s = driver->run(state, write, &stage == &model.scene.stages.front());
        std::ostringstream o;
        o << "stage '" << stage.name << "' done: " << s.steps << " steps, dt " << s.smallest_dt
          << " to " << s.largest_dt << ", worst energy balance error "
          << 100 * s.worst_balance_error << " %";
        Log::info(o.str());
      }
    });
    state.time = stage.end_time;
  }
  std::optional<ErrorNorms> errors;
  if (!model.scene.exact_solution.empty() && ops->exact()) {
    ops->to_overlap(state.d, d_overlap);
    errors = error_norms(model, ops->solid(), d_overlap, *ops->exact());
    std::ostringstream o;
    o << "verification against " << model.scene.exact_solution
      << ": relative L2 displacement error " << errors->l2_relative
      << ", relative energy-norm error " << errors->energy_relative
      << ", largest nodal displacement error " << errors->max_nodal;
    Log::info(o.str());
  }
  output.close();
  if (csv) {
    csv->close();
    std::filesystem::rename(csv_final + ".part", csv_final);
  }
  RunOutcome outcome;
  outcome.records = records;
  outcome.errors = errors;
  const auto checks = reference_checks(*ops, state, history.names(), last_globals);
  for (const auto& c : checks) {
    std::ostringstream o;
    o << "reference value '" << c.name << "' (" << c.quantity << "): " << c.value << " vs "
      << c.reference << " within " << 100 * c.tolerance
      << " %: " << (c.passed() ? "passed" : "FAILED");
    Log::info(o.str());
    if (!c.passed()) outcome.failed_checks.push_back(o.str());
  }
  const double seconds =
      setup_seconds +
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  write_run_report(comm, model, path + ".report.json", path, state, errors, checks, seconds,
                   implicit_reports);
  Log::info("run report: " + path + ".report.json");
  return outcome;
}

}  // namespace efg
