// Geometry of stabilized conforming nodal integration (SCNI; Chen, Wu, Yoon, You 2001): every
// background cell is split among its nodes (node, edge midpoints, side centroids, cell
// centroid), giving each node L its representative domain Omega_L. The smoothed gradient
//   B~_I(x_L) = 1/V_L * integral over the boundary of Omega_L of phi_I n dGamma
// needs quadrature points only on the facets that separate domains of different nodes inside a
// cell, and on the sides of the part's boundary: the facets shared by two cells separate two
// pieces of the same node's domain and cancel exactly, so they are left out.
#pragma once

#include <array>
#include <vector>

#include "mesh/BackgroundMesh.hpp"

namespace efg {

/// One boundary quadrature point of the nodal domains. Its weighted normal (unit normal x
/// quadrature weight x facet measure) points out of the domain of `plus` and into the domain of
/// `minus` (-1 when the point lies on the part's boundary).
struct SmoothingPoint {
  std::array<double, 3> x{};
  std::array<double, 3> weighted_normal{};
  LocalIndex plus = -1;
  LocalIndex minus = -1;
};

/// Smoothing points of the cells of `blocks` for which `wanted(cell's nodes)` holds (all cells
/// when empty), in a fixed order: cells in global order, facets in cell-topology order. 2D
/// segments get 2 Gauss points; 3D facets are split into 4 triangles about their centre, one
/// centroid point each (exact for the linear fields of the patch test, and the same points on
/// every rank).
std::vector<SmoothingPoint> smoothing_points(const BackgroundMesh& mesh, const std::vector<std::string>& blocks,
                                             const std::vector<char>& node_wanted = {});

/// Volumes of the nodal domains by the divergence theorem over the same points,
/// V_L = 1/dim * sum over L's boundary of x . n, indexed by mesh node.
std::vector<double> smoothing_domain_volumes(const std::vector<SmoothingPoint>& points, std::size_t node_count, int dim);

}  // namespace efg
