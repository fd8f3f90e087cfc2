// Tpetra maps of the particles and of their degrees of freedom: owned, and owned plus ghosts
// (overlap). Global ids are the whole mesh's node indices (on a rank's part of a mesh read in
// slices, through its GlobalNumbering); dof gid = node gid * dofs_per_node + component.
#pragma once

#include <Tpetra_Map.hpp>

#include "parallel/NodePartition.hpp"

namespace efg {

using Map = Tpetra::Map<>;
using GlobalOrdinal = Map::global_ordinal_type;

struct DofMaps {
  Teuchos::RCP<const Map> owned_nodes, overlap_nodes, owned_dofs, overlap_dofs;
  int dofs_per_node = 1;
};

/// Overlap maps list the owned entries first, then the ghosts, each ascending, then the remote
/// ghosts (partition.remote_ghosts). `numbering`: the
/// whole mesh's index of each of the partition's mesh nodes (mesh.global; empty for a whole mesh).
DofMaps make_dof_maps(const CommPtr& comm, const NodePartition& partition, int dofs_per_node,
                      const GlobalNumbering& numbering = {});

}  // namespace efg
