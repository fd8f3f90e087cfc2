// Rigid bodies made of mesh blocks on a distributed read (mesh.read: distributed): the root path
// takes their blocks out of the whole mesh before anything is partitioned (model/
// RigidMeshBlocks.hpp); here the same happens to the slices, so that every rank ends with the
// slices of the very mesh the root path partitions. Every rank gathers the rigid blocks whole
// (their cells from every slice, their nodes' coordinates from the slices' holders: a tool's
// mesh is small beside the parts') and sets each mesh body's surface from them as the root path
// does; the slices then lose the rigid cells and nodes, the rest is renumbered as the root path
// renumbers it (nodes and cells in order, the rigid ones skipped), and nodes and cells are dealt
// again in slice_begin's ranges of the smaller mesh (node and side set entries travel by index,
// their positions only order them).
#pragma once

#include "mesh/MeshSlice.hpp"
#include "parallel/Comm.hpp"
#include "scene/Scene.hpp"

namespace efg {

/// Collective; nothing to do without mesh bodies. InputError (on every rank, through
/// run_collectively) as extract_rigid_blocks gives it.
void take_rigid_blocks_from_slices(const CommPtr& comm, Scene& scene, MeshSlice& slice);

}  // namespace efg
