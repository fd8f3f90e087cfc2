// Each rank's part of a mesh read in slices (mesh/MeshSlice.hpp), built without any rank ever
// holding the whole mesh (issue 20, item 3; docs/scaling.md, "Distributed read").
//
// The nodes are partitioned by Zoltan2 RCB from the slices (the partition partition_nodes gives
// the whole mesh, parallel/NodePartition.hpp). A rank's local mesh is then: the nodes it owns;
// every cell with a node inside the box around its owned nodes grown by the halo width on every
// side; and all nodes of those cells. With the halo at least the ghost radius, every node within
// that radius of an owned node is in the box, so its ghost particle finds every cell around it
// (support size and nodal volume as on the whole mesh), and every integration point the rank owns
// lies in a cell it holds. Node and side sets keep the entries on local nodes and cells, in file
// order.
//
// Nodes and cells are routed through their slice holders (a rendezvous: the rank that read node
// g knows its coordinates and owner, the rank that read cell c knows where it went), two
// all-to-all exchanges per item kind; no array over the whole mesh is allocated anywhere.
#pragma once

#include <functional>
#include <vector>

#include "mesh/BackgroundMesh.hpp"
#include "mesh/MeshSlice.hpp"
#include "parallel/Comm.hpp"

namespace efg {

struct LocalMesh {
  BackgroundMesh mesh;     ///< numbered here, nodes and cells ascending in `mesh.global`
  std::vector<int> owner;  ///< owning rank of every node here
};

/// The largest extent of a block's cells in each direction (`dimension` values per block, in the
/// slice's block order), over all ranks: what a halo width is derived from.
using BlockExtents = std::vector<std::vector<double>>;

/// Builds every rank's local mesh from its slice (collective). `halo_width` receives the blocks'
/// extents and returns the width by which the box around each rank's owned nodes grows.
LocalMesh distribute_mesh(const CommPtr& comm, const MeshSlice& slice,
                          const std::function<double(const BlockExtents&)>& halo_width);

}  // namespace efg
