#include <yaml-cpp/yaml.h>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <chrono>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "app/Commands.hpp"
#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "core/Threads.hpp"
#include "core/Version.hpp"
#include "discretization/ParticleCloud.hpp"
#include "io/ResultsOutput.hpp"
#include "model/Model.hpp"
#include "run/OutputPaths.hpp"
#include "run/RunChecks.hpp"
#include "run/RunSummary.hpp"
#include "run/Simulation.hpp"
#include "scene/SceneEcho.hpp"

namespace efg {
namespace {

void log_model(const Model& model, const CommPtr& comm) {
  YAML::Emitter echo;
  echo << compact_for_echo(model.scene.resolved);
  Log::info("efg " + std::string(version_string) + " (" + git_describe + "), " +
            std::to_string(comm->getSize()) + " MPI rank(s) x " + execution_summary());
  Log::info("scene " + model.scene.file + " (resolved):\n" + echo.c_str());
  const auto owned = static_cast<long long>(model.partition.owned.size());
  long long min = 0, max = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, owned, Teuchos::outArg(min));
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, owned, Teuchos::outArg(max));
  Log::info("mesh: " + model.mesh.source + ": " + std::to_string(model.mesh.whole_node_count()) +
            " particles, " + std::to_string(model.mesh.whole_cell_count()) +
            " background cells; particles per rank " + std::to_string(min) + " to " +
            std::to_string(max));
  if (!model.mesh.is_part()) return;
  // mesh.read: distributed: how much of the mesh each rank holds (owned, ghosts, halo cells)
  const auto held = static_cast<long long>(model.mesh.node_count());
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, held, Teuchos::outArg(min));
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, held, Teuchos::outArg(max));
  std::ostringstream o;
  o << std::fixed << std::setprecision(1) << "mesh read in slices: each rank holds " << min
    << " to " << max << " of its nodes (at most "
    << 100.0 * static_cast<double>(max) / static_cast<double>(model.mesh.whole_node_count())
    << " % of the mesh)";
  Log::info(o.str());
}

// Above this the note on the supports' width is logged. Measured: Cook's panel 3.4 (16 x 16
// cells) to 3.7 (128 x 128), the Lame cylinder's perturbed polar grid 2.0 (8 x 16) to 2.4
// (32 x 64), where multigrid stalled; rectangles with 20 % perturbed nodes 1.17-1.27.
constexpr double kWideSupportWarning = 1.8;

void log_discretization(const Model& model, const CommPtr& comm) {
  for (const auto& d : model.parts) {
    long long local[4] = {static_cast<long long>(d.cloud.owned_count),
                          static_cast<long long>(d.points.size()),
                          static_cast<long long>(d.points.gradients.particles.size()),
                          static_cast<long long>(d.cloud.size() - d.cloud.owned_count)};
    long long global[4] = {0, 0, 0, 0};
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 4, local, global);
    const char* scheme = d.points.scheme == Integration::scni            ? "SCNI"
                         : d.points.scheme == Integration::scni_subcells ? "SCNI subcell"
                         : d.points.scheme == Integration::nodal         ? "direct nodal"
                                                                         : "Gauss";
    std::ostringstream o;
    o << "part '" << d.part->name << "': " << global[0] << " particles, " << global[1] << " "
      << scheme << " integration points, "
      << (global[1] > 0 ? static_cast<double>(global[2]) / static_cast<double>(global[1]) : 0.0)
      << " particles per point on average, " << global[3] << " ghost particles over all ranks";
    Log::info(o.str());
    if (d.part->section.spacing != SpacingMeasure::cells) continue;
    // Supports several rows wide across sheared or curved cells: multigrid stalled there.
    double ratio = extent_over_rows(model.mesh, d.part->blocks), largest = ratio;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, ratio, Teuchos::outArg(largest));
    if (largest > kWideSupportWarning) {
      std::ostringstream w;
      w << std::setprecision(3) << "part '" << d.part->name << "': the cells' extents reach "
        << largest
        << " times the distance between rows of particles (cells sheared or curved against "
           "the axes): the supports are that much wider than the rows and multigrid may stall "
           "on them; section.spacing: edges measures the rows (docs/discretization.md)";
      Log::info(w.str());
    }
  }
}

}  // namespace

void run_command(const CommPtr& comm, const CommandLine& cl) {
  const auto started = std::chrono::steady_clock::now();
  const Model model = build_model(comm, cl.scene);
  check_run_inputs(comm, model.scene, model.mesh, cl.output_dir, &model.partition);
  log_model(model, comm);
  for (const auto& w : thread_warnings(cl.threads)) Log::warning(w);
  log_discretization(model, comm);
  const std::filesystem::path path =
      prepare_output_paths(comm, model.scene, cl.output_dir, /*create=*/true);
  const double setup =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const auto outcome = run_stages(comm, model, path.string(), setup);
  if (model.scene.stages.empty())
    Log::info("model check: initial state written (no stages in the scene)");
  const auto results = std::filesystem::absolute(path).lexically_normal().string();
  if (writes_pieces(model.scene.output.per_rank_files, comm->getSize()))
    Log::info("results: one file per rank, " + piece_path(results, comm->getSize(), 0) +
              " ...; join them with SEACAS epu: epu -auto " +
              piece_path(results, comm->getSize(), 0));
  else
    Log::info("results: " + results);
  print_run_summary(comm);
  if (!outcome.failed_checks.empty())
    throw VerificationError(std::to_string(outcome.failed_checks.size()) +
                            " reference value(s) missed; first: " + outcome.failed_checks.front());
}

}  // namespace efg
