// The small-strain stiffness of one background cell as an isoparametric finite element (Q1 on
// quads and hexes, P1 on triangles and tets, the linear wedge): for an isotropic material
//   K_(a i)(b j) = integral of lambda dN_a/dx_i dN_b/dx_j
//                  + mu (dN_a/dx_j dN_b/dx_i + delta_ij grad N_a . grad N_b) dV
// (Hughes, The Finite Element Method, 2000, sec. 2.7), by the cell's Gauss rule of order 2.
// The auxiliary space of the iterative solver (operators/AuxiliaryStiffness). Free of Trilinos.
#pragma once

#include <vector>

#include "mesh/CellTopology.hpp"

namespace efg {

/// `ke` becomes the (n dim) x (n dim) matrix, row (a dim + i), column (b dim + j), row after row,
/// of the cell whose n nodes are at x (dim per node), times `scale` (the thickness in 2D).
void cell_stiffness(CellType type, const double* x, double lambda, double mu, double scale,
                    std::vector<double>& ke);

}  // namespace efg
