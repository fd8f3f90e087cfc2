// Checks between a scene and its mesh: names of blocks and sets exist, vectors have the mesh's
// dimension, every block belongs to at most one part.
#pragma once

#include <optional>
#include <vector>

#include "mesh/BackgroundMesh.hpp"
#include "parallel/Comm.hpp"
#include "scene/Scene.hpp"

namespace efg {

/// The owners of a rank's part of a mesh read in slices (model/DistributedMesh.hpp): the checks
/// then count set sizes and sum the rigid-body test over the ranks' owned nodes.
struct MeshOwners {
  CommPtr comm;
  const std::vector<int>* owner = nullptr;  ///< owning rank of every node of the part
  int rank = 0;
};

/// Throws InputError naming the scene file, line, key path and the names the mesh does have.
/// With `owners` (a rank's part of a mesh) it is collective and every rank reaches the same
/// collective calls: what one rank alone can find (two conditions on one of its nodes) is
/// thrown at the end, for parallel/Collective.hpp's run_collectively to spread.
void check_scene_against_mesh(const Scene& scene, const BackgroundMesh& mesh,
                              const MeshOwners& owners = {});

}  // namespace efg
