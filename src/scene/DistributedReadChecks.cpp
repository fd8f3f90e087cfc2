#include "scene/DistributedReadChecks.hpp"

#include "core/Errors.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {
namespace {

[[noreturn]] void refuse(const Scene& scene, const std::string& what) {
  throw InputError(schema::located_message(
      scene.file, scene.document["mesh"]["read"], "mesh.read",
      "a distributed read does not provide " + what +
          " yet; expected read: root (rank 0 reads the mesh whole) for this scene"));
}

}  // namespace

// Mixed u-p patches need their greedy choice over the whole part. Shell parts on 2D meshes and on
// surfaces read in 3D (charted from the slices: model/SurfaceSliceChart), explicit and implicit
// contact between parts (the surfaces gathered; the rows of other ranks' surface particles as
// remote ghosts: model/ContactGhosts), rigid bodies (mesh blocks taken out of the slices:
// model/SlicedRigidBlocks) and an initial state (run/InitialState) are served: rigid walls and
// bodies touch owned particles only, and a rank's part holds every cell around its owned nodes,
// so their surface (boundary sides) and boundary shares are those of the whole mesh.
void check_distributed_read(Scene& scene) {
  if (!scene.distributed_read) return;
  for (const auto& p : scene.parts)
    if (p.formulation == PartFormulation::mixed_up && p.pressure_cells == PressureCellChoice::patch)
      refuse(scene, "patch pressure cells (part '" + p.name + "', pressure_cells: patch)");
  const auto files = scene.document["output"]["files"];
  if (files && files.as<std::string>() == "gathered")
    throw InputError(schema::located_message(
        scene.file, files, "output.files",
        "no rank holds the whole mesh of a distributed read (mesh.read: distributed); expected "
        "files: per_rank (the pieces join with SEACAS epu)"));
  scene.output.per_rank_files = true;
}

}  // namespace efg
