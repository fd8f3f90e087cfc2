// mesh.read: distributed (model/DistributedMesh.hpp): every rank keeps its part of the mesh, so
// results are written one file per rank; gathered results, which need the whole mesh on a rank,
// are refused where the scene is read, so `efg check` and `efg run` say the same.
#pragma once

#include "scene/Scene.hpp"

namespace efg {

/// For a distributed read: throws InputError at output.files for gathered results; otherwise
/// makes the results one file per rank. Nothing for a read by rank 0.
void check_distributed_read(Scene& scene);

}  // namespace efg
