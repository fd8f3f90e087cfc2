// Quadrature and the isoparametric map of the background cells (cell volumes; integration:
// gauss): Gauss-Legendre tensor rules
// on quads and hexes, collapsed (conical product) rules on triangles, tets and wedges
// (Stroud 1971; Karniadakis & Sherwin sec. 4.1), n points per direction.
#pragma once

#include <vector>

#include "mesh/CellTopology.hpp"

namespace efg {

struct ReferenceRule {
  std::vector<double> xi;      ///< reference coordinates, dim per point
  std::vector<double> weight;  ///< weights on the reference cell
};

/// Gauss-Legendre points and weights on [-1, 1] (n = 1..6).
void gauss_legendre(int n, std::vector<double>& points, std::vector<double>& weights);

/// A rule on the reference cell of `type` (quad, hex: [-1,1]^d; tri, tet: unit simplex; wedge:
/// unit triangle x [-1, 1]) exact for polynomials of degree 2n-1 in each collapsed direction.
ReferenceRule reference_rule(CellType type, int n);

/// Maps reference point xi of a cell with node coordinates x (dim per node) to physical
/// coordinates `point` and returns det J there (isoparametric map of the cell's nodes).
double map_to_cell(CellType type, const double* x, const double* xi, double* point);

/// The gradients of the cell's isoparametric shape functions at reference point xi, in physical
/// coordinates (`grad`: dim per node, node after node), for node coordinates x; returns det J
/// there (as map_to_cell). The finite element space of the background cells
/// (operators/AuxiliaryStiffness).
double shape_gradients(CellType type, const double* x, const double* xi, double* grad);

/// Reference coordinates of the cell's corner nodes, dim per node.
std::vector<double> reference_corners(CellType type);

}  // namespace efg
