// The background mesh: nodes (the future particles), cells grouped in blocks, node and side sets.
// Plain data, shared by the reader, the generator, the writer and the discretization.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/CellTopology.hpp"

namespace efg {

using LocalIndex = std::int32_t;
using GlobalIndex = std::int64_t;

struct ElementBlock {
  std::string name;
  std::int64_t id = 0;  ///< Exodus block id
  CellType type = CellType::hex8;
  std::vector<LocalIndex> connectivity;  ///< 0-based mesh node indices, cell after cell
  /// Shell blocks read from Exodus: each cell's thickness (its "thickness" attribute, or its
  /// only attribute); empty when the block carries none.
  std::vector<double> thickness;

  std::size_t cell_count() const {
    return connectivity.size() / static_cast<std::size_t>(cell_node_count(type));
  }
};

struct NodeSet {
  std::string name;
  std::int64_t id = 0;
  std::vector<LocalIndex> nodes;  ///< 0-based mesh node indices
};

/// Cells are numbered globally in block order (Exodus convention), 0-based here.
struct SideSet {
  std::string name;
  std::int64_t id = 0;
  std::vector<LocalIndex> cells;  ///< 0-based global cell indices
  std::vector<int> sides;         ///< 0-based local side numbers
};

/// The whole mesh's numbering of a rank's part of it (a mesh read in slices,
/// parallel/LocalMesh.hpp): the whole mesh's index of every node and cell here, both ascending,
/// and the whole mesh's sizes.
struct GlobalNumbering {
  std::vector<GlobalIndex> nodes, cells;
  GlobalIndex node_count = 0, cell_count = 0;
  std::vector<double> lower, upper;  ///< the whole mesh's bounding box, `dimension` each
};

/// The plane a shell surface read in 3D is projected onto for its chart (mesh/SurfaceChart.hpp):
/// through `origin`, chart axes e1 and e2, unit normal.
struct SurfaceProjection {
  std::array<double, 3> origin{}, e1{}, e2{}, normal{};
};

struct BackgroundMesh {
  int dimension = 3;
  std::vector<double> coordinates;  ///< node after node, `dimension` components each
  std::vector<ElementBlock> blocks;
  std::vector<NodeSet> node_sets;
  std::vector<SideSet> side_sets;
  std::string source;  ///< file name or generator description, for messages
  /// A shell surface read as a 3D mesh of 2D cells (SHELL4, QUAD4, TRI3; mesh/SurfaceChart.hpp):
  /// its nodes' 3D positions, 3 per node, while `coordinates` hold their 2D chart coordinates
  /// (dimension 2). Empty for every other mesh.
  std::vector<double> surface;
  /// With `surface`: the projection of the whole surface (the chart's plane; the same on every
  /// rank, also when a rank holds only its part of the surface).
  SurfaceProjection chart_plane;
  /// Set on a rank's part of a mesh read in slices; empty for a whole mesh, whose indices are the
  /// global ones.
  GlobalNumbering global;

  std::size_t node_count() const {
    return coordinates.size() / static_cast<std::size_t>(dimension);
  }
  std::size_t cell_count() const;

  /// A rank's part of a mesh (read in slices), not the whole mesh.
  bool is_part() const { return global.node_count > 0; }
  /// The whole mesh's index of node `n` / cell `c` of this mesh.
  GlobalIndex global_node(std::size_t n) const {
    return is_part() ? global.nodes[n] : static_cast<GlobalIndex>(n);
  }
  GlobalIndex global_cell(std::size_t c) const {
    return is_part() ? global.cells[c] : static_cast<GlobalIndex>(c);
  }
  /// This mesh's index of the whole mesh's node `id`, or -1 when it is not here.
  LocalIndex node_of(GlobalIndex id) const;
  /// Nodes and cells of the whole mesh.
  GlobalIndex whole_node_count() const {
    return is_part() ? global.node_count : static_cast<GlobalIndex>(node_count());
  }
  GlobalIndex whole_cell_count() const {
    return is_part() ? global.cell_count : static_cast<GlobalIndex>(cell_count());
  }

  const ElementBlock* find_block(const std::string& name) const;
  const NodeSet* find_node_set(const std::string& name) const;
  const SideSet* find_side_set(const std::string& name) const;

  /// The block and the local cell index within it of global cell `cell`.
  std::pair<const ElementBlock*, std::size_t> locate_cell(std::size_t cell) const;
  /// Mesh node indices of one side of one cell.
  std::vector<LocalIndex> side_node_indices(std::size_t cell, int side) const;
};

}  // namespace efg
