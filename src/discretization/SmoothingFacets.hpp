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
#include "scene/Scene.hpp"

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
/// when empty), in a fixed order: cells in global order, facets in cell-topology order.
/// `cell_of_point` (optional) receives each point's global cell; `every_side` emits every side of
/// every cell, split among its nodes, not only the part's boundary (SCNI subcells: the sides
/// separate the pieces of a nodal domain). 2D
/// segments get 2 Gauss points; 3D facets are split into 4 triangles about their centre, one
/// centroid point each (exact for the linear fields of the patch test, and the same points on
/// every rank). With `inside` centroid, the facets inside a cell (between two nodes' domains)
/// get one point each where they are flat (see flat_facet_point), two where they are warped
/// (the triangles on a diagonal); the part's boundary sides keep the split rule.
std::vector<SmoothingPoint> smoothing_points(
    const BackgroundMesh& mesh, const std::vector<std::string>& blocks,
    const std::vector<char>& node_wanted = {}, std::vector<std::size_t>* cell_of_point = nullptr,
    bool every_side = false, SmoothingQuadrature inside = SmoothingQuadrature::split);

/// The rule a section's `smoothing_quadrature` stands for on a part of the given dimension
/// (`split` and `centroid` as they are). `auto`: centroid for plain SCNI with the linear basis
/// in 3D, where it evaluates 4x fewer shape functions (setup about 3x faster, results about
/// 1e-5 apart); split elsewhere: in 2D the gain is 2x on setups that are small anyway while the
/// L2 errors grow 15 % on a curved annulus, the quadratic basis uses the split rule's exactness
/// for quadratics along 2D segments, and with subcells one point per piece side made the Lame
/// cylinder's nearly incompressible L2 error 2.9x larger (docs/discretization.md).
SmoothingQuadrature facet_rule(const SectionSpec& section, int dimension);

/// The one-point rule of a flat quadrilateral facet p0..p3: the point at its area centroid with
/// the whole facet's vector area, which integrates every linear function over the facet exactly
/// (as the 4 triangles do). False, leaving `out` alone, when the facet's triangles about its
/// vertex average are not parallel to within 1e-10 (a warped facet: one point cannot carry the
/// moments x n of its triangles, so linear consistency would be lost) or it has no area.
bool flat_facet_point(const std::array<std::array<double, 3>, 4>& p, SmoothingPoint& out);

/// The boundary part of the same rule for one side of a cell: the side split among its nodes,
/// 2 Gauss points per half segment (2D) or 4 triangles per node's quarter (3D). `side_x` holds
/// the side's node coordinates (3 per node) in outward order, `side_nodes` their mesh nodes.
/// Tractions and Nitsche terms integrate with these very points, so that boundary integrals and
/// the SCNI divergence identity use one quadrature (the patch test then holds to round-off).
std::vector<SmoothingPoint> side_smoothing_points(const std::vector<std::array<double, 3>>& side_x,
                                                  const std::vector<LocalIndex>& side_nodes,
                                                  int dim);

/// The sides of the blocks' cells that no other cell of the blocks shares (the part's
/// boundary), as (global cell index, side), in global cell order.
std::vector<std::pair<std::size_t, int>> boundary_sides(const BackgroundMesh& mesh,
                                                        const std::vector<std::string>& blocks);

/// Volumes of the nodal domains by the divergence theorem over the same points,
/// V_L = 1/dim * sum over L's boundary of x . n, indexed by mesh node.
std::vector<double> smoothing_domain_volumes(const std::vector<SmoothingPoint>& points,
                                             std::size_t node_count, int dim);

}  // namespace efg
