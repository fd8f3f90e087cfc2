// The bulk split of the iterative solver for mixed u-p parts (operators/BulkSplit.hpp): the
// condensed Jacobian K = A + C^T D_1 B, with A the Jacobian at the bulk modulus kappa_0 and D_1
// the cells' bulk moduli above it, kappa_1 = kappa - kappa_0. A is assembled as such (the rank-one
// part of the cells' tangent and of the transformation conditions' boundary traction at kappa_0)
// rather than as K - C^T D_1 B: the subtraction keeps the round-off of K's kappa-sized entries,
// eps kappa, in A, and on Lame's cylinder at nu = 0.499999 (kappa / mu = 5e5) that moved the
// solution by 1.3e-9 of its size, differently on 1 and 2 ranks (assembled: 4e-13 of MUMPS's).
#pragma once

#include <algorithm>

namespace efg {

/// Which bulk modulus the rank-one (kappa g (x) g) part of a mixed u-p tangent carries.
enum class BulkTangent {
  full,     ///< kappa: the Jacobian
  relieved  ///< kappa_0: the relieved matrix A of the bulk split
};

/// kappa_0 = min(kappa, 5 mu / 3), i.e. nu_0 = 1/4: compressible, where multigrid converges,
/// and below nu = 0.3, so that moderately compressible mixed parts take the same saddle-point
/// path as nearly incompressible ones.
inline double relieved_bulk_modulus(double kappa, double mu) {
  return std::min(kappa, 5.0 * mu / 3.0);
}

}  // namespace efg
