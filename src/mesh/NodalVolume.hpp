// Nodal (particle) volumes from the background cells: each cell's volume shared equally among
// its nodes. The sum over nodes equals the mesh volume exactly.
#pragma once

#include <vector>

#include "mesh/BackgroundMesh.hpp"

namespace efg {

/// Per mesh node; nodes not in `blocks` (all blocks when empty) get 0.
std::vector<double> lumped_nodal_volumes(const BackgroundMesh& mesh,
                                         const std::vector<std::string>& blocks = {});

}  // namespace efg
