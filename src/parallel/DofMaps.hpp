// Tpetra maps of the particles and of their degrees of freedom: owned, and owned plus ghosts
// (overlap). Global ids are mesh node indices; dof gid = node gid * dofs_per_node + component.
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

/// Overlap maps list the owned entries first, then the ghosts, each ascending.
DofMaps make_dof_maps(const CommPtr& comm, const NodePartition& partition, int dofs_per_node);

}  // namespace efg
