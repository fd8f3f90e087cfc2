// The implicit penalty's geometry (contact/ImplicitContact, contact/ImplicitSurfaceContact): a
// surface particle's share A_J of its part's boundary - each boundary side's measure split
// evenly among its nodes, x the thickness in 2D - and the boundary spacing h_J at it, the
// longest boundary side touching it. The penalty is then beta_J A_J with beta_J = alpha E / h_J,
// a pressure from the material's stiffness as Nitsche's beta, not from mass and time step.
#pragma once

#include <string>
#include <vector>

#include "model/Model.hpp"

namespace efg {

struct BoundaryShares {
  std::vector<double> area, size;  ///< per mesh node; 0 off the boundary
};

/// The shares over the boundary sides of `blocks` (thickness: the part's, 1 in 3D).
BoundaryShares boundary_shares(const BackgroundMesh& mesh, const std::vector<std::string>& blocks,
                               double thickness);

/// Part p's shares (its blocks; its thickness in 2D).
BoundaryShares part_boundary_shares(const Model& model, std::size_t p);

/// Young's modulus of part p's material (the implicit penalty's E).
double part_youngs_modulus(const Model& model, std::size_t p);

/// The implicit penalty of boundary node n, k = alpha E / h A (0 off the boundary).
inline double penalty_stiffness(const BoundaryShares& s, std::size_t n, double alpha, double E) {
  return s.area[n] > 0 ? alpha * E / s.size[n] * s.area[n] : 0.0;
}

}  // namespace efg
