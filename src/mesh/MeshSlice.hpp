// One rank's share of a mesh file as read, before any partitioning: a contiguous range of the
// file's nodes, a contiguous range of its cells (in the file's block order) and a contiguous
// range of every node and side set's entries, all in the file's 0-based global numbering. Rank r
// of p holds [n r / p, n (r + 1) / p) of each, so no rank ever holds the whole mesh (issue 20,
// item 3); parallel/LocalMesh.hpp turns the slices into each rank's local mesh. Plain data.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/BackgroundMesh.hpp"

namespace efg {

/// First index of rank `rank`'s share when `count` items are dealt in contiguous ranges.
inline GlobalIndex slice_begin(GlobalIndex count, int rank, int size) {
  return count * rank / size;
}

/// The rank whose share holds item g: the last r with slice_begin(count, r, size) <= g.
inline int slice_holder(GlobalIndex count, int size, GlobalIndex g) {
  int lo = 0, hi = size - 1;
  while (lo < hi) {
    const int mid = (lo + hi + 1) / 2;
    if (slice_begin(count, mid, size) <= g)
      lo = mid;
    else
      hi = mid - 1;
  }
  return lo;
}

struct BlockSlice {
  std::string name;
  std::int64_t id = 0;  ///< Exodus block id
  CellType type = CellType::hex8;
  GlobalIndex first_cell = 0;             ///< global index of the block's first cell
  GlobalIndex cell_count = 0;             ///< cells of the whole block
  GlobalIndex first_read = 0;             ///< global index of the first cell read here
  std::vector<GlobalIndex> connectivity;  ///< global node indices of the cells read here
  std::vector<double> thickness;          ///< per cell read here, shell blocks with one
  bool has_thickness = false;             ///< the whole block carries a thickness attribute

  std::size_t read_count() const {
    return connectivity.size() / static_cast<std::size_t>(cell_node_count(type));
  }
};

struct NodeSetSlice {
  std::string name;
  std::int64_t id = 0;
  GlobalIndex first_entry = 0;     ///< position in the set of the first entry read here
  std::vector<GlobalIndex> nodes;  ///< global node indices
};

struct SideSetSlice {
  std::string name;
  std::int64_t id = 0;
  GlobalIndex first_entry = 0;
  std::vector<GlobalIndex> cells;  ///< global cell indices
  std::vector<int> sides;          ///< 0-based local side numbers
};

struct MeshSlice {
  int dimension = 3;
  std::string source;
  GlobalIndex node_count = 0;       ///< of the whole mesh
  GlobalIndex cell_count = 0;       ///< of the whole mesh
  GlobalIndex first_node = 0;       ///< global index of the first node read here
  std::vector<double> coordinates;  ///< nodes read here, `dimension` each
  std::vector<BlockSlice> blocks;   ///< every block of the file, in file order
  std::vector<NodeSetSlice> node_sets;
  std::vector<SideSetSlice> side_sets;

  std::size_t read_node_count() const {
    return coordinates.size() / static_cast<std::size_t>(dimension);
  }
};

}  // namespace efg
