#include "run/Simulation.hpp"

#include <Teuchos_TimeMonitor.hpp>

#include <memory>

#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "drivers/ImplicitDriver.hpp"
#include "io/ResultsOutput.hpp"
#include "parallel/Collective.hpp"
#include "run/OutputFields.hpp"
#include "verification/ErrorNorms.hpp"

#include <sstream>

namespace efg {
namespace {

std::vector<std::string> global_names(const Model& model) {
  std::vector<std::string> names = {"strain_energy"};
  const auto axes = std::string("xyz");
  for (const auto& bc : model.scene.boundary_conditions)
    for (int d = 0; d < model.mesh.dimension; ++d) names.push_back(("R_" + bc.name).substr(0, 30) + "_" + axes[static_cast<std::size_t>(d)]);
  return names;
}

}  // namespace

void require_available_drivers(const Scene& scene) {
  for (const auto& stage : scene.stages)
    if (stage.driver != "implicit")
      throw std::runtime_error("stage '" + stage.name + "': the " + stage.driver +
                               " driver is not available in this version of efg (only implicit stages run)");
}

int run_stages(const CommPtr& comm, const Model& model, const std::string& path) {
  const auto columns = output_columns(model.scene.output.fields, model.mesh.dimension);
  std::unique_ptr<StaticProblem> problem;
  run_collectively(comm, [&] { problem = std::make_unique<StaticProblem>(model); });
  ResultsOutput output(comm, path, model.mesh, model.maps.owned_nodes, OutputLayout{columns, {}, global_names(model)},
                       model.scene.title.empty() ? model.scene.name : model.scene.title);
  Vector d(model.maps.owned_dofs), d_overlap(model.maps.overlap_dofs);
  int output_records = 0;

  auto write = [&](double time, const Vector& state) {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: output"));
    problem->to_overlap(state, d_overlap);
    const auto reactions = problem->reactions(state);
    std::vector<double> globals = {0.0};
    const double mine = problem->solid().strain_energy(d_overlap);
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, mine, Teuchos::outArg(globals[0]));
    for (const auto& r : reactions)
      for (int k = 0; k < model.mesh.dimension; ++k) globals.push_back(r[static_cast<std::size_t>(k)]);
    const auto values = state_columns(model, problem->solid(), d_overlap, nullptr);
    ResultsOutput::MultiVector nodal(model.maps.owned_nodes, columns.size());
    {
      auto view = nodal.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (std::size_t c = 0; c < values.size(); ++c)
        for (std::size_t i = 0; i < values[c].size(); ++i) view(i, c) = values[c][i];
    }
    output.write(time, nodal, globals);
    ++output_records;
  };

  write(0.0, d);
  double start = 0.0;
  const double first_end = model.scene.stages.empty() ? 1.0 : model.scene.stages.front().end_time;
  for (const auto& stage : model.scene.stages) {
    Log::info("stage '" + stage.name + "' (" + stage.driver + "), t = " + std::to_string(start) + " to " + std::to_string(stage.end_time));
    ImplicitDriver driver(*problem, stage, start, first_end);
    StageSummary s;
    try {
      s = driver.run(d, write);
    } catch (const NumericalError&) {
      output.close();  // the records up to the failure, the last converged state included
      Log::info("results up to the failure: " + path);
      throw;
    }
    Log::info("stage '" + stage.name + "' done: " + std::to_string(s.steps) + " steps, " + std::to_string(s.cutbacks) +
              " cutbacks, " + std::to_string(s.newton_iterations) + " Newton iterations, " + std::to_string(s.linear_iterations) +
              " linear iterations");
    start = stage.end_time;
  }
  if (!model.scene.exact_solution.empty()) {
    problem->to_overlap(d, d_overlap);
    const auto exact = make_exact_solution(model.scene, model.mesh.dimension);
    const auto e = error_norms(model, problem->solid(), d_overlap, exact);
    std::ostringstream o;
    o << "verification against " << model.scene.exact_solution << ": relative L2 displacement error " << e.l2_relative
      << ", relative energy-norm error " << e.energy_relative << ", largest nodal displacement error " << e.max_nodal;
    Log::info(o.str());
  }
  output.close();
  return output_records;
}

}  // namespace efg
