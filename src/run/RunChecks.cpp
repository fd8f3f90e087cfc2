#include "run/RunChecks.hpp"
#include "run/ShellRun.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <memory>
#include <set>
#include <stdexcept>

#include "core/Errors.hpp"
#include "drivers/ExplicitDriver.hpp"
#include "drivers/SolverSettingsCheck.hpp"
#include "parallel/Collective.hpp"
#include "run/InitialState.hpp"
#include "run/OutputPaths.hpp"
#include "run/RunHistory.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {
namespace {

// A reference quantity is a global variable of the records or <displacement|velocity>_<axis>@<set>
// (run/RunReport.cpp evaluates it at the end of the run).
void check_reference_quantities(const Scene& scene, const BackgroundMesh& mesh) {
  if (!scene.verification || !scene.verification["reference_values"]) return;
  const auto globals = history_names(scene, mesh.dimension);
  const auto& written = scene.document["verification"]["reference_values"];
  for (std::size_t i = 0; i < scene.verification["reference_values"].size(); ++i) {
    const auto quantity = scene.verification["reference_values"][i]["quantity"].as<std::string>();
    const auto at = quantity.find('@');
    bool known = false;
    if (at == std::string::npos) {
      known = std::find(globals.begin(), globals.end(), quantity) != globals.end();
    } else {
      const auto field = quantity.substr(0, at);
      known = (field.rfind("displacement_", 0) == 0 || field.rfind("velocity_", 0) == 0) &&
              field.back() >= 'x' && field.back() - 'x' < mesh.dimension &&
              field.size() == field.find('_') + 2 && mesh.find_node_set(quantity.substr(at + 1));
    }
    if (!known) {
      std::string list;
      for (const auto& g : globals) list += (list.empty() ? "" : ", ") + g;
      throw InputError(schema::located_message(
          scene.file, written[i]["quantity"],
          "verification.reference_values[" + std::to_string(i) + "].quantity",
          "unknown quantity '" + quantity + "'; expected <displacement|velocity>_<x|y" +
              (mesh.dimension == 3 ? "|z" : "") +
              ">@<node set of the mesh> or a global variable of the results: " + list));
    }
  }
}

// (On a rank's part of a mesh read in slices: the part nodes owned here, summed over the ranks.)
std::int64_t part_dofs(const CommPtr& comm, const Scene& scene, const BackgroundMesh& mesh,
                       const NodePartition* partition) {
  std::set<LocalIndex> nodes;
  for (const auto& part : scene.parts)
    for (const auto& block : mesh.blocks)
      if (std::find(part.blocks.begin(), part.blocks.end(), block.name) != part.blocks.end())
        nodes.insert(block.connectivity.begin(), block.connectivity.end());
  if (!mesh.is_part()) return static_cast<std::int64_t>(nodes.size()) * mesh.dimension;
  if (!partition) throw std::logic_error("part_dofs: a rank's part of a mesh needs its owners");
  long long owned = 0, all = 0;
  for (auto n : nodes)
    if (partition->owner[static_cast<std::size_t>(n)] == partition->rank) ++owned;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, owned, Teuchos::outArg(all));
  return static_cast<std::int64_t>(all) * mesh.dimension;
}

}  // namespace

void check_run_inputs(const CommPtr& comm, const Scene& scene, const BackgroundMesh& mesh,
                      const std::string& output_dir, const NodePartition* partition) {
  prepare_output_paths(comm, scene, output_dir, /*create=*/false);
  check_reference_quantities(scene, mesh);
  read_initial_state(comm, scene,
                     mesh);  // the restart record exists and fits (read again by the run)
  const auto dofs = part_dofs(comm, scene, mesh, partition);
  for (std::size_t i = 0; i < scene.stages.size(); ++i)
    if (scene.stages[i].driver == "implicit")
      check_solver_settings(scene.stages[i].settings, scene.document["stages"][i], scene.file,
                            "stages[" + std::to_string(i) + "]", dofs, mesh.dimension,
                            scene.largest_poissons_ratio());
}

void check_model_setup(const CommPtr& comm, const Model& model) {
  if (model.scene.has_shells()) return run_collectively(comm, [&] { check_shell_setup(model); });
  std::shared_ptr<ModelOperators> ops;
  run_collectively(comm, [&] { ops = std::make_shared<ModelOperators>(model); });
  double start = 0;
  for (const auto& stage : model.scene.stages) {
    if (stage.driver == "explicit") {
      std::unique_ptr<ExplicitDriver> driver;
      run_collectively(comm, [&] { driver = std::make_unique<ExplicitDriver>(*ops, stage); });
      const Vector d(model.maps.owned_dofs);  // the start state of a first stage
      driver->plan_steps(d, start);
    }
    start = stage.end_time;
  }
}

}  // namespace efg
