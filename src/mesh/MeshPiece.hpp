// One rank's piece of the background mesh, for results written one file per rank (SEACAS's
// decomposed files, joined by `epu`; docs/scaling.md, "Results one file per rank"). Each cell
// goes to the rank owning its lowest node (the rule of discretization/CellOwner.hpp), so every
// cell is in exactly one piece; a piece's nodes are the rank's own nodes and the other nodes of
// its cells (those on the cut appear in several pieces, as in any decomposed Exodus file). Node
// and side sets keep the entries inside the piece. Plain data: no communication.
#pragma once

#include <functional>
#include <vector>

#include "mesh/BackgroundMesh.hpp"

namespace efg {

struct MeshPiece {
  BackgroundMesh mesh;            ///< numbered within the piece, nodes ascending in global index
  std::vector<LocalIndex> nodes;  ///< the whole mesh's index of every piece node
  std::vector<LocalIndex> cells;  ///< the whole mesh's cell index of every piece cell
};

/// The piece of `mesh` of the rank for which `owns(node)` holds (node: the whole mesh's index).
MeshPiece mesh_piece(const BackgroundMesh& mesh, const std::function<bool(LocalIndex)>& owns);

}  // namespace efg
