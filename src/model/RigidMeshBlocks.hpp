// Rigid bodies made of mesh blocks (`shape: mesh`, `blocks: [...]`): a die, a punch or a
// barrier meshed with the model. Their blocks are taken out of the background mesh before
// anything is discretized - their nodes are no particles, they have no stiffness - and kept as
// each body's surface (mesh/RigidSurface: the blocks' outward boundary facets,
// discretization/OrientedFacets, their nodes at the same place welded first: model/WeldedBlocks), with the cells' volume and centroid by the divergence theorem
// over those facets (exact for straight-sided cells: the origin's triangles (2D) or tetrahedra
// (3D) on each facet, signed). A block of surface cells (quad4, tri3 in a 3D mesh: a die's
// skin) is a one-sided tool: its cells are its facets, their node order (right-hand rule) gives
// the normal, the side the parts touch; it adds no volume (a body of such blocks only needs a
// mass to move, and does not turn). The remaining nodes, node sets and side sets are renumbered.
#pragma once

#include "core/Errors.hpp"
#include "mesh/BackgroundMesh.hpp"
#include "scene/Scene.hpp"

namespace efg {

/// The error about rigid body `body`'s blocks, located at rigid_bodies[body].blocks.
InputError rigid_blocks_error(const Scene& scene, std::size_t body, const std::string& message);

/// The blocks of every mesh body (validated as tools: mesh/MeshValidation).
std::vector<std::string> rigid_block_names(const Scene& scene);

/// Sets every mesh body's surface and removes its blocks from `mesh`. InputError (with the key
/// path) for a block the mesh lacks, one a part or another body also names, one that shares
/// nodes with the remaining blocks, or a mesh body in a shell scene.
void extract_rigid_blocks(Scene& scene, BackgroundMesh& mesh);

}  // namespace efg
