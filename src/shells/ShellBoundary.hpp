// Points on the edges of a shell part that a node set covers: the boundary points of the SCNI
// smoothing rule (operators/SideQuadrature), so that every edge integral and the smoothed
// strains share one quadrature, each with the shape functions and direct gradients of the
// particles that reach it. Used by the transformation conditions' edge traction term
// (shells/ShellConstraints) and by edge loads.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "model/Model.hpp"

namespace efg {

struct ShellEdgePoint {
  std::size_t part = 0;
  std::array<double, 2> x{}, normal{};  ///< position, outward unit normal (in the plane)
  double length = 0;                    ///< edge length the point represents
  double spacing = 0;                   ///< particle spacing there (shells/ShellSpacing.hpp)
  std::vector<LocalIndex> node;         ///< mesh nodes of the particles reaching it
  std::vector<double> phi, grad;        ///< value and direct gradient (2 per particle)
};

/// The points of this rank's edges (an edge belongs to the owner of its lowest node) whose
/// nodes all lie in `node_set`; `sides_found` counts the covered edges of every rank (the mesh
/// is the same on all ranks).
std::vector<ShellEdgePoint> shell_edge_points(const Model& model, const std::string& node_set,
                                              long long* sides_found = nullptr);

}  // namespace efg
