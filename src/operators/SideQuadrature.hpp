// Quadrature on the sides of background cells (tractions, pressures, Nitsche terms): the
// boundary points of the SCNI smoothing rule (discretization/SmoothingFacets), so that every
// boundary integral and the SCNI divergence identity share one quadrature.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "mesh/BackgroundMesh.hpp"

namespace efg {

struct SidePoint {
  std::array<double, 3> x{};
  std::array<double, 3> normal{};  ///< outward unit normal
  double weight = 0;               ///< length (2D) or area (3D) represented
};

/// Points on side `side` of global cell `cell`.
std::vector<SidePoint> side_quadrature(const BackgroundMesh& mesh, std::size_t cell, int side);

/// The boundary sides of the blocks (discretization/SmoothingFacets boundary_sides) whose nodes
/// all lie in the node set (`in_set` flags per mesh node) that this rank integrates (the owner
/// of a side's lowest node), as (cell, side). Their count summed over the ranks is the whole
/// mesh's (on a rank's part of a distributed read the part's own boundary sides at its edge are
/// no sides of the mesh, and their lowest node is never owned here).
struct NodeSetSides {
  std::vector<std::pair<std::size_t, int>> here;
};
NodeSetSides node_set_sides(const BackgroundMesh& mesh, const std::vector<std::string>& blocks,
                            const std::vector<char>& in_set, const std::vector<int>& owner,
                            int rank);

}  // namespace efg
