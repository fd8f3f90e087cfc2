#include <yaml-cpp/yaml.h>

#include <iostream>
#include <sstream>

#include "app/Commands.hpp"
#include "core/Log.hpp"
#include "io/ExodusWriter.hpp"
#include "mesh/NodalVolume.hpp"
#include "mesh/SurfaceChart.hpp"
#include "model/Model.hpp"
#include "run/RunChecks.hpp"
#include "scene/SceneEcho.hpp"
#include "scene/SceneSchema.hpp"
#include "scene/SchemaMarkdown.hpp"

namespace efg {
namespace {
std::string mesh_summary(const BackgroundMesh& mesh, bool given_chart) {
  std::ostringstream o;
  o << "# mesh: " << mesh.source << "\n#   " << mesh.dimension << "D, " << mesh.node_count()
    << " nodes, " << mesh.cell_count() << " cells\n";
  if (!mesh.surface.empty()) o << "#   " << surface_chart_summary(mesh, given_chart) << "\n";
  for (const auto& b : mesh.blocks)
    o << "#   block '" << b.name << "' (id " << b.id << "): " << b.cell_count() << " "
      << cell_scene_name(b.type) << "\n";
  for (const auto& s : mesh.node_sets)
    o << "#   node set '" << s.name << "': " << s.nodes.size() << " nodes\n";
  for (const auto& s : mesh.side_sets)
    o << "#   side set '" << s.name << "': " << s.cells.size() << " sides\n";
  return o.str();
}
}  // namespace

void check_command(const CommPtr& comm, const CommandLine& cl) {
  auto scene = load_scene(comm, cl.scene);
  const auto mesh = load_mesh(comm, scene);
  check_run_inputs(comm, scene, mesh, cl.output_dir);
  if (!scene.stages.empty()) check_model_setup(comm, build_model(comm, scene));
  YAML::Emitter out;
  out << compact_for_echo(scene.resolved);
  Log::info("# " + cl.scene + ": valid. Resolved scene (defaults filled in):");
  Log::info(out.c_str());
  Log::info(mesh_summary(mesh, static_cast<bool>(scene.surface_chart)));
}

void mesh_command(const CommPtr& comm, const CommandLine& cl) {
  auto scene = load_scene(comm, cl.scene);
  const auto mesh = load_mesh(comm, scene);
  if (comm->getRank() == 0) {
    ExodusWriter writer(cl.mesh_output, mesh, OutputLayout{}, "efg mesh of " + cl.scene);
    writer.close();
  }
  Log::info(mesh_summary(mesh, static_cast<bool>(scene.surface_chart)));
  Log::info("mesh written to " + cl.mesh_output);
}

void schema_command() {
  std::cout << schema::markdown(scene_schema(), "efg scene files");
}

}  // namespace efg
