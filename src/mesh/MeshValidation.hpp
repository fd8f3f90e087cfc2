// Consistency checks of a background mesh read from a file or generated: every index in range,
// every cell with positive volume and positive Jacobian at its corners.
#pragma once

#include "mesh/BackgroundMesh.hpp"

namespace efg {

/// Throws InputError naming the mesh source, the block or set, the cell and what is wrong.
void validate_mesh(const BackgroundMesh& mesh);

/// Relative tolerance below which a cell counts as degenerate (volume / bounding-box volume).
inline constexpr double degenerate_cell_tolerance = 1e-12;

}  // namespace efg
