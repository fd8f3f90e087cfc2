// Pressure patches of mixed u-p parts (`pressure_cells: patch`, discretization/PressureCells) on
// a mesh read in slices (mesh.read: distributed). The patches are chosen greedily in node order
// over the whole part, so no rank can choose them from its own part: every rank gathers the
// part's cell connectivity from the slices (whole-mesh node indices, renumbered compactly in
// their order; coordinates only for the patches' diameters), chooses the same patches as the
// root path does, and keeps them as whole-mesh cell indices until its part of the mesh exists;
// each rank then keeps the patches all of whose cells its part holds (every patch it owns: the
// halo is grown by the largest patch diameter). What is gathered is transient but replicated:
// the part's connectivity (some 8 indices per cell) and its nodes' coordinates, on every rank
// while the patches are chosen.
#pragma once

#include <vector>

#include "discretization/PressureCells.hpp"
#include "mesh/MeshSlice.hpp"
#include "parallel/Comm.hpp"
#include "scene/Scene.hpp"

namespace efg {

/// Per scene part: its patches in whole-mesh cell indices (PressureCells::cells; `group`
/// empty), chosen over the whole part, or nothing (no patch part).
struct SlicedPatches {
  std::vector<PressureCells> part;
  double largest_diameter = 0;  ///< over every patch of every part
};

/// The patches of the scene's mixed u-p parts with pressure_cells: patch, from the slices.
/// Collective.
SlicedPatches patches_from_slices(const CommPtr& comm, const Scene& scene, const MeshSlice& slice);

}  // namespace efg
