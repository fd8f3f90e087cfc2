// The smoothed gradients of SCNI (Chen, Wu, Yoon, You 2001, eq. 25):
//   B~_I(x_L) = 1/V_L * sum over the smoothing points p of Omega_L's boundary of phi_I(x_p) n_p w_p
// for every owned particle L. The rows' particle sets (the union of the neighbours of L's
// smoothing points, ordered by global id) are built on the host; the sums run as a Kokkos kernel
// with one work item per particle L that gathers its own points, so no two work items write the
// same row and every sum runs in the same order (ascending smoothing point) on any number of
// threads and ranks.
#pragma once

#include <vector>

#include "discretization/IntegrationPoints.hpp"
#include "discretization/ShapeFunctions.hpp"
#include "discretization/SmoothingFacets.hpp"

namespace efg {

/// Rows of B~ for the owned particles [0, cloud.owned_count): `phi` holds the shape functions at
/// `points`, `volume` the nodal domain volume of every mesh node, `owned_index` the cloud index
/// of every mesh node owned here (-1 otherwise).
CsrTable smoothed_gradients(const ParticleCloud& cloud, const std::vector<SmoothingPoint>& points,
                            const ShapeFunctionValues& phi, const std::vector<double>& volume,
                            const std::vector<LocalIndex>& owned_index);

}  // namespace efg
