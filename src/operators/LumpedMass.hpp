// The lumped (diagonal) mass of the generalized particle dofs: the row sums of the consistent
// mass, M_I = sum_J integral rho phi_I phi_J = integral rho phi_I (the shape functions sum to
// one), integrated with the part's integration points. Row-sum lumping keeps the total mass
// exact and, with SCNI, gives M_I = rho V_I up to the spread of phi_I over neighbouring nodes.
#pragma once

#include "operators/ModelOperators.hpp"

namespace efg {

/// Owned dofs; every component of a particle gets its mass. Throws InputError when a part's
/// material has no density, NumericalError (naming the particle) for a mass <= 0.
Vector lumped_mass(const ModelOperators& ops);

}  // namespace efg
