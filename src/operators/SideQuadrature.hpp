// Quadrature on the sides of background cells (tractions, pressures, Nitsche terms): the
// boundary points of the SCNI smoothing rule (discretization/SmoothingFacets), so that every
// boundary integral and the SCNI divergence identity share one quadrature.
#pragma once

#include <array>
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

}  // namespace efg
