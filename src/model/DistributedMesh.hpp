// mesh.read: distributed. Every rank reads only its slice of the Exodus file
// (io/ExodusSliceReader.hpp) and keeps its own part of the mesh (parallel/LocalMesh.hpp): the
// nodes it owns (the RCB partition partition_nodes gives the whole mesh), every cell with a node
// within the halo of them, and those cells' nodes. The halo is bounded from the blocks' largest
// cells before any rank has its part: twice the largest support reach plus the largest cell
// diameter, the ghost radius of discretization/IntegrationPoints.hpp, so every ghost particle a
// rank needs finds all its cells (support size, nodal volume) in the rank's part, as on the
// whole mesh. The mesh arrays per rank then fall as 1 / ranks (docs/scaling.md).
#pragma once

#include "mesh/BackgroundMesh.hpp"
#include "model/SlicedPressurePatches.hpp"
#include "parallel/Comm.hpp"
#include "parallel/NodePartition.hpp"
#include "scene/Scene.hpp"

namespace efg {

/// The rank's part of scene.mesh_file and its owners (partition: rank, size, owner, owned).
/// Throws InputError on every rank when the file, or the scene against it, is wrong, or when the
/// scene uses what a distributed read does not provide yet.
/// `patches` receives the pressure patches of mixed u-p parts with pressure_cells: patch, chosen
/// over the whole part (model/SlicedPressurePatches).
BackgroundMesh load_distributed_mesh(const CommPtr& comm, Scene& scene, NodePartition& partition,
                                     SlicedPatches& patches);

/// The halo width of a distributed read: the largest ghost radius any part can have, from the
/// largest cell extent per block and direction (parallel/LocalMesh.hpp, BlockExtents; block
/// names in the same order).
/// `group_diameter`: the largest pressure patch's (a patch's row couples the particles of its
/// whole boundary).
double halo_width(const Scene& scene, const std::vector<std::string>& block_names,
                  const std::vector<std::vector<double>>& extents, double group_diameter = 0);

}  // namespace efg
