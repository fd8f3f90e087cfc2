// Consistency checks of a background mesh read from a file or generated: every index in range,
// every cell with positive volume and positive Jacobian at its corners.
#pragma once

#include <string>
#include <vector>

#include "mesh/BackgroundMesh.hpp"

namespace efg {

/// Throws InputError naming the mesh source, the block or set, the cell and what is wrong.
/// `tool_blocks`: blocks of rigid bodies (model/RigidMeshBlocks), which may also hold surface
/// cells (one dimension lower: a die's surface) and whose cells need no positive volume.
void validate_mesh(const BackgroundMesh& mesh, const std::vector<std::string>& tool_blocks = {});

/// Relative tolerance below which a cell counts as degenerate (volume / bounding-box volume).
inline constexpr double degenerate_cell_tolerance = 1e-12;

}  // namespace efg
