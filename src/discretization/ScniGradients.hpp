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

/// Rows of B~ for the owned particles [first, first + rows) of the cloud: `points` holds every
/// smoothing point on their domains' boundaries (others may be there too), `phi` the shape
/// functions at them, `volume` the nodal domain volume of every mesh node, `row_index` the row
/// (0 .. rows - 1) of every mesh node among them (-1 otherwise). Called on batches of particles
/// (IntegrationPoints), so that the shape functions at the smoothing points, about ten times the
/// size of the rows they make, are never held for a whole part at once.
CsrTable smoothed_gradients(const ParticleCloud& cloud, const std::vector<SmoothingPoint>& points,
                            const ShapeFunctionValues& phi, const std::vector<double>& volume,
                            const std::vector<LocalIndex>& row_index, std::size_t first,
                            std::size_t rows);

}  // namespace efg
