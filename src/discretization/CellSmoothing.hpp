// Cell-averaged gradients of the shape functions over the background cells of a part, by the
// divergence theorem on each cell's boundary (strain smoothing over the cell, as SCNI smooths over
// nodal cells; Chen, Wu, Yoon & You 2001, eq. 13, with the cell as the smoothing domain):
//
//   b_cI = 1/V_c  integral over the boundary of c of phi_I n ds,    V_c = 1/dim  integral x . n ds,
//
// both with the SCNI facet points of the cell's sides (discretization/SmoothingFacets), so that
// sum_I b_cI (x) X_I = I exactly (linear fields' divergence is exact on every cell) and
// sum_c V_c b_cI = the boundary integral of phi_I n (interior sides cancel): the integration
// constraint a constant pressure field needs to pass the patch test. The mixed u-p operator
// (operators/MixedPressure) takes the cell's dilatation from these rows. A pressure cell may be a
// group of background cells (discretization/PressureCells): its boundary is then the sides of its
// cells that no other cell of the group shares (the interior sides' terms cancel).
#pragma once

#include <vector>

#include "discretization/IntegrationPoints.hpp"
#include "discretization/PressureCells.hpp"

namespace efg {

struct CellAverages {
  std::vector<std::size_t> group;  ///< the pressure cell (index into PressureCells)
  std::vector<std::size_t> cell;   ///< its lowest global cell (mesh order), its name in messages
  std::vector<double> volume;      ///< V_c (area in 2D, without thickness)
  std::vector<double> centroid;    ///< dimension per cell, for messages and output
  CsrTable gradients;              ///< b_cI, dimension values per entry, one row per cell

  std::size_t size() const { return volume.size(); }
};

/// The rows of the given pressure cells (`list`: indices into `groups`), from the cloud's shape
/// functions (owned and ghost particles; the cloud must reach every point of the groups).
CellAverages cell_averages(const BackgroundMesh& mesh, const ParticleCloud& cloud,
                           const PressureCells& groups, const std::vector<std::size_t>& list);

}  // namespace efg
