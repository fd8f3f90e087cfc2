#include "model/Model.hpp"

#include <set>

#include <Teuchos_TimeMonitor.hpp>

#include "core/Errors.hpp"
#include "core/MemoryAccount.hpp"
#include "io/ExodusReader.hpp"
#include "mesh/MeshGenerator.hpp"
#include "mesh/MeshValidation.hpp"
#include "mesh/SurfaceChart.hpp"
#include "model/ContactGhosts.hpp"
#include "model/DistributedMesh.hpp"
#include "model/GradedMaterials.hpp"
#include "model/RigidMeshBlocks.hpp"
#include "model/ScenePoints.hpp"
#include "model/SurfaceSliceChart.hpp"
#include "parallel/Collective.hpp"
#include "parallel/FaultInjection.hpp"
#include "parallel/MeshBroadcast.hpp"
#include "parallel/RootBroadcast.hpp"
#include "scene/SceneMeshChecks.hpp"
#include "scene/SceneNodeSets.hpp"
#include "scene/SceneReader.hpp"
#include "scene/SchemaValidator.hpp"
#include "scene/ShellSurfacePoints.hpp"

namespace efg {

Scene load_scene(const CommPtr& comm, const std::string& scene_file) {
  const auto text = produce_on_root(comm, [&] {
    const auto t = read_scene_text(scene_file);
    return std::vector<char>(t.begin(), t.end());
  });
  return parse_scene(std::string(text.begin(), text.end()), scene_file);
}

BackgroundMesh load_mesh(const CommPtr& comm, Scene& scene) {
  auto mesh = load_on_root_and_broadcast(comm, [&] {
    try {
      fault_point("mesh");
      auto m =
          scene.generator ? generate_mesh(*scene.generator) : read_exodus_mesh(scene.mesh_file);
      for (const auto& block : scene.more_blocks) append_generated(m, block);
      // a shell surface in 3D: the shells work on its chart (mesh/SurfaceChart.hpp)
      if (scene.has_shells() && is_surface_mesh(m)) chart_surface_mesh(m, scene.surface_chart);
      validate_mesh(m, rigid_block_names(scene));
      return m;
    } catch (const InputError& e) {
      // Point at the scene key that named the mesh, then say what is wrong with it.
      const auto key = scene.generator ? "generate" : "file";
      throw InputError(schema::located_message(scene.file, scene.document["mesh"][key],
                                               std::string("mesh.") + key, e.what()));
    }
  });
  if (scene.surface_chart && mesh.surface.empty()) refuse_chart_without_surface(scene);
  extract_rigid_blocks(scene, mesh);  // rigid bodies of mesh blocks: no particles
  chart_shell_points(scene, mesh);
  add_scene_node_sets(scene, mesh);
  check_scene_against_mesh(scene, mesh);
  return mesh;
}

Model build_model(const CommPtr& comm, const std::string& scene_file) {
  Scene scene;
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: scene and mesh"));
    scene = load_scene(comm, scene_file);
  }
  return build_model(comm, std::move(scene));
}

Model build_model(const CommPtr& comm, Scene scene) {
  auto& memory = MemoryAccount::process();
  memory.reset();
  Model model;
  model.scene = std::move(scene);
  SlicedPatches patches;  // a distributed read's pressure patches, chosen over whole parts
  if (model.scene.distributed_read) {
    // Each rank reads its slice and keeps its part: read, partition (RCB of the slices) and mesh
    // checks in one phase.
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: scene and mesh"));
    model.mesh = load_distributed_mesh(comm, model.scene, model.partition, patches);
    memory.mark("scene and mesh");
    memory.mark("partition");
  } else {
    {
      Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: scene and mesh"));
      model.mesh = load_mesh(comm, model.scene);
      set_graded_references(model.scene, model.mesh);
    }
    memory.mark("scene and mesh");
    {
      Teuchos::TimeMonitor timer(
          *Teuchos::TimeMonitor::getNewCounter("efg: partition (Zoltan2 RCB)"));
      model.partition = partition_nodes(comm, model.mesh);
    }
    memory.mark("partition");
  }
  run_collectively(comm, [&] {
    for (std::size_t p = 0; p < model.scene.parts.size(); ++p) {
      const auto* whole =
          p < patches.part.size() && patches.part[p].size() > 0 ? &patches.part[p] : nullptr;
      fault_point("discretization");
      model.parts.push_back(
          discretize_part(model.mesh, model.scene.parts[p], model.partition, whole));
    }
  });
  memory.mark("shape functions and integration points");
  std::set<LocalIndex> ghosts;
  for (const auto& d : model.parts)
    for (std::size_t i = d.cloud.owned_count; i < d.cloud.size(); ++i)
      ghosts.insert(d.cloud.mesh_node[i]);
  auto contact = contact_row_ghosts(comm, model);
  ghosts.insert(contact.held.begin(), contact.held.end());
  model.partition.ghosts.assign(ghosts.begin(), ghosts.end());
  model.partition.remote_ghosts = std::move(contact.remote);
  model.maps = make_dof_maps(comm, model.partition, model.mesh.dimension, model.mesh.global);
  memory.mark("ghosts and maps");
  check_scene_points(comm, model);
  return model;
}

}  // namespace efg
