// mesh.read: distributed (model/DistributedMesh.hpp) serves solid parts on a rank's part of the
// mesh; what needs the whole mesh on a rank is refused where the scene is read, so `efg check`
// and `efg run` say the same.
#pragma once

#include "scene/Scene.hpp"

namespace efg {

/// For a distributed read: throws InputError at mesh.read for shells, contact, rigid bodies and
/// walls, an initial state and mixed u-p, and at output.files for gathered
/// results; otherwise makes the results one file per rank. Nothing for a read by rank 0.
void check_distributed_read(Scene& scene);

}  // namespace efg
