#include "scene/DistributedReadChecks.hpp"

#include "core/Errors.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {

// Everything a scene holds is served on a mesh read in slices: shell parts on 2D meshes and on
// surfaces read in 3D (charted from the slices: model/SurfaceSliceChart), mixed u-p pressure
// patches (chosen over the whole part: model/SlicedPressurePatches), explicit and implicit
// contact between parts (the surfaces gathered; the rows of other ranks' surface particles as
// remote ghosts: model/ContactGhosts), rigid bodies (mesh blocks taken out of the slices:
// model/SlicedRigidBlocks) and an initial state (run/InitialState): rigid walls and
// bodies touch owned particles only, and a rank's part holds every cell around its owned nodes,
// so their surface (boundary sides) and boundary shares are those of the whole mesh.
void check_distributed_read(Scene& scene) {
  if (!scene.distributed_read) return;
  const auto files = scene.document["output"]["files"];
  if (files && files.as<std::string>() == "gathered")
    throw InputError(schema::located_message(
        scene.file, files, "output.files",
        "no rank holds the whole mesh of a distributed read (mesh.read: distributed); expected "
        "files: per_rank (the pieces join with SEACAS epu)"));
  scene.output.per_rank_files = true;
}

}  // namespace efg
