// Which rank owns each background-mesh node (future particle): recursive coordinate bisection
// by Zoltan2, plus the ghost layer each rank needs for meshfree supports.
#pragma once

#include <vector>

#include "mesh/BackgroundMesh.hpp"
#include "parallel/Comm.hpp"

namespace efg {

struct NodePartition {
  int rank = 0;
  int size = 1;
  std::vector<int> owner;          ///< owning rank of every mesh node (same on all ranks)
  std::vector<LocalIndex> owned;   ///< mesh nodes owned here, ascending
  std::vector<LocalIndex> ghosts;  ///< mesh nodes owned elsewhere but needed here, ascending
};

/// Partitions the nodes with Zoltan2 RCB (one part per rank); every rank gets the whole map.
/// On one rank no partitioner is called. The result is deterministic for a given rank count.
NodePartition partition_nodes(const CommPtr& comm, const BackgroundMesh& mesh);

/// Nodes owned by other ranks lying within Euclidean distance `radius` of a node owned by `rank`
/// (the ghost layer for supports of that radius), ascending.
std::vector<LocalIndex> ghost_layer(const BackgroundMesh& mesh, const std::vector<int>& owner,
                                    int rank, double radius);

}  // namespace efg
