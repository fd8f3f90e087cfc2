// The implicit penalty force between a particle of one deformable part and the facet of another
// it presses into (contact/ImplicitSurfaceContact), with or without friction; a plain template, no Trilinos,
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

#include "contact/CoulombFriction.hpp"
#include "contact/FacetProjection.hpp"

namespace efg::contact {

/// Coulomb friction of a pair (contact/CoulombFriction.hpp): the slip increment since the last
/// accepted load step is the particle's motion relative to the facet's point,
///   s = (x - x_old) - sum_a w_a (x_a - x_a,old),
/// the tangential force the return map's from the committed one, with the stick stiffness k_t.
/// Positions and force at the last accepted step are constants of the derivatives.
struct PairFriction {
  Friction law;
  const double* x_old = nullptr;            ///< the particle, 3 components
  const double (*corner_old)[3] = nullptr;  ///< the facet's nodes
  const double* ft_old = nullptr;           ///< the committed tangential force, 3 components
  double stick_stiffness = 0, dt = 1;
};

/// x: the particle; corner: the facet's count = dim nodes (2D segment, 3D triangle); force:
/// 1 + count rows, the particle's first (3 components, z = 0 in 2D). With friction, F_J gains
/// the tangential force F_t (returned in ft, 3 components; slipping: the cap acted).
template <class T>
void pair_penalty_forces(const T* x, const T (*corner)[3], int dim, double k, T (*force)[3],
                         const PairFriction* friction = nullptr, T* ft = nullptr,
                         bool* slipping = nullptr) {
  const auto p = project_on_facet(x, corner, dim, 1.0);  // the facet was chosen: no test here
  T tangential[3] = {0.0, 0.0, 0.0};
  if (friction) {
    T s[3] = {0.0, 0.0, 0.0}, trial = 0.0;
    for (int i = 0; i < dim; ++i) {
      s[i] = x[i] - friction->x_old[i];
      for (int a = 0; a < dim; ++a)
        s[i] -= p.weight[a] * (corner[a][i] - friction->corner_old[a][i]);
    }
    const T fn = -k * p.gap;
    bool slip = false;
    coulomb_return_of(friction->law, friction->ft_old, s, p.normal, friction->stick_stiffness, fn,
                      friction->dt, dim, tangential, slip, trial);
    if (slipping) *slipping = slip;
  }
  for (int i = 0; i < 3; ++i) {
    force[0][i] = -k * p.gap * p.normal[i] + tangential[i];
    if (ft) ft[i] = tangential[i];
    for (int a = 0; a < dim; ++a) force[1 + a][i] = -p.weight[a] * force[0][i];
  }
}

}  // namespace efg::contact
