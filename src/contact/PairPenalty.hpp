// The implicit penalty force between a particle of one deformable part and the facet of another
// it presses into (contact/ImplicitSurfaceContact), frictionless; a plain template, no Trilinos,
// evaluated on doubles for the residual and on forward-AD numbers for the tangent. With the
// facet's projection (contact/FacetProjection.hpp: gap g < 0 inside, outward unit normal n,
// clipped weights w_a summing to one), the force on the particle J and on the facet's nodes a:
//   F_J = k (-g) n,   F_a = -w_a F_J,
// k = beta_J A_J (contact/BoundaryShares.hpp): the particle and the facet receive equal and
// opposite forces (momentum kept; the moment of the pair is second order in the penetration).
// The derivatives of g, n and w with respect to every point - the particle and the facet's
// nodes - are the consistent tangent of the node-to-segment contact; forward AD takes them
// exactly (a clipped weight is constant where clipped).
#pragma once

#include "contact/FacetProjection.hpp"

namespace efg::contact {

/// x: the particle; corner: the facet's count = dim nodes (2D segment, 3D triangle); force:
/// 1 + count rows, the particle's first (3 components, z = 0 in 2D).
template <class T>
void pair_penalty_forces(const T* x, const T (*corner)[3], int dim, double k, T (*force)[3]) {
  const auto p = project_on_facet(x, corner, dim, 1.0);  // the facet was chosen: no test here
  for (int i = 0; i < 3; ++i) {
    force[0][i] = -k * p.gap * p.normal[i];
    for (int a = 0; a < dim; ++a) force[1 + a][i] = -p.weight[a] * force[0][i];
  }
}

}  // namespace efg::contact
