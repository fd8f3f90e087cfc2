// The smoothed gradients of SCNI (Chen, Wu, Yoon, You 2001, eq. 25):
//   B~_I(x_L) = 1/V_L * sum over the smoothing points p of Omega_L's boundary of phi_I(x_p) n_p w_p
// for every owned particle L (or every piece of its domain: integration scni_subcells). The rows' particle sets (the union of the neighbours of L's
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

/// Rows of B~ for `rows` smoothing domains: `points` holds every smoothing point on their
/// boundaries (others may be there too; `plus` and `minus` name domains), `phi` the shape
/// functions at them, `row_index` the row (0 .. rows - 1) of every domain id among them (-1
/// otherwise) and `row_volume` the volume of each row's domain. SCNI's domains are the nodal
/// domains of the owned particles (domain id = mesh node); Called on batches of domains
/// (IntegrationPoints), so that the shape functions at the smoothing points, about ten times the
/// size of the rows they make, are never held for a whole part at once. `global_id`: the
/// cloud's global ids on the device when the caller holds them (CloudIndex), else copied here.
CsrTable smoothed_gradients(const ParticleCloud& cloud, const std::vector<SmoothingPoint>& points,
                            const ShapeFunctionValues& phi,
                            const std::vector<LocalIndex>& row_index,
                            const std::vector<double>& row_volume,
                            DeviceView<const LocalIndex*> global_id = {});

}  // namespace efg
