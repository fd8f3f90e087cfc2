// Which rank owns each background-mesh node (future particle): recursive coordinate bisection
// by Zoltan2, plus the ghost layer each rank needs for meshfree supports.
#pragma once

#include <vector>

#include "mesh/BackgroundMesh.hpp"
#include "mesh/MeshSlice.hpp"
#include "parallel/Comm.hpp"

namespace efg {

struct NodePartition {
  int rank = 0;
  int size = 1;
  std::vector<int> owner;          ///< owning rank of every mesh node (same on all ranks)
  std::vector<LocalIndex> owned;   ///< mesh nodes owned here, ascending
  std::vector<LocalIndex> ghosts;  ///< mesh nodes owned elsewhere but needed here, ascending
  /// On a rank's part of a mesh read in slices: whole-mesh indices of nodes needed here that
  /// the part does not hold (the rows of other ranks' contact surface particles,
  /// model/ContactGhosts), ascending; their overlap entries follow the ghosts'.
  std::vector<GlobalIndex> remote_ghosts;
};

/// Partitions the nodes with Zoltan2 RCB (one part per rank); every rank gets the whole map.
/// On one rank no partitioner is called. The result is deterministic for a given rank count.
NodePartition partition_nodes(const CommPtr& comm, const BackgroundMesh& mesh);

/// Zoltan2 RCB parts (one per rank) of the nodes this rank holds: the contiguous global range
/// from `first` with `coordinates` (`dimension` each). Rank r handing the r-th slice of a mesh's
/// nodes gives the partition partition_nodes() computes, whether the mesh is whole or read in
/// slices (parallel/LocalMesh.hpp). Collective.
std::vector<int> rcb_parts(const CommPtr& comm, int dimension, GlobalIndex first,
                           const std::vector<double>& coordinates);

/// Nodes owned by other ranks lying within Euclidean distance `radius` of a node owned by `rank`
/// (the ghost layer for supports of that radius), ascending.
std::vector<LocalIndex> ghost_layer(const BackgroundMesh& mesh, const std::vector<int>& owner,
                                    int rank, double radius);

}  // namespace efg
